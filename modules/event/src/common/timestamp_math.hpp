// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_COMMON_TIMESTAMP_MATH_HPP
#define OPENCV_EVENT_SRC_COMMON_TIMESTAMP_MATH_HPP

#include "opencv2/core.hpp"
#include <limits>

namespace cv {
namespace event {
namespace detail {

/* Timestamps are int64 microseconds and may lie anywhere in (INT64_MIN, INT64_MAX] (INT64_MIN is
EventSurface::NO_EVENT). "t + lifetime" and "t - time window" overflow near the ends of that range, which is
undefined behaviour and, in practice, turns "100 ms ago" into the far future. These clamp instead: the ends
of the range stand for "before everything" and "never". */

/** t + d for d >= 0, clamped at INT64_MAX. */
inline int64 timeAfter(int64 t, int64 d)
{
    return t > std::numeric_limits<int64>::max() - d ? std::numeric_limits<int64>::max() : t + d;
}

/** t - d for d >= 0, clamped at INT64_MIN + 1 (the earliest valid timestamp). */
inline int64 timeBefore(int64 t, int64 d)
{
    return t < std::numeric_limits<int64>::min() + 1 + d ? std::numeric_limits<int64>::min() + 1 : t - d;
}

/** a - b as a double, exact enough and without int64 overflow whatever the two timestamps. */
inline double timeDifference(int64 a, int64 b)
{
    return (a >= 0) == (b >= 0) ? (double)(a - b) : (double)a - (double)b;
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_COMMON_TIMESTAMP_MATH_HPP
