// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Per-event stereo disparity and lifetime (Hadviger et al. 2019): the per-event pipeline (admission,
// lifetime and activity of each event, the frame + SGBM baseline, the row bands' glue), the parameters and the
// rendering. The matching core is in stereo_event_matching.cpp; the method is described in the public header.

#include "precomp.hpp"
#include "common/ascii.hpp"
#include "common/timestamp_math.hpp"
#include "stereo/rectification_table.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

#include "opencv2/imgproc.hpp"

namespace cv {
namespace event {
namespace detail {

// ---- pipeline

StereoEventMatcherImpl::StereoEventMatcherImpl(Size size, int mode)
{
    estimators_[0] = LifetimeEstimator::create(size);
    estimators_[1] = LifetimeEstimator::create(size);
    checkMode(mode);
    mode_ = mode;
    setSensorSize(size);
}

void StereoEventMatcherImpl::process(InputArray events, OutputArray disparity, OutputArray lifetime, OutputArray flags, OutputArray depth,
             OutputArray flow, OutputArray confidence)
{
    Mat_<Event> ev = getEventMat(events);
    const int n = (int)ev.total();
    disparity.create(n, 1, CV_32F);
    Mat_<float> disp = disparity.getMat(), lt, dep, fl, conf;
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
    if (confidence.needed())
    {
        confidence.create(n, 1, CV_32F);
        conf = confidence.getMat();
    }
    auto store = [&](int i, const StereoEventEstimate& s) {
        disp(i) = s.disparity;
        if (!conf.empty())
            conf(i) = s.confidence;
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
    if (lookAhead_ > 0 || (numThreads_ > 1 && n >= MIN_EVENTS_FOR_BANDS))
    {
        processOperations(ev, store);
        return;
    }
    StereoEventEstimate s;
    for (int i = 0; i < n; i++)
    {
        processEvent(ev(i), s);
        store(i, s);
    }
}

void StereoEventMatcherImpl::processEvent(const Event& e, StereoEventEstimate& est)
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
    processAdmitted(e, r, coldStartEnd_, false, scratch_, est);
    addStatusCounts(*estimators_[e.camera], scratch_.lifetimes[e.camera]);
}

namespace {

// Adds the time from its construction to its destruction to `ticks` when `on` (setTimeLifetimes).
class LifetimeTimer
{
public:
    LifetimeTimer(bool on, int64& ticks) : ticks_(on ? &ticks : nullptr), start_(on ? getTickCount() : 0) {}
    ~LifetimeTimer()
    {
        if (ticks_)
            *ticks_ += getTickCount() - start_;
    }
private:
    int64* ticks_;
    int64 start_;
};

}  // namespace

// processEvent after admit() and the expiries due: the event at rectified pixel r, inside the image.
// Reads and writes only rows within eventRowReach() of r.y, with its own scratch: see processOperations().
void StereoEventMatcherImpl::processAdmitted(const Event& e, Point r, int64 coldStartEnd, bool laterPending, MatchScratch& s,
                                             StereoEventEstimate& est)
{
    const int c = e.camera, p = e.p ? 1 : 0;
    Event re = e;
    re.x = (short)r.x;
    re.y = (short)r.y;
    LifetimeEstimator& estimator = *estimators_[c];

    int status = -1;
    int lifetimeCopies = 0;  // of the lifetime this event ends with (0 unless it was passed on by a match)
    if (mode_ == STEREO_DECOUPLED)
    {
        const LifetimeTimer timer(timeLifetimes_, s.lifetimeTicks);
        est.lifetime = processEventInRows(estimator, re, est.flow, status, s.lifetimes[c]);
    }
    // The event takes part in its own descriptor while it is matched; its final activity follows below.
    activateUndecided(c, r, p, e.t);
    // Where the neighbours put the event's counterpart past the other sensor's border, there is nothing to
    // match: their estimates decide (no counterpart, so no matched window for the lifetime either).
    MatchResult m;
    if (!estimateBeyondView(c, r, e.t, s, m))
        m = match(c, r, p, e.t, s);
    est.flags |= m.flags;
    est.confidence = m.confidence;
    if (m.disparity >= 0)
    {
        if (m.confidence >= minConfidence_)
            est.disparity = m.disparity;
        else
            est.flags |= STEREO_AMBIGUOUS;
    }
    if (mode_ == STEREO_COUPLED)
    {
        const LifetimeTimer timer(timeLifetimes_, s.lifetimeTicks);
        // The other sensor's matched window, whose median is taken only where it is used.
        MatchedWindow window(*this, 1 - c, m.counterpartX, r.y, p, s);
        const bool matchable = est.disparity >= 0 && m.counterpartX >= 0;
        // A lifetime copied back and forth between the sensors is never refitted while the edge changes speed (a
        // swinging limb): past maxLifetimeCopies copies the event fits its own plane first, as it does after a
        // match less confident than lifetimeCopyConfidence_ (most often a wrong one).
        std::pair<float, Vec2f> matched;
        if (matchable && !(m.confidence < lifetimeCopyConfidence_) && window.get(matched)
            && window.copies < maxLifetimeCopies_)
        {
            lifetimeCopies = window.copies + 1;
            if (m.confidence >= matchedLifetimeConfidence_)
            {
                est.lifetime = matched.first;
                est.flow = matched.second;
                insertEventInRows(estimator, re, est.lifetime, est.flow, s.lifetimes[c]);
                status = LIFETIME_MATCHED;
            }
            else
            {
                // Every event keeps its best disparity, noise included, and noise finds some candidate: below
                // matchedLifetimeConfidence_ the event's own plane says whether it is noise before it takes the
                // match's lifetime.
                est.lifetime = processMatchedEventInRows(estimator, re, matched, est.flow, status, s.lifetimes[c]);
            }
        }
        else if (matchable && m.confidence >= matchedLifetimeConfidence_)
        {
            // The event's own plane first; only where it finds none the matched window's median (taken here if
            // not above; an empty window leaves the event noise, as processEventInRows would).
            est.lifetime = refitMatchedEventInRows(estimator, re, window, est.flow, status, s.lifetimes[c]);
            lifetimeCopies = window.copies + 1;
        }
        else
            est.lifetime = processEventInRows(estimator, re, est.flow, status, s.lifetimes[c]);
    }

    int64 activeFor = 0;
    bool noiseActive = false;
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
    else
    {
        // No plane: on a weak edge, where only some pixels fire, often the edge's own event (setNoiseActiveTime).
        activeFor = noiseActiveTime_;
        noiseActive = true;
    }
    // A later event of this pixel and polarity, already in the map (look-ahead), keeps it active until its
    // own decision.
    if (!laterPending)
    {
        if (activeFor > 0)
            maps_[c].activate(r.x, r.y, p, e.t, timeAfter(e.t, activeFor), est.lifetime, est.flow,
                              status == LIFETIME_MATCHED ? lifetimeCopies : 0);
        else
            maps_[c].deactivate(r.x, r.y, p);
    }

    // The neighbours read each event's own estimate (remember below); the output is averaged.
    const float ownDisparity = est.disparity;
    if (ownDisparity >= 0 && averagingRadius_ > 0)
        est.disparity = averagedDisparity(c, r, e.t, ownDisparity, m.counterpartX);
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
    // A noise event's disparity has no plane behind it, and noise finds some candidate: it joins the
    // descriptors (above) but not the neighbours' estimates that the prior, the left-right check and the
    // border's estimates read.
    remember(c, r, e.t, noiseActive ? 0 : activeFor, ownDisparity);
}

void StereoEventMatcherImpl::activateUndecided(int c, Point r, int p, int64 t)
{
    maps_[c].activate(r.x, r.y, p, t, std::numeric_limits<int64>::max(), 0.f, Vec2f());
}

// How long an event with this lifetime (us per pixel) stays active: until its edge has moved
// activeDistance_ pixels, at most maxLifetime_.
int64 StereoEventMatcherImpl::activeSpan(double lifetime) const
{
    const double span = std::min(lifetime * activeDistance_, (double)maxLifetime_);
    return std::max<int64>(1, (int64)std::llround(span));
}

// Checks the event (camera, sensor bounds, time order) and returns its rectified pixel, (-1, -1) when it
// falls outside the rectified image.
Point StereoEventMatcherImpl::admit(const Event& e)
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

void StereoEventMatcherImpl::remember(int c, Point r, int64 t, int64 activeFor, float disparity)
{
    const size_t i = (size_t)r.y * size_.width + r.x;
    lastEventTime_[c][i] = t;
    estimateDisparity_[c][i] = disparity;
    if (disparity < 0)
    {
        estimateUntil_[c][i] = NO_ESTIMATE;
        return;
    }
    const int64 until = timeAfter(t, activeFor);
    estimateUntil_[c][i] = until;
    int64& block = estimateBlockUntil_[c][(size_t)r.y * estimateBlocksPerRow_ + r.x / ESTIMATE_BLOCK];
    block = std::max(block, until);
}

void StereoEventMatcherImpl::processFrames(const Mat_<Event>& ev, const StoreFn& store)
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
                s.confidence = 1.f;
                if (s.disparity > 0 && focalBaseline_ != 0)
                    s.depth = (float)(focalBaseline_ / s.disparity);
            }
            remember(cameras[(size_t)i], s.rectified, times[(size_t)i], frameWindow_, s.disparity);
        }
        store(i, s);
    }
}

// The admission runs here in order (the checks, the rectified pixel and the cold start depend on the events
// before); then the packet's operations (scheduleOperations) run in that order on one thread, or in row bands
// ordered by RowBandScheduler as on one thread.
void StereoEventMatcherImpl::processOperations(const Mat_<Event>& ev, const StoreFn& store)
{
    const int n = (int)ev.total();
    admitted_.resize((size_t)n);
    admittedRows_.resize((size_t)n);
    times_.resize((size_t)n);
    // An event that fails admission ends the packet after the events before it, as on one thread.
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
        admittedRows_[(size_t)i] = a.rectified.x < 0 ? -1 : a.rectified.y;
        times_[(size_t)i] = ev(i).t;
        if (a.rectified.x < 0)
        {
            StereoEventEstimate outside;
            outside.rectified = a.rectified;
            outside.flags = STEREO_OUTSIDE;
            store(i, outside);
        }
    }
    scheduleOperations(valid);
    const int count = (int)operations_.size();
    // Decision: the event's match, lifetime and final activity (processEvent after admission). Arrival (look-ahead
    // only): the event becomes active in its sensor's map, for the decisions of the events before it.
    // Events decided on a band's thread keep their estimates in its scratch until the bands are done: the
    // outputs of events of both bands share cache lines, which the threads would otherwise pass to and fro.
    auto run = [&](int k, MatchScratch& s, bool keep) {
        const int i = operations_[(size_t)k] >> 1;
        const Event& e = ev(i);
        const Admission& a = admitted_[(size_t)i];
        const int p = e.p ? 1 : 0;
        const size_t pixel = ((size_t)a.rectified.y * size_.width + a.rectified.x) * 2 + p;
        if (!(operations_[(size_t)k] & 1))
        {
            activateUndecided(e.camera, a.rectified, p, e.t);
            pendingEvents_[e.camera][pixel]++;
            return;
        }
        const bool laterPending = lookAhead_ > 0 && --pendingEvents_[e.camera][pixel] > 0;
        StereoEventEstimate est;
        est.rectified = a.rectified;
        processAdmitted(e, a.rectified, a.coldStartEnd, laterPending, s, est);
        if (keep)
            s.decided.emplace_back(i, est);
        else
            store(i, est);
    };
    std::exception_ptr failure;
    if (numThreads_ == 1 || n < MIN_EVENTS_FOR_BANDS)
    {
        try
        {
            for (int k = 0; k < count; k++)
            {
                if (operations_[(size_t)k] & 1)
                {
                    maps_[0].expireUntil(operationTimes_[(size_t)k]);
                    maps_[1].expireUntil(operationTimes_[(size_t)k]);
                }
                run(k, scratch_, false);
            }
        }
        catch (...)
        {
            failure = std::current_exception();
        }
        for (int c = 0; c < 2; c++)
            addStatusCounts(*estimators_[c], scratch_.lifetimes[c]);
    }
    else
    {
        const int conflictRows = bandConflictRows();
        const int bands = std::max(1, std::min(numThreads_, size_.height / (conflictRows + 1)));
        const std::vector<int> first = RowBandScheduler::splitRows(operationRows_, count, size_.height, bands,
                                                                   conflictRows + 1);
        const std::vector<int> segments = RowBandScheduler::splitSegments(first, size_.height, conflictRows);
        maps_[0].setRowBands(segments);
        maps_[1].setRowBands(segments);
        if (bandScratch_.size() < (size_t)bands)
        {
            bandScratch_.resize((size_t)bands);
            for (MatchScratch& s : bandScratch_)
                sizeScratch(s);
        }
        RowBandScheduler::Operations ops;
        // The segment's earliest expiry over both maps (the left map's first on a tie); the token is the map.
        ops.earliestExpiry = [this](int segment, int64& time, int& row, int& map) {
            bool found = false;
            time = std::numeric_limits<int64>::max();
            for (int c = 0; c < 2; c++)
            {
                int64 t;
                int y;
                if (maps_[c].earliestExpiry(segment, t, y) && t < time)
                {
                    map = c;
                    time = t;
                    row = y;
                    found = true;
                }
            }
            return found;
        };
        ops.expire = [this](int segment, int map) { maps_[map].expireEarliest(segment); };
        ops.process = [&](int b, int k) { run(k, bandScratch_[(size_t)b], true); };
        failure = bands_.run(first, size_.height, conflictRows, operationRows_, operationTimes_, count, ops);
        for (int b = 0; b < bands; b++)
        {
            for (const std::pair<int, StereoEventEstimate>& d : bandScratch_[(size_t)b].decided)
                store(d.first, d.second);
            bandScratch_[(size_t)b].decided.clear();
        }
        for (int b = 0; b < bands; b++)
            for (int c = 0; c < 2; c++)
                addStatusCounts(*estimators_[c], bandScratch_[(size_t)b].lifetimes[c]);
    }
    if (failure)
    {
        // Arrivals after the failure are never decided: none stays pending.
        for (std::vector<int>& pending : pendingEvents_)
            std::fill(pending.begin(), pending.end(), 0);
        std::rethrow_exception(failure);
    }
    if (badEvent)
        std::rethrow_exception(badEvent);
}

// The operations of the first `valid` admitted events, in the order one thread runs them, with their rows and
// times (the scheduler takes the expiries due before the first operation at or after their time: the single
// thread's expiries before a decision). Without look-ahead an event is decided when it arrives. With it, an
// event arrives (becomes active in its map) in stream order and is decided once an event more than
// lookAhead_ later has arrived, or at the end of the packet; an arrival carries the time of the decision
// before it, so that no expiry moves before it.
void StereoEventMatcherImpl::scheduleOperations(int valid)
{
    operations_.clear();
    operationRows_.clear();
    operationTimes_.clear();
    auto add = [&](int i, bool decide, int64 t) {
        operations_.push_back(i * 2 + (decide ? 1 : 0));
        operationRows_.push_back(admittedRows_[(size_t)i]);
        operationTimes_.push_back(t);
    };
    if (lookAhead_ == 0)
    {
        for (int i = 0; i < valid; i++)
            if (admittedRows_[(size_t)i] >= 0)
                add(i, true, times_[(size_t)i]);
        return;
    }
    // The events arrive and are decided in index order (times do not decrease): the undecided ones are the
    // events from `next` to the last arrival, those outside the image aside.
    int64 decided = std::numeric_limits<int64>::min();
    int next = 0;
    // Decides the events before `end` that are due when an event arrives at `arrival`; all of them at the end.
    auto decideUntil = [&](int end, int64 arrival, bool all) {
        for (; next < end && (all || admittedRows_[(size_t)next] < 0 || timeAfter(times_[(size_t)next], lookAhead_) < arrival);
             next++)
            if (admittedRows_[(size_t)next] >= 0)
            {
                decided = times_[(size_t)next];
                add(next, true, decided);
            }
    };
    for (int j = 0; j < valid; j++)
        if (admittedRows_[(size_t)j] >= 0)
        {
            decideUntil(j, times_[(size_t)j], false);
            add(j, false, decided);
        }
    decideUntil(valid, 0, true);
}

// ---- parameters

void StereoEventMatcherImpl::reset()
{
    const int margin = std::max(aggregationWindow_ / 2, descriptorWindow_ / 2);
    for (int c = 0; c < 2; c++)
    {
        maps_[c].configure(size_, descriptorWindow_, maxVectorLength_, margin);
        estimators_[c]->reset();
        estimateUntil_[c].assign((size_t)size_.area(), NO_ESTIMATE);
        estimateDisparity_[c].assign((size_t)size_.area(), -1.f);
        estimateBlocksPerRow_ = divUp(size_.width, (int)ESTIMATE_BLOCK);
        estimateBlockUntil_[c].assign((size_t)size_.height * estimateBlocksPerRow_, 0);
        lastEventTime_[c].assign((size_t)size_.area(), 0);
        pendingEvents_[c].assign((size_t)size_.area() * 2, 0);
    }
    frames_.configure(size_, minDisparity_, maxDisparity_, frameWindow_);
    lastTime_ = std::numeric_limits<int64>::min();
    sizeScratch(scratch_);
    scratch_.lifetimeTicks = 0;
    for (MatchScratch& s : bandScratch_)
    {
        sizeScratch(s);
        s.lifetimeTicks = 0;
    }
}

double StereoEventMatcherImpl::getLifetimeSeconds() const
{
    int64 ticks = scratch_.lifetimeTicks;
    for (const MatchScratch& s : bandScratch_)
        ticks += s.lifetimeTicks;
    return (double)ticks / getTickFrequency();
}

void StereoEventMatcherImpl::sizeScratch(MatchScratch& s) const
{
    s.matchedValues.resize((size_t)lifetimeWindow_ * lifetimeWindow_ + WINDOW_MEDIAN_PAD);
    s.matchedPositions.resize((size_t)lifetimeWindow_ * lifetimeWindow_ + WINDOW_MEDIAN_PAD);
    s.matchedKeys.resize((size_t)lifetimeWindow_ * lifetimeWindow_);
    const size_t range = (size_t)(maxDisparity_ - minDisparity_ + 1);
    s.candidates.resize(range);
    s.offsets.resize(range);
    s.cost.resize(range);
    s.seenScore.resize(range);
    s.recencyShare.resize(range);
    s.columnTimeGap.resize((size_t)size_.width);
    s.columnMass.resize((size_t)aggregationWindow_);
    s.unseenMass.resize((size_t)aggregationWindow_ + 1);
}

void StereoEventMatcherImpl::setCalibration(const StereoCalibration& calibration)
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
    for (int c = 0; c < 2; c++)
        lut_[c] = buildRectificationTable(calibration, c);
    calibration_ = calibration;
    focalBaseline_ = calibration.focalLength() * calibration.baseline();
    reset();
}

Ptr<LifetimeEstimator> StereoEventMatcherImpl::getLifetimeEstimator(int camera) const
{
    CV_CheckGE(camera, 0, "StereoEventMatcher::getLifetimeEstimator: camera is CAMERA_LEFT or CAMERA_RIGHT");
    CV_CheckLE(camera, 1, "StereoEventMatcher::getLifetimeEstimator: camera is CAMERA_LEFT or CAMERA_RIGHT");
    return estimators_[camera];
}

void StereoEventMatcherImpl::setMode(int mode)
{
    checkMode(mode);
    mode_ = mode;
    reset();
}

void StereoEventMatcherImpl::setSensorSize(Size s)
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

void StereoEventMatcherImpl::setDescriptorWindow(int n)
{
    descriptorWindow_ = oddWindow(n, 1, 15, "descriptor window");
    reset();
}

void StereoEventMatcherImpl::setMaxVectorLength(int r)
{
    if (r < 0 || r > 7)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: max vector length %d; must be 0..7 px", r));
    maxVectorLength_ = r;
    reset();
}

void StereoEventMatcherImpl::setCostWindow(int w)
{
    costWindow_ = oddWindow(w, 1, 31, "cost window");
    aggregationWindow_ = std::max(aggregationWindow_, costWindow_);
    reset();
}

void StereoEventMatcherImpl::setLifetimeWindow(int w)
{
    lifetimeWindow_ = oddWindow(w, 1, 31, "lifetime window");
    reset();
}

void StereoEventMatcherImpl::setAggregationWindow(int a)
{
    aggregationWindow_ = oddWindow(a, costWindow_, 31, "aggregation window (>= the cost window)");
    reset();
}

void StereoEventMatcherImpl::setUniquenessRatio(int u)
{
    if (u < 0 || u > 99)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: uniqueness ratio %d; must be 0..99 %%", u));
    uniquenessRatio_ = u;
}

void StereoEventMatcherImpl::setMinConfidence(double c)
{
    if (!(c >= 0 && c <= 1))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: minimum confidence %g; must be 0..1 (0: every event with a "
                                     "candidate keeps its best disparity)", c));
    minConfidence_ = c;
}

void StereoEventMatcherImpl::setMatchedLifetimeConfidence(double c)
{
    if (!(c >= 0 && c <= 1))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: matched lifetime confidence %g; must be 0..1 (0: every match "
                                     "passes its counterpart's lifetime)", c));
    matchedLifetimeConfidence_ = c;
}

void StereoEventMatcherImpl::setLifetimeCopyConfidence(double c)
{
    if (!(c >= 0 && c <= 1))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: lifetime copy confidence %g; must be 0..1 (0: every match "
                                     "passes its lifetime on)", c));
    lifetimeCopyConfidence_ = c;
}

void StereoEventMatcherImpl::setMaxLifetimeCopies(int copies)
{
    if (copies < 0 || copies > 255)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: max lifetime copies %d; must be 0..255 (0: every event "
                                     "fits its plane, 255: no limit)", copies));
    maxLifetimeCopies_ = copies;
}

void StereoEventMatcherImpl::setPriorTolerance(int percent)
{
    if (percent < 0 || percent > 1000)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: prior tolerance %d %%; must be 0..1000 %% (0: no temporal prior)", percent));
    priorTolerance_ = percent;
}

void StereoEventMatcherImpl::setRecencyWeight(int percent)
{
    if (percent < 0 || percent > 100)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: recency weight %d %%; must be 0..100 %% (0: the cost of the "
                                     "descriptors alone)", percent));
    recencyWeight_ = percent;
}

void StereoEventMatcherImpl::setRecencyTime(double us)
{
    if (!(us >= 1 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: recency time %g us; must be 1..1e6 us", us));
    recencyTime_ = (int64)std::llround(us);
}

void StereoEventMatcherImpl::setAveragingRadius(int px)
{
    // The row bands' reach covers PRIOR_RADIUS rows around an event (eventRowReach).
    if (px < 0 || px > (int)PRIOR_RADIUS)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: averaging radius %d px; must be 0..%d px (0: each event keeps "
                                     "its own estimate)", px, (int)PRIOR_RADIUS));
    averagingRadius_ = px;
}

void StereoEventMatcherImpl::setLookAhead(double us)
{
    if (!(us >= 0 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: look-ahead %g us; must be 0..1e6 us (0: each event is decided "
                                     "when it arrives)", us));
    lookAhead_ = (int64)std::llround(us);
}

void StereoEventMatcherImpl::setNoiseActiveTime(double us)
{
    if (!(us >= 0 && us <= 1e6))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: noise active time %g us; must be 0..1e6 us (0: an event "
                                     "without a lifetime is not active)", us));
    noiseActiveTime_ = (int64)std::llround(us);
}

void StereoEventMatcherImpl::setFrameWindow(double us)
{
    frameWindow_ = duration(us, "frame window");
    reset();
}

void StereoEventMatcherImpl::setActiveDistance(double px)
{
    if (!(px >= 0.1 && px <= 100))
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: active distance %g px; must be 0.1..100 px (1: active "
                                     "for one lifetime, as in the paper)", px));
    activeDistance_ = px;
}

void StereoEventMatcherImpl::setNumThreads(int threads)
{
    if (threads < 1 || threads > 64)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %d threads; must be 1..64", threads));
    numThreads_ = threads;
}

void StereoEventMatcherImpl::write(FileStorage& fs) const
{
    writeFormat(fs);
    fs << "mode" << getStereoModeName(mode_) << "sensorWidth" << size_.width << "sensorHeight" << size_.height
       << "minDisparity" << minDisparity_ << "maxDisparity" << maxDisparity_ << "descriptorWindow" << descriptorWindow_
       << "maxVectorLength" << maxVectorLength_ << "costWindow" << costWindow_ << "lifetimeWindow" << lifetimeWindow_
       << "aggregationWindow" << aggregationWindow_ << "uniquenessRatio" << uniquenessRatio_
       << "minConfidence" << minConfidence_ << "matchedLifetimeConfidence" << matchedLifetimeConfidence_
       << "lifetimeCopyConfidence" << lifetimeCopyConfidence_ << "maxLifetimeCopies" << maxLifetimeCopies_
       << "priorTolerance" << priorTolerance_ << "recencyWeight" << recencyWeight_ << "recencyTime" << (double)recencyTime_
       << "averagingRadius" << averagingRadius_ << "lookAhead" << (double)lookAhead_ << "fixedInterval" << (double)fixedInterval_
       << "frameWindow" << (double)frameWindow_ << "maxLifetime" << (double)maxLifetime_ << "activeDistance"
       << activeDistance_ << "noiseActiveTime" << (double)noiseActiveTime_;
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

void StereoEventMatcherImpl::read(const FileNode& fn)
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
    setLifetimeWindow((int)num("lifetimeWindow", lifetimeWindow_));
    setAggregationWindow((int)num("aggregationWindow", aggregationWindow_));
    setUniquenessRatio((int)num("uniquenessRatio", uniquenessRatio_));
    setMinConfidence(num("minConfidence", minConfidence_));
    setMatchedLifetimeConfidence(num("matchedLifetimeConfidence", matchedLifetimeConfidence_));
    setLifetimeCopyConfidence(num("lifetimeCopyConfidence", lifetimeCopyConfidence_));
    setMaxLifetimeCopies((int)num("maxLifetimeCopies", maxLifetimeCopies_));
    setPriorTolerance((int)num("priorTolerance", priorTolerance_));
    setRecencyWeight((int)num("recencyWeight", recencyWeight_));
    setRecencyTime(num("recencyTime", (double)recencyTime_));
    setAveragingRadius((int)num("averagingRadius", averagingRadius_));
    setLookAhead(num("lookAhead", (double)lookAhead_));
    setFixedInterval(num("fixedInterval", (double)fixedInterval_));
    setFrameWindow(num("frameWindow", (double)frameWindow_));
    setMaxLifetime(num("maxLifetime", (double)maxLifetime_));
    setActiveDistance(num("activeDistance", activeDistance_));
    setNoiseActiveTime(num("noiseActiveTime", (double)noiseActiveTime_));
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

void StereoEventMatcherImpl::checkMode(int mode)
{
    if (mode < STEREO_COUPLED || mode > STEREO_FRAME_SGBM)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: mode %d; use a StereoMatchMode (0..3)", mode));
}

int StereoEventMatcherImpl::oddWindow(int n, int lo, int hi, const char* what)
{
    if (n < lo || n > hi || n % 2 == 0)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %d; must be odd, %d..%d", what, n, lo, hi));
    return n;
}

int64 StereoEventMatcherImpl::duration(double us, const char* what)
{
    if (!(us >= 1) || us > 1e12)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: %s %g us; must be 1 us .. 1e12 us", what, us));
    return (int64)std::llround(us);
}

void StereoEventMatcherImpl::setDisparityRange(int lo, int hi)
{
    if (lo < 0 || hi < lo || hi > 1024)
        CV_Error_(Error::StsBadArg, ("StereoEventMatcher: disparity range [%d, %d]; need 0 <= min <= max <= 1024", lo, hi));
    minDisparity_ = lo;
    maxDisparity_ = hi;
    reset();
}

// See the declaration: every row an event's processing reads or writes lies within this reach.
int StereoEventMatcherImpl::eventRowReach() const
{
    return std::max({ aggregationWindow_ / 2, costWindow_ / 2, lifetimeWindow_ / 2, 1, (int)PRIOR_RADIUS,
                      expiryRowReach(), lifetimeRowReach(*estimators_[0]), lifetimeRowReach(*estimators_[1]) });
}

// ---- rendering

void StereoEventMatcherImpl::renderDisparity(double t, OutputArray image, int camera, bool colourBar) const
{
    CV_CheckGE(camera, 0, "StereoEventMatcher::renderDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
    CV_CheckLE(camera, 1, "StereoEventMatcher::renderDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
    const int barWidth = colourBar ? 56 : 0;
    image.create(size_.height, size_.width + barWidth, CV_8UC3);
    Mat img = image.getMat();
    img.setTo(Scalar::all(0));
    const Mat lut = colourLut();
    const std::vector<int64>& until = estimateUntil_[camera];
    const std::vector<float>& disparity = estimateDisparity_[camera];
    const std::vector<int64>& lastTime = lastEventTime_[camera];
    for (int y = 0; y < size_.height; y++)
    {
        Vec3b* row = img.ptr<Vec3b>(y);
        for (int x = 0; x < size_.width; x++)
        {
            const size_t i = (size_t)y * size_.width + x;
            if (until[i] == NO_ESTIMATE || !((double)lastTime[i] <= t && t < (double)until[i]))
                continue;
            row[x] = lut.at<Vec3b>(colourIndex(disparity[i]));
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

Mat StereoEventMatcherImpl::colourLut() const
{
    Mat ramp(256, 1, CV_8U), lut;
    for (int i = 0; i < 256; i++)
        ramp.at<uchar>(i) = (uchar)i;
    applyColorMap(ramp, lut, COLORMAP_JET);
    return lut;
}

int StereoEventMatcherImpl::colourIndex(float d) const
{
    const double span = std::max(1, maxDisparity_ - minDisparity_);
    return std::max(0, std::min(255, (int)std::lround((d - minDisparity_) / span * 255)));
}

}  // namespace detail

Ptr<StereoEventMatcher> StereoEventMatcher::create(Size sensorSize, int mode)
{
    return makePtr<detail::StereoEventMatcherImpl>(sensorSize, mode);
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
