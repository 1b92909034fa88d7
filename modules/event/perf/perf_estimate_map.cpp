// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The neighbours' estimates as the matcher reads them (ActiveEstimateMap, internal): the filling's median over
// 20,000 windows of 41 x 41 pixels, every other row (the default fill radius), and the averaging's sums over
// 20,000 pairs of 9 x 9 windows. The windows lie at random in a 240 x 180 map, so that, as in the matcher, most
// of them start out of the cache. The estimates are a surface's: 12 px with a spread of 0.3 px, a tenth of them
// anywhere in 0..40 px; a share of the pixels (the parameter) remembered an estimate within the last 100 ms, and
// those of the last 60 ms are active. OPENCV_EVENT_SCALAR_KERNELS=1 times the scalar kernels.

#include "perf_precomp.hpp"
#include "stereo/active_estimate_map.hpp"
#include "stereo/estimate_gather.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

typedef TestBaseWithParam<double> Event_EstimateMap;

const Size MAP_SIZE(240, 180);
const int64 NOW = 100000, ACTIVE_FOR = 60000;

void fillSurface(ActiveEstimateMap& map, double remembered, RNG& rng)
{
    map.reset(MAP_SIZE);
    for (int y = 0; y < MAP_SIZE.height; y++)
        for (int x = 0; x < MAP_SIZE.width; x++)
            if (rng.uniform(0.0, 1.0) < remembered)
            {
                const float d = rng.uniform(0, 10) == 0 ? rng.uniform(0.f, 40.f) : 12.f + (float)rng.gaussian(0.3);
                map.remember(Point(x, y), (int64)rng.uniform(0, (int)NOW), ACTIVE_FOR, std::max(d, 0.f));
            }
}

std::vector<Point> randomCentres(int n, RNG& rng)
{
    std::vector<Point> centres((size_t)n);
    for (Point& c : centres)
        c = Point(rng.uniform(0, MAP_SIZE.width), rng.uniform(0, MAP_SIZE.height));
    return centres;
}

PERF_TEST_P(Event_EstimateMap, fill_median_20k_windows, testing::Values(0.3, 0.8))
{
    RNG rng(11);
    ActiveEstimateMap map;
    fillSurface(map, GetParam(), rng);
    const std::vector<Point> centres = randomCentres(20000, rng);
    std::vector<float> disparities;
    double checksum = 0;
    size_t estimates = 0;
    while (next())
    {
        checksum = 0;
        estimates = 0;
        startTimer();
        for (const Point& c : centres)
        {
            float median = 0;
            const size_t n = map.sampledMedian(c, 20, 20, 2, NOW, disparities, median);
            estimates += n;
            if (n > 0)
                checksum += median;
        }
        stopTimer();
    }
    std::cout << "    " << estimateGatherKernelsForThisCpu().name << ", " << GetParam() * 100 << " % remembered: "
              << (double)estimates / (double)centres.size() << " estimates per window, median checksum " << checksum
              << std::endl;
    SANITY_CHECK_NOTHING();
}

PERF_TEST_P(Event_EstimateMap, averaging_sums_20k_window_pairs, testing::Values(0.3, 0.8))
{
    RNG rng(13);
    ActiveEstimateMap map;
    fillSurface(map, GetParam(), rng);
    const std::vector<Point> centres = randomCentres(40000, rng);
    double checksum = 0;
    while (next())
    {
        checksum = 0;
        startTimer();
        for (size_t i = 0; i + 1 < centres.size(); i += 2)
        {
            // As the averaging reads them: the event's window, then its counterpart's, into one sum.
            double sum = 12;
            int n = 1;
            for (const Point& c : { centres[i], centres[i + 1] })
                map.sumNear(c.x - 4, c.x + 4, c.y - 4, c.y + 4, NOW, 12.f, 1.5f, sum, n);
            checksum += sum / n;
        }
        stopTimer();
    }
    std::cout << "    " << estimateGatherKernelsForThisCpu().name << ", " << GetParam() * 100
              << " % remembered: mean checksum " << checksum << std::endl;
    SANITY_CHECK_NOTHING();
}

}} // namespace
