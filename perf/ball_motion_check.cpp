// What LifetimeArrivalCheck says of lifetimes taken from a swinging ball's tracked motion: prints one Markdown
// table.
//
//   ball_motion_check [--recording=pendulum_left_30cm_2.tsv.txt]
//
// A recording has no true lifetimes, but where one round object moves, its outline moves with it. Every 10 ms
// the ball's centre and radius are taken from the events (the mean of the events near their median, the
// distance that holds 80 % of those), smoothed over the neighbouring bins; an outline event's edge then moves
// along the ball's normal at the centre's velocity along it plus the radius' growth, which gives a lifetime and
// a flow. These go through the check beside LifetimeEstimator's own: first on the simulated pendulum set as the
// TUM recording fires, where the true lifetimes say how well the tracked ones stand in for them, then, when given,
// on the TUM pendulum recording (DVS128, text, its left camera).

#include "command_line.hpp"
#include "test_simulator_helpers.hpp"  // pendulumAsTumFires, perfectLifetimes

#include <opencv2/calib3d.hpp>
#include <opencv2/event.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace cv;
using namespace cv::event;
using opencv_test::generateLeftCamera;
using opencv_test::LeftCameraEvents;
using opencv_test::pendulumAsTumFires;
using opencv_test::perfectLifetimes;

namespace {

const double BIN_US = 10000;
const double NONE = std::numeric_limits<double>::quiet_NaN();

double quantile(std::vector<double> v, double q)
{
    if (v.empty())
        return NONE;
    const size_t k = std::min(v.size() - 1, (size_t)(q * (double)v.size()));
    std::nth_element(v.begin(), v.begin() + (std::ptrdiff_t)k, v.end());
    return v[k];
}

// The mean of the values within `half` bins of each bin that are known (NaN where none is).
std::vector<double> smoothed(const std::vector<double>& v, int half)
{
    std::vector<double> out(v.size(), NONE);
    for (int i = 0; i < (int)v.size(); i++)
    {
        double sum = 0;
        int n = 0;
        for (int j = std::max(0, i - half); j <= std::min((int)v.size() - 1, i + half); j++)
            if (!std::isnan(v[(size_t)j]))
            {
                sum += v[(size_t)j];
                n++;
            }
        if (n > 0)
            out[(size_t)i] = sum / n;
    }
    return out;
}

// The change per second over four bins, centred.
std::vector<double> rate(const std::vector<double>& v)
{
    std::vector<double> out(v.size(), NONE);
    for (size_t i = 2; i + 2 < v.size(); i++)
        out[i] = (v[i + 2] - v[i - 2]) / (4 * BIN_US * 1e-6);
    return out;
}

/** The ball's centre, radius and their rates [px, px/s] per 10 ms bin from the recording's first event. */
struct BallTrack
{
    int64 t0 = 0;
    std::vector<double> cx, cy, radius, vx, vy, growth;
    int bin(const Event& e) const { return (int)((e.t - t0) / (int64)BIN_US); }
};

// `reach`: how far from the centre an event may lie and still be the ball's [px].
BallTrack trackBall(const std::vector<Event>& events, double reach)
{
    BallTrack track;
    if (events.empty())
        return track;
    track.t0 = events.front().t;
    const size_t bins = (size_t)track.bin(events.back()) + 1;
    std::vector<double> cx(bins, NONE), cy(bins, NONE), radius(bins, NONE);
    std::vector<double> xs, ys, near;
    for (size_t first = 0, b = 0; b < bins; b++)
    {
        xs.clear();
        ys.clear();
        for (; first < events.size() && track.bin(events[first]) == (int)b; first++)
        {
            xs.push_back(events[first].x);
            ys.push_back(events[first].y);
        }
        if (xs.size() < 40)
            continue;
        double mx = quantile(xs, 0.5), my = quantile(ys, 0.5);
        for (int it = 0; it < 3; it++)
        {
            double sx = 0, sy = 0;
            int n = 0;
            for (size_t k = 0; k < xs.size(); k++)
                if (std::hypot(xs[k] - mx, ys[k] - my) < reach)
                {
                    sx += xs[k];
                    sy += ys[k];
                    n++;
                }
            if (n < 20)
                break;
            mx = sx / n;
            my = sy / n;
        }
        near.clear();
        for (size_t k = 0; k < xs.size(); k++)
        {
            const double r = std::hypot(xs[k] - mx, ys[k] - my);
            if (r < reach)
                near.push_back(r);
        }
        cx[b] = mx;
        cy[b] = my;
        if (near.size() > 10)
            radius[b] = quantile(near, 0.8);
    }
    track.cx = smoothed(cx, 2);
    track.cy = smoothed(cy, 2);
    track.radius = smoothed(radius, 4);
    track.vx = rate(track.cx);
    track.vy = rate(track.cy);
    track.growth = rate(track.radius);
    return track;
}

/** Each outline event's lifetime [us] and flow [px/s] from the track (0 elsewhere): the events 0.6-1.4 radii
from the centre whose edge moves faster than 20 px/s along the normal. `outline` marks them. */
void motionLifetimes(const std::vector<Event>& events, const BallTrack& track, Mat& lifetimes, Mat& flow,
                     std::vector<bool>& outline)
{
    const int n = (int)events.size();
    lifetimes = Mat::zeros(n, 1, CV_32F);
    flow = Mat::zeros(n, 2, CV_32F);
    outline.assign((size_t)n, false);
    for (int k = 0; k < n; k++)
    {
        const Event& e = events[(size_t)k];
        const size_t b = (size_t)track.bin(e);
        const double dx = e.x - track.cx[b], dy = e.y - track.cy[b], d = std::hypot(dx, dy), r = track.radius[b];
        if (std::isnan(track.vx[b]) || std::isnan(track.growth[b]) || std::isnan(r) || !(d > 0.6 * r && d < 1.4 * r))
            continue;
        const double nx = dx / d, ny = dy / d;
        const double speed = track.vx[b] * nx + track.vy[b] * ny + track.growth[b];  // along the normal, outward
        if (!(std::abs(speed) > 20))
            continue;
        outline[(size_t)k] = true;
        lifetimes.at<float>(k) = (float)(1e6 / std::abs(speed));
        flow.at<float>(k, 0) = (float)(speed * nx);
        flow.at<float>(k, 1) = (float)(speed * ny);
    }
}

// Lifetimes outside `keep` set to 0 (no claim), for a check over the outline events only.
Mat only(const Mat& lifetimes, const std::vector<bool>& keep)
{
    Mat out = lifetimes.clone();
    for (int k = 0; k < out.rows; k++)
        if (!keep[(size_t)k])
            out.at<float>(k) = 0;
    return out;
}

// One row: the check over `lifetimes` and, where given, their median ratio (quartiles) to the tracked ones.
void printRow(const std::string& recording, const std::string& what, const std::vector<Event>& events, Size sensor,
              const Mat& lifetimes, const Mat& flow, const Mat& tracked)
{
    Ptr<LifetimeArrivalCheck> check = LifetimeArrivalCheck::create(sensor);
    check->update(events, lifetimes, flow);
    std::vector<double> ratios;
    int withLifetime = 0;
    for (int k = 0; k < lifetimes.rows; k++)
    {
        const float l = lifetimes.at<float>(k);
        withLifetime += l > 0;
        if (!tracked.empty() && l > 0 && tracked.at<float>(k) > 0)
            ratios.push_back(l / tracked.at<float>(k));
    }
    std::string overTracked = "-";
    if (!ratios.empty())
    {
        char buf[64];
        std::snprintf(buf, sizeof(buf), "%.2f (%.2f / %.2f)", quantile(ratios, 0.5), quantile(ratios, 0.25),
                      quantile(ratios, 0.75));
        overTracked = buf;
    }
    std::printf("| %s | %s | %d | %.0f | %.2f (%.2f / %.2f) | %s |\n", recording.c_str(), what.c_str(), withLifetime,
                check->getSampleCount(), check->getRatioQuantile(0.5), check->getRatioQuantile(0.25),
                check->getRatioQuantile(0.75), overTracked.c_str());
    std::fflush(stdout);
}

// The rows of one recording: the tracked lifetimes, ours over the same events and over all, and, with a
// simulator's truth, the true ones too.
void printRecording(const std::string& name, const std::vector<Event>& events, Size sensor, double reach,
                    const Mat& trueLifetimes, const Mat& trueFlow)
{
    const BallTrack track = trackBall(events, reach);
    Mat tracked, trackedFlow;
    std::vector<bool> outline;
    motionLifetimes(events, track, tracked, trackedFlow, outline);
    Mat ours, ourFlow;
    LifetimeEstimator::create(sensor)->process(events, ours, ourFlow);
    if (!trueLifetimes.empty())
    {
        printRow(name, "true, every event", events, sensor, trueLifetimes, trueFlow, Mat());
        printRow(name, "true, outline", events, sensor, only(trueLifetimes, outline), trueFlow, tracked);
    }
    printRow(name, "tracked motion, outline", events, sensor, tracked, trackedFlow, Mat());
    printRow(name, "ours, outline", events, sensor, only(ours, outline), ourFlow, tracked);
    printRow(name, "ours, every event", events, sensor, ours, ourFlow, Mat());
}

// The simulated pendulum set as the TUM recording fires, its ball (the built octagon: two squares, the second
// turned by 45 degrees) made a 16-sided one by two more squares turned by 22.5 degrees: round, as the
// recording's ball and the tracking take it, so that its outline's normals are radial.
Ptr<StereoEventSimulator> roundPendulum()
{
    const Ptr<StereoEventSimulator> built = pendulumAsTumFires("pendulum");
    std::vector<SimulatedPlane> planes = built->getPlanes();
    const SimulatedPlane* square = nullptr;  // the unturned square: its pivot straight above it
    for (const SimulatedPlane& p : planes)
        if (p.halfSize == Vec2d(0.025, 0.025) && p.swingPivot[0] == 0)
            square = &p;
    CV_Assert(square);
    const SimulatedPlane unturned = *square;
    Matx33d r0;
    Rodrigues(unturned.rotation, r0);
    const double length = -unturned.swingPivot[1];
    for (double turn : { CV_PI / 8, 3 * CV_PI / 8 })
    {
        SimulatedPlane p = unturned;
        Rodrigues(r0 * Matx33d(std::cos(turn), -std::sin(turn), 0, std::sin(turn), std::cos(turn), 0, 0, 0, 1),
                  p.rotation);
        p.swingPivot = Vec2d(-length * std::sin(turn), -length * std::cos(turn));
        planes.push_back(p);
    }
    return StereoEventSimulator::create(planes, built->getSettings());
}

}  // namespace

int main(int argc, char** argv)
{
    try
    {
        const char* keys =
            "{help h      | false | print this message}"
            "{recording   |       | the TUM pendulum recording (DVS128, text; none: the simulated rows only)}"
            "{reach-px    | 18    | how far from the ball's centre its events lie [px]}"
            "{duration-ms | 7000  | simulated time [ms]}";
        ProgramCommandLine cmd(argc, argv, keys,
                               "What LifetimeArrivalCheck says of lifetimes taken from a swinging ball's tracked motion.");
        if (cmd.helpShown())
            return 0;
        const std::string path = cmd.get<std::string>("recording");
        const double reach = cmd.get<double>("reach-px");
        std::cout << "| recording | lifetimes | events with one | check samples | check: median (quartiles) | "
                     "over the tracked lifetime: median (quartiles) |\n|---|---|---|---|---|---|\n";

        const Ptr<StereoEventSimulator> sim = roundPendulum();
        const LeftCameraEvents run = generateLeftCamera(*sim, cmd.get<double>("duration-ms") * 1000);
        Mat trueLifetimes, trueFlow;
        perfectLifetimes(run.groundTruth, run.truthRows, trueLifetimes, trueFlow);
        printRecording("simulated `pendulum`, round, as TUM pendulum fires", run.events, sim->getSensorSize(), reach,
                       trueLifetimes, trueFlow);

        if (path.empty())
            return 0;
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, 128);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, 128);
        cap.set(EVENT_CAP_PROP_WINDOW_US, 100000);
        cap.open(path);
        std::vector<Event> events, packet;
        while (cap.read(packet))
            for (const Event& e : packet)
                if (e.camera == CAMERA_LEFT)
                    events.push_back(e);
        printRecording("TUM pendulum", events, Size(128, 128), reach, Mat(), Mat());
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "ball_motion_check: " << errorText(e) << "\n";
        return 1;
    }
}
