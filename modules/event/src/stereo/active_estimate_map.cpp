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
    rowTime_.assign((size_t)size.height, 0);
    disparity_.assign((size_t)size.area(), -1.f);
    blocksPerRow_ = divUp(size.width, (int)ESTIMATE_BLOCK);
    blockUntil_.assign((size_t)size.height * blocksPerRow_, 0);
    lastEventTime_.assign((size_t)size.area(), 0);
}

namespace {

// a - b clamped to [lowest, INT32_MAX], without overflow whatever the two times.
inline int32_t clampedDifference(int64 a, int64 b, int32_t lowest)
{
    if (a >= b)
    {
        const uint64 d = (uint64)a - (uint64)b;
        return d > (uint64)std::numeric_limits<int32_t>::max() ? std::numeric_limits<int32_t>::max() : (int32_t)d;
    }
    const uint64 d = (uint64)b - (uint64)a;
    return d >= (uint64)-(int64)lowest ? lowest : (int32_t)-(int64)d;
}

}  // namespace

int32_t ActiveEstimateMap::offsetInRow(int y, int64 t) const
{
    return clampedDifference(t, rowTime_[(size_t)y], ENDED_LONG_AGO);
}

void ActiveEstimateMap::moveRowTime(int y, int64 time)
{
    int64& rowTime = rowTime_[(size_t)y];
    int32_t* until = &until_[(size_t)y * size_.width];
    for (int x = 0; x < size_.width; x++)
        if (until[x] != NO_ESTIMATE && until[x] != ENDED_LONG_AGO)
            until[x] = clampedDifference(rowTime + until[x], time, ENDED_LONG_AGO);
    rowTime = time;
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
    int32_t offset = clampedDifference(until, rowTime_[(size_t)r.y], ENDED_LONG_AGO);
    if (offset == ENDED_LONG_AGO || offset == std::numeric_limits<int32_t>::max())
    {
        moveRowTime(r.y, t);
        offset = clampedDifference(until, t, ENDED_LONG_AGO);  // INT32_MAX past t at most
    }
    until_[i] = offset;
    int64& block = blockUntil_[(size_t)r.y * blocksPerRow_ + r.x / ESTIMATE_BLOCK];
    block = std::max(block, rowTime_[(size_t)r.y] + offset);
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

// The bin (code) holding rank k among the n codes, and k's rank within it. Four sets of counts, one per position
// modulo 4: the values of one window fall in few bins, and counting them in one array would wait on the previous
// increment of the same bin at every value.
template <int BINS>
int binOfRank(const uchar* code, size_t n, size_t& k)
{
    int counts[4][BINS] = {};
    size_t i = 0;
    for (; i + 4 <= n; i += 4)
        for (int j = 0; j < 4; j++)
            counts[j][code[i + j]]++;
    for (; i < n; i++)
        counts[0][code[i]]++;
    int b = 0;
    for (;; b++)
    {
        const size_t inBin = (size_t)(counts[0][b] + counts[1][b] + counts[2][b] + counts[3][b]);
        if (k < inBin)
            return b;
        k -= inBin;
    }
}

// The value of rank k (0-based) among v[0, n), as std::nth_element finds it (v may be reordered). A window holds
// a few hundred estimates in random order, and nth_element's comparisons branch on each; counting does not: by
// whole pixels, then by 1/64 px among the values of the pixel that holds rank k, then among that 1/64 px's few
// values. A bin is a range of values (the bins' ends are exact floats), so the values of one are those the range
// kernel keeps.
float valueOfRank(float* v, size_t n, size_t k, ValuesInRangeFn valuesInRange)
{
    // Below MIN_COUNTED values, clearing and scanning the counts costs more than it saves.
    enum { MIN_COUNTED = 64, MAX_COUNTED = 1024 };
    if (n < MIN_COUNTED || n > MAX_COUNTED)
    {
        std::nth_element(v, v + k, v + n);
        return v[k];
    }
    uchar code[MAX_COUNTED];
    for (size_t i = 0; i < n; i++)
        code[i] = (uchar)pixelBin(v[i]);
    const int p = binOfRank<PIXEL_BINS>(code, n, k);
    const float unbounded = std::numeric_limits<float>::infinity();
    const float pixelEnd = p == PIXEL_BINS - 1 ? unbounded : (float)(p + 1);
    float chosen[MAX_COUNTED + VALUES_IN_RANGE_PAD];
    const size_t m = valuesInRange(v, n, (float)p, pixelEnd, chosen);
    for (size_t i = 0; i < m; i++)
        code[i] = (uchar)fractionBin(chosen[i], p);
    const int f = binOfRank<FRACTION_BINS>(code, m, k);
    const float fractionEnd = f == FRACTION_BINS - 1 ? pixelEnd : (float)p + (float)(f + 1) / FRACTION_BINS;
    const size_t c = valuesInRange(chosen, m, (float)p + (float)f / FRACTION_BINS, fractionEnd, chosen);
    // Often one value repeated (whole-pixel estimates, an estimate copied): then there is nothing to select.
    if (std::all_of(chosen + 1, chosen + c, [&chosen](float d) { return d == chosen[0]; }))
        return chosen[0];
    std::nth_element(chosen, chosen + k, chosen + c);
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
    const int block0 = x0 / ESTIMATE_BLOCK, block1 = x1 / ESTIMATE_BLOCK;
    for (; y <= y1; y += rowStep)
    {
        const size_t row = (size_t)y * size_.width;
        const int64* blockUntil = &blockUntil_[(size_t)y * blocksPerRow_];
        const int32_t tInRow = offsetInRow(y, t);
        for (int b = block0; b <= block1; b++)
            if (t < blockUntil[b])
            {
                const int xa = std::max(x0, b * (int)ESTIMATE_BLOCK), xe = std::min(x1, (b + 1) * (int)ESTIMATE_BLOCK - 1);
                n += (size_t)gather_(&until_[row + xa], &disparity_[row + xa], xe - xa + 1, tInRow, out + n);
            }
    }
    disparities.resize(n);
    if (n == 0)
        return 0;
    median = valueOfRank(out, n, n / 2, valuesInRange_);
    return n;
}

void ActiveEstimateMap::sumNear(int x0, int x1, int y0, int y1, int64 t, float value, float tolerance, double& sum,
                                int& n) const
{
    x0 = std::max(0, x0);
    x1 = std::min(size_.width - 1, x1);
    y0 = std::max(0, y0);
    y1 = std::min(size_.height - 1, y1);
    // Every estimate the sum can take lies within tolerance of value (and a float's rounding of that). From 2^-14
    // on, a float is a multiple of 2^-37, and sums of such below 2^16 are exact in a double: then the order of
    // the additions does not change the sum, and the kernel's (vector lanes, no wait on the previous addition)
    // gives the one an ordered loop gives. Outside that range (estimates near 0, a huge window or disparity, a sum
    // that is no such multiple) the additions keep their order.
    const double lowest = (double)value - tolerance, highest = (double)value + tolerance + 1;
    const double pixels = (double)(x1 - x0 + 1) * (double)(y1 - y0 + 1);
    const double scaled = std::ldexp(sum, 37);
    const bool exact = lowest >= 0x1p-13 && std::abs(sum) < 0x1p15 && scaled == std::floor(scaled) &&
                       pixels * highest < 0x1p15;
    for (int y = y0; y <= y1; y++)
    {
        const int32_t* until = &until_[(size_t)y * size_.width + x0];
        const float* disparity = &disparity_[(size_t)y * size_.width + x0];
        const int32_t tInRow = offsetInRow(y, t);
        if (exact)
        {
            n += nearSum_(until, disparity, x1 - x0 + 1, tInRow, value, tolerance, sum);
            continue;
        }
        for (int x = 0; x <= x1 - x0; x++)
        {
            const bool near = (tInRow < until[x]) & (std::abs(disparity[x] - value) <= tolerance);
            sum += near ? (double)disparity[x] : 0.0;
            n += near;
        }
    }
}

bool ActiveEstimateMap::shownAt(int x, int y, double t, float& disparity) const
{
    const size_t i = (size_t)y * size_.width + x;
    if (until_[i] == NO_ESTIMATE || until_[i] == ENDED_LONG_AGO)
        return false;
    const int64 until = rowTime_[(size_t)y] + until_[i];
    if (!((double)lastEventTime_[i] <= t && t < (double)until))
        return false;
    disparity = disparity_[i];
    return true;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
