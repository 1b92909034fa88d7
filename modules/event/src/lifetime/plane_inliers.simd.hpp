// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The plane fit's inlier count (plane_inliers.hpp) on OpenCV's universal intrinsics, compiled once per
// instruction set the module dispatches to and chosen at run time by plane_inliers.cpp.
//
// A window holds a few dozen points at most (often about ten) and RANSAC tries some twenty hypotheses, so the
// lanes run over hypotheses, not points: each point is broadcast once per group of hypotheses and every lane
// keeps its own count, with no partial vector at the end of the points and no sum across lanes per hypothesis.

#include "lifetime/plane_inliers.hpp"

#include "opencv2/core/hal/intrin.hpp"

#include "common/simd_kernel_name.hpp"

namespace cv {
namespace event {
namespace detail {
CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN

/** The kernels of this instruction set (the scalar ones where it has no double-precision vectors). */
PlaneInlierKernels planeInlierKernels();

#ifndef CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

#if CV_SIMD_64F

static void countInliers(const double* x, const double* y, const double* t, int m, const double* a, const double* b,
                         const double* threshold, int n, int* counts)
{
    const int lanes = v_float64::nlanes;
    static_assert((int)v_float64::nlanes <= (int)PLANE_HYPOTHESES_PAD, "the padding fills a vector");
    for (int k = 0; k < n; k += lanes)
    {
        const v_float64 va = vx_load(a + k), vb = vx_load(b + k), limit = vx_load(threshold + k);
        v_int64 inside = vx_setzero_s64();
        for (int i = 0; i < m; i++)
        {
            // The scalar version's order of operations: (a x + b y) - t.
            const v_float64 distance = v_abs(va * vx_setall_f64(x[i]) + vb * vx_setall_f64(y[i]) - vx_setall_f64(t[i]));
            inside -= v_reinterpret_as_s64(distance <= limit);  // a true lane is -1
        }
        int64 lane[v_float64::nlanes];
        v_store(lane, inside);
        for (int j = 0; j < lanes; j++)
            counts[k + j] = (int)lane[j];
    }
}

PlaneInlierKernels planeInlierKernels()
{
    PlaneInlierKernels k;
    k.count = countInliers;
    k.name = simdKernelName();
    return k;
}

#else  // no double-precision vectors

PlaneInlierKernels planeInlierKernels()
{
    return scalarPlaneInlierKernels();
}

#endif  // CV_SIMD_64F

#endif  // CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

CV_CPU_OPTIMIZATION_NAMESPACE_END
}  // namespace detail
}  // namespace event
}  // namespace cv
