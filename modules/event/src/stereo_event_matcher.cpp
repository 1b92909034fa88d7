// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Per-event stereo disparity and lifetime (Hadviger et al. 2019): the coupled method, its decoupled and
// fixed-interval baselines, and the frame + SGBM baseline. See stereo_event_matcher.hpp for the method.

#include "precomp.hpp"
#include "timestamp_math.hpp"
#include "ascii.hpp"
#include "descriptor_cost.hpp"
#include "frame_sgbm_matcher.hpp"
#include "lifetime_estimation_rows.hpp"
#include "zou_descriptor_map.hpp"

#include "opencv2/imgproc.hpp"

#include <atomic>
#include <exception>
#include <limits>
#include <memory>
#include <thread>

namespace cv {
namespace event {

namespace {

struct MatchResult
{
    float disparity = -1.f;
    int counterpartX = -1;  // the matched pixel of the other sensor (integer disparity)
    int flags = 0;          // STEREO_AMBIGUOUS / STEREO_NO_COUNTERPART when no disparity
};

// An active event of the matched window: its lifetime and its index in the map's per-pixel arrays.
struct Neighbour
{
    float lifetime;
    int index;
};

// The working memory of matching one event (one per thread): the candidates as disparity index (disparity -
// min) in increasing order, the byte offset of each one's descriptor in the other sensor from the event's
// column, and their costs (the first `count` of each, sized for the whole disparity range); the matched
// window's lifetimes; the left-right check's disparities; the lifetime estimators' scratch, per camera.
struct MatchScratch
{
    int count = 0;
    std::vector<int> candidates;
    std::vector<ptrdiff_t> offsets;
    std::vector<unsigned> cost;
    std::vector<Neighbour> neighbours;
    std::vector<float> disparities;
    LifetimeScratch lifetimes[2];
};

// A row band's progress for processInBands: the key of the next operation it has not done yet. Padded to a
// cache line: each band's thread writes its own after every operation.
struct BandProgress
{
    std::atomic<int64> key;
    char padding[64 - sizeof(std::atomic<int64>)];
};

class StereoEventMatcherImpl CV_FINAL : public StereoEventMatcher
{
public:
    StereoEventMatcherImpl(Size size, int mode)
    {
        estimators_[0] = LifetimeEstimator::create(size);
        estimators_[1] = LifetimeEstimator::create(size);
        checkMode(mode);
        mode_ = mode;
        setSensorSize(size);
    }

    void process(InputArray events, OutputArray disparity, OutputArray lifetime, OutputArray flags, OutputArray depth,
                 OutputArray flow) CV_OVERRIDE
    {
        Mat_<Event> ev = getEventMat(events);
        const int n = (int)ev.total();
        disparity.create(n, 1, CV_32F);
        Mat_<float> disp = disparity.getMat(), lt, dep, fl;
        Mat_<int> fla;
        if (lifetime.needed())
        {
            lifetime.create(n, 1, CV_32F);
            lt = lifetime.getMat();
        }
        if (flags.needed())
        {
            flags.create(n, 1, CV_32S);
            fla = flags.getMat();
        }
        if (depth.needed())
        {
            depth.create(n, 1, CV_32F);
            dep = depth.getMat();
        }
        if (flow.needed())
        {
            flow.create(n, 2, CV_32F);
            fl = flow.getMat();
        }
        auto store = [&](int i, const StereoEventEstimate& s) {
            disp(i) = s.disparity;
            if (!lt.empty())
                lt(i) = s.lifetime;
            if (!fla.empty())
                fla(i) = s.flags;
            if (!dep.empty())
                dep(i) = s.depth;
            if (!fl.empty())
            {
                fl(i, 0) = s.flow[0];
                fl(i, 1) = s.flow[1];
            }
        };
        if (mode_ == STEREO_FRAME_SGBM)
        {
            processFrames(ev, store);
            return;
        }
        if (numThreads_ > 1 && n >= MIN_EVENTS_FOR_BANDS)
        {
            processInBands(ev, store);
            return;
        }
        StereoEventEstimate s;
        for (int i = 0; i < n; i++)
        {
            processEvent(ev(i), s);
            store(i, s);
        }
    }

    // Smaller packets run on the calling thread: starting the others would cost more than they gain.
    enum { MIN_EVENTS_FOR_BANDS = 1000 };

    void processEvent(const Event& e, StereoEventEstimate& est) CV_OVERRIDE
    {
        if (mode_ == STEREO_FRAME_SGBM)
            CV_Error(Error::StsNotImplemented, "StereoEventMatcher: FRAME_SGBM works on windows of events; use process() "
                                               "with whole windows (processEvent is for the per-event modes)");
        est = StereoEventEstimate();
        const Point r = admit(e);
        est.rectified = r;
        if (r.x < 0)
        {
            est.flags = STEREO_OUTSIDE;
            return;
        }
        maps_[0].expireUntil(e.t);
        maps_[1].expireUntil(e.t);
        processAdmitted(e, r, coldStartEnd_, scratch_, est);
        addStatusCounts(*estimators_[e.camera], scratch_.lifetimes[e.camera]);
    }

    // processEvent after admit() and the expiries due: the event at rectified pixel r, inside the image.
    // Reads and writes only rows within eventRowReach() of r.y, with its own scratch: see processInBands().
    void processAdmitted(const Event& e, Point r, int64 coldStartEnd, MatchScratch& s, StereoEventEstimate& est)
    {
        const int c = e.camera, p = e.p ? 1 : 0;
        Event re = e;
        re.x = (short)r.x;
        re.y = (short)r.y;
        LifetimeEstimator& estimator = *estimators_[c];

        int status = -1;
        if (mode_ == STEREO_DECOUPLED)
            est.lifetime = processEventInRows(estimator, re, est.flow, status, s.lifetimes[c]);
        // The event takes part in its own descriptor while it is matched; its final activity follows below.
        maps_[c].activate(r.x, r.y, p, std::numeric_limits<int64>::max(), 0.f, Vec2f());
        const MatchResult m = match(c, r, p, e.t, s);
        est.disparity = m.disparity;
        est.flags |= m.flags;
        if (mode_ == STEREO_COUPLED)
        {
            if (m.disparity >= 0 && matchedLifetime(1 - c, m.counterpartX, r.y, p, s, est.lifetime, est.flow))
            {
                insertEventInRows(estimator, re, est.lifetime, est.flow, s.lifetimes[c]);
                status = LIFETIME_MATCHED;
            }
            else
                est.lifetime = processEventInRows(estimator, re, est.flow, status, s.lifetimes[c]);
        }

        int64 activeFor = 0;
        if (mode_ == STEREO_FIXED_INTERVAL)
            activeFor = fixedInterval_;
        else if (est.lifetime > 0)
            activeFor = activeSpan(est.lifetime);
        else if (e.t < coldStartEnd)
        {
            // Cold start: during the plane fit's first time window the surface cannot hold the history a fit
            // needs, so a scene's first edges fail it for want of neighbours, not for being noise, and without
            // them neither sensor has anything active to match against. Such an event gets no lifetime of its
            // own but stays visible to matching as if its lifetime were the fixed interval (FIXED_INTERVAL's
            // activity, which needs no history).
            activeFor = activeSpan(fixedInterval_);
        }
        if (activeFor > 0)
            maps_[c].activate(r.x, r.y, p, timeAfter(e.t, activeFor), est.lifetime, est.flow);
        else
            maps_[c].deactivate(r.x, r.y, p);

        if (est.disparity >= 0)
        {
            est.flags |= STEREO_HAS_DISPARITY;
            if (est.disparity > 0 && focalBaseline_ != 0)
                est.depth = (float)(focalBaseline_ / est.disparity);
        }
        if (est.lifetime > 0)
        {
            est.flags |= STEREO_HAS_LIFETIME;
            if (status == LIFETIME_MATCHED)
                est.flags |= STEREO_LIFETIME_MATCHED;
            else if (status == LIFETIME_PREDICTED)
                est.flags |= STEREO_LIFETIME_PREDICTED;
        }
        else if (status == LIFETIME_NOISE)
        {
            est.flags |= STEREO_NOISE;
            est.flow = Vec2f();
        }
        remember(c, r, e.t, activeFor, est.disparity);
    }

    void renderDisparity(double t, OutputArray image, int camera, bool colourBar) const CV_OVERRIDE
    {
        CV_CheckGE(camera, 0, "StereoEventMatcher::renderDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
        CV_CheckLE(camera, 1, "StereoEventMatcher::renderDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
        const int barWidth = colourBar ? 56 : 0;
        image.create(size_.height, size_.width + barWidth, CV_8UC3);
        Mat img = image.getMat();
        img.setTo(Scalar::all(0));
        const Mat lut = colourLut();
        const std::vector<PixelEstimate>& last = lastEstimate_[camera];
        const std::vector<int64>& lastTime = lastEventTime_[camera];
        for (int y = 0; y < size_.height; y++)
        {
            Vec3b* row = img.ptr<Vec3b>(y);
            for (int x = 0; x < size_.width; x++)
            {
                const size_t i = (size_t)y * size_.width + x;
                const PixelEstimate& q = last[i];
                if (q.disparity < 0 || !((double)lastTime[i] <= t && t < (double)q.until))
                    continue;
                row[x] = lut.at<Vec3b>(colourIndex(q.disparity));
            }
        }
        if (!colourBar)
            return;
        // Bar: max disparity at the top, min at the bottom, labelled.
        const int x0 = size_.width + 6, x1 = x0 + 12, top = 12, bottom = size_.height - 12;
        for (int y = top; y <= bottom; y++)
        {
            const double d = maxDisparity_ - (double)(y - top) / std::max(1, bottom - top) * (maxDisparity_ - minDisparity_);
            line(img, Point(x0, y), Point(x1, y), Scalar(lut.at<Vec3b>(colourIndex((float)d))), 1);
        }
        const Scalar white(255, 255, 255);
        putText(img, std::to_string(maxDisparity_), Point(x1 + 3, top + 8), FONT_HERSHEY_PLAIN, 0.8, white, 1);
        putText(img, std::to_string(minDisparity_), Point(x1 + 3, bottom), FONT_HERSHEY_PLAIN, 0.8, white, 1);
        putText(img, "px", Point(x1 + 3, (top + bottom) / 2 + 4), FONT_HERSHEY_PLAIN, 0.8, white, 1);
    }

    void reset() CV_OVERRIDE
    {
        const int margin = std::max(aggregationWindow_ / 2, descriptorWindow_ / 2);
        for (int c = 0; c < 2; c++)
        {
            maps_[c].configure(size_, descriptorWindow_, maxVectorLength_, margin);
            estimators_[c]->reset();
            lastEstimate_[c].assign((size_t)size_.area(), PixelEstimate());
            lastEventTime_[c].assign((size_t)size_.area(), 0);
        }
        frames_.configure(size_, minDisparity_, maxDisparity_, frameWindow_);
        lastTime_ = std::numeric_limits<int64>::min();
        sizeScratch(scratch_);
        for (MatchScratch& s : bandScratch_)
            sizeScratch(s);
    }

    void sizeScratch(MatchScratch& s) const
    {
        s.neighbours.resize((size_t)costWindow_ * costWindow_);
        const size_t range = (size_t)(maxDisparity_ - minDisparity_ + 1);
        s.candidates.resize(range);
        s.offsets.resize(range);
        s.cost.resize(range);
    }

    void setCalibration(const StereoCalibration& calibration) CV_OVERRIDE
    {
        if (calibration.empty())
        {
            calibration_ = StereoCalibration();
            for (std::vector<int>& l : lut_)
                l.clear();
            focalBaseline_ = 0;
            reset();
            return;
        }
        calibration.validate();
        if (calibration.imageSize != size_)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: the calibration is for %d x %d sensors but the matcher's "
                                         "sensor is %d x %d", calibration.imageSize.width, calibration.imageSize.height,
                                         size_.width, size_.height));
        Mat pixels(size_.area(), 1, CV_32FC2);
        for (int y = 0; y < size_.height; y++)
            for (int x = 0; x < size_.width; x++)
                pixels.at<Vec2f>(y * size_.width + x) = Vec2f((float)x, (float)y);
        for (int c = 0; c < 2; c++)
        {
            Mat rect;
            calibration.rectifyPoints(pixels, rect, c);
            lut_[c].resize((size_t)size_.area());
            for (int i = 0; i < size_.area(); i++)
            {
                const Vec2f q = rect.at<Vec2f>(i);
                const int x = cvRound(q[0]), y = cvRound(q[1]);
                const bool inside = std::isfinite(q[0]) && std::isfinite(q[1]) && x >= 0 && y >= 0 && x < size_.width &&
                                    y < size_.height;
                lut_[c][(size_t)i] = inside ? y * size_.width + x : -1;
            }
        }
        calibration_ = calibration;
        focalBaseline_ = calibration.focalLength() * calibration.baseline();
        reset();
    }
    const StereoCalibration& getCalibration() const CV_OVERRIDE { return calibration_; }
    void loadCalibration(const String& path) CV_OVERRIDE { setCalibration(readStereoCalibration(path)); }

    Ptr<LifetimeEstimator> getLifetimeEstimator(int camera) const CV_OVERRIDE
    {
        CV_CheckGE(camera, 0, "StereoEventMatcher::getLifetimeEstimator: camera is CAMERA_LEFT or CAMERA_RIGHT");
        CV_CheckLE(camera, 1, "StereoEventMatcher::getLifetimeEstimator: camera is CAMERA_LEFT or CAMERA_RIGHT");
        return estimators_[camera];
    }

    int getMode() const CV_OVERRIDE { return mode_; }
    void setMode(int mode) CV_OVERRIDE
    {
        checkMode(mode);
        mode_ = mode;
        reset();
    }
    Size getSensorSize() const CV_OVERRIDE { return size_; }
    void setSensorSize(Size s) CV_OVERRIDE
    {
        if (s.width <= 0 || s.height <= 0 || s.width > 32768 || s.height > 32768)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: sensor size %d x %d is not valid", s.width, s.height));
        size_ = s;
        for (const Ptr<LifetimeEstimator>& est : estimators_)
            est->setSensorSize(s);
        if (!calibration_.empty() && calibration_.imageSize != s)
        {
            calibration_ = StereoCalibration();
            lut_[0].clear();
            lut_[1].clear();
            focalBaseline_ = 0;
        }
        reset();
    }
    int getMinDisparity() const CV_OVERRIDE { return minDisparity_; }
    void setMinDisparity(int d) CV_OVERRIDE { setDisparityRange(d, maxDisparity_); }
    int getMaxDisparity() const CV_OVERRIDE { return maxDisparity_; }
    void setMaxDisparity(int d) CV_OVERRIDE { setDisparityRange(minDisparity_, d); }
    int getDescriptorWindow() const CV_OVERRIDE { return descriptorWindow_; }
    void setDescriptorWindow(int n) CV_OVERRIDE
    {
        descriptorWindow_ = oddWindow(n, 1, 15, "descriptor window");
        reset();
    }
    int getMaxVectorLength() const CV_OVERRIDE { return maxVectorLength_; }
    void setMaxVectorLength(int r) CV_OVERRIDE
    {
        if (r < 0 || r > 7)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: max vector length %d; must be 0..7 px", r));
        maxVectorLength_ = r;
        reset();
    }
    int getCostWindow() const CV_OVERRIDE { return costWindow_; }
    void setCostWindow(int w) CV_OVERRIDE
    {
        costWindow_ = oddWindow(w, 1, 31, "cost window");
        aggregationWindow_ = std::max(aggregationWindow_, costWindow_);
        reset();
    }
    int getAggregationWindow() const CV_OVERRIDE { return aggregationWindow_; }
    void setAggregationWindow(int a) CV_OVERRIDE
    {
        aggregationWindow_ = oddWindow(a, costWindow_, 31, "aggregation window (>= the cost window)");
        reset();
    }
    int getUniquenessRatio() const CV_OVERRIDE { return uniquenessRatio_; }
    void setUniquenessRatio(int u) CV_OVERRIDE
    {
        if (u < 0 || u > 99)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: uniqueness ratio %d; must be 0..99 %%", u));
        uniquenessRatio_ = u;
    }
    double getFixedInterval() const CV_OVERRIDE { return (double)fixedInterval_; }
    void setFixedInterval(double us) CV_OVERRIDE { fixedInterval_ = duration(us, "fixed interval"); }
    double getFrameWindow() const CV_OVERRIDE { return (double)frameWindow_; }
    void setFrameWindow(double us) CV_OVERRIDE
    {
        frameWindow_ = duration(us, "frame window");
        reset();
    }
    double getMaxLifetime() const CV_OVERRIDE { return (double)maxLifetime_; }
    void setMaxLifetime(double us) CV_OVERRIDE { maxLifetime_ = duration(us, "max lifetime"); }
    double getActiveDistance() const CV_OVERRIDE { return activeDistance_; }
    void setActiveDistance(double px) CV_OVERRIDE
    {
        if (!(px >= 0.1 && px <= 100))
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: active distance %g px; must be 0.1..100 px (1: active "
                                         "for one lifetime, as in the paper)", px));
        activeDistance_ = px;
    }
    int getNumThreads() const CV_OVERRIDE { return numThreads_; }
    void setNumThreads(int threads) CV_OVERRIDE
    {
        if (threads < 1 || threads > 64)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %d threads; must be 1..64", threads));
        numThreads_ = threads;
    }

    void write(FileStorage& fs) const CV_OVERRIDE
    {
        writeFormat(fs);
        fs << "mode" << getStereoModeName(mode_) << "sensorWidth" << size_.width << "sensorHeight" << size_.height
           << "minDisparity" << minDisparity_ << "maxDisparity" << maxDisparity_ << "descriptorWindow" << descriptorWindow_
           << "maxVectorLength" << maxVectorLength_ << "costWindow" << costWindow_ << "aggregationWindow"
           << aggregationWindow_ << "uniquenessRatio" << uniquenessRatio_ << "fixedInterval" << (double)fixedInterval_
           << "frameWindow" << (double)frameWindow_ << "maxLifetime" << (double)maxLifetime_ << "activeDistance"
           << activeDistance_;
        fs << "lifetimeEstimator" << "{";
        estimators_[0]->write(fs);
        fs << "}";
        if (!calibration_.empty())
        {
            fs << "calibration" << "{";
            calibration_.write(fs);
            fs << "}";
        }
    }

    void read(const FileNode& fn) CV_OVERRIDE
    {
        auto num = [&](const char* key, double def) { return fn[key].empty() ? def : (double)fn[key]; };
        if (!fn["mode"].empty())
        {
            const int m = findStereoMode((String)fn["mode"]);
            if (m < 0)
                CV_Error_(Error::StsParseError, ("StereoEventMatcher: unknown mode '%s'", ((String)fn["mode"]).c_str()));
            checkMode(m);
            mode_ = m;
        }
        const Size s((int)num("sensorWidth", size_.width), (int)num("sensorHeight", size_.height));
        if (s != size_)
            setSensorSize(s);
        setDisparityRange((int)num("minDisparity", minDisparity_), (int)num("maxDisparity", maxDisparity_));
        setDescriptorWindow((int)num("descriptorWindow", descriptorWindow_));
        setMaxVectorLength((int)num("maxVectorLength", maxVectorLength_));
        setCostWindow((int)num("costWindow", costWindow_));
        setAggregationWindow((int)num("aggregationWindow", aggregationWindow_));
        setUniquenessRatio((int)num("uniquenessRatio", uniquenessRatio_));
        setFixedInterval(num("fixedInterval", (double)fixedInterval_));
        setFrameWindow(num("frameWindow", (double)frameWindow_));
        setMaxLifetime(num("maxLifetime", (double)maxLifetime_));
        setActiveDistance(num("activeDistance", activeDistance_));
        if (!fn["lifetimeEstimator"].empty())
            for (const Ptr<LifetimeEstimator>& est : estimators_)
                est->read(fn["lifetimeEstimator"]);
        if (!fn["calibration"].empty())
        {
            StereoCalibration c;
            c.read(fn["calibration"], "StereoEventMatcher calibration");
            setCalibration(c);
        }
        reset();
    }

    String getDefaultName() const CV_OVERRIDE { return "StereoEventMatcher"; }

private:
    // Per pixel of each sensor, the end of its last event's activity and its disparity (-1: none), for the
    // left-right check and for renderDisparity. One struct: the check reads both together. The event's time,
    // which only the rendering reads, lies apart (lastEventTime_), so that a row of the check spans fewer
    // cache lines (16 bytes per pixel instead of 24).
    struct PixelEstimate
    {
        int64 until = 0;
        float disparity = -1.f;
    };

    static void checkMode(int mode)
    {
        if (mode < STEREO_COUPLED || mode > STEREO_FRAME_SGBM)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: mode %d; use a StereoMatchMode (0..3)", mode));
    }

    static int oddWindow(int n, int lo, int hi, const char* what)
    {
        if (n < lo || n > hi || n % 2 == 0)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %d; must be odd, %d..%d", what, n, lo, hi));
        return n;
    }

    static int64 duration(double us, const char* what)
    {
        if (!(us >= 1) || us > 1e12)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %g us; must be 1 us .. 1e12 us", what, us));
        return (int64)std::llround(us);
    }

    void setDisparityRange(int lo, int hi)
    {
        if (lo < 0 || hi < lo || hi > 1024)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: disparity range [%d, %d]; need 0 <= min <= max <= 1024", lo, hi));
        minDisparity_ = lo;
        maxDisparity_ = hi;
        reset();
    }

    // Checks the event (camera, sensor bounds, time order) and returns its rectified pixel, (-1, -1) when it
    // falls outside the rectified image.
    Point admit(const Event& e)
    {
        if (e.camera > 1)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: event (t=%lld us, x=%d, y=%d) has camera %d; a stereo "
                                         "stream has CAMERA_LEFT (0) and CAMERA_RIGHT (1)", (long long)e.t, e.x, e.y, e.camera));
        if ((unsigned)e.x >= (unsigned)size_.width || (unsigned)e.y >= (unsigned)size_.height)
            CV_Error_(Error::StsOutOfRange, ("StereoEventMatcher: event at (x=%d, y=%d), t=%lld us, camera %d, is outside "
                                             "the %d x %d sensor", e.x, e.y, (long long)e.t, e.camera, size_.width, size_.height));
        if (e.t == EventSurface::NO_EVENT)
            CV_Error_(Error::StsOutOfRange, ("StereoEventMatcher: event (x=%d, y=%d, camera %d) has t = INT64_MIN, which is "
                                             "reserved for EventSurface::NO_EVENT", e.x, e.y, e.camera));
        if (e.t < lastTime_)
            CV_Error_(Error::StsBadArg, ("StereoEventMatcher: event at t=%lld us (x=%d, y=%d, camera %d) is earlier than the "
                                         "previous one (t=%lld us): events of both sensors must come merged in time order "
                                         "(mergeStereoEvents, EventCapture::openStereo)", (long long)e.t, e.x, e.y,
                                         e.camera, (long long)lastTime_));
        // The stream starts, or resumes after a gap longer than the plane fit's time window: the surfaces hold
        // no usable history, and the cold start (processEvent) runs for one time window.
        const int64 window = (int64)std::min(estimators_[e.camera]->getTimeWindow(), 1e18);
        if (lastTime_ == std::numeric_limits<int64>::min() || e.t > timeAfter(lastTime_, window))
            coldStartEnd_ = timeAfter(e.t, window);
        lastTime_ = e.t;
        if (lut_[e.camera].empty())
            return Point(e.x, e.y);
        const int r = lut_[e.camera][(size_t)e.y * size_.width + e.x];
        return r < 0 ? Point(-1, -1) : Point(r % size_.width, r / size_.width);
    }

    // Adds the SAD over the rectangle [x0, x1] x [y0, y1] (relative to the event) to every candidate's cost;
    // returns the same sum against an empty map (the event's side alone).
    unsigned addRect(const ZouDescriptorMap& self, const ZouDescriptorMap& other, Point r, int x0, int x1, int y0, int y1,
                     MatchScratch& s) const
    {
        if (!clipToImage(r, x0, x1, y0, y1))
            return 0;
        // Candidate i's rectangle is this one shifted by its disparity along the row: offsets[i] bytes.
        return rectSadBatch_(self.descriptor(r.x + x0, r.y + y0), other.descriptor(r.x + x0, r.y + y0),
                             self.descriptorRowStep(), other.descriptorRowStep(), s.offsets.data(),
                             s.count, x1 - x0 + 1, y1 - y0 + 1, s.cost.data());
    }

    // Clips the rectangle [x0, x1] x [y0, y1] relative to the event's pixel r to the image; false when nothing is
    // left. Cost windows cover only the event's own image: past its border both sensors' descriptors are zero for
    // a candidate that also runs past the other border (d near 0 at the right border of the left image), which
    // would match "nothing" against "nothing" for free and pull border events toward that candidate.
    bool clipToImage(Point r, int& x0, int& x1, int& y0, int& y1) const
    {
        x0 = std::max(x0, -r.x);
        x1 = std::min(x1, size_.width - 1 - r.x);
        y0 = std::max(y0, -r.y);
        y1 = std::min(y1, size_.height - 1 - r.y);
        return x0 <= x1 && y0 <= y1;
    }

    // Sum of the descriptor values over [x0, x1] x [y0, y1] relative to q: the cost of matching against nothing.
    unsigned rectMass(const ZouDescriptorMap& map, Point q, int x0, int x1, int y0, int y1) const
    {
        // The batch kernel without candidates: it returns the rectangle's mass alone.
        return rectSadBatch_(map.descriptor(q.x + x0, q.y + y0), nullptr, map.descriptorRowStep(), 0, nullptr, 0,
                             x1 - x0 + 1, y1 - y0 + 1, nullptr);
    }

    // Matches the event at r (camera c, polarity p, time t) along its row.
    MatchResult match(int c, Point r, int p, int64 t, MatchScratch& s) const
    {
        MatchResult m;
        const ZouDescriptorMap& self = maps_[c];
        const ZouDescriptorMap& other = maps_[1 - c];
        const int sign = c == CAMERA_LEFT ? -1 : 1;  // left x_l matches right x_l - d; right x_r matches left x_r + d
        int* const candidates = s.candidates.data();
        ptrdiff_t* const offsets = s.offsets.data();
        unsigned* const cost = s.cost.data();
        // Disparity indices k whose column xo = r.x + sign * (min + k) lies in the other image; there, a candidate
        // is a column where the other sensor has structure of this polarity. Every k is written and the count
        // advances past the candidates: no branch on the (random) activity pattern.
        const int kEnd = std::min(maxDisparity_, sign < 0 ? r.x : size_.width - 1 - r.x) - minDisparity_ + 1;
        const uchar* structure = other.nearestRow(r.y, p);
        const int x0 = r.x + sign * minDisparity_;
        const ptrdiff_t offsetStep = (ptrdiff_t)sign * ZouDescriptorMap::DESCRIPTOR_BYTES;
        int n = 0;
        for (int k = 0; k < kEnd; k++)
        {
            candidates[n] = k;
            n += structure[x0 + sign * k] != ZouDescriptorMap::NONE;
        }
        for (int i = 0; i < n; i++)
            offsets[i] = (minDisparity_ + candidates[i]) * offsetStep;
        s.count = n;
        if (n == 0)
        {
            m.flags = STEREO_NO_COUNTERPART;
            return m;
        }
        std::fill_n(cost, n, 0u);
        int h = costWindow_ / 2;
        unsigned mass = addRect(self, other, r, -h, h, -h, h, s);
        for (;;)
        {
            int best = 0;  // index into candidates, which run by disparity: ties go to the smaller disparity
            for (int i = 1; i < n; i++)
                if (cost[i] < cost[best])
                    best = i;
            const int kBest = candidates[best];
            // The candidates within one pixel of the best are next to it (they run by disparity, one each):
            // the runner-up is the cheapest outside [lo, hi].
            const int lo = best > 0 && candidates[best - 1] == kBest - 1 ? best - 1 : best;
            const int hi = best < n - 1 && candidates[best + 1] == kBest + 1 ? best + 1 : best;
            unsigned second = std::numeric_limits<unsigned>::max();
            for (int i = 0; i < lo; i++)
                second = std::min(second, cost[i]);
            for (int i = hi + 1; i < n; i++)
                second = std::min(second, cost[i]);
            const unsigned bestCost = cost[best];
            // Unique: clearly better than every candidate further than one pixel away, and clearly better than
            // no match. "No counterpart (yet)" is one more hypothesis, with the cost of matching against nothing
            // (the window's mass); a winner that only just beats it is most often a neighbour of a counterpart
            // that has not arrived yet, off by 2 px, so it must win by the same margin as against a candidate.
            const uint64 margin = (uint64)(100 - uniquenessRatio_);
            const auto clearlyBelow = [margin](unsigned cost, unsigned alternative) {
                return (uint64)cost * 100 < (uint64)alternative * margin;
            };
            const int xo = r.x + sign * (minDisparity_ + kBest);  // the counterpart's column
            bool unique = clearlyBelow(bestCost, second);
            if (unique && !clearlyBelow(bestCost, mass))
            {
                // Not clearly better than nothing from this side; the other side may simply hold more (a more
                // sensitive sensor): compare with its mass too.
                int x0 = -h, x1 = h, y0 = -h, y1 = h;
                clipToImage(r, x0, x1, y0, y1);  // the same columns as the costs, never empty (r is inside)
                unique = clearlyBelow(bestCost, rectMass(other, Point(xo, r.y), x0, x1, y0, y1));
            }
            if (unique)
            {
                double d = minDisparity_ + kBest;
                // Candidates run by disparity: the neighbours, when they are candidates, are next to the best.
                if (lo == best - 1 && hi == best + 1)
                {
                    const double cm = cost[best - 1], c0 = bestCost, cp = cost[best + 1];
                    const double denom = cm + cp - 2 * c0;
                    if (denom > 0)
                        d += std::max(-0.5, std::min(0.5, 0.5 * (cm - cp) / denom));
                }
                m.counterpartX = xo;
                if (!consistent(1 - c, m.counterpartX, r.y, d, t, s))
                {
                    m.flags = STEREO_AMBIGUOUS;
                    return m;
                }
                m.disparity = (float)d;
                return m;
            }
            if (h >= aggregationWindow_ / 2)
                break;
            // Iterative aggregation: add the ring one pixel further out.
            h++;
            mass += addRect(self, other, r, -h, h, -h, -h, s);
            mass += addRect(self, other, r, -h, h, h, h, s);
            mass += addRect(self, other, r, -h, -h, -h + 1, h - 1, s);
            mass += addRect(self, other, r, h, h, -h + 1, h - 1, s);
        }
        m.flags = STEREO_AMBIGUOUS;
        return m;
    }

    // Left-right check against the other sensor's own estimates: the active events around the counterpart
    // were matched the other way (toward this sensor); when they have disparities, their median must agree
    // within one pixel. Without any there is nothing to contradict the match.
    bool consistent(int c, int x, int y, double d, int64 t, MatchScratch& s) const
    {
        const std::vector<PixelEstimate>& last = lastEstimate_[c];
        std::vector<float>& disparities = s.disparities;
        disparities.clear();
        for (int yy = std::max(0, y - 1); yy <= std::min(size_.height - 1, y + 1); yy++)
            for (int xx = std::max(0, x - 1); xx <= std::min(size_.width - 1, x + 1); xx++)
            {
                const size_t i = (size_t)yy * size_.width + xx;
                if (last[i].disparity >= 0 && t < last[i].until)
                    disparities.push_back(last[i].disparity);
            }
        if (disparities.empty())
            return true;
        const size_t mid = disparities.size() / 2;
        std::nth_element(disparities.begin(), disparities.begin() + (std::ptrdiff_t)mid, disparities.end());
        return std::abs(disparities[mid] - d) <= 1.0;
    }

    // How long an event with this lifetime (us per pixel) stays active: until its edge has moved
    // activeDistance_ pixels, at most maxLifetime_.
    int64 activeSpan(double lifetime) const
    {
        const double span = std::min(lifetime * activeDistance_, (double)maxLifetime_);
        return std::max<int64>(1, (int64)std::llround(span));
    }

    // Median lifetime (and the flow of that event) of the active events of polarity p in the cost window
    // around (x, y) of sensor c. False when none has a lifetime.
    bool matchedLifetime(int c, int x, int y, int p, MatchScratch& s, float& lifetime, Vec2f& flow) const
    {
        const ZouDescriptorMap& map = maps_[c];
        const int h = costWindow_ / 2;
        // Every pixel is written, and the end advances past those with a lifetime: no branch on the (random)
        // activity pattern. The scratch holds a whole window (sizeScratch()).
        Neighbour* const first = s.neighbours.data();
        Neighbour* end = first;
        const int x0 = std::max(0, x - h), x1 = std::min(size_.width - 1, x + h);
        const float* const lifetimes = map.lifetimes();
        for (int yy = std::max(0, y - h); yy <= std::min(size_.height - 1, y + h); yy++)
        {
            const int i1 = map.lifetimeIndex(x1, yy, p);
            for (int i = map.lifetimeIndex(x0, yy, p); i <= i1; i++)
            {
                const float v = lifetimes[i];
                *end = Neighbour{ v, i };
                end += v > 0;
            }
        }
        if (end == first)
            return false;
        const std::ptrdiff_t mid = (end - first) / 2;
        std::nth_element(first, first + mid, end, [](const Neighbour& a, const Neighbour& b) { return a.lifetime < b.lifetime; });
        const Neighbour& q = first[mid];
        lifetime = q.lifetime;
        flow = map.flowAt(q.index);
        return true;
    }

    void remember(int c, Point r, int64 t, int64 activeFor, float disparity)
    {
        const size_t i = (size_t)r.y * size_.width + r.x;
        PixelEstimate& q = lastEstimate_[c][i];
        lastEventTime_[c][i] = t;
        q.until = timeAfter(t, activeFor);
        q.disparity = disparity;
    }

    template <typename Store>
    void processFrames(const Mat_<Event>& ev, Store& store)
    {
        const int n = (int)ev.total();
        std::vector<Point> pixels((size_t)n);
        std::vector<int64> times((size_t)n);
        std::vector<uchar> cameras((size_t)n);
        for (int i = 0; i < n; i++)
        {
            const Point r = admit(ev(i));
            pixels[(size_t)i] = r;
            times[(size_t)i] = ev(i).t;
            cameras[(size_t)i] = r.x < 0 ? 255 : ev(i).camera;
        }
        std::vector<float> disparity;
        frames_.process(pixels, times, cameras, disparity);
        for (int i = 0; i < n; i++)
        {
            StereoEventEstimate s;
            s.rectified = pixels[(size_t)i];
            if (cameras[(size_t)i] > 1)
                s.flags = STEREO_OUTSIDE;
            else
            {
                s.disparity = disparity[(size_t)i];
                if (s.disparity >= 0)
                {
                    s.flags = STEREO_HAS_DISPARITY;
                    if (s.disparity > 0 && focalBaseline_ != 0)
                        s.depth = (float)(focalBaseline_ / s.disparity);
                }
                remember(cameras[(size_t)i], s.rectified, times[(size_t)i], frameWindow_, s.disparity);
            }
            store(i, s);
        }
    }

    // How many rows above and below its own an event's processing reads or writes: the aggregation window's
    // descriptors (match), the matched window (its median lifetime), the left-right check's 3 x 3, the vectors
    // an activation or deactivation changes (2 x the max length for the re-search) and their votes, the plane
    // fit's window. Operations further apart in rows than the sum of their reaches touch disjoint state.
    int eventRowReach() const
    {
        return std::max({ aggregationWindow_ / 2, costWindow_ / 2, 1, expiryRowReach(), lifetimeRowReach(*estimators_[0]),
                          lifetimeRowReach(*estimators_[1]) });
    }
    // The same for an expiry (a deactivation).
    int expiryRowReach() const { return std::max(2 * maxVectorLength_, maxVectorLength_ + descriptorWindow_ / 2); }

    // First rows of `bands` bands of at least minHeight rows, each holding about as many of the first `valid`
    // admitted events.
    std::vector<int> splitRows(int valid, int bands, int minHeight) const
    {
        std::vector<int> rows((size_t)size_.height + 1, 0);  // rows[y + 1]: inside events in rows <= y
        for (int i = 0; i < valid; i++)
            if (admitted_[(size_t)i].rectified.x >= 0)
                rows[(size_t)admitted_[(size_t)i].rectified.y + 1]++;
        for (int y = 0; y < size_.height; y++)
            rows[(size_t)y + 1] += rows[(size_t)y];
        const int64 total = rows.back();
        std::vector<int> first(1, 0);
        for (int b = 1; b < bands; b++)
        {
            const int64 target = total * b / bands;
            const int y = (int)(std::lower_bound(rows.begin(), rows.end(), target) - rows.begin());
            first.push_back(std::min(std::max(y, first.back() + minHeight), size_.height - (bands - b) * minHeight));
        }
        return first;
    }

    // process() on several threads, with the results of one. The rows are split into bands, each processed by
    // its own thread in time order: its events, and the expiries of its pixels (both maps) where the single
    // thread would take them (before the first event at or after the expiry time). Every operation has a key,
    // its place in the single thread's order: position x (bands + 1) + band for an expiry (position: the index
    // of that first event; expiries at one position commute, the map's state depends only on what is active),
    // index x (bands + 1) + bands for an event. An operation whose rows (its row +- its reach) may meet rows
    // the neighbouring band's operations touch (that band's rows + the largest reach) first waits until the
    // neighbour's next operation has a larger key: every operation it could conflict with then ran in the
    // single thread's order. Bands are at least 2 x the largest reach + 1 tall, so only neighbours can meet.
    // Two bands never wait on each other at once: the smaller of their keys goes first.
    template <typename Store>
    void processInBands(const Mat_<Event>& ev, Store& store)
    {
        const int n = (int)ev.total();
        admitted_.resize((size_t)n);
        times_.resize((size_t)n);
        // Admission in order: the checks, the rectified pixel and the cold start depend on the events before.
        // An event that fails it ends the packet after the events before it, as on one thread.
        int valid = n;
        std::exception_ptr badEvent;
        for (int i = 0; i < n; i++)
        {
            Admission& a = admitted_[(size_t)i];
            try
            {
                a.rectified = admit(ev(i));
            }
            catch (...)
            {
                badEvent = std::current_exception();
                valid = i;
                break;
            }
            a.coldStartEnd = coldStartEnd_;
            times_[(size_t)i] = ev(i).t;
            if (a.rectified.x < 0)
            {
                StereoEventEstimate outside;
                outside.rectified = a.rectified;
                outside.flags = STEREO_OUTSIDE;
                store(i, outside);
            }
        }
        const int reach = eventRowReach();
        const int bands = std::max(1, std::min(numThreads_, size_.height / (2 * reach + 1)));
        const std::vector<int> first = splitRows(valid, bands, 2 * reach + 1);
        maps_[0].setRowBands(first);
        maps_[1].setRowBands(first);
        if (bandScratch_.size() < (size_t)bands)
        {
            bandScratch_.resize((size_t)bands);
            for (MatchScratch& s : bandScratch_)
                sizeScratch(s);
        }
        progress_.reset(new BandProgress[(size_t)bands]);
        for (int b = 0; b < bands; b++)
            progress_[(size_t)b].key.store(-1, std::memory_order_relaxed);
        std::vector<std::exception_ptr> failures((size_t)bands);
        auto run = [&](int b) {
            try
            {
                runBand(b, bands, valid, ev, store);
            }
            catch (...)
            {
                failures[(size_t)b] = std::current_exception();
            }
            // Done (or failed): never keep the neighbours waiting.
            progress_[(size_t)b].key.store(std::numeric_limits<int64>::max(), std::memory_order_release);
        };
        std::vector<std::thread> threads;
        for (int b = 1; b < bands; b++)
            threads.emplace_back(run, b);
        run(0);
        for (std::thread& t : threads)
            t.join();
        for (int b = 0; b < bands; b++)
            for (int c = 0; c < 2; c++)
                addStatusCounts(*estimators_[c], bandScratch_[(size_t)b].lifetimes[c]);
        for (const std::exception_ptr& f : failures)
            if (f)
                std::rethrow_exception(f);
        if (badEvent)
            std::rethrow_exception(badEvent);
    }

    // Band b's thread of processInBands.
    template <typename Store>
    void runBand(int b, int bands, int valid, const Mat_<Event>& ev, Store& store)
    {
        MatchScratch& s = bandScratch_[(size_t)b];
        const std::vector<int>& first = maps_[0].rowBands();
        const int top = first[(size_t)b], bottom = b + 1 < bands ? first[(size_t)b + 1] : size_.height;
        const int reach = eventRowReach(), expiryReach = expiryRowReach();  // reach is the largest
        const int64 stride = bands + 1, none = std::numeric_limits<int64>::max();
        BandProgress& mine = progress_[(size_t)b];
        // Waits until the neighbours whose operations may touch rows [y - r, y + r] are past `key`.
        auto waitForNeighbours = [&](int y, int r, int64 key) {
            if (b > 0 && y - r < top + reach)
                waitPast(progress_[(size_t)b - 1], key);
            if (b + 1 < bands && y + r >= bottom - reach)
                waitPast(progress_[(size_t)b + 1], key);
        };
        int i = 0;
        for (;;)
        {
            while (i < valid && !(admitted_[(size_t)i].rectified.x >= 0 && admitted_[(size_t)i].rectified.y >= top &&
                                  admitted_[(size_t)i].rectified.y < bottom))
                i++;
            const int64 eventKey = i < valid ? (int64)i * stride + bands : none;
            int64 expiryKey = none;
            int map = -1, expiryRow = 0;
            int64 expiryTime = none;
            for (int c = 0; c < 2; c++)
            {
                int64 t;
                int row;
                if (maps_[c].earliestExpiry(b, t, row) && t < expiryTime)
                {
                    map = c;
                    expiryTime = t;
                    expiryRow = row;
                }
            }
            if (map >= 0)
            {
                const int64 position = std::lower_bound(times_.begin(), times_.begin() + valid, expiryTime) - times_.begin();
                if (position < valid)
                    expiryKey = position * stride + b;
            }
            const int64 key = std::min(eventKey, expiryKey);
            if (key == none)
                break;
            mine.key.store(key, std::memory_order_release);
            if (expiryKey < eventKey)
            {
                waitForNeighbours(expiryRow, expiryReach, key);
                maps_[map].expireEarliest(b);
                continue;
            }
            const Admission& a = admitted_[(size_t)i];
            waitForNeighbours(a.rectified.y, reach, key);
            StereoEventEstimate est;
            est.rectified = a.rectified;
            processAdmitted(ev(i), a.rectified, a.coldStartEnd, s, est);
            store(i, est);
            i++;
        }
    }

    static void waitPast(const BandProgress& neighbour, int64 key)
    {
        for (int spins = 0; neighbour.key.load(std::memory_order_acquire) <= key; spins++)
            if (spins >= 64)
                std::this_thread::yield();
    }

    Mat colourLut() const
    {
        Mat ramp(256, 1, CV_8U), lut;
        for (int i = 0; i < 256; i++)
            ramp.at<uchar>(i) = (uchar)i;
        applyColorMap(ramp, lut, COLORMAP_JET);
        return lut;
    }

    int colourIndex(float d) const
    {
        const double span = std::max(1, maxDisparity_ - minDisparity_);
        return std::max(0, std::min(255, (int)std::lround((d - minDisparity_) / span * 255)));
    }

    Size size_;
    int mode_ = STEREO_COUPLED;
    int minDisparity_ = 0, maxDisparity_ = 40;
    int descriptorWindow_ = 3, maxVectorLength_ = 3, costWindow_ = 9, aggregationWindow_ = 17, uniquenessRatio_ = 15;
    int64 fixedInterval_ = 10000, frameWindow_ = 33000, maxLifetime_ = 100000;
    double activeDistance_ = 2.5;
    StereoCalibration calibration_;
    std::vector<int> lut_[2];  // raw pixel -> rectified pixel index (-1: outside); empty: no calibration
    double focalBaseline_ = 0;
    Ptr<LifetimeEstimator> estimators_[2];
    ZouDescriptorMap maps_[2];
    FrameSgbmMatcher frames_;
    std::vector<PixelEstimate> lastEstimate_[2];
    std::vector<int64> lastEventTime_[2];
    int64 lastTime_ = std::numeric_limits<int64>::min();
    int64 coldStartEnd_ = 0;  // the end of the cold start: see admit()
    // The cost kernel for this CPU (candidates' costs and window masses), fetched once.
    DescriptorRectSadBatchFn rectSadBatch_ = descriptorRectSadBatchFunction();
    MatchScratch scratch_;  // processEvent's
    int numThreads_ = 1;
    // processInBands: each band's scratch and progress; each event's admission and time.
    struct Admission
    {
        Point rectified;
        int64 coldStartEnd;
    };
    std::vector<MatchScratch> bandScratch_;
    std::unique_ptr<BandProgress[]> progress_;
    std::vector<Admission> admitted_;
    std::vector<int64> times_;
};

}  // namespace

Ptr<StereoEventMatcher> StereoEventMatcher::create(Size sensorSize, int mode)
{
    return makePtr<StereoEventMatcherImpl>(sensorSize, mode);
}

String getStereoModeName(int mode)
{
    switch (mode)
    {
    case STEREO_COUPLED: return "coupled";
    case STEREO_DECOUPLED: return "decoupled";
    case STEREO_FIXED_INTERVAL: return "fixed";
    case STEREO_FRAME_SGBM: return "sgbm";
    default: CV_Error_(Error::StsBadArg, ("getStereoModeName: mode %d is not a StereoMatchMode", mode));
    }
}

int findStereoMode(const String& name)
{
    const std::string n = detail::toLowerAscii(name);
    for (int m = STEREO_COUPLED; m <= STEREO_FRAME_SGBM; m++)
        if (n == getStereoModeName(m))
            return m;
    return -1;
}

}  // namespace event
}  // namespace cv
