// Pictures of the stereo samples: which windows of a run get one, and what one shows.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PICTURES_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PICTURES_HPP

#include <opencv2/event.hpp>
#include <opencv2/imgproc.hpp>

#include "sample_pictures.hpp"
#include "stereo_method.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

// Pictures written by default: the first window and one each time the run passes another eighth (live, where
// the length is unknown: windows 1, 2, 4, 8, ...). --all-frames writes every window; the video has them all.
inline bool sampleIsPictureWindow(int64_t window, double fraction, int& lastEighth)
{
    if (window == 0)
        return true;
    if (fraction < 0)
        return (window & (window - 1)) == 0;
    const int eighth = (int)std::floor(fraction * 8);
    if (eighth <= lastEighth)
        return false;
    lastEighth = eighth;
    return true;
}

// Left | right active events coloured by disparity; below, when simulated, the true disparity of the window's
// left events on the left picture's colour scale.
inline cv::Mat stereoWindowPicture(const StereoMethod& method, double t, const cv::Mat& truthDisparity)
{
    cv::Mat left, right, row;
    method.renderDisparity(t, left, cv::event::CAMERA_LEFT, false);
    method.renderDisparity(t, right, cv::event::CAMERA_RIGHT, true);
    cv::hconcat(left, right, row);
    if (truthDisparity.empty())
        return row;
    const cv::Size size = truthDisparity.size();
    cv::Mat below = cv::Mat::zeros(size.height, row.cols, CV_8UC3);
    sampleColourDisparity(truthDisparity, method.getDisparityDisplayRange(t, cv::event::CAMERA_LEFT))
        .copyTo(below(cv::Rect(0, 0, size.width, size.height)));
    cv::putText(below, "ground truth (left events of this window)", cv::Point(size.width + 4, 14),
                cv::FONT_HERSHEY_PLAIN, 0.8, cv::Scalar::all(255), 1);
    cv::vconcat(row, below, row);
    return row;
}

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_PICTURES_HPP
