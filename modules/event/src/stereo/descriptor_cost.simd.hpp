// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The descriptor cost kernels on OpenCV's universal intrinsics, compiled once per instruction set the module
// dispatches to (the baseline: SSE2 on x86-64, NEON on AArch64; plus AVX2 and AVX-512 on x86-64) and chosen at
// run time by descriptor_cost.cpp.
//
// Descriptors are packed (24 bytes each, no padding). A SAD over a rectangle is a sum over its bytes, whatever
// descriptor each byte belongs to, so each row of the rectangle is one run of width x 24 bytes, taken in
// full-width chunks with a shorter tail: 24 bytes is a multiple of 8, so the tail is a multiple of 8 bytes. It is
// taken in one masked load with AVX2 and AVX-512, in 16- and 8-byte loads elsewhere; never past the rectangle.

#include "stereo/descriptor_cost.hpp"

#include "opencv2/core/hal/intrin.hpp"

#include "common/simd_kernel_name.hpp"

namespace cv {
namespace event {
namespace detail {
CV_CPU_OPTIMIZATION_NAMESPACE_BEGIN

/** The kernels of this instruction set (scalar ones where it has no vector unit OpenCV supports). */
DescriptorCostKernels descriptorCostKernels();

#ifndef CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

#if CV_SIMD

// acc + the SAD of a and b, in the accumulator's lanes (the lanes' total is the running SAD; a lane never
// exceeds 32 bits for windows up to 32 x 32 descriptors). Where the instruction set has a SAD instruction it
// sums 8 bytes into a 64-bit lane, whose upper half stays zero; elsewhere the absolute differences are summed
// by a dot product with ones.
inline v_uint32 sadAdd(const v_uint8& a, const v_uint8& b, const v_uint32& acc)
{
#if CV_SIMD512 && CV_AVX512_SKX
    return v_uint32(_mm512_add_epi64(acc.val, _mm512_sad_epu8(a.val, b.val)));
#elif CV_SIMD256 && CV_AVX2
    return v_uint32(_mm256_add_epi64(acc.val, _mm256_sad_epu8(a.val, b.val)));
#elif !CV_SIMD256 && !CV_SIMD512 && CV_SSE2
    return v_uint32(_mm_add_epi64(acc.val, _mm_sad_epu8(a.val, b.val)));
#elif !CV_SIMD256 && !CV_SIMD512 && CV_NEON
    return v_uint32(vpadalq_u16(acc.val, vpaddlq_u8(vabdq_u8(a.val, b.val))));
#else
    return v_dotprod_expand_fast(v_absdiff(a, b), vx_setall_u8(1), acc);
#endif
}

// The same for the 16-byte tail chunks.
inline v_uint32x4 sadAdd16(const v_uint8x16& a, const v_uint8x16& b, const v_uint32x4& acc)
{
#if CV_SSE2
    return v_uint32x4(_mm_add_epi64(acc.val, _mm_sad_epu8(a.val, b.val)));
#elif CV_NEON
    return v_uint32x4(vpadalq_u16(acc.val, vpaddlq_u8(vabdq_u8(a.val, b.val))));
#else
    return v_dotprod_expand_fast(v_absdiff(a, b), v_setall_u8(1), acc);
#endif
}

// 8 bytes at p in the low half, zeros in the high half (v_load_low leaves the high half unspecified).
inline v_uint8x16 load8(const uchar* p)
{
    return v_combine_low(v_load_low(p), v_setzero_u8());
}

// A row's tail (its last bytes after the full chunks, fewer than a vector) in one load where the instruction set
// has masked loads (AVX2 by 8-byte lanes, AVX-512 by bytes): the lanes past the tail read as zeros and are never
// touched in memory, so they add nothing to a SAD. A one-descriptor column then costs one load and one SAD per
// row and candidate instead of a 16- and an 8-byte one.
#if CV_SIMD512 && CV_AVX512_SKX
#define OPENCV_EVENT_MASKED_TAIL 1
struct TailMask
{
    __mmask64 bytes;
    explicit TailMask(int n) : bytes(n >= 64 ? ~(__mmask64)0 : (((__mmask64)1 << n) - 1)) {}
};
inline v_uint8 loadTail(const uchar* p, const TailMask& m)
{
    return v_uint8(_mm512_maskz_loadu_epi8(m.bytes, p));
}
#elif CV_SIMD256 && CV_AVX2
#define OPENCV_EVENT_MASKED_TAIL 1
struct TailMask
{
    __m256i lanes;  // all ones in the 8-byte lanes the tail covers (its length is a multiple of 8)
    explicit TailMask(int n) : lanes(_mm256_cmpgt_epi64(_mm256_set1_epi64x(n / 8), _mm256_setr_epi64x(0, 1, 2, 3))) {}
};
inline v_uint8 loadTail(const uchar* p, const TailMask& m)
{
    return v_uint8(_mm256_maskload_epi64((const long long*)p, m.lanes));
}
#else
#define OPENCV_EVENT_MASKED_TAIL 0
#endif

#if OPENCV_EVENT_MASKED_TAIL
// The total of a vector's 64-bit lanes.
inline uint64 laneSum64(const v_uint64& v)
{
#if CV_SIMD512
    const __m256i half = _mm256_add_epi64(_mm512_castsi512_si256(v.val), _mm512_extracti64x4_epi64(v.val, 1));
#else
    const __m256i half = v.val;
#endif
    const __m128i quarter = _mm_add_epi64(_mm256_castsi256_si128(half), _mm256_extracti128_si256(half, 1));
    return (uint64)_mm_cvtsi128_si64(_mm_add_epi64(quarter, _mm_unpackhi_epi64(quarter, quarter)));
}

// The totals of two SAD accumulators in one reduction: a SAD lands in the low half of a 64-bit lane and a
// rectangle's total stays below 2^32 (at most 32 x 32 descriptors of 24 counts up to 255), so b's lanes moved
// into the upper halves add to a's without a carry between them.
inline void addLaneSums(const v_uint32& a, const v_uint32& b, unsigned& sumA, unsigned& sumB)
{
    const uint64 both = laneSum64(v_reinterpret_as_u64(a) + v_shl<32>(v_reinterpret_as_u64(b)));
    sumA += (unsigned)both;
    sumB += (unsigned)(both >> 32);
}
#endif

enum
{
    LANES = v_uint8::nlanes,
    DESCRIPTOR_BYTES = DescriptorCostKernels::DESCRIPTOR_BYTES,
    // Full chunks of a row of the default 17 x 17 cost window, and of an aggregation ring's one-descriptor column:
    // the two row shapes the matcher uses most, unrolled at compile time.
    WINDOW_ROW_CHUNKS = 17 * DESCRIPTOR_BYTES / LANES,
    COLUMN_CHUNKS = DESCRIPTOR_BYTES / LANES
};

// K candidates in one pass over the rectangle: each descriptor of a is loaded once and compared with the K
// candidates' descriptors, one accumulator per candidate. With MASS, also the SAD of a against zeros (its
// mass), returned; K may then be 0 and b null. CHUNKS is the number of full chunks per row when known at
// compile time (then the row is unrolled), -1 otherwise. The candidates' offsets stay in registers and address
// from one row pointer, so a row advances one pointer per side, not one per candidate.
template <int K, bool MASS, int CHUNKS>
static inline unsigned rectSadBlock(const uchar* a, const uchar* b, size_t aStep, size_t bStep, const ptrdiff_t* offsets,
                                    int width, int height, unsigned* sums)
{
    const v_uint8 zero = vx_setzero_u8();
    v_uint32 acc[K > 0 ? K : 1], accMass = vx_setzero_u32();
    ptrdiff_t off[K > 0 ? K : 1];
    for (int k = 0; k < K; k++)
    {
        acc[k] = vx_setzero_u32();
        off[k] = offsets[k];
    }
    const int bytes = width * DESCRIPTOR_BYTES, full = CHUNKS >= 0 ? CHUNKS * LANES : bytes - bytes % LANES;
    const int rest = bytes - full;  // a multiple of 8, below LANES
#if OPENCV_EVENT_MASKED_TAIL
    const TailMask tailMask(rest);
#else
    const v_uint8x16 zero16 = v_setzero_u8();
    v_uint32x4 tail[K > 0 ? K : 1], tailMass = v_setzero_u32();
    for (int k = 0; k < K; k++)
        tail[k] = v_setzero_u32();
#endif
    for (int y = 0; y < height; y++, a += aStep)
    {
        for (int x = 0; x < full; x += LANES)
        {
            const v_uint8 s = vx_load(a + x);
            if (MASS)
                accMass = sadAdd(s, zero, accMass);
            for (int k = 0; k < K; k++)
                acc[k] = sadAdd(s, vx_load(b + off[k] + x), acc[k]);
        }
#if OPENCV_EVENT_MASKED_TAIL
        if (rest > 0)
        {
            const v_uint8 s = loadTail(a + full, tailMask);
            if (MASS)
                accMass = sadAdd(s, zero, accMass);
            for (int k = 0; k < K; k++)
                acc[k] = sadAdd(s, loadTail(b + off[k] + full, tailMask), acc[k]);
        }
#else
        int x = full;
        for (; x + 16 <= full + rest; x += 16)
        {
            const v_uint8x16 s = v_load(a + x);
            if (MASS)
                tailMass = sadAdd16(s, zero16, tailMass);
            for (int k = 0; k < K; k++)
                tail[k] = sadAdd16(s, v_load(b + off[k] + x), tail[k]);
        }
        if (x < full + rest)  // 8 bytes left
        {
            const v_uint8x16 s = load8(a + x);
            if (MASS)
                tailMass = sadAdd16(s, zero16, tailMass);
            for (int k = 0; k < K; k++)
                tail[k] = sadAdd16(s, load8(b + off[k] + x), tail[k]);
        }
#endif
        if (K > 0)  // without candidates (the mass alone) b may be null
            b += bStep;
    }
#if OPENCV_EVENT_MASKED_TAIL
    // The accumulators are reduced in pairs, the last odd one with the mass (zero without MASS).
    int k = 0;
    for (; k + 1 < K; k += 2)
        addLaneSums(acc[k], acc[k + 1], sums[k], sums[k + 1]);
    unsigned mass = 0, last = 0;
    addLaneSums(accMass, k < K ? acc[k] : accMass, mass, last);
    if (k < K)
        sums[k] += last;
    return mass;
#else
    for (int k = 0; k < K; k++)
        sums[k] += v_reduce_sum(acc[k]) + v_reduce_sum(tail[k]);
    return MASS ? v_reduce_sum(accMass) + v_reduce_sum(tailMass) : 0u;
#endif
}

// One rectangle against another: the block with one candidate at offset 0.
static unsigned rectSad(const uchar* a, const uchar* b, size_t aStep, size_t bStep, int width, int height)
{
    const ptrdiff_t offset = 0;
    unsigned sum = 0;
    rectSadBlock<1, false, -1>(a, b, aStep, bStep, &offset, width, height, &sum);
    return sum;
}

// All candidates, four at a time; the first block also sums the mass, so that a's descriptors are read once for
// it too.
template <int CHUNKS>
static unsigned rectSadBatchBlocks(const uchar* a, const uchar* b, size_t aStep, size_t bStep, const ptrdiff_t* offsets,
                                   int n, int width, int height, unsigned* sums)
{
    int i = n >= 4 ? 4 : n >= 2 ? 2 : n;  // candidates in the first block
    unsigned mass = 0;
    switch (i)
    {
    case 4: mass = rectSadBlock<4, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums); break;
    case 2: mass = rectSadBlock<2, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums); break;
    case 1: mass = rectSadBlock<1, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums); break;
    default: return rectSadBlock<0, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums);
    }
    for (; i + 4 <= n; i += 4)
        rectSadBlock<4, false, CHUNKS>(a, b, aStep, bStep, offsets + i, width, height, sums + i);
    if (i + 2 <= n)
    {
        rectSadBlock<2, false, CHUNKS>(a, b, aStep, bStep, offsets + i, width, height, sums + i);
        i += 2;
    }
    if (i < n)
        rectSadBlock<1, false, CHUNKS>(a, b, aStep, bStep, offsets + i, width, height, sums + i);
    return mass;
}

static unsigned rectSadBatch(const uchar* a, const uchar* b, size_t aStep, size_t bStep, const ptrdiff_t* offsets, int n,
                             int width, int height, unsigned* sums)
{
    const int chunks = width * DESCRIPTOR_BYTES / LANES;
    if (chunks == WINDOW_ROW_CHUNKS)
        return rectSadBatchBlocks<WINDOW_ROW_CHUNKS>(a, b, aStep, bStep, offsets, n, width, height, sums);
    if (chunks == COLUMN_CHUNKS)
        return rectSadBatchBlocks<COLUMN_CHUNKS>(a, b, aStep, bStep, offsets, n, width, height, sums);
    return rectSadBatchBlocks<-1>(a, b, aStep, bStep, offsets, n, width, height, sums);
}

DescriptorCostKernels descriptorCostKernels()
{
    DescriptorCostKernels k;
    k.rectSad = rectSad;
    k.rectSadBatch = rectSadBatch;
    k.name = simdKernelName();
    return k;
}

#else  // no vector unit

DescriptorCostKernels descriptorCostKernels()
{
    return scalarDescriptorCostKernels();
}

#endif  // CV_SIMD

#endif  // CV_CPU_OPTIMIZATION_DECLARATIONS_ONLY

CV_CPU_OPTIMIZATION_NAMESPACE_END
}  // namespace detail
}  // namespace event
}  // namespace cv
