// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_RECTIFICATION_TABLE_HPP
#define OPENCV_EVENT_SRC_STEREO_RECTIFICATION_TABLE_HPP

#include "opencv2/event/stereo_calibration.hpp"

#include <vector>

namespace cv {
namespace event {
namespace detail {

/** Per raw pixel (y * width + x) of sensor @p camera, the index of its rectified pixel, rounded to the
nearest, or -1 when it falls outside the calibration's image: the matcher's per-event lookup. */
std::vector<int> buildRectificationTable(const StereoCalibration& calibration, int camera);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_RECTIFICATION_TABLE_HPP
