// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_TEST_PRECOMP_HPP
#define OPENCV_EVENT_TEST_PRECOMP_HPP

#include "opencv2/ts.hpp"
#include "opencv2/event.hpp"
#include "test_common.hpp"
#include "test_event_helpers.hpp"
#include "test_simulator_helpers.hpp"
#include "test_stereo_methods.hpp"
#include "test_ros_messages.hpp"

#include <cstdio>
#include <map>
#include <numeric>

namespace opencv_test {
using namespace cv::event;
using cv::event::Event;  // perf:: and cv::cuda also have an Event
}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_PRECOMP_HPP
