// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// estimateRowAlignment(): the pair's residual row offset and roll, from event-count images.

#include "precomp.hpp"
#include "common/sensor_bounds.hpp"

namespace cv {
namespace event {
namespace {

const int kMaxRowShift = 4;

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
    // The left strip is the same for every candidate: its zero-mean copy and deviation once. With a zero-mean
    // left side, the correlation's numerator needs no mean of the right side: sum (a - ma)(b - mb) = sum (a - ma) b.
    Scalar mean, sd;
    const Mat strip = left(Rect(x0, kMaxRowShift, x1 - x0, rows));
    meanStdDev(strip, mean, sd);
    StripMatch match{ 0, -2, minD };
    Mat zeroMean;
    subtract(strip, mean, zeroMean);
    const double n = (double)strip.total();
    std::vector<double> row(2 * kMaxRowShift + 1), bestRow;
    int bestDy = 0;
    for (int d = minD; d <= maxD; d++)
    {
        if (x0 - d < 0 || x1 - d > right.cols)
            continue;
        for (int dy = -kMaxRowShift; dy <= kMaxRowShift; dy++)
        {
            const Mat other = right(Rect(x0 - d, kMaxRowShift + dy, x1 - x0, rows));
            Scalar otherMean, otherSd;
            meanStdDev(other, otherMean, otherSd);
            const double c = sd[0] > 0 && otherSd[0] > 0 ? zeroMean.dot(other) / (n * sd[0] * otherSd[0]) : 0;  // 0: flat
            row[(size_t)(dy + kMaxRowShift)] = c;
            if (c > match.score)
            {
                match.score = c;
                match.disparity = d;
                bestDy = dy;
            }
        }
        if (match.disparity == d)
            bestRow = row;
    }
    match.rowShift = bestDy;
    if (!bestRow.empty() && bestDy > -kMaxRowShift && bestDy < kMaxRowShift)
    {
        const double cm = bestRow[(size_t)(bestDy + kMaxRowShift - 1)], c0 = bestRow[(size_t)(bestDy + kMaxRowShift)],
                     cp = bestRow[(size_t)(bestDy + kMaxRowShift + 1)];
        const double curvature = cm - 2 * c0 + cp;
        if (curvature < 0)
            match.rowShift += std::max(-0.5, std::min(0.5, 0.5 * (cm - cp) / curvature));
    }
    return match;
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
        if (detail::onSensor(e.x, e.y, sensorSize) && e.camera <= 1)
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
