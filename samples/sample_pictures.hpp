// Pictures of the sample programs: small sensors (a DVS128 is 128 x 128) are enlarged, pixel for pixel, so that
// the pictures are large enough to look at; disparity maps coloured as the matchers' renderDisparity() does.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_PICTURES_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_PICTURES_HPP

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>

/** The whole-number enlargement that makes @p sensor at least 512 px across (1 for sensors that already are). */
inline int samplePictureZoom(cv::Size sensor)
{
    return std::max(1, 512 / std::max(1, std::max(sensor.width, sensor.height)));
}

/** @p picture enlarged @p zoom times, nearest pixel (an event stays one sharp square). */
inline cv::Mat sampleEnlarge(const cv::Mat& picture, int zoom)
{
    if (zoom <= 1)
        return picture;
    cv::Mat big;
    cv::resize(picture, big, cv::Size(), zoom, zoom, cv::INTER_NEAREST);
    return big;
}

/** A disparity map (CV_32F) in JET over [@p range[0], @p range[1]] px, black where it is <= 0 (no disparity). */
inline cv::Mat sampleColourDisparity(const cv::Mat& disparity, cv::Vec2i range)
{
    cv::Mat scaled, colour;
    const double span = std::max(1, range[1] - range[0]);
    disparity.convertTo(scaled, CV_8U, 255.0 / span, -255.0 * range[0] / span);
    cv::applyColorMap(scaled, colour, cv::COLORMAP_JET);
    colour.setTo(cv::Scalar::all(0), disparity <= 0);
    return colour;
}

#endif
