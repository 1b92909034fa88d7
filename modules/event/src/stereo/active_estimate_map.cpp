// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "common/timestamp_math.hpp"
#include "stereo/active_estimate_map.hpp"

namespace cv {
namespace event {
namespace detail {

void ActiveEstimateMap::reset(Size size)
{
    size_ = size;
    until_.assign((size_t)size.area(), NO_ESTIMATE);
    disparity_.assign((size_t)size.area(), -1.f);
    blocksPerRow_ = divUp(size.width, (int)ESTIMATE_BLOCK);
    blockUntil_.assign((size_t)size.height * blocksPerRow_, 0);
    lastEventTime_.assign((size_t)size.area(), 0);
}

void ActiveEstimateMap::remember(Point r, int64 t, int64 activeFor, float disparity)
{
    const size_t i = (size_t)r.y * size_.width + r.x;
    lastEventTime_[i] = t;
    disparity_[i] = disparity;
    if (disparity < 0)
    {
        until_[i] = NO_ESTIMATE;
        return;
    }
    const int64 until = timeAfter(t, activeFor);
    until_[i] = until;
    int64& block = blockUntil_[(size_t)r.y * blocksPerRow_ + r.x / ESTIMATE_BLOCK];
    block = std::max(block, until);
}

size_t ActiveEstimateMap::median(Point centre, int rows, int columns, int64 t, std::vector<float>& disparities,
                                 float& median) const
{
    return sampledMedian(centre, rows, columns, 1, t, disparities, median);
}

namespace {

// The whole-pixel bin of an estimate (>= 0: remember() keeps no negative one); the last bin takes every larger one.
enum { PIXEL_BINS = 128, FRACTION_BINS = 64 };
inline int pixelBin(float d)
{
    return (int)std::min(d, (float)(PIXEL_BINS - 1));
}

// The 1/64 px bin of an estimate within its whole-pixel bin p (exact: d - p is, for d in [p, 2p] or p = 0).
inline int fractionBin(float d, int p)
{
    return std::min((int)((d - (float)p) * FRACTION_BINS), FRACTION_BINS - 1);
}

// The bin holding rank k of the counts, and k's rank within it.
inline int binOfRank(const int* counts, size_t& k)
{
    int b = 0;
    while (k >= (size_t)counts[b])
        k -= (size_t)counts[b++];
    return b;
}

// The value of rank k (0-based) among v[0, n), as std::nth_element finds it (v may be reordered). A window holds
// a few hundred estimates in random order, and nth_element's comparisons branch on each; counting does not: by
// whole pixels, then by 1/64 px within the pixel that holds rank k, then among that 1/64 px's few values.
float valueOfRank(float* v, size_t n, size_t k)
{
    // Below MIN_COUNTED values, clearing and scanning the counts costs more than it saves.
    enum { MIN_COUNTED = 64, MAX_COUNTED = 1024 };
    if (n < MIN_COUNTED || n > MAX_COUNTED)
    {
        std::nth_element(v, v + k, v + n);
        return v[k];
    }
    // Four sets of counts, one per position modulo 4: the values of one window fall in few bins, and counting
    // them in one array would wait on the previous increment of the same bin at every value.
    int pixels[4][PIXEL_BINS] = {};
    size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (int j = 0; j < 4; j++)
            pixels[j][pixelBin(v[i + j])]++;
    for (; i < n; i++)
        pixels[0][pixelBin(v[i])]++;
    for (int b = 0; b < PIXEL_BINS; b++)
        pixels[0][b] += pixels[1][b] + pixels[2][b] + pixels[3][b];
    const int p = binOfRank(pixels[0], k);
    int fractions[4][FRACTION_BINS + 1] = {};  // the last bin: the values of the other pixels
    uchar code[MAX_COUNTED];
    for (i = 0; i < n; i++)
        code[i] = (uchar)(pixelBin(v[i]) == p ? fractionBin(v[i], p) : (int)FRACTION_BINS);
    for (i = 0; i + 4 <= n; i += 4)
        for (int j = 0; j < 4; j++)
            fractions[j][code[i + j]]++;
    for (; i < n; i++)
        fractions[0][code[i]]++;
    for (int b = 0; b <= FRACTION_BINS; b++)
        fractions[0][b] += fractions[1][b] + fractions[2][b] + fractions[3][b];
    const int f = binOfRank(fractions[0], k);
    // The values of that 1/64 px, every value written and the count advanced past the chosen ones.
    float chosen[MAX_COUNTED];
    size_t m = 0;
    for (i = 0; i < n; i++)
    {
        chosen[m] = v[i];
        m += code[i] == f;
    }
    // Often one value repeated (whole-pixel estimates, an estimate copied): then there is nothing to select.
    if (std::all_of(chosen + 1, chosen + m, [&chosen](float d) { return d == chosen[0]; }))
        return chosen[0];
    std::nth_element(chosen, chosen + k, chosen + m);
    return chosen[k];
}

}  // namespace

size_t ActiveEstimateMap::sampledMedian(Point centre, int rows, int columns, int rowStep, int64 t,
                                        std::vector<float>& disparities, float& median) const
{
    const int x0 = std::max(0, centre.x - columns), x1 = std::min(size_.width - 1, centre.x + columns);
    int y = centre.y - rows;
    if (y < 0)
        y += (-y + rowStep - 1) / rowStep * rowStep;  // the first sampled row inside the image
    const int y1 = std::min(size_.height - 1, centre.y + rows);
    if (x0 > x1 || y > y1)
    {
        disparities.clear();
        return 0;
    }
    // Blocks where nothing can be active are skipped; the kernel stores whole vectors past its count.
    disparities.resize((size_t)((y1 - y) / rowStep + 1) * (size_t)(x1 - x0 + 1) + ESTIMATE_GATHER_PAD);
    float* const out = disparities.data();
    size_t n = 0;
    const EstimateGatherFn gather = gather_;
    forEachLiveBlockRun(x0, x1, y, y1, rowStep, t, [t, out, &n, gather](const int64* until, const float* disparity, int xa, int xe) {
        n += (size_t)gather(until + xa, disparity + xa, xe - xa + 1, t, out + n);
    });
    disparities.resize(n);
    if (n == 0)
        return 0;
    median = valueOfRank(out, n, n / 2);
    return n;
}

void ActiveEstimateMap::sumNear(int x0, int x1, int y0, int y1, int64 t, float value, float tolerance, double& sum,
                                int& n) const
{
    x0 = std::max(0, x0);
    x1 = std::min(size_.width - 1, x1);
    for (int y = std::max(0, y0); y <= std::min(size_.height - 1, y1); y++)
    {
        const int64* until = &until_[(size_t)y * size_.width];
        const float* disparity = &disparity_[(size_t)y * size_.width];
        for (int x = x0; x <= x1; x++)
        {
            // Adding 0 leaves the sum as it was: the same additions in the same order as a branch would make.
            const bool near = t < until[x] && std::abs(disparity[x] - value) <= tolerance;
            sum += near ? (double)disparity[x] : 0.0;
            n += near;
        }
    }
}

bool ActiveEstimateMap::shownAt(int x, int y, double t, float& disparity) const
{
    const size_t i = (size_t)y * size_.width + x;
    if (until_[i] == NO_ESTIMATE || !((double)lastEventTime_[i] <= t && t < (double)until_[i]))
        return false;
    disparity = disparity_[i];
    return true;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
