// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// For the dispatched *.simd.hpp files: the name of the instruction set a copy was compiled for, in that copy's
// namespace (opt_<SET>, or cpu_baseline), so that each copy reports its own.

#ifndef OPENCV_EVENT_SRC_COMMON_SIMD_KERNEL_NAME_HPP
#define OPENCV_EVENT_SRC_COMMON_SIMD_KERNEL_NAME_HPP

#include "opencv2/core/hal/intrin.hpp"

namespace cv {
namespace event {
namespace detail {
CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN

/** "avx512", "avx2", "neon", "sse2" or "simd128": the vector unit the including copy uses. */
static inline const char* simdKernelName()
{
#if CV_SIMD512
    return "avx512";
#elif CV_SIMD256
    return "avx2";
#elif CV_NEON
    return "neon";
#elif CV_SSE2
    return "sse2";
#else
    return "simd128";
#endif
}

CV_CPU_OPTIMIZATION_NAMESPACE_END
}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_COMMON_SIMD_KERNEL_NAME_HPP
