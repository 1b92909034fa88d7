// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The active estimates of one sensor as a disparity map (getActiveDisparity) and as a colour image
// (renderDisparity).

#include "precomp.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"
#include "opencv2/imgproc.hpp"

namespace cv {
namespace event {
namespace detail {

void StereoEventMatcherImpl::getActiveDisparity(double t, OutputArray disparity, int camera) const
{
    CV_CheckGE(camera, 0, "StereoEventMatcher::getActiveDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
    CV_CheckLE(camera, 1, "StereoEventMatcher::getActiveDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
    disparity.create(params_.sensorSize, CV_32F);
    Mat_<float> map = disparity.getMat();
    const ActiveEstimateMap& estimates = estimates_[camera];
    for (int y = 0; y < params_.sensorSize.height; y++)
        for (int x = 0; x < params_.sensorSize.width; x++)
        {
            float d;
            map(y, x) = estimates.shownAt(x, y, t, d) ? d : (float)NO_DISPARITY;
        }
}

void StereoEventMatcherImpl::renderDisparity(double t, OutputArray image, int camera, bool colourBar) const
{
    CV_CheckGE(camera, 0, "StereoEventMatcher::renderDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
    CV_CheckLE(camera, 1, "StereoEventMatcher::renderDisparity: camera is CAMERA_LEFT or CAMERA_RIGHT");
    Mat_<float> disparity;
    getActiveDisparity(t, disparity, camera);
    const int barWidth = colourBar ? 56 : 0;
    image.create(params_.sensorSize.height, params_.sensorSize.width + barWidth, CV_8UC3);
    Mat img = image.getMat();
    img.setTo(Scalar::all(0));
    const Mat lut = colourLut();
    for (int y = 0; y < params_.sensorSize.height; y++)
    {
        Vec3b* row = img.ptr<Vec3b>(y);
        for (int x = 0; x < params_.sensorSize.width; x++)
            if (disparity(y, x) != (float)NO_DISPARITY)
                row[x] = lut.at<Vec3b>(colourIndex(disparity(y, x)));
    }
    if (!colourBar)
        return;
    // Bar: max disparity at the top, min at the bottom, labelled.
    const int x0 = params_.sensorSize.width + 6, x1 = x0 + 12, top = 12, bottom = params_.sensorSize.height - 12;
    for (int y = top; y <= bottom; y++)
    {
        const double d = params_.maxDisparity - (double)(y - top) / std::max(1, bottom - top) * (params_.maxDisparity - params_.minDisparity);
        line(img, Point(x0, y), Point(x1, y), Scalar(lut.at<Vec3b>(colourIndex((float)d))), 1);
    }
    const Scalar white(255, 255, 255);
    putText(img, std::to_string(params_.maxDisparity), Point(x1 + 3, top + 8), FONT_HERSHEY_PLAIN, 0.8, white, 1);
    putText(img, std::to_string(params_.minDisparity), Point(x1 + 3, bottom), FONT_HERSHEY_PLAIN, 0.8, white, 1);
    putText(img, "px", Point(x1 + 3, (top + bottom) / 2 + 4), FONT_HERSHEY_PLAIN, 0.8, white, 1);
}

Mat StereoEventMatcherImpl::colourLut() const
{
    Mat ramp(256, 1, CV_8U), lut;
    for (int i = 0; i < 256; i++)
        ramp.at<uchar>(i) = (uchar)i;
    applyColorMap(ramp, lut, COLORMAP_JET);
    return lut;
}

int StereoEventMatcherImpl::colourIndex(float d) const
{
    const double span = std::max(1, params_.maxDisparity - params_.minDisparity);
    return std::max(0, std::min(255, (int)std::lround((d - params_.minDisparity) / span * 255)));
}

}  // namespace detail
}  // namespace event
}  // namespace cv
