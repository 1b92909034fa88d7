// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

// Time per event of the lifetime estimator on 100 ms of the simulator's moving-line scene, by sensor size,
// with the prediction shortcut off (every event fits a plane) and on (an event that arrives when its
// neighbour's plane predicted it reuses that plane; on this scene about 7 % do, see doc/performance.md).
// The outputs are compared in the unit tests.
CV_ENUM(LifetimeSensor, SENSOR_DAVIS240, SENSOR_DAVIS346, SENSOR_PROPHESEE_GEN3)
typedef TestBaseWithParam<tuple<LifetimeSensor, bool>> Event_Lifetime_Process;

PERF_TEST_P(Event_Lifetime_Process, moving_line, testing::Combine(LifetimeSensor::all(), testing::Bool()))
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("moving_line", get<0>(GetParam()));
    std::vector<Event> ev, left;
    Mat gt;
    sim->generate(100000, ev, gt);
    for (const Event& e : ev)
        if (e.camera == CAMERA_LEFT)
            left.push_back(e);
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(sim->getSensorSize());
    est->setUsePrediction(get<1>(GetParam()));
    Mat lifetimes;
    RecordProperty("events", (int)left.size());
    TEST_CYCLE()
    {
        est->reset();
        est->process(left, lifetimes);
    }
    SANITY_CHECK_NOTHING();
}

}} // namespace
