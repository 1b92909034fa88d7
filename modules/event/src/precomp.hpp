// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_PRECOMP_HPP
#define OPENCV_EVENT_PRECOMP_HPP

#include "opencv2/event.hpp"
#include "opencv2/core/utility.hpp"
#include "common/cpu_dispatch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#endif  // OPENCV_EVENT_PRECOMP_HPP
