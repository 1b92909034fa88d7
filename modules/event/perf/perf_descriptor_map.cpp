// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Incremental maintenance of the Zou descriptors (ZouDescriptorMap, internal): activating events and
// expiring them, by sensor size, at the matcher's defaults (3 x 3 descriptor window, vectors up to 3 px).

#include "perf_precomp.hpp"
#include "stereo/zou_descriptor_map.hpp"

namespace opencv_test { namespace {
using namespace cv::event::detail;

typedef TestBaseWithParam<Size> Event_DescriptorMap;

PERF_TEST_P(Event_DescriptorMap, activate_and_expire_100k, testing::Values(Size(240, 180), Size(346, 260), Size(640, 480)))
{
    const Size size = GetParam();
    const int n = 100000;
    RNG rng(5);
    std::vector<Point3i> events(n);  // x, y, polarity
    for (Point3i& e : events)
        e = Point3i(rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2));
    ZouDescriptorMap map;
    map.configure(size, 3, 3, 8);
    while (next())
    {
        map.reset();
        startTimer();
        // 1 us apart, active for 2 ms (a lifetime at 500 px/s): about 2000 active events at any time.
        for (int i = 0; i < n; i++)
        {
            map.expireUntil(i);
            map.activate(events[(size_t)i].x, events[(size_t)i].y, events[(size_t)i].z, i, i + 2000, 2000.f, Vec2f());
        }
        stopTimer();
    }
    SANITY_CHECK_NOTHING();
}

}} // namespace
