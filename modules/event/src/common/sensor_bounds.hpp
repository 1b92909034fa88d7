// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_COMMON_SENSOR_BOUNDS_HPP
#define OPENCV_EVENT_SRC_COMMON_SENSOR_BOUNDS_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace event {
namespace detail {

/** Whether pixel (x, y) lies on a sensor of @p size. Compared unsigned, so that negative coordinates fail the
    same single test as those past the far border. */
inline bool onSensor(int x, int y, Size size)
{
    return (unsigned)x < (unsigned)size.width && (unsigned)y < (unsigned)size.height;
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif
