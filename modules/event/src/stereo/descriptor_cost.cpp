// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "stereo/descriptor_cost.hpp"
#include "stereo/zou_descriptor_map.hpp"

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GNUC__)
#include <immintrin.h>
#define OPENCV_EVENT_X86_KERNELS 1
#endif

namespace cv {
namespace event {
namespace detail {

// Descriptors are packed (24 bytes each, no padding). A SAD over a rectangle is a sum over its bytes, whatever
// descriptor each byte belongs to, so each row of the rectangle is one run of width x 24 bytes, taken in
// 32-byte (AVX2) or 16-byte (SSE2) chunks with a shorter tail: 24 bytes is a multiple of 8, so the tail is
// 8, 16 or 24 bytes and is loaded in 64-bit lanes, never past the rectangle.
enum { DESCRIPTOR_BYTES = ZouDescriptorMap::DESCRIPTOR_BYTES };

unsigned descriptorRectSadScalar(const uchar* a, const uchar* b, size_t aStep, size_t bStep, int width, int height)
{
    unsigned sum = 0;
    for (int y = 0; y < height; y++, a += aStep, b += bStep)
        for (int x = 0; x < width * DESCRIPTOR_BYTES; x++)
            sum += (unsigned)std::abs((int)a[x] - (int)b[x]);
    return sum;
}

// A batch kernel from a one-rectangle kernel: one call per candidate, and one against a row of zeros for the
// mass (the scalar and SSE2 versions).
template <DescriptorRectSadFn rectSad>
static unsigned rectSadEachCandidate(const uchar* a, const uchar* b, size_t aStep, size_t bStep, const ptrdiff_t* offsets,
                                     int n, int width, int height, unsigned* sums)
{
    static const uchar zeros[32 * DESCRIPTOR_BYTES] = { 0 };
    CV_DbgAssert(width <= 32);
    for (int i = 0; i < n; i++)
        sums[i] += rectSad(a, b + offsets[i], aStep, bStep, width, height);
    return rectSad(a, zeros, aStep, 0, width, height);
}

#ifdef OPENCV_EVENT_X86_KERNELS

static unsigned rectSadSse2(const uchar* a, const uchar* b, size_t aStep, size_t bStep, int width, int height)
{
    __m128i acc = _mm_setzero_si128();
    const int bytes = width * DESCRIPTOR_BYTES, full = bytes & ~15;
    for (int y = 0; y < height; y++, a += aStep, b += bStep)
    {
        for (int x = 0; x < full; x += 16)
            acc = _mm_add_epi64(acc, _mm_sad_epu8(_mm_loadu_si128((const __m128i*)(a + x)),
                                                  _mm_loadu_si128((const __m128i*)(b + x))));
        if (full < bytes)  // 8 bytes left
            acc = _mm_add_epi64(acc, _mm_sad_epu8(_mm_loadl_epi64((const __m128i*)(a + full)),
                                                  _mm_loadl_epi64((const __m128i*)(b + full))));
    }
    return (unsigned)(_mm_cvtsi128_si32(acc) + _mm_cvtsi128_si32(_mm_unpackhi_epi64(acc, acc)));
}

// The sum of the four 64-bit lanes (SAD totals fit 32 bits: windows are at most 32 x 32 descriptors).
__attribute__((target("avx2"))) static inline unsigned sumLanesAvx2(__m256i v)
{
    const __m128i s = _mm_add_epi64(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    return (unsigned)(_mm_cvtsi128_si32(s) + _mm_cvtsi128_si32(_mm_unpackhi_epi64(s, s)));
}

// K candidates in one pass over the rectangle: each descriptor of a is loaded once and compared with the K
// candidates' descriptors, one accumulator (4 x 64-bit lanes) per candidate. With MASS, also the SAD of a
// against zeros (its mass), returned; K may then be 0. CHUNKS is the number of full 32-byte chunks per row when
// known at compile time (then the row is unrolled), -1 otherwise. The candidates' offsets stay in registers and
// address from one row pointer, so a row advances one pointer per side, not one per candidate.
template <int K, bool MASS, int CHUNKS>
__attribute__((target("avx2"))) static inline unsigned rectSadBlockAvx2(const uchar* a, const uchar* b, size_t aStep,
                                                                       size_t bStep, const ptrdiff_t* offsets,
                                                                       int width, int height, unsigned* sums)
{
    const __m256i zero = _mm256_setzero_si256();
    __m256i acc[K > 0 ? K : 1], accMass = zero;
    ptrdiff_t off[K > 0 ? K : 1];
    for (int k = 0; k < K; k++)
    {
        acc[k] = zero;
        off[k] = offsets[k];
    }
    const int bytes = width * DESCRIPTOR_BYTES, full = CHUNKS >= 0 ? CHUNKS * 32 : bytes & ~31;
    // The tail's 64-bit lanes: 1, 2 or 3 of the 4 (none when the row is a multiple of 32 bytes).
    const __m256i tail = _mm256_cmpgt_epi64(_mm256_set1_epi64x((bytes - full) / 8), _mm256_setr_epi64x(0, 1, 2, 3));
    for (int y = 0; y < height; y++, a += aStep)
    {
        for (int x = 0; x < full; x += 32)
        {
            const __m256i s = _mm256_loadu_si256((const __m256i*)(a + x));
            if (MASS)
                accMass = _mm256_add_epi64(accMass, _mm256_sad_epu8(s, zero));
            for (int k = 0; k < K; k++)
                acc[k] = _mm256_add_epi64(acc[k], _mm256_sad_epu8(s, _mm256_loadu_si256((const __m256i*)(b + off[k] + x))));
        }
        if (full < bytes)
        {
            // Masked-off lanes read as zero on both sides and are not accessed.
            const __m256i s = _mm256_maskload_epi64((const long long*)(a + full), tail);
            if (MASS)
                accMass = _mm256_add_epi64(accMass, _mm256_sad_epu8(s, zero));
            for (int k = 0; k < K; k++)
                acc[k] = _mm256_add_epi64(
                    acc[k], _mm256_sad_epu8(s, _mm256_maskload_epi64((const long long*)(b + off[k] + full), tail)));
        }
        if (K > 0)  // without candidates (the mass alone) b may be null
            b += bStep;
    }
    for (int k = 0; k < K; k++)
        sums[k] += sumLanesAvx2(acc[k]);
    return MASS ? sumLanesAvx2(accMass) : 0u;
}

// One rectangle against another: the block with one candidate at offset 0.
__attribute__((target("avx2"))) static unsigned rectSadAvx2(const uchar* a, const uchar* b, size_t aStep, size_t bStep,
                                                            int width, int height)
{
    const ptrdiff_t offset = 0;
    unsigned sum = 0;
    rectSadBlockAvx2<1, false, -1>(a, b, aStep, bStep, &offset, width, height, &sum);
    return sum;
}

// All candidates, four at a time; the first block also sums the mass, so that a's descriptors are read once for
// it too.
template <int CHUNKS>
__attribute__((target("avx2"))) static unsigned rectSadBatchBlocksAvx2(const uchar* a, const uchar* b, size_t aStep,
                                                                        size_t bStep, const ptrdiff_t* offsets, int n,
                                                                        int width, int height, unsigned* sums)
{
    int i = n >= 4 ? 4 : n >= 2 ? 2 : n;  // candidates in the first block
    unsigned mass = 0;
    switch (i)
    {
    case 4: mass = rectSadBlockAvx2<4, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums); break;
    case 2: mass = rectSadBlockAvx2<2, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums); break;
    case 1: mass = rectSadBlockAvx2<1, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums); break;
    default: return rectSadBlockAvx2<0, true, CHUNKS>(a, b, aStep, bStep, offsets, width, height, sums);
    }
    for (; i + 4 <= n; i += 4)
        rectSadBlockAvx2<4, false, CHUNKS>(a, b, aStep, bStep, offsets + i, width, height, sums + i);
    if (i + 2 <= n)
    {
        rectSadBlockAvx2<2, false, CHUNKS>(a, b, aStep, bStep, offsets + i, width, height, sums + i);
        i += 2;
    }
    if (i < n)
        rectSadBlockAvx2<1, false, CHUNKS>(a, b, aStep, bStep, offsets + i, width, height, sums + i);
    return mass;
}

// The default 9 x 9 cost window's rows (216 bytes: six chunks and a 24-byte tail) get an unrolled row; a
// one-descriptor column of an aggregation ring (a tail alone) has no chunk loop at all.
__attribute__((target("avx2"))) static unsigned rectSadBatchAvx2(const uchar* a, const uchar* b, size_t aStep,
                                                                 size_t bStep, const ptrdiff_t* offsets, int n,
                                                                 int width, int height, unsigned* sums)
{
    switch (width * DESCRIPTOR_BYTES / 32)
    {
    case 0: return rectSadBatchBlocksAvx2<0>(a, b, aStep, bStep, offsets, n, width, height, sums);
    case 6: return rectSadBatchBlocksAvx2<6>(a, b, aStep, bStep, offsets, n, width, height, sums);
    default: return rectSadBatchBlocksAvx2<-1>(a, b, aStep, bStep, offsets, n, width, height, sums);
    }
}

struct Kernel
{
    DescriptorRectSadFn fn;
    DescriptorRectSadBatchFn batch;
    const char* name;
};

// Chosen on first use (not during static initialisation, when OpenCV's CPU detection may not have run yet),
// with OpenCV's own detection, so that OPENCV_CPU_DISABLE=AVX2 also turns the AVX2 version off.
static const Kernel& kernel()
{
    static const Kernel k = cv::checkHardwareSupport(CV_CPU_AVX2) ? Kernel{ rectSadAvx2, rectSadBatchAvx2, "avx2" }
                                                                  : Kernel{ rectSadSse2, rectSadEachCandidate<rectSadSse2>, "sse2" };
    return k;
}

DescriptorRectSadFn descriptorRectSadFunction()
{
    return kernel().fn;
}

DescriptorRectSadBatchFn descriptorRectSadBatchFunction()
{
    return kernel().batch;
}

const char* descriptorRectSadKernel()
{
    return kernel().name;
}

#else

DescriptorRectSadFn descriptorRectSadFunction()
{
    return descriptorRectSadScalar;
}

DescriptorRectSadBatchFn descriptorRectSadBatchFunction()
{
    return rectSadEachCandidate<descriptorRectSadScalar>;
}

const char* descriptorRectSadKernel()
{
    return "scalar";
}

#endif

}  // namespace detail
}  // namespace event
}  // namespace cv
