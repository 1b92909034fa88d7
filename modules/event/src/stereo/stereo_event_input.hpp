// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_STEREO_EVENT_INPUT_HPP
#define OPENCV_EVENT_SRC_STEREO_STEREO_EVENT_INPUT_HPP

#include "opencv2/event/stereo_calibration.hpp"
#include "opencv2/event/types.hpp"

#include <limits>
#include <string>
#include <vector>

namespace cv {
namespace event {
namespace detail {

/** What a stereo matcher takes in: the check of each event (camera, sensor bounds, time order, with errors
that name the matcher), its rectified pixel through the calibration's per-pixel table, and the depth of a
disparity. Shared by StereoEventMatcher and FrameStereoMatcher, so that both see the same pixels. */
class StereoEventInput
{
public:
    explicit StereoEventInput(const char* owner) : owner_(owner) {}

    // The sensor events must lie on; a calibration made for another size is dropped.
    void setSensorSize(Size size);

    // Empty: events are taken as rectified and have no depth. Otherwise it is validated and must be for the
    // sensor's size.
    void setCalibration(const StereoCalibration& calibration);
    // What setCalibration() checks of a calibration for a sensor of @p sensorSize, without taking it.
    void checkCalibration(const StereoCalibration& calibration, Size sensorSize) const;
    const StereoCalibration& calibration() const { return calibration_; }

    // The next event may have any time (after a reset).
    void restart() { lastTime_ = std::numeric_limits<int64>::min(); }
    // The time of the last event admitted; INT64_MIN after restart().
    int64 lastTime() const { return lastTime_; }

    // Checks the event (camera, sensor bounds, time order; cv::Exception naming it) and returns its rectified
    // pixel, (-1, -1) when it falls outside the rectified image.
    Point admit(const Event& e);

    // f B / disparity [m] with a calibration, for a positive disparity; 0 otherwise.
    float depthOf(float disparity) const
    {
        return disparity > 0 && focalBaseline_ != 0 ? (float)(focalBaseline_ / disparity) : 0.f;
    }

private:
    std::string owner_;
    Size size_;
    StereoCalibration calibration_;
    std::vector<int> table_[2];  // raw pixel -> rectified pixel index (-1: outside); empty: no calibration
    double focalBaseline_ = 0;
    int64 lastTime_ = std::numeric_limits<int64>::min();
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_STEREO_EVENT_INPUT_HPP
