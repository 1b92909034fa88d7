// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_WINDOW_MEDIAN_HPP
#define OPENCV_EVENT_SRC_STEREO_WINDOW_MEDIAN_HPP

#include "opencv2/core.hpp"

#include <limits>

namespace cv {
namespace event {
namespace detail {

/** The median of n values (n >= 1) in the order (value, position): the position of the one that a sort by value,
ties by position, puts at n / 2. COUPLED's matched-window median: the values are the window's active lifetimes
(a positive float's bits order as the float does), gathered in map order, so that ties go to the same event on
every platform.

`values` holds n + WINDOW_MEDIAN_PAD entries, the ones past n set to WINDOW_MEDIAN_PAD_VALUE; `keys` has room for
n (used only above WINDOW_MEDIAN_RANKED events). Up to that count the ranks are counted with vector compares:
in a matched window (a few dozen events, most with the lifetime they copied from the other sensor) that beats a
selection by partitioning, whose branches mispredict; its n^2 compares do not pay beyond it (a large
lifetimeWindow), where the selection partitions `keys`. (Internal; exported for the tests.) */
enum { WINDOW_MEDIAN_PAD = 4, WINDOW_MEDIAN_RANKED = 64 };
const int WINDOW_MEDIAN_PAD_VALUE = std::numeric_limits<int>::max();  // a NaN's bits: never a lifetime's
CV_EXPORTS int windowMedianPosition(const int* values, int n, uint64* keys);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_WINDOW_MEDIAN_HPP
