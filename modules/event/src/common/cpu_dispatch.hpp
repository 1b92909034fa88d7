// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// CPU dispatch for the standalone build. Inside an OpenCV source build, OpenCV's own machinery compiles each
// *.simd.hpp once per instruction set (ocv_add_dispatched_file) and defines the macros below. Against an
// installed OpenCV those macros are private to OpenCV's build, so this header defines the same ones over the
// instruction sets cmake/event_cpu_dispatch.cmake compiled: the dispatched code is the same in both modes.

#ifndef OPENCV_EVENT_SRC_COMMON_CPU_DISPATCH_HPP
#define OPENCV_EVENT_SRC_COMMON_CPU_DISPATCH_HPP

#include "opencv2/core.hpp"

#ifndef __OPENCV_BUILD

#ifndef CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN
#ifdef CV_CPU_DISPATCH_MODE
#define CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN namespace __CV_CAT(opt_, CV_CPU_DISPATCH_MODE) {
#else
#define CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN namespace cpu_baseline {
#endif
#define CV_CPU_OPTIMIZATION_NAMESPACE_END }
#endif

// CV_CPU_DISPATCH(fn, args, modes...): calls the first of the modes' fn the CPU supports, the baseline last.
#define OPENCV_EVENT_DISPATCH_CHAIN(fn, args, mode, ...) __CV_EXPAND(OPENCV_EVENT_DISPATCH_CHAIN_##mode(fn, args, __VA_ARGS__))
#define OPENCV_EVENT_DISPATCH_EXPAND(fn, args, ...) __CV_EXPAND(OPENCV_EVENT_DISPATCH_CHAIN(fn, args, __VA_ARGS__))
#define CV_CPU_DISPATCH(fn, args, ...) OPENCV_EVENT_DISPATCH_EXPAND(fn, args, __VA_ARGS__, END)
#define OPENCV_EVENT_DISPATCH_CHAIN_AVX512_SKX(fn, args, mode, ...) \
    if (cv::checkHardwareSupport(CV_CPU_AVX512_SKX)) \
        return (opt_AVX512_SKX::fn args); \
    __CV_EXPAND(OPENCV_EVENT_DISPATCH_CHAIN_##mode(fn, args, __VA_ARGS__))
#define OPENCV_EVENT_DISPATCH_CHAIN_AVX2(fn, args, mode, ...) \
    if (cv::checkHardwareSupport(CV_CPU_AVX2)) \
        return (opt_AVX2::fn args); \
    __CV_EXPAND(OPENCV_EVENT_DISPATCH_CHAIN_##mode(fn, args, __VA_ARGS__))
#define OPENCV_EVENT_DISPATCH_CHAIN_BASELINE(fn, args, mode, ...) return (cpu_baseline::fn args);

#endif  // __OPENCV_BUILD

#endif  // OPENCV_EVENT_SRC_COMMON_CPU_DISPATCH_HPP
