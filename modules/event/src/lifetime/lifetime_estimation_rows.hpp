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

/** A past event of the plane fit's window, relative to the current event: px, px, ms. */
struct SurfacePoint
{
    double x, y, t;
};

/** The working memory of one thread of LifetimeEstimator calls: RANSAC's point list and the status counts
of the events it processed (added to the estimator's own by addStatusCounts). */
struct LifetimeScratch
{
    std::vector<SurfacePoint> points;
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
/** processEventInRows for a matched event whose match's lifetime has been copied too often: its own plane first;
where the fit finds none, it takes `matched` instead, counted as LIFETIME_MATCHED. */
float refitMatchedEventInRows(LifetimeEstimator& estimator, const Event& e, const std::pair<float, Vec2f>& matched,
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
