// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "common/sensor_bounds.hpp"
#include "stereo/rectification_table.hpp"
#include "stereo/stereo_event_input.hpp"

namespace cv {
namespace event {
namespace detail {

void StereoEventInput::setSensorSize(Size size)
{
    size_ = size;
    if (!calibration_.empty() && calibration_.imageSize != size)
        setCalibration(StereoCalibration());
}

void StereoEventInput::setCalibration(const StereoCalibration& calibration)
{
    if (calibration.empty())
    {
        calibration_ = StereoCalibration();
        for (std::vector<int>& t : table_)
            t.clear();
        focalBaseline_ = 0;
        return;
    }
    checkCalibration(calibration, size_);
    for (int c = 0; c < 2; c++)
        table_[c] = buildRectificationTable(calibration, c);
    calibration_ = calibration;
    focalBaseline_ = calibration.focalLength() * calibration.baseline();
}

void StereoEventInput::checkCalibration(const StereoCalibration& calibration, Size sensorSize) const
{
    calibration.validate();
    if (calibration.imageSize != sensorSize)
        CV_Error_(Error::StsBadArg, ("%s: the calibration is for %d x %d sensors but the matcher's sensor is %d x %d",
                                     owner_.c_str(), calibration.imageSize.width, calibration.imageSize.height,
                                     sensorSize.width, sensorSize.height));
}

Point StereoEventInput::admit(const Event& e)
{
    if (e.camera > 1)
        CV_Error_(Error::StsBadArg, ("%s: event (t=%lld us, x=%d, y=%d) has camera %d; a stereo stream has "
                                     "CAMERA_LEFT (0) and CAMERA_RIGHT (1)", owner_.c_str(), (long long)e.t, e.x, e.y,
                                     e.camera));
    if (!onSensor(e.x, e.y, size_))
        CV_Error_(Error::StsOutOfRange, ("%s: event at (x=%d, y=%d), t=%lld us, camera %d, is outside the %d x %d "
                                         "sensor", owner_.c_str(), e.x, e.y, (long long)e.t, e.camera, size_.width,
                                         size_.height));
    if (e.t == EventSurface::NO_EVENT)
        CV_Error_(Error::StsOutOfRange, ("%s: event (x=%d, y=%d, camera %d) has t = INT64_MIN, which is reserved for "
                                         "EventSurface::NO_EVENT", owner_.c_str(), e.x, e.y, e.camera));
    if (e.t < lastTime_)
        CV_Error_(Error::StsBadArg, ("%s: event at t=%lld us (x=%d, y=%d, camera %d) is earlier than the previous one "
                                     "(t=%lld us): events of both sensors must come merged in time order "
                                     "(mergeStereoEvents, EventCapture::openStereo)", owner_.c_str(), (long long)e.t,
                                     e.x, e.y, e.camera, (long long)lastTime_));
    lastTime_ = e.t;
    if (table_[e.camera].empty())
        return Point(e.x, e.y);
    const int r = table_[e.camera][(size_t)e.y * size_.width + e.x];
    return r < 0 ? Point(-1, -1) : Point(r % size_.width, r / size_.width);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
