// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Helpers of opencv_test_event: simulator scenes with closed-form answers.

#ifndef OPENCV_EVENT_TEST_SIMULATOR_HELPERS_HPP
#define OPENCV_EVENT_TEST_SIMULATOR_HELPERS_HPP

#include "opencv2/event.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace opencv_test {

/** A bright uniform plane (0.9) whose right edge sweeps right over a dark uniform background (0.1, at twice
the depth): one straight vertical edge of log contrast ln 9 moving at f * speed / depth px/s. At t = 0 the
edge is @p edgeStartX metres right of the optical axis (negative: left of it) at @p depth. */
inline std::vector<cv::event::SimulatedPlane> sweepingEdgeScene(double depth, double speed, double edgeStartX)
{
    cv::event::SimulatedPlane back;
    back.center = cv::Vec3d(0, 0, 2 * depth);
    back.halfSize = cv::Vec2d(10, 10);
    back.texture = cv::event::TEXTURE_UNIFORM;
    back.intensity = 0.1;
    cv::event::SimulatedPlane front = back;
    front.center = cv::Vec3d(edgeStartX - 1.0, 0, depth);  // 1 m half width: the right edge at edgeStartX
    front.halfSize = cv::Vec2d(1.0, 10);
    front.intensity = 0.9;
    front.velocity = cv::Vec3d(speed, 0, 0);
    return { back, front };
}

/** A small sensor (96 x 32) where every crossing counts: every pixel at the nominal threshold, no refractory
period. */
inline cv::event::SimulatorSettings idealSmallSensor()
{
    cv::event::SimulatorSettings s;
    s.resolution = cv::Size(96, 32);
    s.thresholdSigma = 0;
    s.refractoryUs = 0;
    return s;
}

/** The left camera's events of a simulation run, with each one's row in the run's ground truth. */
struct LeftCameraEvents
{
    std::vector<cv::event::Event> events;
    std::vector<int> truthRows;  // events[k] is row truthRows[k] of groundTruth
    cv::Mat groundTruth;         // both cameras' rows, as StereoEventSimulator::generate() gives them
};

/** Simulates @p sim up to @p untilUs and keeps the left camera's events. */
inline LeftCameraEvents generateLeftCamera(cv::event::StereoEventSimulator& sim, double untilUs)
{
    LeftCameraEvents run;
    std::vector<cv::event::Event> all;
    sim.generate(untilUs, all, run.groundTruth);
    for (size_t i = 0; i < all.size(); i++)
        if (all[i].camera == cv::event::CAMERA_LEFT)
        {
            run.events.push_back(all[i]);
            run.truthRows.push_back((int)i);
        }
    return run;
}

/** A perfect estimator's outputs for events whose ground truth is row rows[k] of @p groundTruth: each one's true
lifetime [us] and normal flow [px/s] (N x 1 and N x 2 CV_32F), 0 for noise (no edge: a perfect estimator finds
no plane there). */
inline void perfectLifetimes(const cv::Mat& groundTruth, const std::vector<int>& rows, cv::Mat& lifetimes, cv::Mat& flow)
{
    const int n = (int)rows.size();
    lifetimes.create(n, 1, CV_32F);
    flow.create(n, 2, CV_32F);
    for (int k = 0; k < n; k++)
    {
        const float* g = groundTruth.ptr<float>(rows[(size_t)k]);
        const bool noise = ((int)g[cv::event::GT_FLAGS] & cv::event::GT_FLAG_NOISE) != 0;
        lifetimes.at<float>(k) = noise ? 0.f : g[cv::event::GT_LIFETIME];
        flow.at<float>(k, 0) = noise ? 0.f : g[cv::event::GT_FLOW_X];
        flow.at<float>(k, 1) = noise ? 0.f : g[cv::event::GT_FLOW_Y];
    }
}

/** A DVS128 pendulum scene (`pendulum` or `pendulum_patterned`) set as the TUM pendulum recording fires: half
the swing's speed, 0.8 px of blur, thresholds of 0.2 (each pixel fires a train of events as the ball's outline
passes). design_figures and ball_motion_check share it. */
inline cv::Ptr<cv::event::StereoEventSimulator> pendulumAsTumFires(const cv::String& scene)
{
    using namespace cv::event;
    const cv::Ptr<StereoEventSimulator> built = StereoEventSimulator::create(scene, SENSOR_DVS128);
    SimulatorSettings s = built->getSettings();
    std::vector<SimulatedPlane> planes = built->getPlanes();
    s.blurSigmaPx = 0.8;
    s.thresholdOn = s.thresholdOff = 0.2;
    for (SimulatedPlane& p : planes)
    {
        p.velocity *= 0.5;
        p.angularVelocity *= 0.5;
        p.swingFrequency *= 0.5;
    }
    return StereoEventSimulator::create(planes, s);
}

/** The `fan` scene's blade side edges (in the left camera, clear of the hub, where the two bars cross, and of
the tips: 6-12 px from the centre): each event's true lifetime over the closed form 1 / (omega sqrt(r^2 - w^2))
of a side edge r px from the hub and half a blade's width w off its axis, sorted. */
inline std::vector<double> fanSideEdgeLifetimeRatios(const LeftCameraEvents& run, const cv::event::SimulatorSettings& s)
{
    const double omega = 2 * CV_PI * 25, w = 0.012 * s.focalLength / 1.0;
    const double cx = 0.5 * (s.resolution.width - 1), cy = 0.5 * (s.resolution.height - 1);
    std::vector<double> ratios;
    for (size_t k = 0; k < run.events.size(); k++)
    {
        const cv::event::Event& e = run.events[k];
        const float* g = run.groundTruth.ptr<float>(run.truthRows[k]);
        const double r = std::hypot(e.x - cx, e.y - cy);
        if (((int)g[cv::event::GT_FLAGS] & cv::event::GT_FLAG_NOISE) || r < 6 || r > 12 || g[cv::event::GT_LIFETIME] <= 0)
            continue;
        ratios.push_back(g[cv::event::GT_LIFETIME] * 1e-6 * omega * std::sqrt(r * r - w * w));
    }
    std::sort(ratios.begin(), ratios.end());
    return ratios;
}

/** LifetimeEstimator's default inlierDistance, for the tests that compare it with other settings. */
inline double defaultInlierDistance()
{
    return cv::event::LifetimeEstimator::create()->getInlierDistance();
}

/** A plain wall (intensity 0.2, 3 m away) and, 1 m away, bright bars of log contrast @p logContrast over it,
each @p halfSizePx (half width, half height [px]) about its centre, turned in the image by @p angleRad, with
centres @p centresPx px right of the optical axis at t = 0 (on its row), all sliding right at @p speed px/s, for
a camera of focal length @p focalLength [px]. */
inline std::vector<cv::event::SimulatedPlane> barsOnAWall(double focalLength, const std::vector<double>& centresPx,
                                                          cv::Vec2d halfSizePx, double logContrast, double angleRad,
                                                          double speed)
{
    using namespace cv::event;
    const double px = 1.0 / focalLength;  // metres per pixel at 1 m
    std::vector<SimulatedPlane> planes(1);
    planes[0].center = cv::Vec3d(0, 0, 3);
    planes[0].halfSize = cv::Vec2d(2, 2);
    planes[0].texture = TEXTURE_UNIFORM;
    planes[0].intensity = 0.2;
    for (double x : centresPx)
    {
        SimulatedPlane bar = planes[0];
        bar.center = cv::Vec3d(x * px, 0, 1);
        bar.halfSize = halfSizePx * px;
        bar.rotation = cv::Vec3d(0, 0, angleRad);
        bar.intensity = 0.2 * std::exp(logContrast);
        bar.velocity = cv::Vec3d(speed * px, 0, 0);
        planes.push_back(bar);
    }
    return planes;
}

/** Bright vertical bars, 4 px wide and 12 px apart, 1 m away, sliding right at @p speed px/s over a plain wall,
seen by the realistic scenes' sensor (boxes: threshold spread, 0.5 ms refractory period, latency and jitter,
noise) on a 64 x 32 crop, through a LifetimeEstimator with @p inlierDistance, @p timeWindowUs,
@p skipEarlierEdges and, when not negative, @p crossingLifetimes. Returns the median ratio of the estimated
lifetimes to the closed form 1 / speed over the left signal events after the first 20 px of travel, and the
share of them with a lifetime. The unit tests and the design_figures benchmark share it. */
inline std::pair<double, double> barsLifetimeRatio(double speed, double logContrast, double blurPx,
                                                   double inlierDistance, double timeWindowUs = 100000,
                                                   double crossingLifetimes = -1, bool skipEarlierEdges = true)
{
    using namespace cv::event;
    SimulatorSettings s = StereoEventSimulator::create("boxes")->getSettings();
    s.resolution = cv::Size(64, 32);
    s.blurSigmaPx = blurPx;
    const double travel = 100;  // px
    std::vector<double> centres;
    for (double x = -32 - travel - 12; x < 32 + 12; x += 12)
        centres.push_back(x);
    cv::Ptr<StereoEventSimulator> sim =
        StereoEventSimulator::create(barsOnAWall(s.focalLength, centres, cv::Vec2d(2, 40), logContrast, 0, speed), s);
    cv::Ptr<LifetimeEstimator> est = LifetimeEstimator::create(s.resolution);
    est->setInlierDistance(inlierDistance);
    est->setTimeWindow(timeWindowUs);
    if (crossingLifetimes >= 0)
        est->setCrossingLifetimes(crossingLifetimes);
    est->setSkipEarlierEdges(skipEarlierEdges);
    const LeftCameraEvents run = generateLeftCamera(*sim, travel / speed * 1e6);
    const std::vector<Event>& left = run.events;
    cv::Mat lifetimes;
    est->process(left, lifetimes);
    std::vector<double> ratio;
    int signal = 0;
    for (size_t k = 0; k < left.size(); k++)
    {
        const bool noise = ((int)run.groundTruth.at<float>(run.truthRows[k], GT_FLAGS) & GT_FLAG_NOISE) != 0;
        if (noise || left[k].t < 20 / speed * 1e6)
            continue;
        signal++;
        if (lifetimes.at<float>((int)k) > 0)
            ratio.push_back(lifetimes.at<float>((int)k) / (1e6 / speed));
    }
    CV_Assert(signal > 1000);
    std::nth_element(ratio.begin(), ratio.begin() + (std::ptrdiff_t)(ratio.size() / 2), ratio.end());
    return std::make_pair(ratio[ratio.size() / 2], (double)ratio.size() / signal);
}

/** The first @p untilUs of a built-in scene (both cameras' events), with its settings changed by
@p change (called with the scene's SimulatorSettings) first. */
template <typename SettingsChange>
inline std::vector<cv::event::Event> simulateChangedScene(const cv::String& scene, SettingsChange change, double untilUs)
{
    cv::Ptr<cv::event::StereoEventSimulator> base = cv::event::StereoEventSimulator::create(scene);
    cv::event::SimulatorSettings s = base->getSettings();
    change(s);
    cv::Ptr<cv::event::StereoEventSimulator> sim = cv::event::StereoEventSimulator::create(base->getPlanes(), s);
    std::vector<cv::event::Event> ev;
    cv::Mat gt;
    sim->generate(untilUs, ev, gt);
    return ev;
}

/** The first @p untilUs of a built-in scene with the right camera's rows moved by the simulator's
rightRowOffset / rightRollRad (both cameras' events). */
inline std::vector<cv::event::Event> misalignedScene(const cv::String& scene, double rowOffset, double roll,
                                                     double untilUs = 200000)
{
    return simulateChangedScene(scene, [&](cv::event::SimulatorSettings& s) {
        s.rightRowOffset = rowOffset;
        s.rightRollRad = roll;
    }, untilUs);
}

}  // namespace opencv_test

#endif
