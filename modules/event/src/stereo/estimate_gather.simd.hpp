// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The estimate scan's kernels (estimate_gather.hpp), compiled once per instruction set the module dispatches to
// and chosen at run time by estimate_gather.cpp.
//
// A window's activity is random, so the scalar versions write every value and advance their count past the
// kept ones, with no branch on the data. The ends and the selection's values are 32-bit: AVX-512 compares 16 at
// once and compresses the kept values into a register (stored whole: compressing to memory runs in microcode on
// some CPUs); AVX2 compares 8 (the selection 4) and moves the kept values of each 4 together with a permutation
// from a table. Other instruction sets (SSE2, NEON) take the scalar versions.

#include "stereo/estimate_gather.hpp"

#include "opencv2/core/hal/intrin.hpp"

#include "common/simd_kernel_name.hpp"

#include <cmath>
#include <cstring>

namespace cv {
namespace event {
namespace detail {
CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN

/** The kernels of this instruction set (the scalar code below AVX2, under the instruction set's name). */
EstimateGatherKernels estimateGatherKernels();

#ifndef CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

// The scalar version: the reference, and the vector versions' tail.
static inline int gatherEstimatesScalar(const int32_t* until, const float* disparity, int n, int32_t t, float* out)
{
    int count = 0;
    for (int i = 0; i < n; i++)
    {
        out[count] = disparity[i];
        count += t < until[i];
    }
    return count;
}

static inline size_t valuesInRangeScalar(const float* v, size_t n, float lo, float hi, float* out)
{
    size_t count = 0;
    for (size_t i = 0; i < n; i++)
    {
        const float value = v[i];  // read before the write: out may be v
        out[count] = value;
        count += (lo <= value) & (value < hi);
    }
    return count;
}

// v as a double where `keep`, else +0, without a branch.
static inline double maskedValue(float v, bool keep)
{
    const double d = v;
    uint64 bits;
    std::memcpy(&bits, &d, sizeof(bits));
    bits &= (uint64)0 - (uint64)keep;
    double masked;
    std::memcpy(&masked, &bits, sizeof(masked));
    return masked;
}

// Four running sums, so that no addition waits on the one before.
static inline int nearSumScalar(const int32_t* until, const float* disparity, int n, int32_t t, float value,
                                float tolerance, double& sum)
{
    int count = 0;
    const auto term = [&](int i) {
        const bool near = (t < until[i]) & (std::abs(disparity[i] - value) <= tolerance);
        count += near;
        return maskedValue(disparity[i], near);
    };
    double a = 0, b = 0, c = 0, d = 0;
    int i = 0;
    for (; i + 4 <= n; i += 4)
    {
        a += term(i);
        b += term(i + 1);
        c += term(i + 2);
        d += term(i + 3);
    }
    for (; i < n; i++)
        a += term(i);
    sum += (a + b) + (c + d);
    return count;
}

#if CV_AVX512_SKX
// The first min(left, 16) lanes.
static inline __mmask16 firstLanes(size_t left)
{
    return (__mmask16)(left >= 16 ? 0xFFFFu : (1u << left) - 1u);
}

static int gatherEstimates(const int32_t* until, const float* disparity, int n, int32_t t, float* out)
{
    const __m512i time = _mm512_set1_epi32(t);
    int count = 0;
    for (int i = 0; i < n; i += 16)
    {
        const __mmask16 lanes = firstLanes((size_t)(n - i));
        const __mmask16 active = _mm512_mask_cmpgt_epi32_mask(lanes, _mm512_maskz_loadu_epi32(lanes, until + i), time);
        _mm512_storeu_ps(out + count, _mm512_maskz_compress_ps(active, _mm512_maskz_loadu_ps(lanes, disparity + i)));
        count += (int)_mm_popcnt_u32(active);
    }
    return count;
}

static size_t valuesInRange(const float* v, size_t n, float lo, float hi, float* out)
{
    const __m512 low = _mm512_set1_ps(lo), high = _mm512_set1_ps(hi);
    size_t count = 0;
    for (size_t i = 0; i < n; i += 16)
    {
        const __mmask16 lanes = firstLanes((size_t)(n - i));
        const __m512 value = _mm512_maskz_loadu_ps(lanes, v + i);
        const __mmask16 kept = _mm512_mask_cmp_ps_mask(_mm512_mask_cmp_ps_mask(lanes, value, low, _CMP_GE_OQ), value,
                                                       high, _CMP_LT_OQ);
        _mm512_storeu_ps(out + count, _mm512_maskz_compress_ps(kept, value));
        count += (size_t)_mm_popcnt_u32(kept);
    }
    return count;
}

static int nearSum(const int32_t* until, const float* disparity, int n, int32_t t, float value, float tolerance,
                   double& sum)
{
    const __m512i time = _mm512_set1_epi32(t);
    const __m512 centre = _mm512_set1_ps(value), reach = _mm512_set1_ps(tolerance);
    __m512d total = _mm512_setzero_pd();
    int count = 0;
    for (int i = 0; i < n; i += 16)
    {
        const __mmask16 lanes = firstLanes((size_t)(n - i));
        const __mmask16 active = _mm512_mask_cmpgt_epi32_mask(lanes, _mm512_maskz_loadu_epi32(lanes, until + i), time);
        const __m512 d = _mm512_maskz_loadu_ps(lanes, disparity + i);
        const __mmask16 near =
            _mm512_mask_cmp_ps_mask(active, _mm512_abs_ps(_mm512_sub_ps(d, centre)), reach, _CMP_LE_OQ);
        // (GCC 12 warns of the undefined lanes _mm512_castps512_ps256 and _mm512_cvtps_pd start from.)
        const __m256 low = _mm256_castpd_ps(_mm512_maskz_extractf64x4_pd(0xFF, _mm512_castps_pd(d), 0));
        const __m256 high = _mm256_castpd_ps(_mm512_maskz_extractf64x4_pd(0xFF, _mm512_castps_pd(d), 1));
        total = _mm512_mask_add_pd(total, (__mmask8)near, total, _mm512_maskz_cvtps_pd((__mmask8)near, low));
        total = _mm512_mask_add_pd(total, (__mmask8)(near >> 8), total,
                                   _mm512_maskz_cvtps_pd((__mmask8)(near >> 8), high));
        count += (int)_mm_popcnt_u32(near);
    }
    const __m256d half =
        _mm256_add_pd(_mm512_maskz_extractf64x4_pd(0xFF, total, 0), _mm512_maskz_extractf64x4_pd(0xFF, total, 1));
    const __m128d quarter = _mm_add_pd(_mm256_castpd256_pd128(half), _mm256_extractf128_pd(half, 1));
    sum += _mm_cvtsd_f64(_mm_add_sd(quarter, _mm_unpackhi_pd(quarter, quarter)));
    return count;
}
#elif CV_AVX2
// Per mask of 4 active lanes: the permutation that moves those lanes to the front, in order.
static const int frontOfMask[16][4] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 },
                                        { 2, 0, 0, 0 }, { 0, 2, 0, 0 }, { 1, 2, 0, 0 }, { 0, 1, 2, 0 },
                                        { 3, 0, 0, 0 }, { 0, 3, 0, 0 }, { 1, 3, 0, 0 }, { 0, 1, 3, 0 },
                                        { 2, 3, 0, 0 }, { 0, 2, 3, 0 }, { 1, 2, 3, 0 }, { 0, 1, 2, 3 } };

// Stores the lanes of `values` set in the 4-bit `kept` to out, in order (a whole vector); returns their count.
static inline int packFront(__m128 values, int kept, float* out)
{
    _mm_storeu_ps(out, _mm_permutevar_ps(values, _mm_loadu_si128((const __m128i*)frontOfMask[kept])));
    return _mm_popcnt_u32((unsigned)kept);
}

static int gatherEstimates(const int32_t* until, const float* disparity, int n, int32_t t, float* out)
{
    const __m256i time = _mm256_set1_epi32(t);
    int count = 0, i = 0;
    for (; i + 8 <= n; i += 8)
    {
        const __m256i live = _mm256_cmpgt_epi32(_mm256_loadu_si256((const __m256i*)(until + i)), time);
        const int active = _mm256_movemask_ps(_mm256_castsi256_ps(live));
        const __m256 d = _mm256_loadu_ps(disparity + i);
        count += packFront(_mm256_castps256_ps128(d), active & 15, out + count);
        count += packFront(_mm256_extractf128_ps(d, 1), active >> 4, out + count);
    }
    return count + gatherEstimatesScalar(until + i, disparity + i, n - i, t, out + count);
}

static size_t valuesInRange(const float* v, size_t n, float lo, float hi, float* out)
{
    const __m128 low = _mm_set1_ps(lo), high = _mm_set1_ps(hi);
    size_t count = 0, i = 0;
    for (; i + 4 <= n; i += 4)
    {
        const __m128 value = _mm_loadu_ps(v + i);
        const __m128 inside = _mm_and_ps(_mm_cmp_ps(value, low, _CMP_GE_OQ), _mm_cmp_ps(value, high, _CMP_LT_OQ));
        count += (size_t)packFront(value, _mm_movemask_ps(inside), out + count);
    }
    return count + valuesInRangeScalar(v + i, n - i, lo, hi, out + count);
}

static int nearSum(const int32_t* until, const float* disparity, int n, int32_t t, float value, float tolerance,
                   double& sum)
{
    const __m256i time = _mm256_set1_epi32(t);
    const __m256 centre = _mm256_set1_ps(value), reach = _mm256_set1_ps(tolerance);
    const __m256 magnitude = _mm256_castsi256_ps(_mm256_set1_epi32(0x7FFFFFFF));
    __m256d total = _mm256_setzero_pd();
    int count = 0, i = 0;
    for (; i + 8 <= n; i += 8)
    {
        const __m256i live = _mm256_cmpgt_epi32(_mm256_loadu_si256((const __m256i*)(until + i)), time);
        const __m256 d = _mm256_loadu_ps(disparity + i);
        const __m256 close = _mm256_cmp_ps(_mm256_and_ps(_mm256_sub_ps(d, centre), magnitude), reach, _CMP_LE_OQ);
        const __m256i near = _mm256_and_si256(live, _mm256_castps_si256(close));
        // each half's 32-bit lane masks widened to the 64-bit lanes of its doubles
        const __m256d nearLow = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm256_castsi256_si128(near)));
        const __m256d nearHigh = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm256_extracti128_si256(near, 1)));
        total = _mm256_add_pd(total, _mm256_and_pd(nearLow, _mm256_cvtps_pd(_mm256_castps256_ps128(d))));
        total = _mm256_add_pd(total, _mm256_and_pd(nearHigh, _mm256_cvtps_pd(_mm256_extractf128_ps(d, 1))));
        count += (int)_mm_popcnt_u32((unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(near)));
    }
    const __m128d half = _mm_add_pd(_mm256_castpd256_pd128(total), _mm256_extractf128_pd(total, 1));
    sum += _mm_cvtsd_f64(_mm_add_sd(half, _mm_unpackhi_pd(half, half)));
    return count + nearSumScalar(until + i, disparity + i, n - i, t, value, tolerance, sum);
}
#endif

EstimateGatherKernels estimateGatherKernels()
{
    EstimateGatherKernels k;
#if CV_AVX512_SKX || CV_AVX2
    k.gather = gatherEstimates;
    k.valuesInRange = valuesInRange;
    k.nearSum = nearSum;
#else
    k.gather = gatherEstimatesScalar;
    k.valuesInRange = valuesInRangeScalar;
    k.nearSum = nearSumScalar;
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
