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

/** COUPLED's matched-window median: the median lifetime of the active events in a window of the other sensor,
and which event holds it (its flow goes with it). Two kernels, compiled once per instruction set
(window_median.simd.hpp) and chosen at run time like the descriptor costs:

- `gather`: the active events of a window of `rows` rows of `width` (<= 32) floats, row r starting at
  `lifetimes + first + r * rowStep`; a value > 0 is an active event's lifetime. Writes their bits to `values` and
  their indices (`first + r * rowStep + column`) to `positions`, in row-major order, and returns their count n.
  Both arrays need room for n + WINDOW_MEDIAN_PAD entries: a vector version may write a whole vector past the
  last event (the entries past n are left unspecified).
- `medianPosition`: the median of n values (n >= 1) in the order (value, position): the position of the one that
  a sort by value, ties by position, puts at n / 2. The values are positive floats' bits (they order as the
  floats do) gathered in map order, so that ties go to the same event on every platform. `values` holds
  n + WINDOW_MEDIAN_PAD entries, the ones past n set to WINDOW_MEDIAN_PAD_VALUE; `keys` has room for n (used only
  above WINDOW_MEDIAN_RANKED events). Up to that count each distinct value's rank is counted with vector
  compares: in a matched window (a few dozen events, most with the lifetime they copied from the other sensor)
  that beats a selection by partitioning, whose branches mispredict; its n^2 compares do not pay beyond it (a
  large lifetimeWindow), where the selection partitions `keys`.

All versions give the same results. (Internal; exported for the tests.) */
enum { WINDOW_MEDIAN_PAD = 16, WINDOW_MEDIAN_RANKED = 64 };
const int WINDOW_MEDIAN_PAD_VALUE = std::numeric_limits<int>::max();  // a NaN's bits: never a lifetime's

typedef int (*WindowGatherFn)(const float* lifetimes, int first, int rowStep, int width, int rows, int* values,
                              int* positions);
typedef int (*WindowMedianPositionFn)(const int* values, int n, uint64* keys);

struct WindowMedianKernels
{
    WindowGatherFn gather;
    WindowMedianPositionFn medianPosition;
    const char* name;  //!< "avx512", "avx2", "sse2", "neon", "simd128" or "scalar"
};

/** The scalar kernels: the reference the tests compare the vector ones with. */
CV_EXPORTS WindowMedianKernels scalarWindowMedianKernels();

/** The kernels for this CPU, chosen on the first call (OPENCV_EVENT_SCALAR_KERNELS=1 forces the scalar ones). */
CV_EXPORTS const WindowMedianKernels& windowMedianKernelsForThisCpu();

/** The selection above WINDOW_MEDIAN_RANKED values, which every version shares. */
CV_EXPORTS int windowMedianPositionBySelection(const int* values, int n, uint64* keys);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_WINDOW_MEDIAN_HPP
