// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_TEST_STEREO_METHODS_HPP
#define OPENCV_EVENT_TEST_STEREO_METHODS_HPP

// Every stereo method behind one call, for the tests that hold all of them to the same standard: the three
// StereoEventMatcher modes and the frame baseline (FrameStereoMatcher).

#include "opencv2/event.hpp"

#include <string>
#include <vector>

namespace opencv_test {
using namespace cv;
using namespace cv::event;

// The frame baseline where a StereoMatchMode is expected.
const int FRAME_BASELINE = -1;
const int kStereoMethods[] = { STEREO_COUPLED, STEREO_DECOUPLED, STEREO_FIXED_INTERVAL, FRAME_BASELINE };

class StereoMethod
{
public:
    StereoMethod(Size size, int method)
    {
        if (method == FRAME_BASELINE)
            frames = FrameStereoMatcher::create(size);
        else
            matcher = StereoEventMatcher::create(size, method);
    }

    std::string name() const { return frames ? std::string("frames + SGBM") : getStereoModeName(matcher->getMode()); }

    void setCalibration(const StereoCalibration& calibration)
    {
        if (frames)
            frames->setCalibration(calibration);
        else
            matcher->setCalibration(calibration);
    }

    // StereoEventMatcher::process(); the frame baseline outputs no lifetime and no flow (0), and its confidence
    // is 1 where it gave a disparity, 0 elsewhere.
    void process(InputArray events, OutputArray disparity, OutputArray lifetime = noArray(),
                 OutputArray flags = noArray(), OutputArray depth = noArray(), OutputArray flow = noArray(),
                 OutputArray confidence = noArray())
    {
        if (matcher)
            return matcher->process(events, disparity, lifetime, flags, depth, flow, confidence);
        frames->process(events, disparity, flags, depth);
        const Mat d = disparity.getMat();
        if (lifetime.needed())
        {
            lifetime.create(d.rows, 1, CV_32F);
            lifetime.setTo(Scalar::all(0));
        }
        if (flow.needed())
        {
            flow.create(d.rows, 2, CV_32F);
            flow.setTo(Scalar::all(0));
        }
        if (confidence.needed())
        {
            Mat shown = d >= 0;
            shown.convertTo(confidence, CV_32F, 1.0 / 255);
        }
    }

    void reset()
    {
        if (frames)
            frames->reset();
        else
            matcher->reset();
    }

    void renderDisparity(double t, OutputArray image, int camera, bool colourBar) const
    {
        if (frames)
            frames->renderDisparity(t, image, camera, colourBar);
        else
            matcher->renderDisparity(t, image, camera, colourBar);
    }

    Ptr<StereoEventMatcher> matcher;  // one of the two is set
    Ptr<FrameStereoMatcher> frames;
};

// The message of the cv::Exception that processing `events` after a reset raises; empty when none does.
inline std::string processingError(StereoMethod& method, const std::vector<Event>& events)
{
    method.reset();
    try
    {
        Mat disparity;
        method.process(events, disparity);
    }
    catch (const cv::Exception& e)
    {
        return e.what();
    }
    return "";
}

}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_STEREO_METHODS_HPP
