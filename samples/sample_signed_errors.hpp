// The mean signed disparity error of the left camera's estimates by third of the image's columns, against the
// ground truth, as event_stereo's summary and event_evaluate's report give it: what tells a rectification a
// little off along the rows from the matcher's own errors. A constant error is a disparity bias (a principal
// point off: SimulatorSettings::rightColumnOffset); one that changes sign across the image a focal length off
// (rightScale). Neither can a matcher correct.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_SIGNED_ERRORS_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_SIGNED_ERRORS_HPP

#include <opencv2/event.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

class SampleSignedErrors
{
public:
    /** One event of a sensor @p sensorWidth pixels wide, with its estimate and ground truth: counted when it is the
        left camera's, not noise, and estimated within 3 px of the truth (further off, a wrong match, not a bias). */
    void add(const cv::event::Event& e, int sensorWidth, float disparity, float truthDisparity, int truthFlags)
    {
        const double d = disparity, error = d - (double)truthDisparity;
        if (e.camera != cv::event::CAMERA_LEFT || (truthFlags & cv::event::GT_FLAG_NOISE) || d < 0 || std::abs(error) > 3)
            return;
        const int third = std::min(2, 3 * std::max(0, (int)e.x) / std::max(1, sensorWidth));
        // In 1/1024 px, so that any order of addition gives the same sum (samples/python/event_stereo.py's too).
        sum_[third] += (int64_t)std::floor(error * 1024 + 0.5);
        count_[third]++;
    }

    /** "left / middle / right px": each mean to the hundredth with its sign, "-" where a third has no event. */
    std::string text() const
    {
        return mean(0) + " / " + mean(1) + " / " + mean(2) + " px";
    }

private:
    std::string mean(int third) const
    {
        if (count_[third] == 0)
            return "-";
        // Rounded to the hundredth here, so that an error just below zero reads +0.00, not -0.00.
        const double rounded = std::floor((double)sum_[third] / 1024.0 / (double)count_[third] * 100 + 0.5) / 100;
        return cv::format("%+.2f", rounded == 0 ? 0.0 : rounded);
    }

    int64_t sum_[3] = { 0, 0, 0 }, count_[3] = { 0, 0, 0 };
};

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_SIGNED_ERRORS_HPP
