// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Per-event disparities scored against the simulator's ground truth.

#include "precomp.hpp"

namespace cv {
namespace event {
namespace {

// A per-event column (N x 1 or 1 x N, continuous) of @p type, or raises naming @p what.
Mat perEventColumn(InputArray a, int n, int type, const char* what)
{
    Mat m = a.getMat();
    if (m.type() != type)
        CV_Error_(Error::StsBadArg, ("scoreStereoEvents: %s must be %s, got %s", what, typeToString(type).c_str(),
                                     typeToString(m.type()).c_str()));
    if (m.total() != (size_t)n || (m.rows != 1 && m.cols != 1) || !m.isContinuous())
        CV_Error_(Error::StsBadSize, ("scoreStereoEvents: %s must hold one value per event (%d), got %d x %d", what,
                                      n, m.rows, m.cols));
    return m;
}

}  // namespace

void scoreStereoEvents(InputArray events, InputArray disparity, InputArray groundTruth, StereoEventScores& scores,
                       InputArray depth, InputArray mask)
{
    const Mat_<Event> ev = getEventMat(events);
    const int n = (int)ev.total();
    if (n == 0)
        return;  // an empty packet's outputs may be empty arrays of any type
    const Mat d = perEventColumn(disparity, n, CV_32F, "disparity");
    const Mat gt = groundTruth.getMat();
    if (gt.type() != CV_32F || gt.cols != 6 || gt.rows != n)
        CV_Error_(Error::StsBadSize, ("scoreStereoEvents: groundTruth must be %d x 6 CV_32F (one row per event), got "
                                      "%d x %d %s", n, gt.rows, gt.cols, typeToString(gt.type()).c_str()));
    const Mat z = depth.empty() ? Mat() : perEventColumn(depth, n, CV_32F, "depth");
    const Mat k = mask.empty() ? Mat() : perEventColumn(mask, n, CV_8U, "mask");
    const float* dp = d.ptr<float>();
    for (int i = 0; i < n; i++)
    {
        if (!k.empty() && !k.ptr<uchar>()[i])
            continue;
        const float* g = gt.ptr<float>(i);
        const int flags = (int)g[GT_FLAGS];
        if (flags & GT_FLAG_NOISE)
            continue;
        const float error = std::abs(dp[i] - g[GT_DISPARITY]);
        const bool estimated = dp[i] >= 0;
        if (ev(i).camera == CAMERA_LEFT)
        {
            scores.leftSignal++;
            scores.leftEstimated += estimated;
            scores.leftWithin1 += estimated && error <= 1;
            scores.leftWithin2 += estimated && error <= 2;
        }
        if (flags & GT_FLAG_OCCLUDED)
            continue;
        scores.visibleSignal++;
        if (!estimated)
            continue;
        scores.estimated++;
        scores.within1 += error <= 1;
        scores.absErrorSum += error;
        // A disparity of 0 has no depth: the matcher outputs 0 there, and an infinite one would swamp the mean.
        const float estimatedDepth = z.empty() ? 0.f : z.ptr<float>()[i];
        if (g[GT_DEPTH] > 0 && estimatedDepth > 0 && std::isfinite(estimatedDepth))
        {
            scores.depthErrorSum += std::abs(estimatedDepth - g[GT_DEPTH]) / g[GT_DEPTH];
            scores.depthEstimated++;
        }
    }
}

}  // namespace event
}  // namespace cv
