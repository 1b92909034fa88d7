// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// COUPLED's matched-window median (WindowMedianKernels, internal): gathering the active lifetimes of 20,000
// 9 x 9 windows of the other sensor and selecting their median, with this CPU's kernels and the scalar ones,
// at 20 % and 50 % of the pixels active. The windows lie at random in a 240 x 180 map, so that, as in the
// matcher, most of them start out of the cache; the lifetimes take four values (matched events copy theirs).

#include "perf_precomp.hpp"
#include "stereo/window_median.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

typedef tuple<bool, double> KernelsAndDensity;
typedef TestBaseWithParam<KernelsAndDensity> Event_WindowMedian;

PERF_TEST_P(Event_WindowMedian, gather_and_median_20k_windows,
            testing::Combine(testing::Values(false, true), testing::Values(0.2, 0.5)))
{
    const bool scalar = get<0>(GetParam());
    const double density = get<1>(GetParam());
    const WindowMedianKernels kernels = scalar ? scalarWindowMedianKernels() : windowMedianKernelsForThisCpu();
    const int width = 240, height = 180, window = 9, n = 20000;
    RNG rng(9);
    std::vector<float> lifetimes((size_t)width * height, 0.f);
    for (float& v : lifetimes)
        if (rng.uniform(0.0, 1.0) < density)
            v = 1000.f + 100.f * (float)rng.uniform(0, 4);
    std::vector<int> firsts(n);
    for (int& f : firsts)
        f = rng.uniform(0, height - window + 1) * width + rng.uniform(0, width - window + 1);
    std::vector<int> values(window * window + WINDOW_MEDIAN_PAD), positions(window * window + WINDOW_MEDIAN_PAD);
    std::vector<uint64> keys(window * window);
    int64 checksum = 0;
    while (next())
    {
        checksum = 0;
        startTimer();
        for (int first : firsts)
        {
            const int count = kernels.gather(lifetimes.data(), first, width, window, window, values.data(), positions.data());
            if (count == 0)
                continue;
            std::fill_n(values.data() + count, (int)WINDOW_MEDIAN_PAD, WINDOW_MEDIAN_PAD_VALUE);
            checksum += positions[(size_t)kernels.medianPosition(values.data(), count, keys.data())];
        }
        stopTimer();
    }
    std::cout << "    " << kernels.name << ", " << density * 100 << " % active: median position checksum " << checksum
              << std::endl;
    SANITY_CHECK_NOTHING();
}

}} // namespace
