// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// StereoEventMatcher's per-event decision: admission (camera, bounds, time order, rectification), the match,
// then the event's lifetime (COUPLED's policy for a matched event in one place), its activity in the
// descriptor map and the estimate its neighbours read.

#include "precomp.hpp"
#include "common/timestamp_math.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

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

void StereoEventMatcherImpl::processAdmitted(const Event& e, Point r, int64 coldStartEnd, bool laterPending, MatchScratch& s,
                                             StereoEventEstimate& est)
{
    const int c = e.camera, p = e.p ? 1 : 0;
    Event re = e;
    re.x = (short)r.x;
    re.y = (short)r.y;
    RowBandLifetimeEstimator& estimator = *estimators_[c];

    int status = -1;
    int lifetimeCopies = 0;  // of the lifetime this event ends with (0 unless it was passed on by a match)
    if (params_.mode == STEREO_DECOUPLED)
    {
        const LifetimeTimer timer(timeLifetimes_, s.lifetimeTicks);
        est.lifetime = estimator.processEvent(re, est.flow, status, s.lifetimes[c]);
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
        if (m.confidence >= params_.minConfidence)
            est.disparity = m.disparity;
        else
            est.flags |= STEREO_AMBIGUOUS;
    }
    if (params_.mode == STEREO_COUPLED)
    {
        const LifetimeTimer timer(timeLifetimes_, s.lifetimeTicks);
        // The other sensor's matched window, whose median is taken only where it is used.
        MatchedWindow window(*this, 1 - c, m.counterpartX, r.y, p, s);
        const bool matchable = est.disparity >= 0 && m.counterpartX >= 0;
        // A lifetime copied back and forth between the sensors is never refitted while the edge changes speed (a
        // swinging limb): past maxLifetimeCopies copies the event fits its own plane first, as it does after a
        // match less confident than params_.lifetimeCopyConfidence (most often a wrong one).
        std::pair<float, Vec2f> matched;
        if (matchable && !(m.confidence < params_.lifetimeCopyConfidence) && window.get(matched)
            && window.copies < params_.maxLifetimeCopies)
        {
            lifetimeCopies = window.copies + 1;
            if (m.confidence >= params_.matchedLifetimeConfidence)
            {
                est.lifetime = matched.first;
                est.flow = matched.second;
                estimator.insertEvent(re, est.lifetime, est.flow, s.lifetimes[c]);
                status = LIFETIME_MATCHED;
            }
            else
            {
                // Every event keeps its best disparity, noise included, and noise finds some candidate: below
                // params_.matchedLifetimeConfidence the event's own plane says whether it is noise before it takes the
                // match's lifetime.
                est.lifetime = estimator.processMatchedEvent(re, matched, est.flow, status, s.lifetimes[c]);
            }
        }
        else if (matchable && m.confidence >= params_.matchedLifetimeConfidence)
        {
            // The event's own plane first; only where it finds none the matched window's median (taken here if
            // not above; an empty window leaves the event noise, as processEvent would).
            est.lifetime = estimator.refitMatchedEvent(re, window, est.flow, status, s.lifetimes[c]);
            lifetimeCopies = window.copies + 1;
        }
        else
            est.lifetime = estimator.processEvent(re, est.flow, status, s.lifetimes[c]);
    }

    int64 activeFor = 0;
    bool noiseActive = false;
    if (params_.mode == STEREO_FIXED_INTERVAL)
        activeFor = params_.fixedInterval;
    else if (est.lifetime > 0)
        activeFor = activeSpan(est.lifetime);
    else if (e.t < coldStartEnd)
    {
        // Cold start: during the plane fit's first time window the surface cannot hold the history a fit
        // needs, so a scene's first edges fail it for want of neighbours, not for being noise, and without
        // them neither sensor has anything active to match against. Such an event gets no lifetime of its
        // own but stays visible to matching as if its lifetime were the fixed interval (FIXED_INTERVAL's
        // activity, which needs no history).
        activeFor = activeSpan(params_.fixedInterval);
    }
    else
    {
        // No plane: on a weak edge, where only some pixels fire, often the edge's own event (setNoiseActiveTime).
        activeFor = params_.noiseActiveTime;
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
    if (ownDisparity >= 0 && params_.averagingRadius > 0)
        est.disparity = averagedDisparity(c, r, e.t, ownDisparity, m.counterpartX);
    float filled = 0;
    // Below minConfidence (rejected, or without a candidate) an event gets no disparity, filled or not: the
    // user asked for none rather than a guess.
    if (!(est.flags & STEREO_AMBIGUOUS) && m.confidence >= params_.minConfidence &&
        filledDisparity(c, r, e.t, s, est.disparity, m.confidence, filled))
    {
        est.disparity = filled;
        est.flags |= STEREO_FILLED;
    }
    if (est.disparity >= 0)
    {
        est.flags |= STEREO_HAS_DISPARITY;
        est.depth = input_.depthOf(est.disparity);
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
    estimates_[c].remember(r, e.t, noiseActive ? 0 : activeFor, ownDisparity);
    rememberConfident(c, r, e.t, noiseActive ? -1.f : ownDisparity, m.confidence);
}

void StereoEventMatcherImpl::activateUndecided(int c, Point r, int p, int64 t)
{
    maps_[c].activate(r.x, r.y, p, t, std::numeric_limits<int64>::max(), 0.f, Vec2f());
}

int64 StereoEventMatcherImpl::activeSpan(double lifetime) const
{
    const double span = std::min(lifetime * params_.activeDistance, (double)params_.maxLifetime);
    return std::max<int64>(1, (int64)std::llround(span));
}

Point StereoEventMatcherImpl::admit(const Event& e)
{
    const int64 previous = input_.lastTime();
    const Point r = input_.admit(e);
    // The stream starts, or resumes after a gap longer than the plane fit's time window: the surfaces hold
    // no usable history, and the cold start (processEvent) runs for one time window.
    const int64 window = (int64)std::min(estimators_[e.camera]->getTimeWindow(), 1e18);
    if (previous == std::numeric_limits<int64>::min() || e.t > timeAfter(previous, window))
        coldStartEnd_ = timeAfter(e.t, window);
    return r;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
