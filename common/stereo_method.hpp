// The stereo methods the tools run side by side, by the name --mode / --method gives: StereoEventMatcher's
// modes (coupled, decoupled, fixed) and the frame baseline (sgbm: FrameStereoMatcher), behind one process().

#ifndef OPENCV_EVENT_COMMON_STEREO_METHOD_HPP
#define OPENCV_EVENT_COMMON_STEREO_METHOD_HPP

#include <opencv2/event.hpp>

#include "algorithm_settings.hpp"

#include <stdexcept>
#include <string>

class StereoMethod
{
public:
    static const char* names() { return "coupled, decoupled, fixed or sgbm"; }
    static bool known(const std::string& name)
    {
        return name == "sgbm" || cv::event::findStereoMode(name) >= 0;
    }

    /** The method @p name, at its defaults, for sensors of @p size; std::runtime_error for an unknown name. */
    StereoMethod(const std::string& name, cv::Size size)
    {
        if (!known(name))
            throw std::runtime_error("unknown stereo method \"" + name + "\": use " + names());
        if (name == "sgbm")
            frames = cv::event::FrameStereoMatcher::create(size);
        else
            matcher = cv::event::StereoEventMatcher::create(size, cv::event::findStereoMode(name));
    }

    /** --set's "name=value,..." (see applyAlgorithmSettings()). */
    void applySettings(const std::string& settings)
    {
        if (frames)
            applyAlgorithmSettings(frames, settings, "--set", "frame baseline");
        else
            applyMatcherSettings(matcher, settings);
    }

    /** Lifetimes come from COUPLED and DECOUPLED; a confidence from every matcher mode, not from SGBM. */
    bool hasLifetime() const
    {
        return matcher && (matcher->getMode() == cv::event::STEREO_COUPLED || matcher->getMode() == cv::event::STEREO_DECOUPLED);
    }
    bool hasConfidence() const { return frames.empty(); }

    void setDisparityRange(int minDisparity, int maxDisparity)
    {
        if (frames)
        {
            frames->setMinDisparity(minDisparity);
            frames->setMaxDisparity(maxDisparity);
            return;
        }
        matcher->setMinDisparity(minDisparity);
        matcher->setMaxDisparity(maxDisparity);
    }
    void setCalibration(const cv::event::StereoCalibration& calibration)
    {
        if (frames)
            frames->setCalibration(calibration);
        else
            matcher->setCalibration(calibration);
    }

    /** StereoEventMatcher::process()'s outputs (without the flow); SGBM gives no lifetime (0) and, for
        confidence, 1 where it gave a disparity, else 0. */
    void process(cv::InputArray events, cv::OutputArray disparity, cv::OutputArray lifetime, cv::OutputArray flags,
                 cv::OutputArray depth, cv::OutputArray confidence)
    {
        if (matcher)
            return matcher->process(events, disparity, lifetime, flags, depth, cv::noArray(), confidence);
        frames->process(events, disparity, flags, depth);
        const cv::Mat d = disparity.getMat();
        if (lifetime.needed())
        {
            lifetime.create(d.rows, 1, CV_32F);
            lifetime.setTo(cv::Scalar::all(0));
        }
        if (confidence.needed())
            cv::Mat(d >= 0).convertTo(confidence, CV_32F, 1.0 / 255);
    }

    void renderDisparity(double t, cv::OutputArray image, int camera, bool colourBar) const
    {
        if (frames)
            frames->renderDisparity(t, image, camera, colourBar);
        else
            matcher->renderDisparity(t, image, camera, colourBar);
    }

    cv::Vec2i getDisparityDisplayRange(double t, int camera) const
    {
        return frames ? frames->getDisparityDisplayRange(t, camera) : matcher->getDisparityDisplayRange(t, camera);
    }

    cv::Ptr<cv::event::StereoEventMatcher> matcher;  // one of the two is set
    cv::Ptr<cv::event::FrameStereoMatcher> frames;
};

#endif  // OPENCV_EVENT_COMMON_STEREO_METHOD_HPP
