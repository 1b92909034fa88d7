// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "davis/davis_pair_clock.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

// A running camera sends a timestamp word at least once a wrap period (32.768 ms), so the pulse came at most
// that long after the last time word either reader has seen; 1 ms more covers the two clocks' start-up skew.
const int64 kResetEpochMarginUs = 0x8000 + 1000;

}  // namespace

void DavisPairClock::publish(int camera, int64 timeUs)
{
    std::lock_guard<std::mutex> lock(mutex_);
    latest_[camera & 1] = std::max(latest_[camera & 1], timeUs);
}

int64 DavisPairClock::agree(int camera, int k, int64 lastTimeUs)
{
    std::lock_guard<std::mutex> lock(mutex_);
    CV_Assert(k >= 0);
    while ((int)epochs_.size() <= k)
    {
        const int64 known = std::max(lastTimeUs, std::max(latest_[0], latest_[1]));
        const int64 previous = epochs_.empty() ? INT64_MIN : epochs_.back();
        epochs_.push_back(std::max(previous, known + kResetEpochMarginUs));
    }
    latest_[camera & 1] = std::max(latest_[camera & 1], epochs_[(size_t)k]);
    return epochs_[(size_t)k];
}

}  // namespace detail
}  // namespace event
}  // namespace cv
