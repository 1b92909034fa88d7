// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The estimate scan's kernels (estimate_gather.hpp), compiled once per instruction set the module dispatches to
// and chosen at run time by estimate_gather.cpp.
//
// A window's activity is random, so the scalar version writes every pixel's disparity and advances its count
// past the active ones, with no branch on the data. The times are 64-bit: AVX-512 compares 8 at once and
// compresses their disparities into a register (stored whole: compressing to memory runs in microcode on some
// CPUs); AVX2 compares 4 and moves their disparities together with a permutation from a table. Instruction sets
// without a 64-bit compare (SSE2, NEON's baseline here) take the scalar version.

#include "stereo/estimate_gather.hpp"

#include "opencv2/core/hal/intrin.hpp"

#include "common/simd_kernel_name.hpp"

namespace cv {
namespace event {
namespace detail {
CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN

/** The kernels of this instruction set (the scalar code where it has no 64-bit vector compare, under the
instruction set's name). */
EstimateGatherKernels estimateGatherKernels();

#ifndef CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

// The scalar version: the reference, and the vector versions' tail.
static inline int gatherEstimatesScalar(const int64* until, const float* disparity, int n, int64 t, float* out)
{
    int count = 0;
    for (int i = 0; i < n; i++)
    {
        out[count] = disparity[i];
        count += t < until[i];
    }
    return count;
}

#if CV_AVX512_SKX
static int gatherEstimates(const int64* until, const float* disparity, int n, int64 t, float* out)
{
    const __m512i time = _mm512_set1_epi64(t);
    int count = 0;
    for (int i = 0; i < n; i += 8)
    {
        const __mmask8 lanes = (__mmask8)(n - i >= 8 ? 0xFFu : (1u << (n - i)) - 1u);
        const __mmask8 active = _mm512_mask_cmpgt_epi64_mask(lanes, _mm512_maskz_loadu_epi64(lanes, until + i), time);
        _mm256_storeu_ps(out + count, _mm256_maskz_compress_ps(active, _mm256_maskz_loadu_ps(lanes, disparity + i)));
        count += (int)_mm_popcnt_u32(active);
    }
    return count;
}
#elif CV_AVX2
// Per mask of 4 active lanes: the permutation that moves those lanes to the front, in order.
static const int frontOfMask[16][4] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 },
                                        { 2, 0, 0, 0 }, { 0, 2, 0, 0 }, { 1, 2, 0, 0 }, { 0, 1, 2, 0 },
                                        { 3, 0, 0, 0 }, { 0, 3, 0, 0 }, { 1, 3, 0, 0 }, { 0, 1, 3, 0 },
                                        { 2, 3, 0, 0 }, { 0, 2, 3, 0 }, { 1, 2, 3, 0 }, { 0, 1, 2, 3 } };

static int gatherEstimates(const int64* until, const float* disparity, int n, int64 t, float* out)
{
    const __m256i time = _mm256_set1_epi64x(t);
    int count = 0, i = 0;
    for (; i + 4 <= n; i += 4)
    {
        const __m256i live = _mm256_cmpgt_epi64(_mm256_loadu_si256((const __m256i*)(until + i)), time);
        const int active = _mm256_movemask_pd(_mm256_castsi256_pd(live));
        const __m128i order = _mm_loadu_si128((const __m128i*)frontOfMask[active]);
        _mm_storeu_ps(out + count, _mm_permutevar_ps(_mm_loadu_ps(disparity + i), order));
        count += (int)_mm_popcnt_u32((unsigned)active);
    }
    return count + gatherEstimatesScalar(until + i, disparity + i, n - i, t, out + count);
}
#endif

EstimateGatherKernels estimateGatherKernels()
{
    EstimateGatherKernels k;
#if CV_AVX512_SKX || CV_AVX2
    k.gather = gatherEstimates;
#else
    k.gather = gatherEstimatesScalar;
#endif
#if CV_SIMD
    k.name = simdKernelName();
#else
    k.name = "scalar";
#endif
    return k;
}

#endif  // CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

CV_CPU_OPTIMIZATION_NAMESPACE_END
}  // namespace detail
}  // namespace event
}  // namespace cv
