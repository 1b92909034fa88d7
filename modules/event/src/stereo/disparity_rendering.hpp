// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_DISPARITY_RENDERING_HPP
#define OPENCV_EVENT_SRC_STEREO_DISPARITY_RENDERING_HPP

#include "stereo/active_estimate_map.hpp"

namespace cv {
namespace event {
namespace detail {

/** The estimates of sensor @p camera (of the two in @p sensors) shown at time @p t (ActiveEstimateMap::shownAt)
as a CV_32F map of @p size, -1 (StereoEventMatcher::NO_DISPARITY) where none is: both matchers'
getActiveDisparity(). @p caller names the call in the error for a camera other than 0 or 1. */
void activeDisparityMap(const ActiveEstimateMap (&sensors)[2], Size size, double t, int camera, const char* caller,
                        OutputArray disparity);

/** That map colour-coded, JET from @p range[0] (blue) to @p range[1] (red), black where there is no
disparity, with a labelled colour bar on the right when @p colourBar is set: both matchers' renderDisparity(). */
void renderDisparityMap(const Mat_<float>& disparity, Vec2i range, bool colourBar, OutputArray image);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_DISPARITY_RENDERING_HPP
