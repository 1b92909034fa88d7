// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stereo event simulator (ESIM-style, Rebecq et al. 2018): ray-cast the log intensity of textured moving
// planes for both cameras at adaptively spaced instants; each pixel fires whenever its log intensity has
// moved by its threshold since its last event, at a time interpolated between the two renders. Ground truth
// (depth, disparity, normal flow, lifetime, occlusion) comes from the same ray casts.

#include "precomp.hpp"
#include "simulation/simulated_scenes.hpp"
#include "opencv2/calib3d.hpp"
#include "opencv2/imgproc.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>

namespace cv {
namespace event {

SimulatorSettings SimulatorSettings::preset(int sensorModel)
{
    SimulatorSettings s;
    s.resolution = getSensorSize(sensorModel);
    if (sensorModel == SENSOR_DAVIS346)
        s.focalLength = 250;
    else if (sensorModel != SENSOR_DAVIS240)
        s.focalLength = 0.8 * s.resolution.width;  // about a 64-degree horizontal field of view
    return s;
}

namespace {

// Deterministic hash of a texture cell -> [0, 1).
double cellValue(int64 i, int64 j, int seed)
{
    uint64 h = (uint64)i * 0x9E3779B97F4A7C15ULL ^ (uint64)j * 0xC2B2AE3D27D4EB4FULL ^ (uint64)(seed + 1) * 0x165667B19E3779F9ULL;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 32;
    return (double)(h >> 11) * (1.0 / 9007199254740992.0);
}

// Cells around position p along one axis with the weight of the upper one: sharp edges 1/8 cell wide.
inline void edgeBlend(double p, int64& lo, int64& hi, double& wHi)
{
    const double halfWidth = 1.0 / 16;
    const double k = std::floor(p + 0.5);  // nearest cell boundary
    const double d = p - k;
    if (d >= halfWidth || d <= -halfWidth)
    {
        lo = hi = (int64)std::floor(p);
        wHi = 0;
        return;
    }
    lo = (int64)k - 1;
    hi = (int64)k;
    wHi = (d + halfWidth) / (2 * halfWidth);
}

struct PlanePose
{
    Vec3d c, u, v, n;   // centre, in-plane axes, normal
    double cosT, sinT;  // texture rotation
    // Swinging planes: a point X moves at pivotVelocity + angularVelocity x (X - pivot).
    bool swinging = false;
    Vec3d pivot, pivotVelocity, angularVelocity;
};

// A plane at one render, from one camera (StereoEventSimulatorImpl::planeInView()). A ray with direction d
// (d.z = 1) can only hit the plane's rectangle within the box of its corners' directions, when the corners
// lie in front of the camera.
struct PlaneInView
{
    double distance = 0;  // n . (c - origin): a ray's depth at the plane is distance / (n . d)
    float uniformLogI = 0;
    bool bounded = false;
    double lo[2] = { std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity() };
    double hi[2] = { -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
    bool mayHit(const Vec3d& d) const
    {
        return !bounded || (d[0] >= lo[0] && d[0] <= hi[0] && d[1] >= lo[1] && d[1] <= hi[1]);
    }
};

using SimulatedEvent = std::pair<Event, std::array<float, 6>>;

bool earlierEvent(const SimulatedEvent& a, const SimulatedEvent& b)
{
    const Event& e = a.first;
    const Event& g = b.first;
    if (e.t != g.t) return e.t < g.t;
    if (e.camera != g.camera) return e.camera < g.camera;
    if (e.y != g.y) return e.y < g.y;
    return e.x < g.x;
}

struct Render
{
    std::vector<float> logI, depth, flowX, flowY;
    std::vector<int> plane;          // the plane each pixel sees (-1: none)
    std::vector<float> flickerLogI;  // with flickering planes: the flicker's share of logI (log of its factor)
    // The planes at the render's time, for the rays the ground truth casts between the pixel centres.
    std::vector<PlanePose> poses;
    std::vector<PlaneInView> views;
};

// Where a ray meets the nearest plane: its index (-1: none), the depth, the point and its in-plane coordinates.
struct RayHit
{
    int plane = -1;
    double depth = std::numeric_limits<double>::infinity();
    Vec3d point;
    double a = 0, b = 0;
};

class StereoEventSimulatorImpl CV_FINAL : public StereoEventSimulator
{
public:
    StereoEventSimulatorImpl(const std::vector<SimulatedPlane>& planes, const SimulatorSettings& s)
        : planes_(planes), s_(s), rng_((uint64)(s.seed * 7919 + 17)), jitterRng_((uint64)(s.seed * 7919 + 303)),
          thresholdRng_((uint64)(s.seed * 7919 + 909)),
          hotRng_((uint64)(s.seed * 7919 + 505)), leakRng_((uint64)(s.seed * 7919 + 707))
    {
        if (s.resolution.width <= 0 || s.resolution.height <= 0 || !(s.focalLength > 0) || !(s.baseline > 0))
            CV_Error(Error::StsBadArg, "StereoEventSimulator: resolution, focal length and baseline must be positive");
        if (!(s.thresholdOn > 0 && s.thresholdOff > 0 && s.maxPixelStep > 0 && s.maxStepUs > 0))
            CV_Error(Error::StsBadArg, "StereoEventSimulator: thresholds and step limits must be positive");
        if (!(s.latencyUs >= 0 && s.latencySigmaUs >= 0 && s.jitterUs >= 0 && s.hotPixelShare >= 0 &&
              s.hotPixelShare <= 1 && s.hotPixelRateHz >= 0 && s.leakRateHz >= 0 && s.noiseRateHz >= 0 &&
              std::abs(s.rightRollRad) < 0.5 && std::abs(s.rightRowOffset) < s.resolution.height &&
              std::abs(s.rightScale) < 0.5 && std::abs(s.rightColumnOffset) < s.resolution.width &&
              s.thresholdNoise >= 0 && s.blurSigmaPx >= 0 && s.blurSigmaPx <= 10 && s.extraLatencyUs[0] >= 0 &&
              s.extraLatencyUs[1] >= 0 && s.extraLatencyUs[2] >= 0 && s.extraLatencyUs[3] >= 0 &&
              std::abs(s.rightClockOffsetUs) < 1e12 && std::abs(s.rightClockDriftPpm) < 1e5))
            CV_Error(Error::StsBadArg, "StereoEventSimulator: latencies, jitter, rates and the hot-pixel share must "
                                       "be >= 0 (share <= 1), the roll and the scale below 0.5, the offsets within the image, "
                                       "the blur at most 10 px, the right clock's drift below 1e5 ppm");
        for (const SimulatedPlane& p : planes)
        {
            if (!(p.flickerDepth >= 0 && p.flickerDepth < 1))
                CV_Error_(Error::StsBadArg, ("StereoEventSimulator: a plane's flickerDepth is %g; expected [0, 1)", p.flickerDepth));
            flickering_ = flickering_ || p.flickerDepth > 0;
        }
        if (flickering_ && !(s.flickerFrequencyHz > 0))
            CV_Error_(Error::StsBadArg, ("StereoEventSimulator: flickerFrequencyHz is %g; a flickering plane needs it > 0",
                                         s.flickerFrequencyHz));
        for (size_t k = 0; k < planes.size(); k++)
            if (!isStatic(planes[k]))
                movingPlanes_.push_back((int)k);
        rollCos_ = std::cos(s.rightRollRad);
        rollSin_ = std::sin(s.rightRollRad);
        for (int j = 0; j < EDGE_STEPS; j++)
            circle_.push_back(Vec2d(std::cos(2 * CV_PI * j / EDGE_STEPS), std::sin(2 * CV_PI * j / EDGE_STEPS)));
        const int n = s.resolution.area();
        RNG latencyRng((uint64)(s.seed * 7919 + 101)), hotPixelRng((uint64)(s.seed * 7919 + 202));
        delayed_ = s.latencyUs > 0 || s.latencySigmaUs > 0 || s.jitterUs > 0 || s.extraLatencyUs != Vec4d::all(0);
        for (int c = 0; c < 2; c++)
        {
            const double scale = c == CAMERA_RIGHT ? s.rightThresholdScale : 1.0;
            cOn_[c].resize(n);
            cOff_[c].resize(n);
            for (int i = 0; i < n; i++)
            {
                cOn_[c][i] = (float)std::max(0.01, scale * (s.thresholdOn + s.thresholdSigma * rng_.gaussian(1.0)));
                cOff_[c][i] = (float)std::max(0.01, scale * (s.thresholdOff + s.thresholdSigma * rng_.gaussian(1.0)));
            }
            lastEvent_[c].assign(n, -1e18);
            if (delayed_)
            {
                lastStamp_[c].assign(n, std::numeric_limits<int64>::min());
                latency_[c].resize(n);
                for (int i = 0; i < n; i++)
                    latency_[c][i] = (float)std::max(0.0, s.latencyUs + s.latencySigmaUs * latencyRng.gaussian(1.0));
            }
            if (s.hotPixelShare > 0)
                for (int i = 0; i < n; i++)
                    if (hotPixelRng.uniform(0.0, 1.0) < s.hotPixelShare)
                        hotPixels_[c].push_back(std::make_pair(i, hotPixelRng.uniform(0, 2)));
            if (!flickering_)
                render(c, 0.0, staticScene_[c], true);
            render(c, 0.0, cur_[c]);
            ref_[c] = cur_[c].logI;
            if (flickering_)
                for (int i = 0; i < n; i++)
                    steadyAtCrossing_[c].push_back(cur_[c].logI[i] - cur_[c].flickerLogI[i]);
        }
    }

    bool generate(double untilUs, OutputArray events, OutputArray groundTruth) CV_OVERRIDE
    {
        if (!(untilUs > delivered_))
        {
            events.release();
            groundTruth.release();
            return false;
        }
        // A right clock behind the shared one stamps events earlier than they fire: simulate far enough ahead
        // that every event stamped before untilUs exists.
        const double behind = std::max(0.0, -s_.rightClockOffsetUs) + std::max(0.0, -s_.rightClockDriftPpm * 1e-6 * untilUs);
        const double lead = behind > 0 ? behind + 1 : 0.0;  // + 1: the restamping rounds
        while (t_ < untilUs + lead)
            step();
        // Hand out what is before untilUs; events after it wait for the next call, so the output does not
        // depend on how the simulation is chunked.
        const int64 until = (int64)std::ceil(untilUs);
        size_t k = 0;
        while (k < pending_.size() && pending_[k].first.t < until)
            k++;
        std::vector<Event> out(k);
        Mat gt((int)k, 6, CV_32F);
        for (size_t i = 0; i < k; i++)
        {
            out[i] = pending_[i].first;
            std::memcpy(gt.ptr<float>((int)i), pending_[i].second.data(), 6 * sizeof(float));
        }
        Mat(out).copyTo(events);
        gt.copyTo(groundTruth);
        pending_.erase(pending_.begin(), pending_.begin() + k);
        delivered_ = untilUs;
        return true;
    }

    double getTime() const CV_OVERRIDE { return delivered_; }

    void renderDisparity(int camera, OutputArray disparity) const CV_OVERRIDE
    {
        checkCamera(camera);
        Mat_<float> d(s_.resolution, 0.f);
        const Render& r = cur_[camera];
        for (int i = 0; i < s_.resolution.area(); i++)
            if (r.depth[i] > 0)
                d(i) = (float)(s_.focalLength * s_.baseline / r.depth[i]);
        d.copyTo(disparity);
    }

    void renderIntensity(int camera, OutputArray intensity) const CV_OVERRIDE
    {
        checkCamera(camera);
        Mat_<float> m(s_.resolution);
        for (int i = 0; i < s_.resolution.area(); i++)
            m(i) = std::exp(cur_[camera].logI[i]);
        m.copyTo(intensity);
    }

    const SimulatorSettings& getSettings() const CV_OVERRIDE { return s_; }
    const std::vector<SimulatedPlane>& getPlanes() const CV_OVERRIDE { return planes_; }
    Size getSensorSize() const CV_OVERRIDE { return s_.resolution; }
    String getDefaultName() const CV_OVERRIDE { return "StereoEventSimulator"; }

private:
    static void checkCamera(int camera)
    {
        if (camera != CAMERA_LEFT && camera != CAMERA_RIGHT)
            CV_Error_(Error::StsBadArg, ("StereoEventSimulator: camera %d; expected 0 (left) or 1 (right)", camera));
    }

    PlanePose pose(const SimulatedPlane& p, double tUs) const
    {
        const double t = tUs * 1e-6;
        Matx33d r0, rt;
        Rodrigues(p.rotation, r0);
        Rodrigues(p.angularVelocity * t, rt);
        const Matx33d r = rt * r0;
        PlanePose q;
        q.c = p.center + p.velocity * t;
        q.u = Vec3d(r(0, 0), r(1, 0), r(2, 0));
        q.v = Vec3d(r(0, 1), r(1, 1), r(2, 1));
        q.n = Vec3d(r(0, 2), r(1, 2), r(2, 2));
        const double angle = 0.35 + 1.1 * cellValue(p.textureSeed, 7, 3);  // not axis-aligned: edges of all directions
        q.cosT = std::cos(angle);
        q.sinT = std::sin(angle);
        if (p.swingAmplitude != 0)
        {
            // Turn the rigidly moved plane about its pivot: X = P + S (Y - P). A point's velocity is then
            // dP/dt + (swing rate + S w) x (X - P), with dP/dt = v + w x (P - c).
            const double phase = 2 * CV_PI * p.swingFrequency * t + p.swingPhase;
            const Vec3d axis = p.swingAxis * (1.0 / std::max(1e-12, norm(p.swingAxis)));
            Matx33d sw;
            Rodrigues(axis * (p.swingAmplitude * std::sin(phase)), sw);
            q.swinging = true;
            q.pivot = q.c + p.swingPivot[0] * q.u + p.swingPivot[1] * q.v;
            q.pivotVelocity = p.velocity + p.angularVelocity.cross(q.pivot - q.c);
            q.angularVelocity = axis * (p.swingAmplitude * 2 * CV_PI * p.swingFrequency * std::cos(phase)) +
                                sw * p.angularVelocity;
            q.c = q.pivot + sw * (q.c - q.pivot);
            q.u = sw * q.u;
            q.v = sw * q.v;
            q.n = sw * q.n;
        }
        return q;
    }

    // What every pixel's ray shares for one plane at one render: the numerator of its depth, the plane's
    // rectangle as seen from the camera (a bounding box of its corners' directions) and a uniform plane's log
    // intensity. Most planes cover a small part of the view, so most rays skip them after four comparisons.
    static PlaneInView planeInView(const SimulatedPlane& p, const PlanePose& q, const Vec3d& origin)
    {
        PlaneInView view;
        view.distance = q.n.dot(q.c - origin);
        view.uniformLogI = (float)std::log(std::max(p.intensity, 1e-4));
        for (int corner = 0; corner < 4; corner++)
        {
            const Vec3d r = q.c + ((corner & 1) ? 1.0 : -1.0) * p.halfSize[0] * q.u +
                            ((corner & 2) ? 1.0 : -1.0) * p.halfSize[1] * q.v - origin;
            if (!(r[2] > 1e-3))
                return view;  // a corner near or behind the camera: no box, every ray is tested
            view.lo[0] = std::min(view.lo[0], r[0] / r[2]);
            view.hi[0] = std::max(view.hi[0], r[0] / r[2]);
            view.lo[1] = std::min(view.lo[1], r[1] / r[2]);
            view.hi[1] = std::max(view.hi[1], r[1] / r[2]);
        }
        // The margin (about 1e-4 px) keeps the box conservative against the rounding of the hit test.
        for (int j = 0; j < 2; j++)
        {
            view.lo[j] -= 1e-6;
            view.hi[j] += 1e-6;
        }
        view.bounded = true;
        return view;
    }

    double texture(const SimulatedPlane& p, const PlanePose& q, double a, double b) const
    {
        if (p.texture == TEXTURE_UNIFORM)
            return p.intensity;
        const double x = (q.cosT * a + q.sinT * b) / p.cellSize, y = (-q.sinT * a + q.cosT * b) / p.cellSize;
        int64 x0, x1, y0, y1;
        double wx, wy;
        edgeBlend(x, x0, x1, wx);
        edgeBlend(y, y0, y1, wy);
        auto value = [&](int64 i, int64 j) { return p.intensity * (1.0 - p.contrast * cellValue(i, j, p.textureSeed)); };
        const double top = (1 - wx) * value(x0, y0) + wx * value(x1, y0);
        const double bottom = (1 - wx) * value(x0, y1) + wx * value(x1, y1);
        return (1 - wy) * top + wy * bottom;
    }

    // The lens blur's kernel: out to 4 sigma, as GaussianBlur sizes it for float images.
    Size blurKernel() const
    {
        const int k = cvRound(s_.blurSigmaPx * 8 + 1) | 1;
        return Size(k, k);
    }

    // A plane whose pose is the same at every time (velocity * t and the rotation by angularVelocity * t are
    // exact zeros): its rays' results are too, bit for bit.
    static bool isStatic(const SimulatedPlane& p)
    {
        return p.velocity == Vec3d::all(0) && p.angularVelocity == Vec3d::all(0) && p.swingAmplitude == 0;
    }

    // The direction (z = 1) of the ray through point (x, y) of @p camera's pixel grid, pixel centres at whole
    // coordinates. The right camera's grid may be off the ideal rectified one (rightRollRad, rightScale,
    // rightColumnOffset, rightRowOffset).
    Vec3d rayDirection(int camera, double x, double y) const
    {
        const Size sz = s_.resolution;
        const double f = s_.focalLength, cx = 0.5 * (sz.width - 1), cy = 0.5 * (sz.height - 1);
        if (misrectified(camera))
        {
            // Raw pixel -> ideal pixel: undo the offsets, the scale, then the roll.
            const double cr = rollCos_, sr = rollSin_;
            const double rx = x - cx - s_.rightColumnOffset, ry = y - cy - s_.rightRowOffset;
            const double g = f * (1 + s_.rightScale);
            return Vec3d((cr * rx + sr * ry) / g, (-sr * rx + cr * ry) / g, 1.0);
        }
        return Vec3d((x - cx) / f, (y - cy) / f, 1.0);
    }

    // Whether @p camera's pixel grid is off the ideal rectified one (the right camera's rightRollRad, rightScale,
    // rightColumnOffset, rightRowOffset).
    bool misrectified(int camera) const
    {
        return camera == CAMERA_RIGHT &&
               (s_.rightRollRad != 0 || s_.rightRowOffset != 0 || s_.rightScale != 0 || s_.rightColumnOffset != 0);
    }

    // The nearest of the planes (posed as in @p poses) that the ray from @p origin along @p d hits.
    RayHit castRay(const std::vector<PlanePose>& poses, const std::vector<PlaneInView>& views, const Vec3d& origin,
                   const Vec3d& d, bool staticOnly = false) const
    {
        RayHit h;
        for (size_t k = 0; k < planes_.size(); k++)
        {
            const PlaneInView& view = views[k];
            if (!view.mayHit(d) || (staticOnly && !isStatic(planes_[k])))
                continue;
            const PlanePose& q = poses[k];
            const double denom = q.n.dot(d);
            if (std::abs(denom) < 1e-12)
                continue;
            const double s = view.distance / denom;  // depth along +Z, since d.z = 1
            if (s <= 1e-6 || s >= h.depth)
                continue;
            const Vec3d pt = origin + s * d;
            const double a = q.u.dot(pt - q.c), b = q.v.dot(pt - q.c);
            if (std::abs(a) > planes_[k].halfSize[0] || std::abs(b) > planes_[k].halfSize[1])
                continue;
            h.depth = s;
            h.plane = (int)k;
            h.point = pt;
            h.a = a;
            h.b = b;
        }
        return h;
    }

    // The log intensity a ray's hit shows without flicker (the background's where it hits nothing).
    float steadyLogIntensity(const std::vector<PlanePose>& poses, const std::vector<PlaneInView>& views,
                             const RayHit& h) const
    {
        if (h.plane < 0)
            return (float)std::log(s_.backgroundIntensity);
        const SimulatedPlane& p = planes_[(size_t)h.plane];
        return p.texture == TEXTURE_UNIFORM ? views[(size_t)h.plane].uniformLogI
                                            : (float)std::log(std::max(texture(p, poses[(size_t)h.plane], h.a, h.b), 1e-4));
    }

    // Ray-casts one camera at time t: log intensity, depth, and the image motion of the visible point.
    // @p staticOnly: the static planes alone, sharp (staticScene_). Otherwise a pixel that no moving plane can
    // reach takes its static result as it is, unless the scene flickers (its intensities change with time): the
    // loop below would only compute it again.
    void render(int camera, double tUs, Render& out, bool staticOnly = false) const
    {
        const Size sz = s_.resolution;
        const double f = s_.focalLength;
        const Vec3d origin(camera == CAMERA_RIGHT ? s_.baseline : 0.0, 0, 0);
        const bool offGrid = misrectified(camera);
        const double flickerWave = flickering_ ? std::sin(2 * CV_PI * s_.flickerFrequencyHz * tUs * 1e-6) : 0.0;
        const double cr = rollCos_, sr = rollSin_;
        std::vector<PlanePose>& poses = out.poses;
        std::vector<PlaneInView>& views = out.views;
        poses.clear();
        views.clear();
        for (const SimulatedPlane& p : planes_)
        {
            poses.push_back(pose(p, tUs));
            views.push_back(planeInView(p, poses.back(), origin));
        }
        const int n = sz.area();
        out.logI.resize(n);
        out.depth.resize(n);
        out.plane.resize(n);
        out.flowX.resize(n);
        out.flowY.resize(n);
        if (flickering_)
            out.flickerLogI.assign(n, 0.f);
        const double background = std::log(s_.backgroundIntensity);
        const Render& still = staticScene_[camera];
        const bool reuseStatic = !staticOnly && !flickering_ && !still.logI.empty();
        // The moving planes' boxes together: most rays miss it after four comparisons.
        PlaneInView moving;
        moving.bounded = true;
        for (int k : movingPlanes_)
        {
            const PlaneInView& view = views[(size_t)k];
            moving.bounded = moving.bounded && view.bounded;
            for (int j = 0; j < 2; j++)
            {
                moving.lo[j] = std::min(moving.lo[j], view.lo[j]);
                moving.hi[j] = std::max(moving.hi[j], view.hi[j]);
            }
        }
        const auto movingMayHit = [&](const Vec3d& d) {
            return moving.mayHit(d) &&
                   std::any_of(movingPlanes_.begin(), movingPlanes_.end(), [&](int k) { return views[(size_t)k].mayHit(d); });
        };
        for (int y = 0; y < sz.height; y++)
        {
            for (int x = 0; x < sz.width; x++)
            {
                const Vec3d d = rayDirection(camera, x, y);
                const int i = y * sz.width + x;
                if (reuseStatic && !movingMayHit(d))
                {
                    out.logI[i] = still.logI[i];
                    out.depth[i] = still.depth[i];
                    out.plane[i] = still.plane[i];
                    out.flowX[i] = still.flowX[i];
                    out.flowY[i] = still.flowY[i];
                    continue;
                }
                const RayHit h = castRay(poses, views, origin, d, staticOnly);
                const int hit = h.plane;
                const double best = h.depth;
                const Vec3d& point = h.point;
                if (hit < 0)
                {
                    out.logI[i] = (float)background;
                    out.depth[i] = 0;
                    out.plane[i] = -1;
                    out.flowX[i] = out.flowY[i] = 0;
                    continue;
                }
                out.logI[i] = steadyLogIntensity(poses, views, h);
                if (flickering_ && planes_[hit].flickerDepth > 0)
                {
                    out.flickerLogI[i] = (float)std::log(1 + planes_[hit].flickerDepth * flickerWave);
                    out.logI[i] += out.flickerLogI[i];
                }
                out.depth[i] = (float)best;
                out.plane[i] = hit;
                // Motion of the visible point, projected: u = f X / Z + cx.
                const SimulatedPlane& p = planes_[hit];
                const PlanePose& q = poses[hit];
                const Vec3d vel = q.swinging ? q.pivotVelocity + q.angularVelocity.cross(point - q.pivot)
                                             : p.velocity + p.angularVelocity.cross(point - q.c);
                const Vec3d rel = point - origin;
                out.flowX[i] = (float)(f * (vel[0] * rel[2] - rel[0] * vel[2]) / (rel[2] * rel[2]));
                out.flowY[i] = (float)(f * (vel[1] * rel[2] - rel[1] * vel[2]) / (rel[2] * rel[2]));
                if (offGrid)
                {
                    // Ideal image motion -> the raw grid's (the roll turns it, the scale stretches it; the offsets
                    // do not move it).
                    const double fx = out.flowX[i], fy = out.flowY[i], g = 1 + s_.rightScale;
                    out.flowX[i] = (float)(g * (cr * fx - sr * fy));
                    out.flowY[i] = (float)(g * (sr * fx + cr * fy));
                }
            }
        }
        if (s_.blurSigmaPx > 0 && !staticOnly)
        {
            // The lens: blur the linear intensity, then back to log (the depth and motion stay the sharp ones).
            Mat logI(sz, CV_32F, out.logI.data()), linear;
            Mat steadyLinear;
            if (flickering_)
            {
                // The flicker's share after the lens: the blurred image against the blurred steady one.
                Mat flicker(sz, CV_32F, out.flickerLogI.data());
                exp(logI - flicker, steadyLinear);
                GaussianBlur(steadyLinear, steadyLinear, blurKernel(), s_.blurSigmaPx, s_.blurSigmaPx, BORDER_REPLICATE);
            }
            exp(logI, linear);
            GaussianBlur(linear, linear, blurKernel(), s_.blurSigmaPx, s_.blurSigmaPx, BORDER_REPLICATE);
            log(linear, logI);
            if (flickering_)
            {
                Mat flicker(sz, CV_32F, out.flickerLogI.data()), steadyLogI;
                log(steadyLinear, steadyLogI);
                subtract(logI, steadyLogI, flicker);
            }
        }
    }

    void step()
    {
        const Size sz = s_.resolution;
        double maxFlow = 0;
        for (int c = 0; c < 2; c++)
            for (int i = 0; i < sz.area(); i++)
                if (cur_[c].flowX[i] != 0 || cur_[c].flowY[i] != 0)  // most pixels see still planes
                    maxFlow = std::max(maxFlow, (double)std::hypot(cur_[c].flowX[i], cur_[c].flowY[i]));
        // Sized on the current motion; accelerations within one step are small for the rigid scenes simulated.
        // Whole microseconds: each step then owns the integer timestamps [t0, t1), so sorting a step's events
        // by (t, camera, y, x) orders the whole stream that way (left first on equal times).
        // Flicker: 40 renders per period keep the linear interpolation within 0.3 % of the sine's amplitude.
        const double maxStep = flickering_ ? std::min(s_.maxStepUs, 1e6 / (40 * s_.flickerFrequencyHz)) : s_.maxStepUs;
        const double dt = std::max(1.0, std::floor(std::min(maxStep, maxFlow > 0 ? s_.maxPixelStep / maxFlow * 1e6 : maxStep)));
        const double t0 = t_, t1 = t_ + dt;
        std::vector<SimulatedEvent> stepEvents;
        for (int c = 0; c < 2; c++)
            render(c, t1, next_[c]);
        for (int c = 0; c < 2; c++)  // after both renders: the occlusion test looks at the other camera
            fire(c, t0, t1, stepEvents);
        addNoise(t0, t1, stepEvents);
        std::sort(stepEvents.begin(), stepEvents.end(), earlierEvent);
        // Without delays every event of this step is later than every pending one and the merge only
        // appends; delayed events may land among those of earlier steps.
        const size_t before = pending_.size();
        pending_.insert(pending_.end(), stepEvents.begin(), stepEvents.end());
        std::inplace_merge(pending_.begin(), pending_.begin() + (std::ptrdiff_t)before, pending_.end(), earlierEvent);
        for (int c = 0; c < 2; c++)
            std::swap(cur_[c], next_[c]);
        t_ = t1;
    }

    // Events of one camera between the renders at t0 (cur_) and t1 (next_).
    void fire(int c, double t0, double t1, std::vector<SimulatedEvent>& out)
    {
        const Size sz = s_.resolution;
        const Render& a = cur_[c];
        const Render& b = next_[c];
        for (int y = 0; y < sz.height; y++)
        {
            for (int x = 0; x < sz.width; x++)
            {
                const int i = y * sz.width + x;
                const double l0 = a.logI[i], l1 = b.logI[i];
                if (l0 == l1)
                    continue;
                float& ref = ref_[c][i];
                const bool up = l1 > l0;
                const double pixelThreshold = up ? cOn_[c][i] : cOff_[c][i];
                // Flickering scenes: the steady (flicker-free) log intensity at the render times.
                const double s0 = flickering_ ? l0 - a.flickerLogI[i] : 0.0, s1 = flickering_ ? l1 - b.flickerLogI[i] : 0.0;
                for (;;)
                {
                    const double threshold = s_.thresholdNoise > 0
                        ? std::max(0.01, pixelThreshold + s_.thresholdNoise * thresholdRng_.gaussian(1.0))
                        : pixelThreshold;
                    const double level = up ? ref + threshold : ref - threshold;
                    if (up ? level > l1 : level < l1)
                        break;
                    ref = (float)level;
                    // The crossing time, linear between the renders (the ESIM interpolation).
                    const double frac = std::min(1.0, std::max(0.0, (level - l0) / (l1 - l0)));
                    // The flicker caused the crossing when the steady scene has moved by less than half a
                    // threshold in the crossing's direction since the pixel's previous crossing: motion alone
                    // would not have fired it.
                    bool byFlicker = false;
                    if (flickering_)
                    {
                        const double steady = s0 + frac * (s1 - s0);
                        const double towards = up ? steady - steadyAtCrossing_[c][i] : steadyAtCrossing_[c][i] - steady;
                        byFlicker = towards < 0.5 * threshold;
                        steadyAtCrossing_[c][i] = (float)steady;
                    }
                    const double te = t0 + frac * (t1 - t0);
                    if (te - lastEvent_[c][i] < s_.refractoryUs)
                        continue;  // inside the refractory period: the level is consumed, no event
                    lastEvent_[c][i] = te;
                    int64 ts = std::min((int64)t1 - 1, std::max((int64)t0, (int64)std::floor(te)));
                    if (delayed_)
                    {
                        const double jitter = s_.jitterUs > 0 ? -s_.jitterUs * std::log(1.0 - jitterRng_.uniform(0.0, 1.0)) : 0.0;
                        const double extra = s_.extraLatencyUs[2 * c + (up ? 0 : 1)];
                        ts = std::max(lastStamp_[c][i], std::max((int64)t0, (int64)std::floor(te + latency_[c][i] + extra + jitter)));
                        lastStamp_[c][i] = ts;
                    }
                    ts = cameraClock(c, ts);
                    std::array<float, 6> g = truth(c, x, y);
                    if (byFlicker)
                        g[GT_FLAGS] = (float)((int)g[GT_FLAGS] | GT_FLAG_FLICKER);
                    out.push_back(std::make_pair(Event(ts, x, y, up ? POLARITY_ON : POLARITY_OFF, c), g));
                }
            }
        }
    }

    std::array<float, 6> truth(int c, int x, int y) const
    {
        const Size sz = s_.resolution;
        const int i = y * sz.width + x;
        if (s_.blurSigmaPx > 0)
        {
            // Through the lens blur a pixel also fires for an edge as far away as the blur reaches: the nearest
            // surface within that reach caused it, and its depth is the truth. Even the blur's far tail fires where
            // a pixel's reference level lies just above the surface behind (after one ON event, two OFF events of
            // half its threshold bring it back exactly there). Its motion is that of the surface's pixel nearest
            // the event, where its contour passes: a surface that turns, nears or recedes moves differently across
            // its extent, and its nearest point in depth may lie on the far side of the reach.
            const int reach = blurKernel().width / 2;
            double best = std::numeric_limits<double>::infinity();
            int bestIndex = i, surface = -1;
            for (int yy = std::max(0, y - reach); yy <= std::min(sz.height - 1, y + reach); yy++)
                for (int xx = std::max(0, x - reach); xx <= std::min(sz.width - 1, x + reach); xx++)
                    for (const Render* r : { &cur_[c], &next_[c] })
                    {
                        const double z = r->depth[yy * sz.width + xx];
                        if (z > 0 && z < best - 1e-9)
                        {
                            best = z;
                            bestIndex = yy * sz.width + xx;
                            surface = r->plane[bestIndex];
                        }
                    }
            int motionIndex = bestIndex, closest = std::numeric_limits<int>::max();
            for (int yy = std::max(0, y - reach); yy <= std::min(sz.height - 1, y + reach); yy++)
                for (int xx = std::max(0, x - reach); xx <= std::min(sz.width - 1, x + reach); xx++)
                {
                    const int j = yy * sz.width + xx, apart = (xx - x) * (xx - x) + (yy - y) * (yy - y);
                    if (apart < closest && surface >= 0 && (cur_[c].plane[j] == surface || next_[c].plane[j] == surface))
                    {
                        closest = apart;
                        motionIndex = j;
                    }
                }
            return surfaceTruth(c, bestIndex % sz.width, bestIndex / sz.width, x, y, motionIndex);
        }
        return surfaceTruth(c, x, y, x, y, y * sz.width + x);
    }

    // The truth of the surface seen at pixel (x, y) for an event at pixel (ex, ey): through a lens blur a pixel
    // fires for a surface up to 4 sigma away. Its depth, disparity and occlusion are the surface's at (x, y); its
    // normal flow is the surface's motion at pixel motionIndex (where its contour passes nearest the event)
    // along the edge's normal at the event's pixel (edgeNormal()).
    std::array<float, 6> surfaceTruth(int c, int x, int y, int ex, int ey, int motionIndex) const
    {
        const Size sz = s_.resolution;
        const int i = y * sz.width + x;
        // An edge between two surfaces belongs to the nearer one (it is that surface's contour that moves):
        // take the ground truth from the render, before or after the crossing, that sees the nearer surface.
        const double z0 = cur_[c].depth[i], z1 = next_[c].depth[i];
        const bool before = z0 > 0 && (z1 <= 0 || z0 < z1);
        const Render& r = before ? cur_[c] : next_[c];
        const Render& other = before ? cur_[1 - c] : next_[1 - c];
        std::array<float, 6> g = { { 0, 0, 0, 0, 0, 0 } };
        const double z = r.depth[i];
        if (z <= 0)
            return g;  // the background: no geometry, no disparity
        g[GT_DEPTH] = (float)z;
        g[GT_DISPARITY] = (float)(s_.focalLength * s_.baseline / z);
        // The motion at motionIndex, in the render where that pixel sees this surface.
        const Render& moving = r.plane[motionIndex] == r.plane[i] ? r : (before ? next_[c] : cur_[c]);
        const int m = moving.plane[motionIndex] == r.plane[i] ? motionIndex : i;
        setNormalFlow(c, r, ex, ey, moving.flowX[m], moving.flowY[m], g);
        // Occlusion: is the same scene point the one the other camera sees at its projection?
        const double f = s_.focalLength, cx = 0.5 * (sz.width - 1);
        const double X = (x - cx) / f * z + (c == CAMERA_RIGHT ? s_.baseline : 0.0);
        const double xo = c == CAMERA_LEFT ? f * (X - s_.baseline) / z + cx : f * X / z + cx;
        const int xi = (int)std::lround(xo);
        bool occluded = xi < 0 || xi >= sz.width;
        if (!occluded)
        {
            const double zo = other.depth[y * sz.width + xi];
            occluded = zo <= 0 || zo < z * (1 - 0.02);
        }
        g[GT_FLAGS] = occluded ? (float)GT_FLAG_OCCLUDED : 0.f;
        return g;
    }

    // edgeNormal()'s circle: EDGE_RAYS rays, each interval bisected EDGE_BISECTIONS times.
    enum { EDGE_RAYS = 16, EDGE_BISECTIONS = 5, EDGE_STEPS = EDGE_RAYS << EDGE_BISECTIONS };

    // The direction of the sharp scene's log-intensity gradient around pixel (x, y) of camera c's render r: the
    // first moment of the log intensity on a circle around the pixel centre. Across a straight edge the brighter
    // arc is symmetric about the edge's normal whatever the edge's offset from the centre, so the direction is
    // the contour's, as the events' times along it run. A gradient of the rendered pixels (Sobel) is not: they
    // sample the edge at the pixel centres, a staircase whose step sits at the pixel that has just fired, which
    // turns a slanted edge's normal by 15 degrees and more.
    // The circle is sampled by EDGE_RAYS rays, each change between neighbouring rays located by bisection (to
    // within 360 / EDGE_STEPS degrees), and the arcs between the changes taken as constant.
    // A circle of EDGE_RADII[0] reaches an edge through the pixel; the wider one, those that fire the pixel
    // through the lens blur. False where neither circle meets an edge (or meets a line through its centre).
    bool edgeNormal(int c, const Render& r, int x, int y, double& nx, double& ny) const
    {
        static const double EDGE_RADII[2] = { 1.5, 3.0 };
        const Vec3d origin(c == CAMERA_RIGHT ? s_.baseline : 0.0, 0, 0);
        for (double radius : EDGE_RADII)
        {
            // Angle index j: 2 pi j / EDGE_STEPS.
            const auto logIntensityAt = [&](int j) {
                const Vec2d& u = circle_[(size_t)(j % EDGE_STEPS)];
                return (double)steadyLogIntensity(r.poses, r.views,
                                                  castRay(r.poses, r.views, origin, rayDirection(c, x + radius * u[0], y + radius * u[1])));
            };
            const int spacing = 1 << EDGE_BISECTIONS;
            double value[EDGE_RAYS];
            for (int k = 0; k < EDGE_RAYS; k++)
                value[k] = logIntensityAt(k * spacing);
            // The changes: between ray k and the next, at angle change[k] (none: NaN).
            double change[EDGE_RAYS];
            int changes = 0;
            for (int k = 0; k < EDGE_RAYS; k++)
            {
                const double v0 = value[k], v1 = value[(k + 1) % EDGE_RAYS];
                change[k] = std::numeric_limits<double>::quiet_NaN();
                if (v0 == v1)
                    continue;
                int lo = k * spacing, hi = (k + 1) * spacing;
                while (hi - lo > 1)
                {
                    const int mid = (lo + hi) / 2;
                    const double v = logIntensityAt(mid);
                    // A blended texture edge changes gradually: it is where the level is halfway.
                    (std::abs(v - v0) < std::abs(v - v1) ? lo : hi) = mid;
                }
                change[k] = CV_PI * (lo + hi) / EDGE_STEPS;
                changes++;
            }
            if (changes == 0)
                continue;
            // Each arc from one change to the next holds its rays' value: its moment is value x the integral of
            // (cos, sin) over it.
            double gx = 0, gy = 0;
            int first = 0;
            while (std::isnan(change[first]))
                first++;
            for (int k = first, n = 0; n < changes; n++)
            {
                int next = (k + 1) % EDGE_RAYS;
                while (std::isnan(change[next]))
                    next = (next + 1) % EDGE_RAYS;
                const double a0 = change[k], a1 = change[next] + (next <= k ? 2 * CV_PI : 0.0);
                const double v = value[(k + 1) % EDGE_RAYS];
                gx += v * (std::sin(a1) - std::sin(a0));
                gy += v * (std::cos(a0) - std::cos(a1));
                k = next;
            }
            const double gn = std::hypot(gx, gy);
            // A moment far below the contrast on the circle: a line through the centre.
            double lo = value[0], hi = value[0];
            for (double v : value)
            {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
            if (gn > 1e-3 * (hi - lo))
            {
                nx = gx / gn;
                ny = gy / gn;
                return true;
            }
        }
        return false;
    }

    // Normal flow at pixel (x, y) of camera c's render r for an image motion (flowX, flowY) [px/s]: the motion's
    // component along the log-intensity gradient there (edgeNormal(); Sobel on the render where no edge is near),
    // and its lifetime.
    void setNormalFlow(int c, const Render& r, int x, int y, double flowX, double flowY, std::array<float, 6>& g) const
    {
        double nx = 0, ny = 0;
        if (!edgeNormal(c, r, x, y, nx, ny))
        {
            const Size sz = s_.resolution;
            auto L = [&](int xx, int yy) {
                xx = std::min(std::max(xx, 0), sz.width - 1);
                yy = std::min(std::max(yy, 0), sz.height - 1);
                return (double)r.logI[yy * sz.width + xx];
            };
            const double gx = (L(x + 1, y - 1) + 2 * L(x + 1, y) + L(x + 1, y + 1)) - (L(x - 1, y - 1) + 2 * L(x - 1, y) + L(x - 1, y + 1));
            const double gy = (L(x - 1, y + 1) + 2 * L(x, y + 1) + L(x + 1, y + 1)) - (L(x - 1, y - 1) + 2 * L(x, y - 1) + L(x + 1, y - 1));
            const double gn = std::hypot(gx, gy);
            if (gn > 1e-9)
            {
                nx = gx / gn;
                ny = gy / gn;
            }
        }
        const double along = flowX * nx + flowY * ny;
        g[GT_FLOW_X] = (float)(along * nx);
        g[GT_FLOW_Y] = (float)(along * ny);
        g[GT_LIFETIME] = std::abs(along) > 1e-9 ? (float)(1e6 / std::abs(along)) : 0.f;
    }

    // The stamp camera c gives an event that a shared clock stamps ts: the right camera's clock is off by
    // rightClockOffsetUs and runs rightClockDriftPpm fast.
    int64 cameraClock(int c, int64 ts) const
    {
        if (c != CAMERA_RIGHT || (s_.rightClockOffsetUs == 0 && s_.rightClockDriftPpm == 0))
            return ts;
        return ts + (int64)std::llround(s_.rightClockOffsetUs + s_.rightClockDriftPpm * 1e-6 * (double)ts);
    }

    // Poisson count by inversion. exp(-lambda) underflows to 0 beyond lambda ~ 745 (high noise rates on
    // large sensors), after which inversion would never stop; a Poisson(lambda) count is the sum of
    // Poisson(lambda / k) counts, so larger means are drawn in chunks of at most 500.
    static int poissonCount(double lambda, RNG& rng)
    {
        int total = 0;
        while (lambda > 0)
        {
            const double chunk = std::min(lambda, 500.0);
            lambda -= chunk;
            int count = 0;
            double p = std::exp(-chunk), cdf = p;
            const double u = rng.uniform(0.0, 1.0);
            while (u > cdf && p > 0)
            {
                count++;
                p *= chunk / count;
                cdf += p;
            }
            total += count;
        }
        return total;
    }

    void addNoise(double t0, double t1, std::vector<SimulatedEvent>& out)
    {
        const std::array<float, 6> noise = { { 0, 0, 0, 0, 0, (float)GT_FLAG_NOISE } };
        const Size sz = s_.resolution;
        const double seconds = (t1 - t0) * 1e-6;
        for (int c = 0; c < 2; c++)
        {
            for (const std::pair<int, int>& hot : hotPixels_[c])
            {
                const int count = poissonCount(s_.hotPixelRateHz * seconds, hotRng_);
                for (int k = 0; k < count; k++)
                {
                    const int64 ts = std::min((int64)t1 - 1, (int64)std::floor(hotRng_.uniform(t0, t1)));
                    out.push_back(std::make_pair(Event(cameraClock(c, ts), hot.first % sz.width, hot.first / sz.width, hot.second, c), noise));
                }
            }
            if (s_.leakRateHz > 0)
            {
                const int count = poissonCount(s_.leakRateHz * seconds * sz.area(), leakRng_);
                for (int k = 0; k < count; k++)
                {
                    const int x = leakRng_.uniform(0, sz.width), y = leakRng_.uniform(0, sz.height);
                    const int64 ts = std::min((int64)t1 - 1, (int64)std::floor(leakRng_.uniform(t0, t1)));
                    out.push_back(std::make_pair(Event(cameraClock(c, ts), x, y, POLARITY_ON, c), noise));
                }
            }
        }
        if (!(s_.noiseRateHz > 0))
            return;
        const double expected = s_.noiseRateHz * (t1 - t0) * 1e-6 * sz.area();
        for (int c = 0; c < 2; c++)
        {
            const int count = poissonCount(expected, rng_);
            for (int k = 0; k < count; k++)
            {
                const int x = rng_.uniform(0, sz.width), y = rng_.uniform(0, sz.height);
                const int64 ts = std::min((int64)t1 - 1, (int64)std::floor(rng_.uniform(t0, t1)));
                const int polarity = rng_.uniform(0, 2);
                std::array<float, 6> g = { { 0, 0, 0, 0, 0, (float)GT_FLAG_NOISE } };
                out.push_back(std::make_pair(Event(cameraClock(c, ts), x, y, polarity, c), g));
            }
        }
    }

    std::vector<SimulatedPlane> planes_;
    SimulatorSettings s_;
    RNG rng_, jitterRng_, thresholdRng_, hotRng_, leakRng_;
    std::vector<float> cOn_[2], cOff_[2], ref_[2], latency_[2];
    std::vector<float> steadyAtCrossing_[2];  // flickering scenes: the steady log intensity at each pixel's last crossing
    std::vector<double> lastEvent_[2];
    std::vector<int64> lastStamp_[2];  // with delays: each pixel's last stamp, which its next may not precede
    std::vector<std::pair<int, int>> hotPixels_[2];  // pixel index, polarity
    bool delayed_ = false;
    bool flickering_ = false;  // some plane flickers
    Render cur_[2], next_[2];
    double rollCos_ = 1, rollSin_ = 0;  // the right camera's roll (rightRollRad)
    std::vector<Vec2d> circle_;         // (cos, sin) of edgeNormal()'s EDGE_STEPS angles
    Render staticScene_[2];         // each camera's sharp render of the static planes alone (render(staticOnly))
    std::vector<int> movingPlanes_;  // indices of the planes that are not static (isStatic())
    double t_ = 0, delivered_ = 0;
    std::vector<SimulatedEvent> pending_;  // simulated, not yet handed out; in stream order
};

}  // namespace

std::vector<String> StereoEventSimulator::sceneNames()
{
    return detail::simulatedSceneNames();
}

Ptr<StereoEventSimulator> StereoEventSimulator::create(const String& scene, int sensorModel, int seed)
{
    SimulatorSettings s = SimulatorSettings::preset(sensorModel);
    s.seed = seed;
    const std::vector<SimulatedPlane> planes = detail::simulatedScene(scene, sensorModel, s);
    return makePtr<StereoEventSimulatorImpl>(planes, s);
}

Ptr<StereoEventSimulator> StereoEventSimulator::create(const std::vector<SimulatedPlane>& planes, const SimulatorSettings& settings)
{
    return makePtr<StereoEventSimulatorImpl>(planes, settings);
}

double writeSimulatedRecording(const Ptr<StereoEventSimulator>& simulator, const String& path, double durationUs)
{
    CV_Assert(!simulator.empty());
    EventWriter writer;
    writer.set(EVENT_WRITER_PROP_STEREO, 1);
    writer.open(path, simulator->getSensorSize());
    const std::string gtPath = path + ".gt.csv";
    std::FILE* gt = std::fopen(gtPath.c_str(), "w");
    if (!gt)
        CV_Error_(Error::StsError, ("%s: cannot create the ground-truth file", gtPath.c_str()));
    std::fprintf(gt, "t,x,y,p,camera,depth,disparity,flow_x,flow_y,lifetime,flags\n");
    double written = 0;
    const double chunk = 10000;  // 10 ms at a time: memory does not grow with the duration
    std::vector<Event> events;
    Mat truth;
    for (double t = simulator->getTime() + chunk; ; t += chunk)
    {
        const double until = std::min(t, durationUs);
        simulator->generate(until, events, truth);
        writer.write(events);
        for (size_t i = 0; i < events.size(); i++)
        {
            const float* g = truth.ptr<float>((int)i);
            const Event& e = events[i];
            // Nine significant digits read back as the same float: an evaluation from the file scores exactly
            // as one from the simulator in memory.
            std::fprintf(gt, "%lld,%d,%d,%d,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%d\n", (long long)e.t, e.x, e.y, e.p, e.camera,
                         g[GT_DEPTH], g[GT_DISPARITY], g[GT_FLOW_X], g[GT_FLOW_Y], g[GT_LIFETIME], (int)g[GT_FLAGS]);
        }
        written += (double)events.size();
        if (until >= durationUs)
            break;
    }
    writer.release();
    if (std::fclose(gt) != 0)
        CV_Error_(Error::StsError, ("%s: write failed", gtPath.c_str()));
    return written;
}

}  // namespace event
}  // namespace cv
