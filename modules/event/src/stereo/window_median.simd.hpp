// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The matched-window median's kernels (window_median.hpp) on OpenCV's universal intrinsics, compiled once per
// instruction set the module dispatches to and chosen at run time by window_median.cpp.
//
// The gather's cost is in its branches: a window of 9 rows holds a few dozen active events, a different number
// in each row, and a loop over each row's events mispredicts its exit. With AVX-512 each row is one compare and
// two compressions (the lifetimes, and their indices), with no branch on the data; compressing into a register
// and storing the whole vector is used rather than compressing to memory, which some CPUs run in microcode.
// Elsewhere each row's activity is a bit mask from vector compares and the events are visited bit by bit.

#include "stereo/window_median.hpp"

#include "opencv2/core/hal/intrin.hpp"

#include "common/simd_kernel_name.hpp"

#include <cstring>

namespace cv {
namespace event {
namespace detail {
CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN

/** The kernels of this instruction set (scalar ones where it has no vector unit OpenCV supports). */
WindowMedianKernels windowMedianKernels();

#ifndef CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

#if CV_SIMD

#if CV_SIMD512 && CV_AVX512_SKX
// Up to 16 lifetimes at lifetimes + index, the lanes of `lanes`: the active ones' bits to values + n and their
// indices to positions + n (a whole vector is stored each time); returns n plus their count.
static inline int gatherLanes(const float* lifetimes, int index, __mmask16 lanes, int* values, int* positions, int n)
{
    const __m512i columns = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
    const __m512 a = _mm512_maskz_loadu_ps(lanes, lifetimes + index);
    const __mmask16 active = _mm512_mask_cmp_ps_mask(lanes, a, _mm512_setzero_ps(), _CMP_GT_OQ);
    _mm512_storeu_si512(values + n, _mm512_maskz_compress_epi32(active, _mm512_castps_si512(a)));
    _mm512_storeu_si512(positions + n,
                        _mm512_maskz_compress_epi32(active, _mm512_add_epi32(_mm512_set1_epi32(index), columns)));
    return n + (int)_mm_popcnt_u32(active);
}
#endif

static int gatherWindow(const float* lifetimes, int first, int rowStep, int width, int rows, int* values,
                        int* positions)
{
    CV_DbgAssert(width <= 32);
    int n = 0;
#if CV_SIMD512 && CV_AVX512_SKX
    const __mmask16 left = (__mmask16)(width >= 16 ? 0xFFFFu : (1u << width) - 1u);
    const __mmask16 right = (__mmask16)(width > 16 ? (1u << (width - 16)) - 1u : 0u);
    for (int r = 0, index = first; r < rows; r++, index += rowStep)
    {
        n = gatherLanes(lifetimes, index, left, values, positions, n);
        if (right)
            n = gatherLanes(lifetimes, index + 16, right, values, positions, n);
    }
#else
    // First every row's activity, with no branch: the rows' loads are independent, so that their cache misses
    // (the other sensor's lifetimes are seldom cached) overlap instead of queuing behind the visits of the
    // active pixels.
    unsigned rowActive[32];
    CV_DbgAssert(rows <= 32);
    const v_float32 zero = vx_setzero_f32();
    for (int r = 0; r < rows; r++)
    {
        const float* row = lifetimes + first + r * rowStep;
        unsigned active = 0;
        int i = 0;
        for (; i + v_float32::nlanes <= width; i += v_float32::nlanes)
            active |= (unsigned)v_signmask(vx_load(row + i) > zero) << i;
        for (; i < width; i++)
            active |= (unsigned)(row[i] > 0) << i;
        rowActive[r] = active;
    }
    for (int r = 0; r < rows; r++)
    {
        const int index = first + r * rowStep;
        for (unsigned active = rowActive[r]; active != 0; active &= active - 1)
        {
            const int i = index + (int)trailingZeros32(active);
            std::memcpy(&values[n], &lifetimes[i], sizeof(int));
            positions[n++] = i;
        }
    }
#endif
    return n;
}

// The sum of v's lanes (GCC 12 warns about OpenCV's 512-bit v_reduce_sum: an uninitialised half it never reads).
static inline int laneSum(const v_int32& v)
{
#if CV_SIMD512 && CV_AVX512_SKX
    const __m256i half = _mm256_add_epi32(_mm512_extracti32x8_epi32(v.val, 0), _mm512_extracti32x8_epi32(v.val, 1));
    __m128i quarter = _mm_add_epi32(_mm256_extracti128_si256(half, 0), _mm256_extracti128_si256(half, 1));
    quarter = _mm_add_epi32(quarter, _mm_unpackhi_epi64(quarter, quarter));
    return _mm_cvtsi128_si32(_mm_add_epi32(quarter, _mm_srli_epi64(quarter, 32)));
#else
    return v_reduce_sum(v);
#endif
}

static int medianPosition(const int* values, int n, uint64* keys)
{
    CV_DbgAssert(n >= 1);
    if (n > WINDOW_MEDIAN_RANKED)
        return windowMedianPositionBySelection(values, n, keys);
    static_assert((int)v_int32::nlanes <= (int)WINDOW_MEDIAN_PAD, "the padding fills a vector");
    const int want = n / 2;
    const int padded = alignSize(n, v_int32::nlanes);
    for (int i = 0; i < n; i++)
    {
        if (i > 0 && values[i] == values[i - 1])
            continue;  // the same rank as the one before
        const v_int32 value = vx_setall_s32(values[i]);
        v_int32 below = vx_setzero_s32(), equal = vx_setzero_s32();
        for (int j = 0; j < padded; j += v_int32::nlanes)
        {
            const v_int32 other = vx_load(values + j);
            below -= v_reinterpret_as_s32(other < value);  // a true lane is -1
            equal -= v_reinterpret_as_s32(other == value);
        }
        const int less = laneSum(below);
        if (less <= want && want < less + laneSum(equal))
        {
            // The median has this value: it is the (want - less)-th with it, in position order.
            for (int j = 0, k = want - less;; j++)
                if (values[j] == values[i] && k-- == 0)
                    return j;
        }
    }
    CV_Error(Error::StsInternal, "WindowMedianKernels::medianPosition: no median (a value equal to the padding?)");
}

WindowMedianKernels windowMedianKernels()
{
    WindowMedianKernels k;
    k.gather = gatherWindow;
    k.medianPosition = medianPosition;
    k.name = simdKernelName();
    return k;
}

#else  // no vector unit

WindowMedianKernels windowMedianKernels()
{
    return scalarWindowMedianKernels();
}

#endif  // CV_SIMD

#endif  // CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

CV_CPU_OPTIMIZATION_NAMESPACE_END
}  // namespace detail
}  // namespace event
}  // namespace cv
