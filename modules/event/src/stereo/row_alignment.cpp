// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// estimateRowAlignment(): the pair's residual row offset and roll, from event-count images.

#include "precomp.hpp"

namespace cv {
namespace event {
namespace {

const int kMaxRowShift = 4;

// Normalised correlation of two equally sized float images (0 when either is flat).
double correlation(const Mat& a, const Mat& b)
{
    Scalar ma, sa, mb, sb;
    meanStdDev(a, ma, sa);
    meanStdDev(b, mb, sb);
    if (sa[0] <= 0 || sb[0] <= 0)
        return 0;
    Mat za, zb;
    subtract(a, ma, za);
    subtract(b, mb, zb);
    return za.dot(zb) / ((double)a.total() * sa[0] * sb[0]);
}

struct StripMatch
{
    double rowShift, score;
    int disparity;
};

// Best row shift, correlation and disparity of the left strip [x0, x1) against the right image; the row shift
// refined by a parabola through its neighbours at the best disparity.
StripMatch stripShift(const Mat& left, const Mat& right, int x0, int x1, int minD, int maxD)
{
    const int rows = left.rows - 2 * kMaxRowShift;
    double best = -2;
    int bestD = minD, bestDy = 0;
    std::vector<double> byShift(2 * kMaxRowShift + 1, -2);
    for (int d = minD; d <= maxD; d++)
    {
        if (x0 - d < 0 || x1 - d > right.cols)
            continue;
        for (int dy = -kMaxRowShift; dy <= kMaxRowShift; dy++)
        {
            const double c = correlation(left(Rect(x0, kMaxRowShift, x1 - x0, rows)),
                                         right(Rect(x0 - d, kMaxRowShift + dy, x1 - x0, rows)));
            if (c > best)
            {
                best = c;
                bestD = d;
                bestDy = dy;
            }
        }
    }
    for (int dy = -kMaxRowShift; dy <= kMaxRowShift; dy++)
        if (x0 - bestD >= 0 && x1 - bestD <= right.cols)
            byShift[(size_t)(dy + kMaxRowShift)] = correlation(left(Rect(x0, kMaxRowShift, x1 - x0, rows)),
                                                               right(Rect(x0 - bestD, kMaxRowShift + dy, x1 - x0, rows)));
    double shift = bestDy;
    if (bestDy > -kMaxRowShift && bestDy < kMaxRowShift)
    {
        const double cm = byShift[(size_t)(bestDy + kMaxRowShift - 1)], c0 = byShift[(size_t)(bestDy + kMaxRowShift)],
                     cp = byShift[(size_t)(bestDy + kMaxRowShift + 1)];
        const double curvature = cm - 2 * c0 + cp;
        if (curvature < 0)
            shift += std::max(-0.5, std::min(0.5, 0.5 * (cm - cp) / curvature));
    }
    return StripMatch{ shift, best, bestD };
}

}  // namespace

Vec2d estimateRowAlignment(InputArray events, Size sensorSize, int minDisparity, int maxDisparity, double* score)
{
    if (sensorSize.width < 12 || sensorSize.height < 4 * kMaxRowShift)
        CV_Error_(Error::StsBadArg, ("estimateRowAlignment: sensor %d x %d is too small (at least 12 x %d)",
                                     sensorSize.width, sensorSize.height, 4 * kMaxRowShift));
    if (minDisparity < 0 || maxDisparity < minDisparity || maxDisparity >= sensorSize.width / 3 * 2)
        CV_Error_(Error::StsBadArg, ("estimateRowAlignment: disparities %d..%d; expected 0 <= min <= max < two "
                                     "thirds of the width (%d)", minDisparity, maxDisparity, sensorSize.width));
    Mat_<Event> ev = getEventMat(events);
    Mat counts[2] = { Mat::zeros(sensorSize, CV_32F), Mat::zeros(sensorSize, CV_32F) };
    for (const Event& e : ev)
        if ((unsigned)e.x < (unsigned)sensorSize.width && (unsigned)e.y < (unsigned)sensorSize.height && e.camera <= 1)
            counts[e.camera].at<float>(e.y, e.x) += 1;
    // Three strips of the left image, each a third wide, placed so that every disparity finds its strip in
    // the right image: the search runs x - d, so the strips start at maxDisparity.
    const int usable = sensorSize.width - maxDisparity, width = usable / 3;
    std::vector<double> centres, shifts;
    double worst = 1;
    for (int k = 0; k < 3; k++)
    {
        const int x0 = maxDisparity + k * width;
        const StripMatch s = stripShift(counts[0], counts[1], x0, x0 + width, minDisparity, maxDisparity);
        // The right camera's strip sits d px further left; its centre is where the row shift was measured.
        centres.push_back(x0 + 0.5 * width - s.disparity - 0.5 * (sensorSize.width - 1));
        shifts.push_back(s.rowShift);
        worst = std::min(worst, s.score);
    }
    if (score)
        *score = std::max(0.0, worst);
    // Least-squares line shift = offset + slope * x over the three strips.
    const double mx = (centres[0] + centres[1] + centres[2]) / 3, my = (shifts[0] + shifts[1] + shifts[2]) / 3;
    double sxy = 0, sxx = 0;
    for (int k = 0; k < 3; k++)
    {
        sxy += (centres[(size_t)k] - mx) * (shifts[(size_t)k] - my);
        sxx += (centres[(size_t)k] - mx) * (centres[(size_t)k] - mx);
    }
    const double slope = sxx > 0 ? sxy / sxx : 0;
    return Vec2d(my - slope * mx, std::atan(slope));
}

}  // namespace event
}  // namespace cv
