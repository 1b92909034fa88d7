// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The whole stereo pipeline (rectification, lifetimes, descriptors, matching) per mode, by sensor size and
// event rate: one 10 ms window of the simulated two_planes scene after a 20 ms warm-up (not timed), with
// 0 or 5 Hz of background activity per pixel on top (DAVIS240: +0.43 Mev/s; VGA: +3.1 Mev/s). The events
// per window are recorded as the property "events" (in the XML / JSON output) so that time per event and
// Mev/s follow from the table.

#include "perf_precomp.hpp"

#include <map>

namespace opencv_test { namespace {

struct SimulatedWindow
{
    Size size;
    std::vector<Event> warmUp, window;
};

// Simulated once per (sensor, noise) and shared by the modes: the simulator costs more than the matcher.
const SimulatedWindow& simulatedWindow(int sensorModel, double noiseHz)
{
    static std::map<std::pair<int, double>, SimulatedWindow> cache;
    SimulatedWindow& w = cache[std::make_pair(sensorModel, noiseHz)];
    if (w.window.empty())
    {
        Ptr<StereoEventSimulator> scene = StereoEventSimulator::create("two_planes", sensorModel);
        SimulatorSettings settings = scene->getSettings();
        settings.noiseRateHz = noiseHz;
        Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene->getPlanes(), settings);
        Mat gt;
        sim->generate(20000, w.warmUp, gt);
        sim->generate(30000, w.window, gt);
        w.size = sim->getSensorSize();
    }
    return w;
}

CV_ENUM(StereoModeParam, STEREO_COUPLED, STEREO_DECOUPLED, STEREO_FIXED_INTERVAL)
CV_ENUM(SensorParam, SENSOR_DAVIS240, SENSOR_DAVIS346, SENSOR_PROPHESEE_GEN3)

typedef tuple<SensorParam, double, StereoModeParam> PipelineParams;
typedef TestBaseWithParam<PipelineParams> Event_StereoPipeline;

PERF_TEST_P(Event_StereoPipeline, two_planes_window,
            testing::Combine(SensorParam::all(), testing::Values(0.0, 5.0), StereoModeParam::all()))
{
    const SimulatedWindow& w = simulatedWindow(get<0>(GetParam()), get<1>(GetParam()));
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(w.size, get<2>(GetParam()));
    Mat disparity, lifetime;
    RecordProperty("events", (int)w.window.size());
    while (next())
    {
        m->reset();
        m->process(w.warmUp, disparity, lifetime);
        startTimer();
        m->process(w.window, disparity, lifetime);
        stopTimer();
    }
    SANITY_CHECK_NOTHING();
}

// Row bands (StereoEventMatcher::setNumThreads): the same window through process() on 2 and 4 threads, by
// sensor size, COUPLED and DECOUPLED; one thread is Event_StereoPipeline's case without background activity.
// The outputs must equal one thread's bit for bit (sameBits, checked outside the timed part): a speed-up that
// changed the results would not count.

CV_ENUM(BandModeParam, STEREO_COUPLED, STEREO_DECOUPLED)
typedef tuple<SensorParam, int, BandModeParam> RowBandParams;
typedef TestBaseWithParam<RowBandParams> Event_StereoRowBands;

PERF_TEST_P(Event_StereoRowBands, two_planes_window,
            testing::Combine(SensorParam::all(), testing::Values(2, 4), BandModeParam::all()))
{
    const SimulatedWindow& w = simulatedWindow(get<0>(GetParam()), 0.0);
    const int threads = get<1>(GetParam()), mode = get<2>(GetParam());
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(w.size, mode);
    Mat disparity, lifetime, expectedDisparity, expectedLifetime;
    m->process(w.warmUp, disparity, lifetime);
    m->process(w.window, expectedDisparity, expectedLifetime);
    m->setNumThreads(threads);
    RecordProperty("events", (int)w.window.size());
    while (next())
    {
        m->reset();
        m->process(w.warmUp, disparity, lifetime);
        startTimer();
        m->process(w.window, disparity, lifetime);
        stopTimer();
        ASSERT_TRUE(sameBits(disparity, expectedDisparity)) << threads << " threads changed the disparities";
        ASSERT_TRUE(sameBits(lifetime, expectedLifetime)) << threads << " threads changed the lifetimes";
    }
    SANITY_CHECK_NOTHING();
}

// Per event, the incremental API as a live loop calls it (same window, one processEvent per event).
typedef TestBaseWithParam<StereoModeParam> Event_StereoPerEvent;

PERF_TEST_P(Event_StereoPerEvent, davis240_two_planes, StereoModeParam::all())
{
    const SimulatedWindow& w = simulatedWindow(SENSOR_DAVIS240, 0.0);
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(w.size, GetParam());
    Mat disparity;
    StereoEventEstimate estimate;
    RecordProperty("events", (int)w.window.size());
    while (next())
    {
        m->reset();
        m->process(w.warmUp, disparity);
        startTimer();
        for (const Event& e : w.window)
            m->processEvent(e, estimate);
        stopTimer();
    }
    SANITY_CHECK_NOTHING();
}

}} // namespace
