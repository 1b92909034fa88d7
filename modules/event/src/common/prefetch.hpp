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

/** Asks for the cache lines of the bytes [first, end) without waiting for them: a later read of them finds
them loaded when enough work lies in between. Only a hint; a no-op where the compiler has none. */
inline void prefetchRange(const void* first, const void* end)
{
    const char* const last = (const char*)end - 1;
    for (const char* b = (const char*)first; b < last; b += 64)
    {
#if defined(__GNUC__)
        __builtin_prefetch(b);
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
        _mm_prefetch(b, _MM_HINT_T0);
#endif
    }
#if defined(__GNUC__)
    __builtin_prefetch(last);  // the line of the last byte, when the step above passed over it
#elif defined(_MSC_VER) && (defined(_M_X64) || defined(_M_IX86))
    _mm_prefetch(last, _MM_HINT_T0);
#endif
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_COMMON_PREFETCH_HPP
