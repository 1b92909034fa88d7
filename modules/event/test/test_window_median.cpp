// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// COUPLED's matched-window median against a stable sort: for every count up to a 31 x 31 window (the ranked
// selection and, past its limit, the partitioning one), with few distinct values (matched windows, where most
// events copied the same lifetime: ties decide whose flow is passed on) and with all values distinct.

#include "test_precomp.hpp"
#include "stereo/window_median.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

// The position a stable sort by value puts at n / 2.
int sortedMedianPosition(const std::vector<int>& values)
{
    std::vector<int> order(values.size());
    for (size_t i = 0; i < order.size(); i++)
        order[i] = (int)i;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return values[(size_t)a] < values[(size_t)b]; });
    return order[order.size() / 2];
}

TEST(Event_WindowMedian, position_of_a_stable_sort_for_every_count_and_ties)
{
    RNG rng(20261126);
    for (int n = 1; n <= 31 * 31; n += n < 100 ? 1 : 7)
        for (int distinct : { 1, 2, 3, 7, 1 << 20 })
            for (int trial = 0; trial < 3; trial++)
            {
                // Lifetimes' bits: positive floats between 0.1 ms and 1 s.
                std::vector<int> lifetimes((size_t)n);
                for (int& v : lifetimes)
                {
                    const float lifetime = 100.f + (float)rng.uniform(0, distinct) * (1e6f / (float)distinct);
                    std::memcpy(&v, &lifetime, sizeof(v));
                }
                std::vector<int> padded(lifetimes);
                padded.resize((size_t)n + WINDOW_MEDIAN_PAD, WINDOW_MEDIAN_PAD_VALUE);
                std::vector<uint64> keys((size_t)n);
                ASSERT_EQ(sortedMedianPosition(lifetimes), windowMedianPosition(padded.data(), n, keys.data()))
                    << n << " values, " << distinct << " distinct, trial " << trial;
            }
}

}}  // namespace
