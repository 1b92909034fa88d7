// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// checkStereoPair(): whether a pair's streams overlap, its rows line up and its events line up inside the range.

#include "precomp.hpp"

#include <algorithm>
#include <cmath>

namespace cv {
namespace event {
namespace {

const int kMinEvents = 2000;
// Below these the estimates are not worth acting on (estimateRowAlignment()'s and estimateDominantDisparity()'s
// own documented limits).
const double kMinRowScore = 0.4;
const double kMinLineUpScore = 0.1;
const double kRowsOffPx = 0.5;  // half a pixel at the sides: the matcher's row search starts to miss

void checkLineUp(const Mat_<Event>& events, Size size, int minDisparity, int maxDisparity, StereoPairCheck& check)
{
    const int reach = std::min(size.width / 2, std::max(20, 2 * std::max(maxDisparity, -minDisparity)));
    check.lineUpDisparity = estimateDominantDisparity(events, size, reach, noArray(), &check.lineUpScore);
    check.lineUpEstimated = true;
    check.lineUpTrusted = check.lineUpScore >= kMinLineUpScore;
    if (!check.lineUpTrusted)
        return;
    const int d = check.lineUpDisparity;
    check.camerasExchanged = d < 0 && d < minDisparity - 1;
    check.beyondRange = d > maxDisparity;
    check.belowRange = !check.camerasExchanged && d < minDisparity - 1;
}

void checkRows(const Mat_<Event>& events, Size size, int minDisparity, int maxDisparity, StereoPairCheck& check)
{
    if (size.width < 3 * maxDisparity / 2 + 12)
        return;
    const Vec2d a = estimateRowAlignment(events, size, minDisparity, maxDisparity, &check.rowScore);
    check.rowsEstimated = true;
    check.rowOffset = a[0];
    check.roll = a[1];
    check.rowsOffAtSides = std::abs(a[0]) + std::abs(std::sin(a[1])) * 0.5 * size.width;
    check.rowsTrusted = check.rowScore >= kMinRowScore;
    check.rowsOff = check.rowsTrusted && check.rowsOffAtSides > kRowsOffPx;
}

}  // namespace

StereoPairCheck checkStereoPair(InputArray _events, Size sensorSize, int minDisparity, int maxDisparity)
{
    CV_Check(sensorSize, !sensorSize.empty(), "checkStereoPair: the sensor size is empty");
    CV_Check(maxDisparity, minDisparity <= maxDisparity, "checkStereoPair: minDisparity above maxDisparity");
    const Mat_<Event> events = getEventMat(_events);
    StereoPairCheck check;
    const int n = (int)events.total();
    for (const Event& e : events)
        (e.camera ? check.rightEvents : check.leftEvents) += 1;
    if (n > 0)
        check.spanUs = (double)(events(n - 1).t - events(0).t);
    const double fewer = std::min(check.leftEvents, check.rightEvents);
    check.overlap = fewer > 0 && fewer * 100 >= std::max(check.leftEvents, check.rightEvents);
    if (n < kMinEvents || !check.overlap)
        return check;
    checkLineUp(events, sensorSize, minDisparity, maxDisparity, check);
    checkRows(events, sensorSize, minDisparity, maxDisparity, check);
    return check;
}

}  // namespace event
}  // namespace cv
