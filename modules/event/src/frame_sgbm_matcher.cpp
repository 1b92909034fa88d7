// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "frame_sgbm_matcher.hpp"

namespace cv {
namespace event {

void FrameSgbmMatcher::configure(Size size, int minDisparity, int maxDisparity, int64 windowUs)
{
    size_ = size;
    minDisparity_ = minDisparity;
    maxDisparity_ = maxDisparity;
    windowUs_ = windowUs;
    // dv-processing's defaultStereoMatcher(): block 11, P1 8*11^2, P2 32*11^2, uniqueness 15, speckle 240/1,
    // 3-way; numDisparities covers [min, max] in steps of 16 as SGBM requires.
    const int numDisparities = ((maxDisparity - minDisparity + 1 + 15) / 16) * 16;
    sgbm_ = StereoSGBM::create(minDisparity, numDisparities, 11, 8 * 121, 32 * 121, 0, 0, 15, 240, 1,
                               StereoSGBM::MODE_SGBM_3WAY);
    reset();
}

void FrameSgbmMatcher::reset()
{
    window_ = INT64_MIN;
    for (Mat& f : frames_)
        f = Mat::zeros(size_, CV_8U);
}

void FrameSgbmMatcher::process(const std::vector<Point>& pixels, const std::vector<int64>& times,
                               const std::vector<uchar>& cameras, std::vector<float>& disparity)
{
    disparity.assign(pixels.size(), -1.f);
    size_t begin = 0;
    while (begin < pixels.size())
    {
        // floor division: windows [k w, (k + 1) w) also for negative times
        const int64 t = times[begin];
        const int64 k = t >= 0 ? t / windowUs_ : -((-t + windowUs_ - 1) / windowUs_);
        if (k != window_)
        {
            window_ = k;
            for (Mat& f : frames_)
                f.setTo(Scalar::all(0));
        }
        size_t end = begin;
        while (end < pixels.size() && times[end] < (window_ + 1) * windowUs_)
            end++;
        computeWindow(pixels, cameras, begin, end, disparity);
        begin = end;
    }
}

void FrameSgbmMatcher::computeWindow(const std::vector<Point>& pixels, const std::vector<uchar>& cameras, size_t begin,
                                     size_t end, std::vector<float>& disparity)
{
    for (size_t i = begin; i < end; i++)
        if (cameras[i] <= 1)
        {
            uchar& v = frames_[cameras[i]].at<uchar>(pixels[i]);
            v = (uchar)std::min(255, v + 64);
        }
    Mat left, right, flippedLeft, flippedRight, flippedDisparity;
    sgbm_->compute(frames_[0], frames_[1], left);
    // The right sensor's view: mirror both frames and swap them.
    flip(frames_[1], flippedRight, 1);
    flip(frames_[0], flippedLeft, 1);
    sgbm_->compute(flippedRight, flippedLeft, flippedDisparity);
    flip(flippedDisparity, right, 1);
    for (size_t i = begin; i < end; i++)
    {
        if (cameras[i] > 1)
            continue;
        const short d = (cameras[i] == 0 ? left : right).at<short>(pixels[i]);
        // SGBM marks "none" with (minDisparity - 1) * 16; anything at or above min*16 is an estimate.
        if (d >= minDisparity_ * 16 && d <= maxDisparity_ * 16)
            disparity[i] = d / 16.f;
    }
}

}  // namespace event
}  // namespace cv
