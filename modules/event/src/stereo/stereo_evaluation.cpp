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

double StereoEventScores::precisionAtDensity(double density) const
{
    const double wanted = (double)std::llround(density / 100.0 * visibleSignal);
    if (!(wanted > 0) || confidenceEstimated.size() != (size_t)CONFIDENCE_BINS ||
        confidenceWithin1.size() != (size_t)CONFIDENCE_BINS)
        return -1;
    double taken = 0, good = 0;
    for (int b = CONFIDENCE_BINS - 1; b >= 0; b--)
    {
        const double n = confidenceEstimated[(size_t)b];
        if (taken + n >= wanted)
        {
            // The bin's events are alike in confidence: as many of its right ones as its share taken.
            good += n > 0 ? confidenceWithin1[(size_t)b] * (wanted - taken) / n : 0.0;
            return 100.0 * good / wanted;
        }
        taken += n;
        good += confidenceWithin1[(size_t)b];
    }
    return -1;
}

void scoreStereoEvents(InputArray events, InputArray disparity, InputArray groundTruth, StereoEventScores& scores,
                       InputArray depth, InputArray mask, InputArray confidence)
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
    const Mat c = confidence.empty() ? Mat() : perEventColumn(confidence, n, CV_32F, "confidence");
    if (!c.empty())
    {
        for (int i = 0; i < n; i++)
            if (!(c.ptr<float>()[i] >= 0.f && c.ptr<float>()[i] <= 1.f))
                CV_Error_(Error::StsBadArg, ("scoreStereoEvents: confidence %g of event %d is not in 0..1",
                                             (double)c.ptr<float>()[i], i));
        const size_t bins = (size_t)StereoEventScores::CONFIDENCE_BINS;
        const bool fresh = scores.confidenceEstimated.empty() && scores.confidenceWithin1.empty();
        if (!fresh && (scores.confidenceEstimated.size() != bins || scores.confidenceWithin1.size() != bins))
            CV_Error_(Error::StsBadSize, ("scoreStereoEvents: the scores' confidence bins must number %d, got %d and %d",
                                          (int)bins, (int)scores.confidenceEstimated.size(),
                                          (int)scores.confidenceWithin1.size()));
        if (fresh)
        {
            scores.confidenceEstimated.assign(bins, 0.0);
            scores.confidenceWithin1.assign(bins, 0.0);
        }
    }
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
        if (!c.empty())
        {
            const int bin = std::min((int)(c.ptr<float>()[i] * StereoEventScores::CONFIDENCE_BINS),
                                     StereoEventScores::CONFIDENCE_BINS - 1);
            scores.confidenceEstimated[(size_t)bin]++;
            scores.confidenceWithin1[(size_t)bin] += error <= 1;
        }
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
