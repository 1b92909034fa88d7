// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Event lifetime by local plane fitting on the Surface of Active Events (Mueggler et al. 2015), with the
// prediction shortcut of Hadviger et al. 2019. See lifetime_estimator.hpp for the method.

#include "precomp.hpp"
#include "lifetime/row_band_lifetime_estimator.hpp"
#include "lifetime/neighbour_along_motion.hpp"
#include "lifetime/plane_inliers.hpp"
#include "common/timestamp_math.hpp"
#include "common/optional_output.hpp"
#include "common/sensor_bounds.hpp"

#include <Eigen/Dense>

namespace cv {
namespace event {
namespace detail {

namespace {

struct Prediction
{
    float a = 0, b = 0;   // time-surface gradient [ms/px]
    int64 t = 0;          // predicted arrival [us]
    float quality = 0;    // the quality of the lifetime the plane gives (0: passed on by a stereo match)
    bool valid = false;
};

// The plane of a pixel's crossing in progress: the first of its events' planes.
struct CrossingPlane
{
    float a = 0, b = 0, quality = 0;
    bool valid = false;
};

class LifetimeEstimatorImpl CV_FINAL : public RowBandLifetimeEstimator
{
public:
    explicit LifetimeEstimatorImpl(Size size) { setSensorSize(size); }

    void process(InputArray events, OutputArray lifetimes, OutputArray flow, OutputArray status,
                 OutputArray quality) CV_OVERRIDE
    {
        Mat_<Event> ev = getEventMat(events);
        const int n = (int)ev.total();
        lifetimes.create(n, 1, CV_32F);
        Mat_<float> lt = lifetimes.getMat();
        Mat_<float> fl = optionalOutput<float>(flow, n, 2);
        Mat_<uchar> st = optionalOutput<uchar>(status, n);
        Mat_<float> q = optionalOutput<float>(quality, n);
        for (int i = 0; i < n; i++)
        {
            Vec2f v;
            int s;
            lt(i) = estimate(ev(i), nullptr, true, v, s, own_);
            if (!q.empty())
                q(i) = own_.quality;
            if (!fl.empty())
            {
                fl(i, 0) = v[0];
                fl(i, 1) = v[1];
            }
            if (!st.empty())
                st(i) = (uchar)s;
        }
    }

    float processEvent(const Event& e, Vec2f& flow, int& status) CV_OVERRIDE
    {
        return processEvent(e, flow, status, own_);
    }

    float processEvent(const Event& e, Vec2f& flow, int& status, float& quality) CV_OVERRIDE
    {
        const float lifetime = processEvent(e, flow, status, own_);
        quality = own_.quality;
        return lifetime;
    }

    float processEvent(const Event& e, Vec2f& flow, int& status, LifetimeScratch& scratch) CV_OVERRIDE
    {
        return estimate(e, nullptr, true, flow, status, scratch);
    }

    float processMatchedEvent(const Event& e, const std::pair<float, Vec2f>& matched, Vec2f& flow, int& status,
                              LifetimeScratch& scratch) CV_OVERRIDE
    {
        GivenMatch given(matched);
        return estimate(e, &given, true, flow, status, scratch);
    }

    float refitMatchedEvent(const Event& e, MatchedLifetimeSource& matched, Vec2f& flow, int& status,
                            LifetimeScratch& scratch) CV_OVERRIDE
    {
        return estimate(e, &matched, false, flow, status, scratch);
    }

    void insertEvent(const Event& e, float lifetime, const Vec2f& flow) CV_OVERRIDE
    {
        insertEvent(e, lifetime, flow, own_);
    }

    void insertEvent(const Event& e, float lifetime, const Vec2f& flow, LifetimeScratch& scratch) CV_OVERRIDE
    {
        checkInside(e);
        const int p = e.p ? 1 : 0;
        const size_t idx = index(e.x, e.y, p);
        predictions_[idx].valid = false;
        if (!continuesCrossing(e, p, idx))
        {
            surface_[idx] = e.t;
            crossings_[idx] = CrossingPlane();
        }
        predictFromFlow(e, surface_[idx], p, lifetime, flow);
        scratch.counts[LIFETIME_MATCHED]++;
        Active& act = active_[(size_t)e.y * size_.width + e.x];
        act.t = e.t;
        act.lifetime = std::max(lifetime, 0.f);
        act.quality = 0;
        act.p = (uchar)p;
    }

    void renderActiveEvents(double t, OutputArray image, double minQuality) const CV_OVERRIDE
    {
        if (!(minQuality >= 0 && minQuality <= 1))
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator::renderActiveEvents: minQuality %g; must be 0..1", minQuality));
        image.create(size_, CV_8U);
        Mat_<uchar> img = image.getMat();
        for (int i = 0; i < size_.area(); i++)
        {
            const Active& a = active_[i];
            const bool alive = a.lifetime > 0 && a.quality >= minQuality && a.t <= t && t < (double)a.t + a.lifetime;
            img(i) = alive ? (a.p ? 255 : 128) : 0;
        }
    }

    void reset() CV_OVERRIDE
    {
        const size_t n = (size_t)size_.area();
        surface_.assign(2 * n, EventSurface::NO_EVENT);
        predictions_.assign(2 * n, Prediction());
        crossings_.assign(2 * n, CrossingPlane());
        active_.assign(n, Active());
        for (double& c : own_.counts)
            c = 0;
    }

    void addStatusCounts(LifetimeScratch& scratch) CV_OVERRIDE
    {
        for (int s = 0; s < 4; s++)
        {
            own_.counts[s] += scratch.counts[s];
            scratch.counts[s] = 0;
        }
    }

    // The fit's window, and the predicted neighbour (one row).
    int rowReach() const CV_OVERRIDE { return std::max(window_ / 2, 1); }

    double getStatusCount(int s) const CV_OVERRIDE
    {
        CV_CheckGE(s, 0, "LifetimeEstimator::getStatusCount: status 0..3");
        CV_CheckLE(s, 3, "LifetimeEstimator::getStatusCount: status 0..3");
        return own_.counts[s];
    }

    Size getSensorSize() const CV_OVERRIDE { return size_; }
    void setSensorSize(Size s) CV_OVERRIDE
    {
        if (s.width <= 0 || s.height <= 0 || s.width > 32768 || s.height > 32768)
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator: sensor size %d x %d is not valid", s.width, s.height));
        size_ = s;
        reset();
    }
    int getWindowSize() const CV_OVERRIDE { return window_; }
    void setWindowSize(int n) CV_OVERRIDE
    {
        if (n < 3 || n % 2 == 0 || n > 31)
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator: window size %d; must be odd, 3..31", n));
        window_ = n;
    }
    double getTimeWindow() const CV_OVERRIDE { return timeWindow_; }
    void setTimeWindow(double us) CV_OVERRIDE { timeWindow_ = positive(us, "time window"); }
    double getInlierThreshold() const CV_OVERRIDE { return inlierThreshold_; }
    void setInlierThreshold(double ms) CV_OVERRIDE { inlierThreshold_ = positive(ms, "inlier threshold"); }
    double getInlierDistance() const CV_OVERRIDE { return inlierDistance_; }
    void setInlierDistance(double px) CV_OVERRIDE { inlierDistance_ = zeroOrPositive(px, "inlierDistance [px]"); }
    int getMinInliers() const CV_OVERRIDE { return minInliers_; }
    void setMinInliers(int n) CV_OVERRIDE
    {
        if (n < 3)
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator: minInliers %d; a plane needs at least 3 points", n));
        minInliers_ = n;
    }
    int getMaxIterations() const CV_OVERRIDE { return maxIterations_; }
    void setMaxIterations(int n) CV_OVERRIDE
    {
        if (n < 1)
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator: maxIterations %d; at least 1", n));
        maxIterations_ = n;
    }
    double getRegularization() const CV_OVERRIDE { return lambda_; }
    void setRegularization(double l) CV_OVERRIDE
    {
        if (!(l >= 0))
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator: regularization %g; must be >= 0", l));
        lambda_ = l;
    }
    double getPredictionTolerance() const CV_OVERRIDE { return predictionTolerance_; }
    void setPredictionTolerance(double us) CV_OVERRIDE { predictionTolerance_ = positive(us, "prediction tolerance"); }
    bool getUsePrediction() const CV_OVERRIDE { return usePrediction_; }
    void setUsePrediction(bool u) CV_OVERRIDE { usePrediction_ = u; }
    double getCrossingLifetimes() const CV_OVERRIDE { return crossingLifetimes_; }
    void setCrossingLifetimes(double lifetimes) CV_OVERRIDE
    {
        crossingLifetimes_ = zeroOrPositive(lifetimes, "crossingLifetimes");
    }
    bool getSkipEarlierEdges() const CV_OVERRIDE { return skipEarlierEdges_; }
    void setSkipEarlierEdges(bool skip) CV_OVERRIDE { skipEarlierEdges_ = skip; }
    double getRefitCrossingLifetimes() const CV_OVERRIDE { return refitCrossingLifetimes_; }
    void setRefitCrossingLifetimes(double lifetimes) CV_OVERRIDE
    {
        refitCrossingLifetimes_ = zeroOrPositive(lifetimes, "refitCrossingLifetimes");
    }
    int getSeed() const CV_OVERRIDE { return seed_; }
    void setSeed(int s) CV_OVERRIDE { seed_ = s; }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeFormat(fs);
        fs << "sensorWidth" << size_.width << "sensorHeight" << size_.height << "windowSize" << window_
           << "timeWindow" << timeWindow_ << "inlierThreshold" << inlierThreshold_ << "inlierDistance" << inlierDistance_
           << "minInliers" << minInliers_
           << "maxIterations" << maxIterations_ << "regularization" << lambda_
           << "predictionTolerance" << predictionTolerance_ << "usePrediction" << (int)usePrediction_
           << "crossingLifetimes" << crossingLifetimes_ << "skipEarlierEdges" << (int)skipEarlierEdges_
           << "refitCrossingLifetimes" << refitCrossingLifetimes_ << "seed" << seed_;
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        auto num = [&](const char* key, double def) { return fn[key].empty() ? def : (double)fn[key]; };
        const Size s((int)num("sensorWidth", size_.width), (int)num("sensorHeight", size_.height));
        setWindowSize((int)num("windowSize", window_));
        setTimeWindow(num("timeWindow", timeWindow_));
        setInlierThreshold(num("inlierThreshold", inlierThreshold_));
        setInlierDistance(num("inlierDistance", inlierDistance_));
        setMinInliers((int)num("minInliers", minInliers_));
        setMaxIterations((int)num("maxIterations", maxIterations_));
        setRegularization(num("regularization", lambda_));
        setPredictionTolerance(num("predictionTolerance", predictionTolerance_));
        setUsePrediction(num("usePrediction", usePrediction_) != 0);
        setCrossingLifetimes(num("crossingLifetimes", crossingLifetimes_));
        setSkipEarlierEdges(num("skipEarlierEdges", skipEarlierEdges_) != 0);
        setRefitCrossingLifetimes(num("refitCrossingLifetimes", refitCrossingLifetimes_));
        setSeed((int)num("seed", seed_));
        if (s != size_)
            setSensorSize(s);
    }

    String getDefaultName() const CV_OVERRIDE { return "LifetimeEstimator"; }

private:
    // A match's lifetime known before the fit.
    class GivenMatch CV_FINAL : public MatchedLifetimeSource
    {
    public:
        explicit GivenMatch(const std::pair<float, Vec2f>& matched) : matched_(matched) {}
        bool get(std::pair<float, Vec2f>& matched) CV_OVERRIDE
        {
            matched = matched_;
            return true;
        }
    private:
        const std::pair<float, Vec2f>& matched_;
    };

    // processEvent(), or, when `source` is given, processMatchedEvent() (`matchedNeedsPlane`: the event takes
    // the match's lifetime when its plane says it is no noise) or refitMatchedEvent() (when its plane says it is).
    float estimate(const Event& e, MatchedLifetimeSource* source, bool matchedNeedsPlane, Vec2f& flow,
                   int& status, LifetimeScratch& scratch)
    {
        checkInside(e);
        const int p = e.p ? 1 : 0;
        const size_t idx = index(e.x, e.y, p);
        double a = 0, b = 0;
        float quality = 0;
        status = LIFETIME_NOISE;
        // A later event of a crossing in progress is fitted at the crossing's first time, where the edge arrived.
        bool continues = continuesCrossing(e, p, idx);
        int64 origin = continues ? surface_[idx] : e.t;
        Prediction& pred = predictions_[idx];
        CrossingPlane& crossing = crossings_[idx];
        if (usePrediction_ && pred.valid && std::abs(timeDifference(e.t, pred.t)) <= predictionTolerance_)
        {
            a = pred.a;
            b = pred.b;
            quality = pred.quality;
            status = LIFETIME_PREDICTED;
        }
        else if (!continues && mayContinueCrossing(e, p, idx) &&
                 fit(e, surface_[idx], p, pred, scratch, a, b, quality) &&
                 (double)timeDifference(e.t, surface_[idx]) < refitCrossingLifetimes_ * planeLifetimeUs(a, b))
        {
            continues = true;
            origin = surface_[idx];
            status = LIFETIME_FITTED;
        }
        else if (fit(e, origin, p, pred, scratch, a, b, quality))
            status = LIFETIME_FITTED;
        else if (continues && crossing.valid)
        {
            a = crossing.a;
            b = crossing.b;
            quality = crossing.quality;
            status = LIFETIME_PREDICTED;
        }
        pred.valid = false;  // consumed (or stale)
        if (!continues)
        {
            surface_[idx] = e.t;
            crossing = CrossingPlane();
        }

        float lifetime = 0;
        flow = Vec2f(0, 0);
        const double g2 = a * a + b * b;
        const bool plane = status != LIFETIME_NOISE && g2 > 1e-12;
        if (plane && !crossing.valid)
        {
            crossing.a = (float)a;
            crossing.b = (float)b;
            crossing.quality = quality;
            crossing.valid = true;
        }
        std::pair<float, Vec2f> matched;
        if (source && plane == matchedNeedsPlane && source->get(matched))
        {
            lifetime = matched.first;
            flow = matched.second;
            status = LIFETIME_MATCHED;
            quality = 0;
            predictFromFlow(e, origin, p, lifetime, flow);
        }
        else if (plane)
        {
            lifetime = (float)planeLifetimeUs(a, b);  // |g| ms -> us
            flow = Vec2f((float)(1000.0 * a / g2), (float)(1000.0 * b / g2));  // g / |g|^2 px/ms -> px/s
            predictNeighbour(e, origin, p, a, b, quality);
        }
        else
        {
            status = LIFETIME_NOISE;
            quality = 0;
        }
        scratch.quality = quality;
        scratch.counts[status]++;
        Active& act = active_[(size_t)e.y * size_.width + e.x];
        act.t = e.t;
        act.lifetime = lifetime;
        act.quality = quality;
        act.p = (uchar)p;
        return lifetime;
    }

    struct Active
    {
        int64 t = 0;
        float lifetime = 0;
        float quality = 0;  // as process() gives it
        uchar p = 0;
    };

    // Whether @p e continues the crossing of its pixel whose first time the surface holds: a blurred or strong
    // edge fires a pixel several times as it passes, and the edge arrived with the first of them. It does when
    // the pixel's last event had its polarity and a lifetime, and the crossing began less than
    // crossingLifetimes of that lifetime before.
    bool continuesCrossing(const Event& e, int p, size_t idx) const
    {
        const int64 first = surface_[idx];
        const Active& last = active_[(size_t)e.y * size_.width + e.x];
        return crossingLifetimes_ > 0 && first != EventSurface::NO_EVENT && last.p == (uchar)p && last.lifetime > 0 &&
               timeDifference(e.t, first) < crossingLifetimes_ * last.lifetime;
    }

    // Whether an event that continuesCrossing() does not hold is fitted at its crossing's first time first, that
    // plane then deciding (see setRefitCrossingLifetimes()). Where the crossing's first events had a plane, the
    // time since it began must be within refitCrossingLifetimes of that plane's lifetime too: an edge that comes
    // back sparsely would otherwise be taken for the one before, through a plane fitted to both.
    bool mayContinueCrossing(const Event& e, int p, size_t idx) const
    {
        const int64 first = surface_[idx];
        const Active& last = active_[(size_t)e.y * size_.width + e.x];
        if (!(refitCrossingLifetimes_ > 0) || !(crossingLifetimes_ > 0) || first == EventSurface::NO_EVENT ||
            last.p != (uchar)p || first >= e.t)
            return false;
        const double since = (double)timeDifference(e.t, first);
        const CrossingPlane& crossing = crossings_[idx];
        return since < timeWindow_ &&
               (!crossing.valid || since < refitCrossingLifetimes_ * planeLifetimeUs(crossing.a, crossing.b));
    }

    static double positive(double v, const char* what)
    {
        if (!(v > 0))
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator: %s %g; must be > 0", what, v));
        return v;
    }

    // For settings where 0 switches a rule off.
    static double zeroOrPositive(double v, const char* what)
    {
        if (!(v >= 0) || !std::isfinite(v))
            CV_Error_(Error::StsBadArg, ("LifetimeEstimator: %s %g; must be >= 0 and finite (0: off)", what, v));
        return v;
    }

    // The lifetime [us] of the time-surface plane t = a x + b y [ms/px]: the time its edge takes to move one pixel.
    static double planeLifetimeUs(double a, double b) { return 1000.0 * std::sqrt(a * a + b * b); }

    void checkInside(const Event& e) const
    {
        if (!onSensor(e.x, e.y, size_))
            CV_Error_(Error::StsOutOfRange, ("LifetimeEstimator: event at (x=%d, y=%d), t=%lld us, is outside the "
                                             "%d x %d sensor", e.x, e.y, (long long)e.t, size_.width, size_.height));
        if (e.t == EventSurface::NO_EVENT)
            CV_Error_(Error::StsOutOfRange, ("LifetimeEstimator: event at (x=%d, y=%d) has t = INT64_MIN, which is "
                                             "reserved for EventSurface::NO_EVENT", e.x, e.y));
    }

    size_t index(int x, int y, int p) const { return (size_t)p * size_.area() + (size_t)y * size_.width + x; }

    // A 64-bit mix (splitmix64's finaliser) of the seed and the event: pixel, polarity, time.
    uint64 sampleSeed(const Event& e, int p) const
    {
        uint64 z = (uint64)(uint32_t)seed_ * 0x9E3779B97F4A7C15ULL;
        z ^= ((uint64)(uint16_t)e.x << 48) ^ ((uint64)(uint16_t)e.y << 32) ^ ((uint64)p << 31) ^ (uint64)e.t;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        z ^= z >> 31;
        return z ? z : 1;
    }

    // A hypothesis' inlier threshold [ms]: inlierDistance pixels in its own time per pixel, at most
    // inlierThreshold. A fixed threshold spans several pixels of a fast edge (2 ms is 7 px at 0.3 ms/px), so
    // planes through stale points of earlier edges then collect as many inliers as the true one.
    double inlierThreshold(double a, double b) const
    {
        return inlierDistance_ > 0 ? std::min(inlierThreshold_, inlierDistance_ * std::sqrt(a * a + b * b))
                                   : inlierThreshold_;
    }

    // With skipEarlierEdges, the time before which the window's timestamps belong to an earlier edge (else the
    // oldest time there is). An edge crosses the window in its half-diagonal times its lifetime; when the pixel's
    // previous crossing (of this polarity, with a plane) began more than twice that before the event, that edge
    // had left the window before this one entered it, and what the window holds from before it left is its.
    // Without this, an edge that comes back at a steady rate (a fan's blades) and fires sparsely gets planes
    // through both edges: lifetimes a whole number of periods too long.
    int64 earlierEdgeLeft(const Event& e, int64 origin, int p) const
    {
        const size_t idx = index(e.x, e.y, p);
        const int64 previous = surface_[idx];
        const CrossingPlane& plane = crossings_[idx];
        const int64 none = std::numeric_limits<int64>::min();
        if (!skipEarlierEdges_ || origin != e.t || previous == EventSurface::NO_EVENT || previous >= e.t ||
            !plane.valid)
            return none;
        const double crossingUs = (window_ / 2) * std::sqrt(2.0) * planeLifetimeUs(plane.a, plane.b);
        if (!((double)(e.t - previous) > 2 * crossingUs))
            return none;
        return previous + 1 + (int64)crossingUs;
    }

    // RANSAC + refit, in time relative to @p origin (the event's own time, or its crossing's first), over the
    // past events up to the event's own time. On success, (a, b) is the time-surface gradient [ms/px].
    bool fit(const Event& e, int64 origin, int p, const Prediction& pred, LifetimeScratch& scratch, double& a,
             double& b, float& quality)
    {
        const int r = window_ / 2;
        const size_t capacity = (size_t)window_ * window_;
        if (scratch.x.size() < capacity)
        {
            scratch.x.resize(capacity);
            scratch.y.resize(capacity);
            scratch.t.resize(capacity);
        }
        double* const px = scratch.x.data();
        double* const py = scratch.y.data();
        double* const pt = scratch.t.data();
        int m = 0;
        const int64 oldest = std::max(timeBefore(origin, (int64)timeWindow_), earlierEdgeLeft(e, origin, p));
        for (int dy = -r; dy <= r; dy++)
        {
            const int y = e.y + dy;
            if (y < 0 || y >= size_.height)
                continue;
            const int64* row = &surface_[index(0, y, p)];
            for (int dx = -r; dx <= r; dx++)
            {
                const int x = e.x + dx;
                if ((dx == 0 && dy == 0) || x < 0 || x >= size_.width)
                    continue;
                const int64 ts = row[x];
                if (ts == EventSurface::NO_EVENT || ts < oldest || ts > e.t)
                    continue;
                px[m] = (double)dx;
                py[m] = (double)dy;
                pt[m] = (double)(ts - origin) * 1e-3;
                m++;
            }
        }
        if (m + 1 < minInliers_ || m < 2)
            return false;

        // The hypotheses first, then their inliers counted together (plane_inliers.hpp). The samples depend on
        // the seed and the event alone, not on how many fits ran before: the same results whatever the order of
        // calls for events in distant rows (StereoEventMatcher's row bands).
        const size_t slots = alignSize(maxIterations_, (int)PLANE_HYPOTHESES_PAD);
        if (scratch.a.size() < slots)
        {
            scratch.a.assign(slots, 0.0);
            scratch.b.assign(slots, 0.0);
            scratch.threshold.assign(slots, 0.0);
            scratch.inliers.assign(slots, 0);
        }
        RNG rng(sampleSeed(e, p));
        int n = 0;
        for (int it = 0; it < maxIterations_; it++)
        {
            const int i = rng.uniform(0, m);
            int j = rng.uniform(0, m - 1);
            if (j >= i)
                j++;
            // Plane t = a x + b y through the current event (origin) and the two samples.
            const double det = px[i] * py[j] - px[j] * py[i];
            if (std::abs(det) < 1e-9)
                continue;  // collinear with the current event: degenerate
            const double ha = (pt[i] * py[j] - pt[j] * py[i]) / det;
            const double hb = (px[i] * pt[j] - px[j] * pt[i]) / det;
            scratch.a[(size_t)n] = ha;
            scratch.b[(size_t)n] = hb;
            scratch.threshold[(size_t)n] = inlierThreshold(ha, hb);
            n++;
        }
        inlierKernels_.count(px, py, pt, m, scratch.a.data(), scratch.b.data(), scratch.threshold.data(), n,
                             scratch.inliers.data());
        int bestCount = 0;
        double bestA = 0, bestB = 0, bestThreshold = inlierThreshold_;
        for (int k = 0; k < n; k++)
        {
            const int count = 1 + scratch.inliers[(size_t)k];  // the current event lies on every hypothesis
            if (count > bestCount)
            {
                bestCount = count;
                bestThreshold = scratch.threshold[(size_t)k];
                bestA = scratch.a[(size_t)k];
                bestB = scratch.b[(size_t)k];
            }
        }
        if (bestCount < minInliers_)
            return false;

        // Least squares t = a x + b y + c over the inliers and the current event (the origin), pulled toward the
        // plane predicted for this pixel when one exists (ridge on a, b). The normal equations' sums, each
        // added up in the points' order.
        double sxx = 0, sxy = 0, sx = 0, syy = 0, sy = 0, sxt = 0, syt = 0, st = 0;
        int count = 1;
        for (int i = 0; i < m; i++)
            if (std::abs(bestA * px[i] + bestB * py[i] - pt[i]) <= bestThreshold)
            {
                const double x = px[i], y = py[i], t = pt[i];
                sxx += x * x;
                sxy += x * y;
                sx += x;
                syy += y * y;
                sy += y;
                sxt += x * t;
                syt += y * t;
                st += t;
                count++;
            }
        Eigen::Matrix3d normal;
        normal << sxx, sxy, sx, sxy, syy, sy, sx, sy, (double)count;
        Eigen::Matrix3d ata = normal;
        Eigen::Vector3d atb(sxt, syt, st);
        if (pred.valid && lambda_ > 0)
        {
            ata(0, 0) += lambda_;
            ata(1, 1) += lambda_;
            atb(0) += lambda_ * pred.a;
            atb(1) += lambda_ * pred.b;
        }
        const Eigen::Vector3d sol = ata.ldlt().solve(atb);
        if (!sol.allFinite())
            return false;
        a = sol(0);
        b = sol(1);
        quality = planeQuality(px, py, pt, m, bestA, bestB, bestThreshold, normal, sol, count);
        return true;
    }

    // The quality of a refitted plane's lifetime: 1 / (1 + e + 1 / (n - 2)) for its n inliers (the current event
    // included) and e, the lifetime's relative standard error from the refit's residuals (the plain least squares'
    // covariance s^2 (A^T A)^-1 along the gradient); 1 / (n - 2) for the few points a small fit rests on. Three
    // points or fewer leave no residual to judge by: 0.
    // `normal` is the unregularised A^T A of the inliers, `plane` the refit (a, b, c).
    static float planeQuality(const double* px, const double* py, const double* pt, int m, double hypothesisA,
                              double hypothesisB, double threshold, const Eigen::Matrix3d& normal,
                              const Eigen::Vector3d& plane, int count)
    {
        const double a = plane(0), b = plane(1), g2 = a * a + b * b;
        if (count <= 3 || !(g2 > 0))
            return 0.f;
        double rss = plane(2) * plane(2);  // the current event, at the origin
        for (int i = 0; i < m; i++)
            if (std::abs(hypothesisA * px[i] + hypothesisB * py[i] - pt[i]) <= threshold)
            {
                const double r = a * px[i] + b * py[i] + plane(2) - pt[i];
                rss += r * r;
            }
        bool invertible = false;
        Eigen::Matrix3d inverse;
        normal.computeInverseWithCheck(inverse, invertible);
        if (!invertible)
            return 0.f;  // inliers on one line: the plane is the regularisation's, not theirs
        const double s2 = rss / (count - 3);
        const double variance = s2 * (a * a * inverse(0, 0) + 2 * a * b * inverse(0, 1) + b * b * inverse(1, 1)) / g2;
        if (!(variance >= 0) || !std::isfinite(variance))
            return 0.f;
        return (float)(1.0 / (1.0 + std::sqrt(variance / g2) + 1.0 / (count - 2)));
    }

    // The neighbour's prediction from a lifetime and flow obtained elsewhere (a stereo match).
    void predictFromFlow(const Event& e, int64 arrival, int p, float lifetime, const Vec2f& flow)
    {
        const double v2 = (double)flow[0] * flow[0] + (double)flow[1] * flow[1];
        if (lifetime > 0 && v2 > 0)
        {
            // Gradient g = v / |v|^2, with v in px/ms: the plane that produced this flow.
            const double vx = flow[0] * 1e-3, vy = flow[1] * 1e-3, v2ms = v2 * 1e-6;
            predictNeighbour(e, arrival, p, vx / v2ms, vy / v2ms, 0.f);
        }
    }

    // Stores the plane at the 8-neighbour the edge moves to, with the time it should get there from its
    // @p arrival at the event's pixel (the crossing's first time).
    void predictNeighbour(const Event& e, int64 arrival, int p, double a, double b, float quality)
    {
        Point next;  // the edge moves along the gradient
        if (!neighbourAlongMotion(a, b, next))
            return;  // no direction (an infinite flow given to insertEvent): nothing to predict
        const int dx = next.x, dy = next.y;
        const int x = e.x + dx, y = e.y + dy;
        if (x < 0 || x >= size_.width || y < 0 || y >= size_.height)
            return;
        const double stepUs = 1000.0 * (a * dx + b * dy);  // the plane's time to that pixel
        if (!(std::abs(stepUs) < 9e18))
            return;  // an edge too slow to reach it in any time an int64 holds (a tiny flow given to insertEvent)
        Prediction& q = predictions_[index(x, y, p)];
        q.a = (float)a;
        q.b = (float)b;
        const int64 step = (int64)std::llround(stepUs);
        q.t = step >= 0 ? timeAfter(arrival, step) : timeBefore(arrival, -step);
        q.quality = quality;
        q.valid = true;
    }

    Size size_;
    int window_ = 5;
    double timeWindow_ = 100000;
    double inlierThreshold_ = 2.0;
    double inlierDistance_ = 0.5;
    int minInliers_ = 5;
    int maxIterations_ = 19;
    double lambda_ = 1.0;
    double predictionTolerance_ = 1000;
    bool usePrediction_ = true;
    double crossingLifetimes_ = 2.0;
    bool skipEarlierEdges_ = true;
    double refitCrossingLifetimes_ = 4.0;
    int seed_ = 0;
    const PlaneInlierKernels& inlierKernels_ = planeInlierKernelsForThisCpu();
    std::vector<int64> surface_;
    std::vector<Prediction> predictions_;
    std::vector<CrossingPlane> crossings_;
    std::vector<Active> active_;
    LifetimeScratch own_;  // the working memory of the public calls; its counts are the estimator's
};

}  // namespace

Ptr<RowBandLifetimeEstimator> createRowBandLifetimeEstimator(Size sensorSize)
{
    return makePtr<LifetimeEstimatorImpl>(sensorSize);
}

}  // namespace detail

Ptr<LifetimeEstimator> LifetimeEstimator::create(Size sensorSize)
{
    return detail::createRowBandLifetimeEstimator(sensorSize);
}

}  // namespace event
}  // namespace cv
