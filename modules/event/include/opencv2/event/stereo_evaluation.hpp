// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_STEREO_EVALUATION_HPP
#define OPENCV_EVENT_STEREO_EVALUATION_HPP

#include "opencv2/event/types.hpp"

#include <vector>

namespace cv {
namespace event {

//! @addtogroup event_stereo
//! @{

/** @brief Per-event disparities scored against ground truth (StereoEventSimulator, or a recording written
with its ground truth), summed over the packets given to scoreStereoEvents().

Two views of the same estimates: over the signal events of both cameras that the other camera sees
(density, precision, error), and over every left signal event, occluded ones included (the matching rate,
as event-stereo papers report it). Given the estimates' confidences, the first view is also kept per
confidence bin, for the precision of the most confident estimates (precisionAtDensity()). Counts are doubles
so that the struct crosses to Python as it is. */
struct CV_EXPORTS_W_SIMPLE StereoEventScores
{
    CV_WRAP StereoEventScores()
        : visibleSignal(0), estimated(0), within1(0), absErrorSum(0), depthErrorSum(0), depthEstimated(0),
          leftSignal(0), leftEstimated(0), leftWithin1(0), leftWithin2(0) {}

    CV_PROP_RW double visibleSignal;  //!< events of either camera flagged neither GT_FLAG_NOISE nor GT_FLAG_OCCLUDED
    CV_PROP_RW double estimated;      //!< of those, the events with a disparity (>= 0)
    CV_PROP_RW double within1;        //!< of those, the disparities within 1 px of the truth
    CV_PROP_RW double absErrorSum;    //!< sum of |disparity - truth| over the estimated ones [px]
    /** Sum of |depth - true depth| / true depth over the estimated ones, when depths were given. */
    CV_PROP_RW double depthErrorSum;
    CV_PROP_RW double depthEstimated; //!< the estimated ones whose depth entered depthErrorSum
    CV_PROP_RW double leftSignal;     //!< left-camera events not flagged GT_FLAG_NOISE (occluded ones included)
    CV_PROP_RW double leftEstimated;  //!< of those, the events with a disparity
    CV_PROP_RW double leftWithin1;    //!< of those, the disparities within 1 px of the truth
    CV_PROP_RW double leftWithin2;    //!< ... within 2 px of the truth (near misses: leftWithin2 - leftWithin1)
    /** With confidences: the estimated ones of the visible signal events per confidence bin, CONFIDENCE_BINS
        equal bins over 0..1 (bin i holds the confidences from i / CONFIDENCE_BINS up to the next bin's; the
        last also holds 1). Empty until scoreStereoEvents() is given confidences. */
    CV_PROP_RW std::vector<double> confidenceEstimated;
    CV_PROP_RW std::vector<double> confidenceWithin1;  //!< of those, per bin, the ones within 1 px of the truth

    enum { CONFIDENCE_BINS = 1000 };

    /** Estimated over visible signal events [%] (0 when there are none). */
    CV_WRAP double density() const { return visibleSignal > 0 ? 100.0 * estimated / visibleSignal : 0.0; }
    /** Disparities within 1 px over estimated events [%] (0 when there are none). */
    CV_WRAP double precision() const { return estimated > 0 ? 100.0 * within1 / estimated : 0.0; }
    /** Left signal events with a disparity within 1 px, over all of them [%] (0 when there are none). */
    CV_WRAP double matchingRate() const { return leftSignal > 0 ? 100.0 * leftWithin1 / leftSignal : 0.0; }
    /** Mean absolute disparity error over estimated events [px] (0 when there are none). */
    CV_WRAP double meanAbsError() const { return estimated > 0 ? absErrorSum / estimated : 0.0; }
    /** Mean relative depth error over the estimated events with a depth (0 when there are none). */
    CV_WRAP double meanDepthError() const { return depthEstimated > 0 ? depthErrorSum / depthEstimated : 0.0; }
    /** Precision at a density [%]: the share within 1 px of the most confident estimates, as many as
        @p density % of the visible signal events (rounded to a whole event; within the confidence bin where
        they end, that bin's share). -1 when the estimates with a confidence do not reach that many, or none
        are wanted. */
    CV_WRAP double precisionAtDensity(double density) const;
};

/** @brief Adds one packet's estimates to @p scores.

@param events the packet (any form getEventMat() accepts), N events.
@param disparity N x 1 (or 1 x N) CV_32F: each event's disparity, negative for none (as
StereoEventMatcher::process() gives it).
@param groundTruth N x 6 CV_32F, rows as the events (StereoEventSimulator::generate()'s columns).
@param scores the sums to add to; start from a default StereoEventScores.
@param depth optional N x 1 CV_32F estimated depths [m]; with it, depthErrorSum adds
|depth - true depth| / true depth over the estimated events whose true depth is positive and whose estimated
depth is positive and finite (a disparity of 0 has none: StereoEventMatcher outputs 0 there).
@param mask optional N x 1 CV_8U: only events with a non-zero entry count.
@param confidence optional N x 1 CV_32F confidences in 0..1 (as StereoEventMatcher::process() gives them):
the estimated visible signal events are also counted per confidence bin (StereoEventScores::confidenceEstimated).

Sizes or types that disagree, a confidence outside 0..1 and bins of @p scores of another size than
CONFIDENCE_BINS raise cv::Error::StsBadSize / StsBadArg naming the argument; @p scores is then unchanged. An
estimate is within 1 px when |disparity - truth| <= 1, compared in single precision. */
CV_EXPORTS_W void scoreStereoEvents(InputArray events, InputArray disparity, InputArray groundTruth,
                                    CV_IN_OUT StereoEventScores& scores, InputArray depth = noArray(),
                                    InputArray mask = noArray(), InputArray confidence = noArray());

//! @}

}  // namespace event
}  // namespace cv

#endif
