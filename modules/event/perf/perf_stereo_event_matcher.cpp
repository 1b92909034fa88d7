// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

// The whole stereo pipeline per mode, and the frame baseline, on one 33 ms window of the simulator's two_planes scene (240 x 180),
// after 66 ms of warm-up so that the descriptors and lifetimes are in their steady state. Divide by the
// window's event count (printed by the Table I program, perf/event_stereo_table) for time per event.
Size twoPlanesWindows(std::vector<Event>& warmUp, std::vector<Event>& window)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("two_planes");
    Mat gt;
    sim->generate(66000, warmUp, gt);
    sim->generate(99000, window, gt);
    return sim->getSensorSize();
}

// What each cycle times: the warm-up and the window through the matcher from its reset.
void processFromReset(StereoEventMatcher& m, const std::vector<Event>& warmUp, const std::vector<Event>& window)
{
    Mat disparity, lifetime;
    m.reset();
    m.process(warmUp, disparity, lifetime);
    m.process(window, disparity, lifetime);
}

// Per mode at the defaults, then COUPLED with the cost windows on every other and every third row
// (setCostRowStep).
typedef TestBaseWithParam<tuple<int, int>> Event_StereoMatcher_Window;

PERF_TEST_P(Event_StereoMatcher_Window, two_planes,
            testing::Values(make_tuple((int)STEREO_COUPLED, 1), make_tuple((int)STEREO_DECOUPLED, 1),
                            make_tuple((int)STEREO_FIXED_INTERVAL, 1), make_tuple((int)STEREO_COUPLED, 2),
                            make_tuple((int)STEREO_COUPLED, 3)))
{
    std::vector<Event> warmUp, window;
    const Size size = twoPlanesWindows(warmUp, window);
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(size, get<0>(GetParam()));
    m->setCostRowStep(get<1>(GetParam()));
    TEST_CYCLE() processFromReset(*m, warmUp, window);
    SANITY_CHECK_NOTHING();
}

// COUPLED at the defaults with every event finding its own fill surface (0) and with the surfaces reused for the
// default 5 ms (setFillReuseTime).
typedef TestBaseWithParam<double> Event_StereoMatcher_FillReuse;

PERF_TEST_P(Event_StereoMatcher_FillReuse, two_planes, testing::Values(0.0, 5000.0))
{
    std::vector<Event> warmUp, window;
    const Size size = twoPlanesWindows(warmUp, window);
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(size, STEREO_COUPLED);
    m->setFillReuseTime(GetParam());
    TEST_CYCLE() processFromReset(*m, warmUp, window);
    SANITY_CHECK_NOTHING();
}

PERF_TEST(Event_FrameStereoMatcher_Window, two_planes)
{
    std::vector<Event> warmUp, window;
    const Size size = twoPlanesWindows(warmUp, window);
    Ptr<FrameStereoMatcher> m = FrameStereoMatcher::create(size);
    Mat disparity;
    TEST_CYCLE()
    {
        m->reset();
        m->process(warmUp, disparity);
        m->process(window, disparity);
    }
    SANITY_CHECK_NOTHING();
}

}} // namespace
