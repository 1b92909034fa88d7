// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_COMMON_OPTIONAL_OUTPUT_HPP
#define OPENCV_EVENT_SRC_COMMON_OPTIONAL_OUTPUT_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace event {
namespace detail {

/** A per-event output the caller may leave out (noArray()): created as @p rows x @p cols of T and returned
when asked for, empty otherwise, so that the loop filling it tests empty() once per output. */
template <typename T>
Mat_<T> optionalOutput(OutputArray output, int rows, int cols = 1)
{
    if (!output.needed())
        return Mat_<T>();
    output.create(rows, cols, traits::Type<T>::value);
    return output.getMat();
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_COMMON_OPTIONAL_OUTPUT_HPP
