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

/** The cost kernels of one instruction set. The vector versions (descriptor_cost.simd.hpp, on OpenCV's
universal intrinsics) cost four candidates per pass over the rectangle, each descriptor of @p a loaded once
for the four and once for the mass; all versions give the same integers. */
struct DescriptorCostKernels
{
    enum { DESCRIPTOR_BYTES = 24 };  //!< ZouDescriptorMap::DESCRIPTOR_BYTES
    DescriptorRectSadFn rectSad;
    DescriptorRectSadBatchFn rectSadBatch;
    const char* name;  //!< "avx512", "avx2", "sse2", "neon", "simd128" or "scalar"
};

/** The scalar kernels: the reference the tests compare the vector ones with. */
DescriptorCostKernels scalarDescriptorCostKernels();

/** The kernels for this CPU, chosen on the first call among the instruction sets the module was built for,
with OpenCV's CPU detection (OPENCV_CPU_DISABLE=AVX2 turns the AVX2 version off); the environment variable
OPENCV_EVENT_SCALAR_KERNELS=1 forces the scalar ones. (Exported for opencv_test_event and opencv_perf_event;
not public API.) */
CV_EXPORTS const DescriptorCostKernels& descriptorCostKernelsForThisCpu();

/** descriptorCostKernelsForThisCpu().rectSad: the one-rectangle kernel. */
CV_EXPORTS DescriptorRectSadFn descriptorRectSadFunction();

/** descriptorCostKernelsForThisCpu().rectSadBatch: the kernel the matcher calls. */
CV_EXPORTS DescriptorRectSadBatchFn descriptorRectSadBatchFunction();

/** The scalar one-rectangle kernel. */
CV_EXPORTS unsigned descriptorRectSadScalar(const uchar* a, const uchar* b, size_t aStep, size_t bStep, int width, int height);

/** Name of the kernels descriptorCostKernelsForThisCpu() returns, for messages. */
CV_EXPORTS const char* descriptorRectSadKernel();

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_DESCRIPTOR_COST_HPP
