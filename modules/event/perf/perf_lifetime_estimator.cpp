// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

// Time per event of the lifetime estimator on 100 ms of the simulator's moving-line scene, with and without
// the prediction shortcut (the outputs are compared in the unit tests).
typedef TestBaseWithParam<bool> Event_Lifetime_Process;

PERF_TEST_P(Event_Lifetime_Process, moving_line, testing::Bool())
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("moving_line");
    std::vector<Event> ev, left;
    Mat gt;
    sim->generate(100000, ev, gt);
    for (const Event& e : ev)
        if (e.camera == CAMERA_LEFT)
            left.push_back(e);
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(sim->getSensorSize());
    est->setUsePrediction(GetParam());
    Mat lifetimes;
    TEST_CYCLE()
    {
        est->reset();
        est->process(left, lifetimes);
    }
    SANITY_CHECK_NOTHING();
}

}} // namespace
