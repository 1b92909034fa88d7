// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "stereo/disparity_rendering.hpp"
#include "opencv2/imgproc.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

const float NO_DISPARITY = (float)StereoEventMatcher::NO_DISPARITY;

Mat jetLut()
{
    Mat ramp(256, 1, CV_8U), lut;
    for (int i = 0; i < 256; i++)
        ramp.at<uchar>(i) = (uchar)i;
    applyColorMap(ramp, lut, COLORMAP_JET);
    return lut;
}

int colourIndex(float d, int minDisparity, int maxDisparity)
{
    const double span = std::max(1, maxDisparity - minDisparity);
    return std::max(0, std::min(255, (int)std::lround((d - minDisparity) / span * 255)));
}

}  // namespace

void activeDisparityMap(const ActiveEstimateMap (&sensors)[2], Size size, double t, int camera, const char* caller,
                        OutputArray disparity)
{
    if (camera != CAMERA_LEFT && camera != CAMERA_RIGHT)
        CV_Error_(Error::StsBadArg, ("%s: camera %d; use CAMERA_LEFT (0) or CAMERA_RIGHT (1)", caller, camera));
    const ActiveEstimateMap& estimates = sensors[camera];
    disparity.create(size, CV_32F);
    Mat_<float> map = disparity.getMat();
    for (int y = 0; y < size.height; y++)
        for (int x = 0; x < size.width; x++)
        {
            float d;
            map(y, x) = estimates.shownAt(x, y, t, d) ? d : NO_DISPARITY;
        }
}

Vec2i activeDisparityDisplayRange(const ActiveEstimateMap (&sensors)[2], Size size, double t, int camera,
                                  int minDisparity, int maxDisparity, const char* caller)
{
    Mat_<float> disparity;
    activeDisparityMap(sensors, size, t, camera, caller, disparity);
    return disparityDisplayRange(disparity, minDisparity, maxDisparity);
}

void renderDisparityMap(const Mat_<float>& disparity, int searchMin, int searchMax, bool colourBar,
                        OutputArray image)
{
    const Vec2i range = disparityDisplayRange(disparity, searchMin, searchMax);
    const int minDisparity = range[0], maxDisparity = range[1];
    const int width = disparity.cols, height = disparity.rows;
    const int barWidth = colourBar ? 56 : 0;
    image.create(height, width + barWidth, CV_8UC3);
    Mat img = image.getMat();
    img.setTo(Scalar::all(0));
    const Mat lut = jetLut();
    for (int y = 0; y < height; y++)
    {
        Vec3b* row = img.ptr<Vec3b>(y);
        for (int x = 0; x < width; x++)
            if (disparity(y, x) != NO_DISPARITY)
                row[x] = lut.at<Vec3b>(colourIndex(disparity(y, x), minDisparity, maxDisparity));
    }
    if (!colourBar)
        return;
    // Bar: max disparity at the top, min at the bottom, labelled.
    const int x0 = width + 6, x1 = x0 + 12, top = 12, bottom = height - 12;
    for (int y = top; y <= bottom; y++)
    {
        const double d = maxDisparity - (double)(y - top) / std::max(1, bottom - top) * (maxDisparity - minDisparity);
        line(img, Point(x0, y), Point(x1, y), Scalar(lut.at<Vec3b>(colourIndex((float)d, minDisparity, maxDisparity))), 1);
    }
    const Scalar white(255, 255, 255);
    putText(img, std::to_string(maxDisparity), Point(x1 + 3, top + 8), FONT_HERSHEY_PLAIN, 0.8, white, 1);
    putText(img, std::to_string(minDisparity), Point(x1 + 3, bottom), FONT_HERSHEY_PLAIN, 0.8, white, 1);
    putText(img, "px", Point(x1 + 3, (top + bottom) / 2 + 4), FONT_HERSHEY_PLAIN, 0.8, white, 1);
}

}  // namespace detail

Vec2i disparityDisplayRange(InputArray disparity, int minDisparity, int maxDisparity)
{
    if (maxDisparity <= minDisparity)
        CV_Error_(Error::StsBadArg, ("disparityDisplayRange: the range [%d, %d] is empty", minDisparity, maxDisparity));
    if (disparity.empty())
        return Vec2i(minDisparity, maxDisparity);
    if (disparity.type() != CV_32F)
        CV_Error_(Error::StsUnsupportedFormat, ("disparityDisplayRange: the map is of type %s; CV_32F expected",
                                                typeToString(disparity.type()).c_str()));
    // A histogram of whole pixels (the ends take what lies beyond), then the bins holding the 2nd and the 98th
    // percentile: [lo, hi + 1) in pixels.
    std::vector<int64> counts((size_t)(maxDisparity - minDisparity + 1), 0);
    int64 total = 0;
    const Mat map = disparity.getMat();
    for (int y = 0; y < map.rows; y++)
    {
        const float* row = map.ptr<float>(y);
        for (int x = 0; x < map.cols; x++)
            if (row[x] >= 0)  // (NaN: none)
            {
                const double d = std::min((double)row[x], (double)maxDisparity);  // +inf too: the last bin
                counts[(size_t)std::max(0, (int)std::floor(d) - minDisparity)]++;
                total++;
            }
    }
    if (total == 0)
        return Vec2i(minDisparity, maxDisparity);
    int lo = 0, hi = (int)counts.size() - 1;
    int64 below = 0, above = 0;
    while (lo < hi && (below + counts[(size_t)lo]) * 50 <= total)
        below += counts[(size_t)lo++];
    while (hi > lo && (above + counts[(size_t)hi]) * 50 <= total)
        above += counts[(size_t)hi--];
    int low = minDisparity + lo, high = std::min(maxDisparity, minDisparity + hi + 1);
    while (high - low < 2 && (low > minDisparity || high < maxDisparity))
    {
        if (low > minDisparity)
            low--;
        if (high - low < 2 && high < maxDisparity)
            high++;
    }
    return Vec2i(low, high);
}

}  // namespace event
}  // namespace cv
