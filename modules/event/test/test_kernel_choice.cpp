// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Which kernels run. The ctests that force the baseline instruction set (OPENCV_CPU_DISABLE) or the scalar
// reference (OPENCV_EVENT_SCALAR_KERNELS) run this test too: if the variable stopped taking effect, they would
// test the default kernels and pass; this test fails instead.

#include "test_precomp.hpp"
#include "stereo/descriptor_cost.hpp"
#include "stereo/window_median.hpp"
#include "stereo/estimate_gather.hpp"
#include "lifetime/plane_inliers.hpp"

#include <cstdlib>

namespace opencv_test { namespace {

using namespace cv::event::detail;

std::string environment(const char* name)
{
    const char* v = std::getenv(name);
    return v ? std::string(v) : std::string();
}

TEST(Event_KernelChoice, every_kernel_family_runs_the_version_the_environment_asks_for)
{
    const std::string scalar = environment("OPENCV_EVENT_SCALAR_KERNELS");
    const std::string disabled = environment("OPENCV_CPU_DISABLE");
    const std::vector<std::string> names = { descriptorCostKernelsForThisCpu().name,
                                             windowMedianKernelsForThisCpu().name,
                                             planeInlierKernelsForThisCpu().name,
                                             estimateGatherKernelsForThisCpu().name };
    for (const std::string& name : names)
    {
        if (!scalar.empty() && scalar != "0")
        {
            EXPECT_EQ("scalar", name);
            continue;
        }
        EXPECT_NE("scalar", name) << "the vector kernels are not used";
#if defined(__x86_64__) || defined(_M_X64)
        if (disabled.find("AVX2") != std::string::npos && disabled.find("AVX512-SKX") != std::string::npos)
        {
            EXPECT_EQ("sse2", name) << "OPENCV_CPU_DISABLE=" << disabled << " did not take effect";
        }
        else if (!checkHardwareSupport(CV_CPU_AVX2) && !checkHardwareSupport(CV_CPU_AVX512_SKX))
        {
            EXPECT_EQ("sse2", name);  // a CPU without either runs the baseline
        }
#endif
    }
}

}}  // namespace
