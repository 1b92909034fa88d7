// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Helpers shared by opencv_test_event (test_precomp.hpp) and opencv_perf_event (perf_precomp.hpp).

#ifndef OPENCV_EVENT_TEST_COMMON_HPP
#define OPENCV_EVENT_TEST_COMMON_HPP

#include "opencv2/ts.hpp"

#include <cstdlib>
#include <cstring>
#include <string>
#include <sys/stat.h>

namespace opencv_test {

/** Where the build found ../shared/data and the repository root (a source CMake generates per test program,
test_paths.cpp.in). */
const char* sharedDataDefault();
const char* sourceRoot();

/** Path of a real recording under ../shared/data (or $OPENCV_EVENT_SHARED_DATA); the test is skipped, with
a message, when it is absent: the recordings are never part of the repository. */
inline std::string requireSharedData(const std::string& relative)
{
    const char* env = std::getenv("OPENCV_EVENT_SHARED_DATA");
    const std::string root = env && *env ? std::string(env) : std::string(sharedDataDefault());
    const std::string path = root + "/" + relative;
    struct stat st;
    if (::stat(path.c_str(), &st) != 0)
        throw SkipTestException("shared recording " + path + " is absent (set OPENCV_EVENT_SHARED_DATA)");
    return path;
}

/** Bit for bit: the same size, type and bytes, so that -0 against 0 or two NaNs count as different too. */
inline bool sameBits(const cv::Mat& a, const cv::Mat& b)
{
    if (a.size != b.size || a.type() != b.type())
        return false;
    CV_Assert(a.dims <= 2);
    for (int y = 0; y < a.rows; y++)
        if (std::memcmp(a.ptr(y), b.ptr(y), (size_t)a.cols * a.elemSize()) != 0)
            return false;
    return true;
}

}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_COMMON_HPP
