// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Standalone build: declares the functions of CV_CPU_SIMD_FILENAME compiled for CV_CPU_DISPATCH_MODE (in
// namespace opt_<mode>), as OpenCV's own build does for its dispatched files. The build's generated
// *.simd_declarations.hpp includes this once per dispatched instruction set. No include guard: that is its use.

#define CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

#undef CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN
#undef CV_CPU_OPTIMIZATION_NAMESPACE_END
#define CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN namespace __CV_CAT(opt_, CV_CPU_DISPATCH_MODE) {
#define CV_CPU_OPTIMIZATION_NAMESPACE_END }

#include CV_CPU_SIMD_FILENAME

#undef CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN
#undef CV_CPU_OPTIMIZATION_NAMESPACE_END
#undef CV_CPU_DISPATCH_MODE
