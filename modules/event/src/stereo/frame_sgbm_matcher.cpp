// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "stereo/frame_sgbm_matcher.hpp"

namespace cv {
namespace event {
namespace detail {

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
        const int64 k = windowIndex(times[begin]);
        if (k != window_)
        {
            window_ = k;
            for (Mat& f : frames_)
                f.setTo(Scalar::all(0));
        }
        size_t end = begin;
        while (end < pixels.size() && windowIndex(times[end]) == k)
            end++;
        computeWindow(pixels, cameras, begin, end, disparity);
        begin = end;
    }
}

int64 FrameSgbmMatcher::windowIndex(int64 t) const
{
    // Floor division, so that windows are [k w, (k + 1) w) also for negative times; neither the quotient nor
    // the remainder can overflow, whereas k w or (k + 1) w can near the int64 limits.
    const int64 q = t / windowUs_, r = t % windowUs_;
    return r < 0 ? q - 1 : q;
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
    // StereoSGBM needs an image wider than its disparity range plus its block; a narrower sensor is padded on
    // the right with empty columns (no events there, so nothing changes for the real ones).
    Mat frameLeft = frames_[0], frameRight = frames_[1];
    const int minWidth = sgbm_->getNumDisparities() + sgbm_->getBlockSize() + 1;
    if (size_.width < minWidth)
    {
        copyMakeBorder(frames_[0], frameLeft, 0, 0, 0, minWidth - size_.width, BORDER_CONSTANT, Scalar::all(0));
        copyMakeBorder(frames_[1], frameRight, 0, 0, 0, minWidth - size_.width, BORDER_CONSTANT, Scalar::all(0));
    }
    Mat left, right, flippedLeft, flippedRight, flippedDisparity;
    sgbm_->compute(frameLeft, frameRight, left);
    // The right sensor's view: mirror both frames and swap them.
    flip(frameRight, flippedRight, 1);
    flip(frameLeft, flippedLeft, 1);
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

}  // namespace detail
}  // namespace event
}  // namespace cv
