// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

// 500 ms of the boxes_fast scene on a DAVIS346 (both cameras, with the realistic noise model), simulated once:
// a real event stream's locality, which decides the cache misses of the per-pixel state.
const std::vector<Event>& davis346Stream()
{
    static std::vector<Event> events;
    if (events.empty())
    {
        Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("boxes_fast", SENSOR_DAVIS346);
        Mat ev, gt;
        sim->generate(500000, ev, gt);
        events = toEventVector(ev);
    }
    return events;
}

typedef TestBaseWithParam<std::string> Event_Filter;

// Events per second = the stream's events / the median time (the perf log prints both: events as a
// parameter of the run, time per cycle). One packet of the whole stream, one thread, kept events and mask out.
PERF_TEST_P(Event_Filter, davis346_boxes_fast,
            testing::Values("background_activity", "trail", "refractory", "hot_pixels", "anti_flicker"))
{
    const std::vector<Event>& ev = davis346Stream();
    Ptr<EventFilter> f = createEventFilter(GetParam(), getSensorSize(SENSOR_DAVIS346));
    Ptr<HotPixelFilter> hot = f.dynamicCast<HotPixelFilter>();
    if (hot)
    {
        // Masks learnt beforehand, as a user loads them: the timed call is the filtering itself.
        hot->setLearningTime(0);
        hot->learn(ev);
        hot->detect();
    }
    std::vector<Event> kept;
    Mat mask;
    RecordProperty("events", (int)ev.size());
    while (next())
    {
        f->reset();  // the stream starts again: not timed, it costs the same however long the stream
        startTimer();
        f->filter(ev, kept, mask);
        stopTimer();
    }
    printf("%s: %d events, %d kept\n", GetParam().c_str(), (int)ev.size(), (int)kept.size());
    SANITY_CHECK_NOTHING();
}

}} // namespace
