// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_DESCRIPTOR_COST_HPP
#define OPENCV_EVENT_SRC_STEREO_DESCRIPTOR_COST_HPP

#include "opencv2/core.hpp"

namespace cv {
namespace event {
namespace detail {

/** Sum of absolute differences between two rectangles of descriptors (ZouDescriptorMap layout: 24 counts
per descriptor, packed), @p width x @p height descriptors; rows are @p aStep / @p bStep bytes apart (a step
of 0 reuses one row, e.g. a row of zeros). */
typedef unsigned (*DescriptorRectSadFn)(const uchar* a, const uchar* b, size_t aStep, size_t bStep, int width, int height);

/** For each of @p n candidates i, adds to @p sums[i] the SAD between the rectangle at @p a and the one at
@p b + @p offsets[i] (bytes), both @p width x @p height descriptors: the same rectangle of one sensor against
the candidates' rectangles of the other, which share their rows and differ by a shift along them. Returns the
rectangle's mass, its SAD against zeros (the cost of matching it against nothing); @p width is at most 32.
With @p n = 0 only the mass is computed, and @p b, @p offsets and @p sums are not read. */
typedef unsigned (*DescriptorRectSadBatchFn)(const uchar* a, const uchar* b, size_t aStep, size_t bStep,
                                         const ptrdiff_t* offsets, int n, int width, int height, unsigned* sums);

/** The DescriptorRectSadFn for this CPU, chosen on the first call: the one-rectangle kernel the SSE2 and
scalar batch kernels are built from (the matcher itself calls the batch kernel only). The AVX2 version (when
the CPU has it) is the batch kernel's one-candidate block: each row of the rectangle in 32-byte SADs into
64-bit lanes, reduced once per call; the SSE2 one does the same in 16-byte SADs; elsewhere the scalar loop.
All give the same integers. (Exported for opencv_test_event and opencv_perf_event; not public API.) */
CV_EXPORTS DescriptorRectSadFn descriptorRectSadFunction();

/** The DescriptorRectSadBatchFn for this CPU, chosen like descriptorRectSadFunction(). The AVX2 version costs
four candidates per pass over the rectangle: each descriptor of @p a is loaded once for the four, and once for
the mass, which the first pass sums too. The SSE2 and scalar versions call their one-rectangle kernel once per
candidate and once against zeros. */
CV_EXPORTS DescriptorRectSadBatchFn descriptorRectSadBatchFunction();

/** The scalar version: the reference the tests compare the SIMD ones with. */
CV_EXPORTS unsigned descriptorRectSadScalar(const uchar* a, const uchar* b, size_t aStep, size_t bStep, int width, int height);

/** Name of the version descriptorRectSadFunction() returns ("avx2", "sse2" or "scalar"), for messages. */
CV_EXPORTS const char* descriptorRectSadKernel();

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_DESCRIPTOR_COST_HPP
