// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_LIFETIME_LIFETIME_ESTIMATION_ROWS_HPP
#define OPENCV_EVENT_SRC_LIFETIME_LIFETIME_ESTIMATION_ROWS_HPP

#include "opencv2/event/lifetime_estimator.hpp"

#include <utility>
#include <vector>

namespace cv {
namespace event {
namespace detail {

/** The working memory of one thread of LifetimeEstimator calls: the plane fit's points and RANSAC's hypotheses,
and the status counts of the events it processed (added to the estimator's own by addStatusCounts). */
struct LifetimeScratch
{
    // The past events of the fit's window relative to the current event (px, px, ms), one array per coordinate.
    std::vector<double> x, y, t;
    // The hypotheses' planes t = a x + b y, inlier thresholds [ms] and inlier counts.
    std::vector<double> a, b, threshold;
    std::vector<int> inliers;
    double counts[4] = { 0, 0, 0, 0 };
};

/** LifetimeEstimator::processEvent and insertEvent with the caller's working memory: calls for events whose
rows are more than lifetimeRowReach() apart touch disjoint state, so StereoEventMatcher's row bands make them
from several threads at once. The estimator must come from LifetimeEstimator::create. (Internal.) */
float processEventInRows(LifetimeEstimator& estimator, const Event& e, Vec2f& flow, int& status, LifetimeScratch& scratch);
/** processEventInRows for an event matched with little confidence: its plane fit decides whether it is noise;
if it is not, it takes `matched` (the lifetime and flow of its match) instead of its plane's, counted as
LIFETIME_MATCHED. */
float processMatchedEventInRows(LifetimeEstimator& estimator, const Event& e, const std::pair<float, Vec2f>& matched,
                                Vec2f& flow, int& status, LifetimeScratch& scratch);
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
/** processEventInRows for a matched event that fits its own plane first (its match's lifetime was copied too
often, or the match is not confident enough to pass it on): where the fit finds no plane, it asks `matched` and
takes what that gives, counted as LIFETIME_MATCHED (noise when it gives nothing). */
float refitMatchedEventInRows(LifetimeEstimator& estimator, const Event& e, MatchedLifetimeSource& matched,
                              Vec2f& flow, int& status, LifetimeScratch& scratch);
void insertEventInRows(LifetimeEstimator& estimator, const Event& e, float lifetime, const Vec2f& flow,
                       LifetimeScratch& scratch);
/** Adds the scratch's status counts to the estimator's (getStatusCount) and clears them. */
void addStatusCounts(LifetimeEstimator& estimator, LifetimeScratch& scratch);
/** How many rows above and below its own an event's processEvent / insertEvent reads or writes. */
int lifetimeRowReach(const LifetimeEstimator& estimator);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_LIFETIME_LIFETIME_ESTIMATION_ROWS_HPP
