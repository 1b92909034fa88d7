// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_ESTIMATE_GATHER_HPP
#define OPENCV_EVENT_SRC_STEREO_ESTIMATE_GATHER_HPP

#include "opencv2/core.hpp"

#include <cstdint>

namespace cv {
namespace event {
namespace detail {

/** ActiveEstimateMap's window scan, one run of a row at a time: the disparities of the pixels i < n whose
estimate is active at t (t < until[i]; the ends and t as offsets from a time of the row), in order, to out;
returns their count. `out` needs room for the count plus ESTIMATE_GATHER_PAD entries: a vector version stores
whole vectors (the entries past the count are left unspecified). Compiled once per instruction set
(estimate_gather.simd.hpp) and chosen at run time like the descriptor costs; all versions give the same
results. (Internal; exported for the tests.) */
enum { ESTIMATE_GATHER_PAD = 16 };

typedef int (*EstimateGatherFn)(const int32_t* until, const float* disparity, int n, int32_t t, float* out);

/** The median's selection (ActiveEstimateMap): the values v[i], i < n, with lo <= v[i] < hi, in order, to out;
returns their count. `out` needs room for the count plus VALUES_IN_RANGE_PAD entries, and may be v itself. */
enum { VALUES_IN_RANGE_PAD = 16 };

typedef size_t (*ValuesInRangeFn)(const float* v, size_t n, float lo, float hi, float* out);

/** The averaging's sum (ActiveEstimateMap::sumNear), one run of a row at a time: adds to sum the disparities of
the pixels i < n whose estimate is active at t and lies within `tolerance` of `value` (|disparity - value| <=
tolerance, in float), and returns their count. The additions are in no particular order: the caller takes it
only where every order gives the same sum. */
typedef int (*EstimateNearSumFn)(const int32_t* until, const float* disparity, int n, int32_t t, float value,
                                 float tolerance, double& sum);

struct EstimateGatherKernels
{
    EstimateGatherFn gather;
    ValuesInRangeFn valuesInRange;
    EstimateNearSumFn nearSum;
    const char* name;  //!< "avx512", "avx2", "sse2", "neon", "simd128" or "scalar"
};

/** The scalar kernel: the reference the tests compare the vector ones with. */
CV_EXPORTS EstimateGatherKernels scalarEstimateGatherKernels();

/** The kernels for this CPU, chosen on the first call (OPENCV_EVENT_SCALAR_KERNELS=1 forces the scalar ones). */
CV_EXPORTS const EstimateGatherKernels& estimateGatherKernelsForThisCpu();

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_ESTIMATE_GATHER_HPP
