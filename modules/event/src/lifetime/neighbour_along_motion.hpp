// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_LIFETIME_NEIGHBOUR_ALONG_MOTION_HPP
#define OPENCV_EVENT_SRC_LIFETIME_NEIGHBOUR_ALONG_MOTION_HPP

#include "opencv2/core.hpp"

#include <cmath>

namespace cv {
namespace event {
namespace detail {

/** The 8-neighbour offset an edge moving along (dx, dy) reaches next (image y down): the direction rounded to
45 degrees. False when the direction has no angle (infinite components). LifetimeEstimator predicts that
neighbour's plane, LifetimeArrivalCheck checks when it fires. */
inline bool neighbourAlongMotion(double dx, double dy, Point& offset)
{
    const double angle = std::atan2(dy, dx);
    if (!std::isfinite(angle))
        return false;
    const int k = (int)std::lround(angle / (CV_PI / 4));  // -4..4, in steps of 45 degrees
    // cos and sin of k x 45 degrees rounded to integers.
    static const int kDx[9] = { -1, -1, 0, 1, 1, 1, 0, -1, -1 }, kDy[9] = { 0, -1, -1, -1, 0, 1, 1, 1, 0 };
    offset = Point(kDx[k + 4], kDy[k + 4]);
    return true;
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_LIFETIME_NEIGHBOUR_ALONG_MOTION_HPP
