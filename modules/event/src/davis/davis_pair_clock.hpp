// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_DAVIS_DAVIS_PAIR_CLOCK_HPP
#define OPENCV_EVENT_SRC_DAVIS_DAVIS_PAIR_CLOCK_HPP

// The time two cameras on a sync cable agree on after a timestamp reset that nobody here asked for (a user's
// reset of the pair, a sync glitch, the FPGA's forced reset after a long USB stall). The pulse reaches both
// at the same instant, but each reader sees its reset word on its own thread and knows only the last
// timestamp word before it: taking that as the new epoch would skew the two by up to a wrap period.

#include "opencv2/event.hpp"

#include <mutex>

namespace cv {
namespace event {
namespace detail {

class DavisPairClock
{
public:
    /** Camera @p camera's (0 or 1) device time after its latest transfer. */
    void publish(int camera, int64 timeUs);
    /** The epoch both cameras take at their @p k-th (from 0) reset that was not asked for, given the time of
    @p camera's last timestamp word before it: the first camera there fixes it for both, late enough that
    no event either sent before the pulse is later. */
    int64 agree(int camera, int k, int64 lastTimeUs);

private:
    std::mutex mutex_;
    int64 latest_[2] = { INT64_MIN, INT64_MIN };
    std::vector<int64> epochs_;
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_DAVIS_DAVIS_PAIR_CLOCK_HPP
