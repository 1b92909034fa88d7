// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The neighbours' estimates as the matcher reads them: ActiveEstimateMap's windowed median and near-sum against
// the test's own record of what it remembered (each pixel's last estimate and when it ends), the median taken
// by std::nth_element. Windows of every size from one pixel to 51 x 51, with every row or every second or
// third row, clipped at every border, hold from none to thousands of estimates; the disparities include
// whole pixels, exact multiples of 1/64 px, long runs of one value, values beyond 127 px and values below
// 1e-9 px. The vector kernels against their scalar references: the scan's over runs of every length up to 40
// from every alignment, times at and around the ends of the estimates (t < until is the test: equal is
// inactive) and the 64-bit extremes; the selection's over the median's bins (whole pixels, 1/64 px, the last
// one unbounded), values on and beside their ends, in place and not; the near-sum's over values on and beside
// the tolerance's ends.

#include "test_precomp.hpp"
#include "stereo/active_estimate_map.hpp"
#include "stereo/estimate_gather.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

// What the test remembered at each pixel: the estimate and the end of its activity (none: INT64_MIN).
struct RememberedEstimates
{
    Size size;
    std::vector<int64> until;
    std::vector<float> disparity;

    explicit RememberedEstimates(Size s) : size(s), until((size_t)s.area(), std::numeric_limits<int64>::min()), disparity((size_t)s.area(), -1.f) {}

    void remember(ActiveEstimateMap& map, Point r, int64 t, int64 activeFor, float d)
    {
        map.remember(r, t, activeFor, d);
        const size_t i = (size_t)r.y * size.width + r.x;
        disparity[i] = d;
        until[i] = d < 0 ? std::numeric_limits<int64>::min() : t + activeFor;
    }

    bool active(int x, int y, int64 t) const { return t < until[(size_t)y * size.width + x]; }
    float at(int x, int y) const { return disparity[(size_t)y * size.width + x]; }
};

// Disparities of five kinds: continuous, on a 1/64 px grid (the edges of the map's finest counts), whole pixels
// with long runs of one value, far ones (beyond 127 px, and 0), and a pixel's worth of values half of which are
// tiny (below 1e-9 px: a sum of them and the others is rounded, so its order matters).
float drawDisparity(RNG& rng, int kind)
{
    switch (kind)
    {
    case 0: return rng.uniform(0.f, 40.f);
    case 1: return 12.f + (float)rng.uniform(-64, 128) / 64.f;
    case 2: return (float)rng.uniform(9, 12);
    case 3: return rng.uniform(0, 4) == 0 ? 0.f : rng.uniform(120.f, 300.f);
    default: return rng.uniform(0, 2) == 0 ? rng.uniform(1e-12f, 1e-9f) : rng.uniform(0.f, 1.f);
    }
}

// Fills a DAVIS240-sized map: each pixel remembered up to three times at times 0..999 (the last one counts),
// active for 1..400 us, a tenth of them with no estimate (a negative disparity).
void fillMap(RNG& rng, int kind, double density, ActiveEstimateMap& map, RememberedEstimates& mine)
{
    map.reset(mine.size);
    for (int y = 0; y < mine.size.height; y++)
        for (int x = 0; x < mine.size.width; x++)
        {
            if (rng.uniform(0., 1.) >= density)
                continue;
            int64 t = 0;
            for (int k = rng.uniform(1, 4); k > 0; k--)
            {
                t += rng.uniform(0, 334);
                const float d = rng.uniform(0, 10) == 0 ? -1.f : drawDisparity(rng, kind);
                mine.remember(map, Point(x, y), t, rng.uniform(1, 401), d);
            }
        }
}

TEST(Event_ActiveEstimateMap, median_is_the_middle_value_of_the_active_estimates_of_the_sampled_rows)
{
    RNG rng(23);
    const Size size(240, 180);
    std::vector<float> got, expected;
    int windowsBySize[3] = {};  // fewer than 64 estimates, 64..1024, more
    for (int kind = 0; kind < 5; kind++)
        for (double density : { 0.05, 0.5, 1.0 })
        {
            ActiveEstimateMap map;
            RememberedEstimates mine(size);
            fillMap(rng, kind, density, map, mine);
            for (int trial = 0; trial < 200; trial++)
            {
                // Centres up to a few pixels outside the image, so that windows are clipped on every side.
                const Point centre(rng.uniform(-3, size.width + 3), rng.uniform(-3, size.height + 3));
                // Every fourth window 51 x 51 with every row: the most estimates one window holds.
                const bool largest = trial % 4 == 0;
                const int rows = largest ? 25 : rng.uniform(0, 26), columns = largest ? 25 : rng.uniform(0, 26);
                const int step = largest ? 1 : rng.uniform(1, 4);
                const int64 t = rng.uniform(0, 1200);
                expected.clear();
                for (int y = centre.y - rows; y <= centre.y + rows; y += step)
                    for (int x = centre.x - columns; x <= centre.x + columns; x++)
                        if (y >= 0 && y < size.height && x >= 0 && x < size.width && mine.active(x, y, t))
                            expected.push_back(mine.at(x, y));
                float median = -100.f;
                const size_t n = map.sampledMedian(centre, rows, columns, step, t, got, median);
                ASSERT_EQ(expected.size(), n);
                ASSERT_EQ(n, got.size());
                windowsBySize[n < 64 ? 0 : n <= 1024 ? 1 : 2]++;
                if (n == 0)
                    continue;
                std::nth_element(expected.begin(), expected.begin() + (std::ptrdiff_t)(n / 2), expected.end());
                ASSERT_EQ(expected[n / 2], median) << "kind " << kind << ", " << n << " estimates";
                // The same estimates, in any order.
                std::sort(expected.begin(), expected.end());
                std::sort(got.begin(), got.end());
                ASSERT_EQ(expected, got);
            }
        }
    // The draw covers every path of the selection.
    EXPECT_GT(windowsBySize[0], 100);
    EXPECT_GT(windowsBySize[1], 100);
    EXPECT_GT(windowsBySize[2], 20);
}

// As the averaging reads it: two windows (the event's and its counterpart's) added to one sum that starts at the
// event's own estimate. The sum must be the one row-order additions give, bit for bit, whatever order the map adds
// in; the draw includes estimates near 0 (tiny ones among them) and windows whose sum could pass 2^15 (far
// disparities, many pixels).
TEST(Event_ActiveEstimateMap, near_sum_adds_the_active_estimates_within_the_tolerance_as_in_row_order)
{
    RNG rng(29);
    const Size size(240, 180);
    int nearZero = 0, large = 0;
    for (int kind = 0; kind < 5; kind++)
    {
        ActiveEstimateMap map;
        RememberedEstimates mine(size);
        fillMap(rng, kind, 0.7, map, mine);
        for (int trial = 0; trial < 300; trial++)
        {
            const float value = drawDisparity(rng, kind), tolerance = 1.5f;
            double expectedSum = value, sum = value;
            int expectedCount = 1, count = 1;
            for (int window = 0; window < 2; window++)
            {
                const Point centre(rng.uniform(-3, size.width + 3), rng.uniform(-3, size.height + 3));
                const int radius = rng.uniform(0, 8);
                const int64 t = rng.uniform(0, 1200);
                for (int y = centre.y - radius; y <= centre.y + radius; y++)
                    for (int x = centre.x - radius; x <= centre.x + radius; x++)
                        if (y >= 0 && y < size.height && x >= 0 && x < size.width && mine.active(x, y, t) &&
                            std::abs(mine.at(x, y) - value) <= tolerance)
                        {
                            expectedSum += mine.at(x, y);
                            expectedCount++;
                        }
                map.sumNear(centre.x - radius, centre.x + radius, centre.y - radius, centre.y + radius, t, value,
                            tolerance, sum, count);
                ASSERT_EQ(expectedCount, count);
                ASSERT_EQ(expectedSum, sum) << "kind " << kind << ", value " << value << ", window " << window;
                large += (2 * radius + 1) * (2 * radius + 1) * (value + tolerance) >= 32768;
            }
            nearZero += value < 2 * tolerance;
        }
    }
    EXPECT_GT(nearZero, 10);
    EXPECT_GT(large, 10);
}

// The map keeps each end as a 32-bit offset from a time of its row: times far from zero (an epoch's
// microseconds, negative ones), and gaps of 2^29 to 2^31 + 2^29 us within rows (so that rows' times move while
// long estimates, up to 2^30 us, are still active), against the test's own 64-bit record. Every remember is
// followed by a query a little before or after it: the window's count, estimates, median and near-sum, and what
// a pixel shows.
TEST(Event_ActiveEstimateMap, ends_far_from_time_zero_and_across_gaps_beyond_32_bits)
{
    RNG rng(43);
    const Size size(64, 12);
    std::vector<float> got, expected;
    int longActive = 0, shown = 0;
    for (const int64 origin : { (int64)0, (int64)1700000000000000LL, (int64)-4000000000000LL })
    {
        ActiveEstimateMap map;
        map.reset(size);
        RememberedEstimates mine(size);
        std::vector<int64> last((size_t)size.area(), 0);
        int64 t = origin;
        for (int step = 0; step < 3000; step++)
        {
            t += rng.uniform(0, 40) == 0 ? (int64)rng.uniform(1 << 29, (1 << 30) + (1 << 29)) * 2 : rng.uniform(0, 300);
            const Point r(rng.uniform(0, size.width), rng.uniform(0, size.height));
            const int64 activeFor = rng.uniform(0, 10) == 0 ? rng.uniform(1 << 29, 1 << 30) : rng.uniform(1, 401);
            const float d = rng.uniform(0, 10) == 0 ? -1.f : drawDisparity(rng, 1);
            mine.remember(map, r, t, activeFor, d);
            last[(size_t)r.y * size.width + r.x] = t;

            const int64 q = t + rng.uniform(-500, 501);
            expected.clear();
            for (int y = 0; y < size.height; y++)
                for (int x = 0; x < size.width; x++)
                    if (mine.active(x, y, q))
                        expected.push_back(mine.at(x, y));
            float median = -100.f;
            const Point centre(size.width / 2, size.height / 2);
            ASSERT_EQ(expected.size(), map.sampledMedian(centre, size.height, size.width, 1, q, got, median)) << step;
            std::sort(expected.begin(), expected.end());
            std::sort(got.begin(), got.end());
            ASSERT_EQ(expected, got) << step;
            if (!expected.empty())
            {
                ASSERT_EQ(expected[expected.size() / 2], median);
            }
            longActive += (int)std::count_if(mine.until.begin(), mine.until.end(),
                                             [&](int64 u) { return u > q + 1000; });

            const float value = drawDisparity(rng, 1);
            double sum = value, expectedSum = value;
            int count = 1, expectedCount = 1;
            map.sumNear(0, size.width - 1, 0, size.height - 1, q, value, 1.5f, sum, count);
            for (int y = 0; y < size.height; y++)
                for (int x = 0; x < size.width; x++)
                    if (mine.active(x, y, q) && std::abs(mine.at(x, y) - value) <= 1.5f)
                    {
                        expectedSum += mine.at(x, y);
                        expectedCount++;
                    }
            ASSERT_EQ(expectedCount, count);
            ASSERT_EQ(expectedSum, sum);

            // Half the time the pixel just remembered.
            const bool remembered = rng.uniform(0, 2) == 0;
            const int x = remembered ? r.x : rng.uniform(0, size.width);
            const int y = remembered ? r.y : rng.uniform(0, size.height);
            const size_t i = (size_t)y * size.width + x;
            const bool expectShown = mine.at(x, y) >= 0 && last[i] <= q && mine.active(x, y, q);
            float disparity = -100.f;
            ASSERT_EQ(expectShown, map.shownAt(x, y, (double)q, disparity)) << step;
            if (expectShown)
            {
                ASSERT_EQ(mine.at(x, y), disparity);
            }
            shown += expectShown;
        }
    }
    EXPECT_GT(longActive, 10000);  // estimates still active across the gaps
    EXPECT_GT(shown, 100);
}

TEST(Event_EstimateGather, kernel_equals_scalar_reference)
{
    RNG rng(31);
    const EstimateGatherFn vector = estimateGatherKernelsForThisCpu().gather;
    const EstimateGatherFn scalar = scalarEstimateGatherKernels().gather;
    const int32_t extremes[] = { std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max() };
    std::vector<int32_t> until(80);
    std::vector<float> disparity(80), got(80 + ESTIMATE_GATHER_PAD), expected(80 + ESTIMATE_GATHER_PAD);
    int actives = 0;
    for (int trial = 0; trial < 2000; trial++)
    {
        const int32_t t = trial % 50 == 0 ? extremes[trial / 50 % 2] : rng.uniform(-5, 6);
        for (size_t i = 0; i < until.size(); i++)
        {
            // Mostly around t (at it, just before, just after), sometimes an extreme.
            until[i] = rng.uniform(0, 8) == 0 ? extremes[rng.uniform(0, 2)] : rng.uniform(-6, 7);
            disparity[i] = rng.uniform(0.f, 40.f);
        }
        const int start = rng.uniform(0, 17), n = rng.uniform(0, 64);
        const int count = vector(&until[start], &disparity[start], n, t, got.data());
        ASSERT_EQ(scalar(&until[start], &disparity[start], n, t, expected.data()), count);
        for (int i = 0; i < count; i++)
            ASSERT_EQ(expected[i], got[i]);
        actives += count;
        int direct = 0;  // and the reference against the definition
        for (int i = 0; i < n; i++)
            direct += t < until[start + i];
        ASSERT_EQ(direct, count);
    }
    EXPECT_GT(actives, 10000);
}

TEST(Event_EstimateGather, range_kernel_equals_scalar_reference)
{
    RNG rng(37);
    const ValuesInRangeFn vector = estimateGatherKernelsForThisCpu().valuesInRange;
    const ValuesInRangeFn scalar = scalarEstimateGatherKernels().valuesInRange;
    std::vector<float> values(80 + VALUES_IN_RANGE_PAD), inPlace, got(values.size()), expected(values.size());
    int kept = 0, boundary = 0;
    for (int trial = 0; trial < 3000; trial++)
    {
        // A bin as the median counts them: [p, p + 1) or [p + f/64, p + (f + 1)/64), the last one unbounded.
        const int p = trial % 10 == 0 ? 127 : rng.uniform(0, 20), f = rng.uniform(0, 64);
        const bool fraction = rng.uniform(0, 2) == 1;
        const float lo = fraction ? (float)p + (float)f / 64 : (float)p;
        float hi = fraction ? (float)p + (float)(f + 1) / 64 : (float)(p + 1);
        if (p == 127 && (!fraction || f == 63))
            hi = std::numeric_limits<float>::infinity();
        for (float& v : values)
        {
            // On an end, a float beside it, inside, or anywhere.
            const float end = rng.uniform(0, 2) == 0 ? lo : (hi == std::numeric_limits<float>::infinity() ? 300.f : hi);
            switch (rng.uniform(0, 4))
            {
            case 0: v = end; break;
            case 1: v = std::nextafter(end, rng.uniform(0, 2) == 0 ? 0.f : 1000.f); break;
            case 2: v = lo + (float)rng.uniform(0., 1.) * (std::min(hi, 300.f) - lo); break;
            default: v = rng.uniform(0.f, 140.f);
            }
        }
        const int start = rng.uniform(0, 17), n = rng.uniform(0, 64);
        const size_t count = vector(&values[start], (size_t)n, lo, hi, got.data());
        ASSERT_EQ(scalar(&values[start], (size_t)n, lo, hi, expected.data()), count);
        int direct = 0;  // and the reference against the definition
        for (int i = 0; i < n; i++)
        {
            const float v = values[start + i];
            direct += lo <= v && v < hi;
            boundary += v == lo || v == hi;
        }
        ASSERT_EQ((size_t)direct, count);
        for (size_t i = 0; i < count; i++)
            ASSERT_EQ(expected[i], got[i]);
        // In place: the same values, over the input.
        inPlace = values;
        ASSERT_EQ(count, vector(&inPlace[start], (size_t)n, lo, hi, &inPlace[start]));
        for (size_t i = 0; i < count; i++)
            ASSERT_EQ(expected[i], inPlace[start + i]);
        kept += (int)count;
    }
    EXPECT_GT(kept, 10000);
    EXPECT_GT(boundary, 10000);
}

// Values on the 1/64 px grid, so that every order of the additions gives one sum (the kernel's contract).
TEST(Event_EstimateGather, near_sum_kernel_equals_scalar_reference)
{
    RNG rng(41);
    const EstimateNearSumFn vector = estimateGatherKernelsForThisCpu().nearSum;
    const EstimateNearSumFn scalar = scalarEstimateGatherKernels().nearSum;
    std::vector<int32_t> until(80);
    std::vector<float> disparity(80);
    int nears = 0, boundary = 0;
    for (int trial = 0; trial < 3000; trial++)
    {
        const int32_t t = rng.uniform(-5, 6);
        const float value = (float)rng.uniform(64, 64 * 40) / 64, tolerance = 1.5f;
        for (size_t i = 0; i < until.size(); i++)
        {
            until[i] = rng.uniform(0, 8) == 0 ? std::numeric_limits<int32_t>::min() : rng.uniform(-6, 7);
            // The tolerance's ends, or anywhere within 3 px.
            disparity[i] = rng.uniform(0, 3) == 0 ? value + (rng.uniform(0, 2) == 0 ? -tolerance : tolerance)
                                                  : value + (float)rng.uniform(-192, 193) / 64;
        }
        const int start = rng.uniform(0, 17), n = rng.uniform(0, 64);
        double sum = value, expectedSum = value, directSum = value;
        const int count = vector(&until[start], &disparity[start], n, t, value, tolerance, sum);
        ASSERT_EQ(scalar(&until[start], &disparity[start], n, t, value, tolerance, expectedSum), count);
        ASSERT_EQ(expectedSum, sum);
        int direct = 0;  // and the reference against the definition, in order
        for (int i = start; i < start + n; i++)
            if (t < until[i] && std::abs(disparity[i] - value) <= tolerance)
            {
                directSum += disparity[i];
                direct++;
                boundary += std::abs(disparity[i] - value) == tolerance;
            }
        ASSERT_EQ(direct, count);
        ASSERT_EQ(directSum, sum);
        nears += count;
    }
    EXPECT_GT(nears, 10000);
    EXPECT_GT(boundary, 1000);
}

}}  // namespace
