// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

typedef tuple<Size, int> SurfaceParams;
typedef TestBaseWithParam<SurfaceParams> Event_Surface_Update;

// Updates per second = events / time; one packet of uniformly spread events at 1 Mev/s.
PERF_TEST_P(Event_Surface_Update, packet,
            testing::Combine(testing::Values(Size(240, 180), Size(346, 260), Size(640, 480)),
                             testing::Values(100000, 1000000)))
{
    const Size size = get<0>(GetParam());
    const int n = get<1>(GetParam());
    std::vector<Event> ev(n);
    RNG rng(7);
    for (int i = 0; i < n; i++)
        ev[i] = Event(i, rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2));
    Ptr<EventSurface> s = EventSurface::create(size);
    TEST_CYCLE() s->update(ev);
    SANITY_CHECK_NOTHING();
}

typedef TestBaseWithParam<Size> Event_Surface_Render;

PERF_TEST_P(Event_Surface_Render, time_surface, testing::Values(Size(240, 180), Size(346, 260), Size(640, 480)))
{
    const Size size = GetParam();
    Ptr<EventSurface> s = EventSurface::create(size);
    RNG rng(9);
    for (int i = 0; i < size.area(); i++)
        s->update(Event(i, rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2)));
    Mat out;
    TEST_CYCLE() s->renderTimeSurface(size.area(), 30000, out, CV_8U);
    SANITY_CHECK_NOTHING();
}

}} // namespace
