// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_LIFETIME_ROW_BAND_LIFETIME_ESTIMATOR_HPP
#define OPENCV_EVENT_SRC_LIFETIME_ROW_BAND_LIFETIME_ESTIMATOR_HPP

#include "opencv2/event/lifetime_estimator.hpp"

#include <utility>
#include <vector>

namespace cv {
namespace event {
namespace detail {

/** The working memory of one thread of LifetimeEstimator calls: the plane fit's points and RANSAC's hypotheses,
and the status counts of the events it processed (added to the estimator's own by addStatusCounts()). */
struct LifetimeScratch
{
    // The past events of the fit's window relative to the current event (px, px, ms), one array per coordinate.
    std::vector<double> x, y, t;
    // The hypotheses' planes t = a x + b y, inlier thresholds [ms] and inlier counts.
    std::vector<double> a, b, threshold;
    std::vector<int> inliers;
    double counts[4] = { 0, 0, 0, 0 };
    float quality = 0;  // the last event's lifetime quality (LifetimeEstimator::process)
};

/** A stereo match's lifetime and flow, asked for only when needed (a matched window's median costs a gather and
a selection). */
class MatchedLifetimeSource
{
public:
    /** The match's lifetime and flow; false when the match has none to give. */
    virtual bool get(std::pair<float, Vec2f>& matched) = 0;
protected:
    ~MatchedLifetimeSource() {}
};

/** The LifetimeEstimator that StereoEventMatcher drives: its per-event calls take the caller's working memory, so
that calls for events whose rows are more than rowReach() apart touch disjoint state, and the matcher's row bands
make them from several threads at once. LifetimeEstimator::create() makes one; the matcher hands it out as the
public LifetimeEstimator. */
class RowBandLifetimeEstimator : public LifetimeEstimator
{
public:
    using LifetimeEstimator::processEvent;
    using LifetimeEstimator::insertEvent;

    virtual float processEvent(const Event& e, Vec2f& flow, int& status, LifetimeScratch& scratch) = 0;
    /** processEvent for an event matched with little confidence: its plane fit decides whether it is noise; if
    it is not, it takes @p matched (the lifetime and flow of its match) instead of its plane's, counted as
    LIFETIME_MATCHED. */
    virtual float processMatchedEvent(const Event& e, const std::pair<float, Vec2f>& matched, Vec2f& flow,
                                      int& status, LifetimeScratch& scratch) = 0;
    /** processEvent for a matched event that fits its own plane first (its match's lifetime was copied too often,
    or the match is not confident enough to pass it on): where the fit finds no plane, it asks @p matched and
    takes what that gives, counted as LIFETIME_MATCHED (noise when it gives nothing). */
    virtual float refitMatchedEvent(const Event& e, MatchedLifetimeSource& matched, Vec2f& flow, int& status,
                                    LifetimeScratch& scratch) = 0;
    virtual void insertEvent(const Event& e, float lifetime, const Vec2f& flow, LifetimeScratch& scratch) = 0;
    /** Adds the scratch's status counts to the estimator's (getStatusCount) and clears them. */
    virtual void addStatusCounts(LifetimeScratch& scratch) = 0;
    /** How many rows above and below its own an event's processEvent / insertEvent reads or writes. */
    virtual int rowReach() const = 0;
};

Ptr<RowBandLifetimeEstimator> createRowBandLifetimeEstimator(Size sensorSize);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_LIFETIME_ROW_BAND_LIFETIME_ESTIMATOR_HPP
