// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_FRAME_SGBM_MATCHER_HPP
#define OPENCV_EVENT_SRC_STEREO_FRAME_SGBM_MATCHER_HPP

#include "opencv2/calib3d.hpp"

namespace cv {
namespace event {
namespace detail {

/** FrameStereoMatcher's frames and SGBM, as dv-processing's semi-dense stereo matcher does it: per time window
each sensor's events are accumulated into an edge frame (+64 per event, saturating, like its
EdgeMapAccumulator with contribution 0.25), cv::StereoSGBM with dv-processing's defaults computes the left
disparity map, the right one from the mirrored pair, and every event takes its pixel's disparity.
Windows are aligned to multiples of the window length; a window's frames persist across calls, so a window
split over several packets is computed from the events seen so far. */
class FrameSgbmMatcher
{
public:
    // The camera of an event outside the rectified image: it takes no part.
    enum { NOT_IN_IMAGE = 255 };

    void configure(Size size, int minDisparity, int maxDisparity, int64 windowUs);
    void reset();
    // Disparity per event (-1: none) for rectified, time-ordered events; those of camera NOT_IN_IMAGE get none.
    void process(const std::vector<Point>& pixels, const std::vector<int64>& times, const std::vector<uchar>& cameras,
                 std::vector<float>& disparity);

private:
    int64 windowIndex(int64 t) const;
    void computeWindow(const std::vector<Point>& pixels, const std::vector<uchar>& cameras, size_t begin, size_t end,
                       std::vector<float>& disparity);

    Size size_;
    int minDisparity_ = 0, maxDisparity_ = 40;
    int64 windowUs_ = 33000, window_ = INT64_MIN;
    Mat frames_[2];
    Ptr<StereoSGBM> sgbm_;
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_FRAME_SGBM_MATCHER_HPP
