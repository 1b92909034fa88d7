// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// COUPLED's matched-window median, for this CPU's kernels and the scalar ones: the median against a stable sort
// for every count up to a 31 x 31 window (the ranked selection and, past its limit, the partitioning one), with
// few distinct values (matched windows, where most events copied the same lifetime: ties decide whose flow is
// passed on) and with all values distinct; the gather against a plain scan for every window shape up to 31 x 31,
// on rows whose neighbours outside the window are active, so that a kernel that reads past a row is caught.

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

std::vector<WindowMedianKernels> kernelsUnderTest()
{
    return { windowMedianKernelsForThisCpu(), scalarWindowMedianKernels() };
}

TEST(Event_WindowMedian, position_of_a_stable_sort_for_every_count_and_ties)
{
    for (const WindowMedianKernels& kernels : kernelsUnderTest())
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
                    ASSERT_EQ(sortedMedianPosition(lifetimes), kernels.medianPosition(padded.data(), n, keys.data()))
                        << kernels.name << ": " << n << " values, " << distinct << " distinct, trial " << trial;
                }
    }
}

TEST(Event_WindowMedian, gather_takes_the_positive_values_of_the_window_in_row_order)
{
    const int stride = 45, height = 35;
    for (const WindowMedianKernels& kernels : kernelsUnderTest())
    {
        RNG rng(7);
        std::vector<float> lifetimes((size_t)stride * height);
        for (float& v : lifetimes)
        {
            // Active (positive), inactive (0) and, as a kernel must not take them, negative values.
            const int kind = rng.uniform(0, 4);
            v = kind == 0 ? 0.f : kind == 1 ? -5.f : rng.uniform(1.f, 1e5f);
        }
        for (int width = 1; width <= 31; width++)
            for (int rows = 1; rows <= 31; rows += rows < 10 ? 1 : 5)
            {
                const int first = rng.uniform(0, stride - width + 1) + stride * rng.uniform(0, height - rows + 1);
                std::vector<int> expectedValues, expectedPositions;
                for (int r = 0; r < rows; r++)
                    for (int i = first + r * stride; i < first + r * stride + width; i++)
                        if (lifetimes[(size_t)i] > 0)
                        {
                            int bits;
                            std::memcpy(&bits, &lifetimes[(size_t)i], sizeof(bits));
                            expectedValues.push_back(bits);
                            expectedPositions.push_back(i);
                        }
                const size_t room = (size_t)width * rows + WINDOW_MEDIAN_PAD;
                std::vector<int> values(room, -1), positions(room, -1);
                const int n = kernels.gather(lifetimes.data(), first, stride, width, rows, values.data(), positions.data());
                ASSERT_EQ((int)expectedValues.size(), n) << kernels.name << ": " << width << " x " << rows;
                values.resize((size_t)n);
                positions.resize((size_t)n);
                ASSERT_EQ(expectedValues, values) << kernels.name << ": " << width << " x " << rows;
                ASSERT_EQ(expectedPositions, positions) << kernels.name << ": " << width << " x " << rows;
            }
    }
}

}}  // namespace
