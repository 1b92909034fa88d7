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

/** The colour scale of that map at time @p t within the search range: both matchers' getDisparityDisplayRange(). */
Vec2i activeDisparityDisplayRange(const ActiveEstimateMap (&sensors)[2], Size size, double t, int camera,
                                  int minDisparity, int maxDisparity, const char* caller);

/** That map colour-coded, JET over its disparityDisplayRange() within [@p minDisparity, @p maxDisparity] (blue
to red), black where there is no disparity, with a labelled colour bar on the right when @p colourBar is set:
both matchers' renderDisparity(). */
void renderDisparityMap(const Mat_<float>& disparity, int minDisparity, int maxDisparity, bool colourBar,
                        OutputArray image);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_DISPARITY_RENDERING_HPP
