// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_COMMON_PREFETCH_HPP
#define OPENCV_EVENT_SRC_COMMON_PREFETCH_HPP

#if defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
#include <xmmintrin.h>
#endif

namespace cv {
namespace event {
namespace detail {

/** Asks for the cache line holding `address` without waiting for it. Only a hint; a no-op where the compiler
has none. */
inline void prefetchLine(const char* address)
{
#if defined(__GNUC__)
    __builtin_prefetch(address);
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
    _mm_prefetch(address, _MM_HINT_T0);
#else
    (void)address;
#endif
}

/** Asks for the cache lines of the bytes [first, end) without waiting for them: a later read of them finds
them loaded when enough work lies in between. */
inline void prefetchRange(const void* first, const void* end)
{
    const char* const last = (const char*)end - 1;
    for (const char* b = (const char*)first; b < last; b += 64)
        prefetchLine(b);
    prefetchLine(last);  // the line of the last byte, when the step above passed over it
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_COMMON_PREFETCH_HPP
