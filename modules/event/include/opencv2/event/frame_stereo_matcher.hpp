// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_FRAME_STEREO_MATCHER_HPP
#define OPENCV_EVENT_FRAME_STEREO_MATCHER_HPP

#include "opencv2/event/stereo_calibration.hpp"
#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_stereo
//! @{

/** @brief The frame baseline for StereoEventMatcher: what event-camera users do today, as dv-processing's
semi-dense stereo matcher does it.

Per time window (getFrameWindow(), aligned to multiples of it) each sensor's events are accumulated into an
edge frame (+64 per event, saturating), cv::StereoSGBM with dv-processing's settings (block 11, P1 8*11^2,
P2 32*11^2, uniqueness 15, speckle window 240 with range 1, 3-way) computes the left disparity map and, from
the mirrored pair, the right one, and every event takes its pixel's disparity. Events are checked and
rectified as StereoEventMatcher does it, and give the same outputs where the baseline has them (disparity,
StereoEventFlags, depth), so that the two can be compared event by event.

It works on packets: process() with whole windows (EventCapture with EVENT_CAP_PROP_WINDOW_US = the frame
window gives them) matches each window once. A window split over several calls is matched each time from the
events seen so far; an event's disparity comes from the frames up to its own packet.

Memory is O(sensor pixels): two frames, the two disparity maps and the shown estimates.

write() stores the frame window, the disparity range, the sensor size and the calibration; read() sets those
a node holds, and a value out of range raises cv::Exception and changes none of them. */
class CV_EXPORTS_W FrameStereoMatcher : public Algorithm
{
public:
    /** @brief A baseline for two sensors of @p sensorSize. */
    CV_WRAP static Ptr<FrameStereoMatcher> create(Size sensorSize = Size(240, 180));

    /** @brief Matches a time-ordered packet of stereo events (both cameras, any form getEventMat() accepts).
    @param events the packet.
    @param disparity output N x 1 CV_32F [px]; StereoEventMatcher::NO_DISPARITY where SGBM gave none.
    @param flags output N x 1 CV_32S: STEREO_HAS_DISPARITY, or STEREO_OUTSIDE for an event whose rectified
    pixel is outside the image.
    @param depth output N x 1 CV_32F [m] (needs a calibration); 0 where unknown.
    Time must not go backwards, within a packet or across calls (cv::Exception naming the event). */
    CV_WRAP virtual void process(InputArray events, OutputArray disparity, OutputArray flags = noArray(),
                                 OutputArray depth = noArray()) = 0;

    /** @brief Colour-coded disparity of the events of @p camera shown at time @p t [us], as
    StereoEventMatcher::renderDisparity() draws it; an event's disparity is shown for one frame window. */
    CV_WRAP virtual void renderDisparity(double t, OutputArray image, int camera = CAMERA_LEFT,
                                         bool colourBar = true) const = 0;

    /** @brief The disparities renderDisparity() shows, as numbers (CV_32F, the sensor's size, NO_DISPARITY
    where none), as StereoEventMatcher::getActiveDisparity() gives them. */
    CV_WRAP virtual void getActiveDisparity(double t, OutputArray disparity, int camera = CAMERA_LEFT) const = 0;
    /** @brief The colour scale of renderDisparity(), as StereoEventMatcher::getDisparityDisplayRange() gives it. */
    CV_WRAP virtual Vec2i getDisparityDisplayRange(double t, int camera = CAMERA_LEFT) const = 0;

    /** @brief Forgets all events and the current window's frames (keeps parameters and calibration). */
    CV_WRAP virtual void reset() = 0;

    /** @brief Rectification and depth, as StereoEventMatcher::setCalibration(). */
    virtual void setCalibration(const StereoCalibration& calibration) = 0;
    virtual const StereoCalibration& getCalibration() const = 0;
    /** @brief setCalibration(readStereoCalibration(path)). */
    CV_WRAP virtual void loadCalibration(const String& path) = 0;

    CV_WRAP virtual Size getSensorSize() const = 0;
    CV_WRAP virtual void setSensorSize(Size size) = 0;
    /** @brief Smallest disparity searched [px] (default 0). */
    CV_WRAP virtual int getMinDisparity() const = 0;
    CV_WRAP virtual void setMinDisparity(int d) = 0;
    /** @brief Largest disparity searched [px] (default 40); SGBM searches [min, max] rounded up to a multiple of
    16 disparities and keeps the estimates within [min, max]. */
    CV_WRAP virtual int getMaxDisparity() const = 0;
    CV_WRAP virtual void setMaxDisparity(int d) = 0;
    /** @brief Accumulation window [us] (default 33000; at least 1). */
    CV_WRAP virtual double getFrameWindow() const = 0;
    CV_WRAP virtual void setFrameWindow(double us) = 0;
};

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_FRAME_STEREO_MATCHER_HPP
