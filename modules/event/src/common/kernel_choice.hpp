// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_COMMON_KERNEL_CHOICE_HPP
#define OPENCV_EVENT_SRC_COMMON_KERNEL_CHOICE_HPP

#include <cstdlib>
#include <cstring>

namespace cv {
namespace event {
namespace detail {

/** The environment variable OPENCV_EVENT_SCALAR_KERNELS set to anything but empty or 0: every dispatched kernel
family (descriptor costs, window medians) takes its scalar version, to rule the vector ones out of a problem. */
inline bool scalarKernelsForced()
{
    const char* v = std::getenv("OPENCV_EVENT_SCALAR_KERNELS");
    return v && *v && std::strcmp(v, "0") != 0;
}

/** A kernel family's versions for this CPU: the scalar ones when scalarKernelsForced(), else `dispatched()`
(CV_CPU_DISPATCH over the instruction sets the module was built for). Chosen on the first call, not during
static initialisation, when OpenCV's CPU detection may not have run yet. */
template <typename Kernels>
const Kernels& kernelsForThisCpu(Kernels (*scalar)(), Kernels (*dispatched)())
{
    static const Kernels k = scalarKernelsForced() ? scalar() : dispatched();
    return k;
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_COMMON_KERNEL_CHOICE_HPP
