// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_LIFETIME_PLANE_INLIERS_HPP
#define OPENCV_EVENT_SRC_LIFETIME_PLANE_INLIERS_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace event {
namespace detail {

/** The plane fit's RANSAC scoring: how many past events of the window lie on each hypothesis plane. Compiled
once per instruction set (plane_inliers.simd.hpp) and chosen at run time like the stereo kernels.

`count`: for each hypothesis k < n, the number of points i < m with |a[k] x[i] + b[k] y[i] - t[i]| <=
threshold[k], into counts[k]. The points are the window's past events relative to the current one (px, px, ms),
one array per coordinate; a, b, threshold and counts hold n rounded up to PLANE_HYPOTHESES_PAD entries (the
ones past n are read and written, their values unspecified). The vector versions score several hypotheses at
once, one per lane, over the points; each lane does the scalar version's arithmetic in double precision, in its
order and with its roundings (the module is compiled without fused multiply-adds), so every version gives the
same counts. (Internal; exported for the tests.) */
enum { PLANE_HYPOTHESES_PAD = 8 };

typedef void (*PlaneInlierCountFn)(const double* x, const double* y, const double* t, int m, const double* a,
                                   const double* b, const double* threshold, int n, int* counts);

struct PlaneInlierKernels
{
    PlaneInlierCountFn count;
    const char* name;  //!< "avx512", "avx2", "sse2", "neon", "simd128" or "scalar"
};

/** The scalar kernel: the reference the tests compare the vector ones with. */
CV_EXPORTS PlaneInlierKernels scalarPlaneInlierKernels();

/** The kernels for this CPU, chosen on the first call (OPENCV_EVENT_SCALAR_KERNELS=1 forces the scalar ones). */
CV_EXPORTS const PlaneInlierKernels& planeInlierKernelsForThisCpu();

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_LIFETIME_PLANE_INLIERS_HPP
