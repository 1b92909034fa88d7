// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_STEREO_PAIR_CHECK_HPP
#define OPENCV_EVENT_STEREO_PAIR_CHECK_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_stereo
//! @{

/** @brief What checkStereoPair() found out about a stereo pair from its events. */
struct CV_EXPORTS_W_SIMPLE StereoPairCheck
{
    CV_WRAP StereoPairCheck()
        : leftEvents(0), rightEvents(0), spanUs(0), overlap(false), rowsEstimated(false), rowOffset(0), roll(0),
          rowScore(0), rowsOffAtSides(0), rowsTrusted(false), rowsOff(false), lineUpEstimated(false),
          lineUpDisparity(0), lineUpScore(0), lineUpTrusted(false), camerasExchanged(false), beyondRange(false),
          belowRange(false) {}

    CV_PROP_RW double leftEvents;   //!< left-camera events looked at
    CV_PROP_RW double rightEvents;  //!< right-camera events looked at
    CV_PROP_RW double spanUs;       //!< time from the first to the last event looked at [us]
    /** Both cameras fired: each has at least 1 % of the other's events. Two recordings whose clocks are apart
    (each started its own), or a camera that fires nothing, give false, and nothing else is estimated. */
    CV_PROP_RW bool overlap;

    /** The rows were estimated (estimateRowAlignment()): at least 2000 events whose streams overlap, on a
    sensor at least 1.5 x maxDisparity + 12 columns wide (three strips must each fit the range). */
    CV_PROP_RW bool rowsEstimated;
    CV_PROP_RW double rowOffset;       //!< the right camera's row offset at the image centre [px]
    CV_PROP_RW double roll;            //!< the right camera's roll [rad]
    CV_PROP_RW double rowScore;        //!< estimateRowAlignment()'s score, 0..1
    /** How far apart the rows are at the image's sides: |rowOffset| + |sin roll| x width / 2 [px]. */
    CV_PROP_RW double rowsOffAtSides;
    CV_PROP_RW bool rowsTrusted;  //!< rowScore >= 0.4: the events say enough about the rows to act on
    /** rowsTrusted and rowsOffAtSides > 0.5 px: matches are searched along the rows, so the pair's
    rectification should be checked. */
    CV_PROP_RW bool rowsOff;

    /** The line-up was estimated (estimateDominantDisparity()): at least 2000 events whose streams overlap. */
    CV_PROP_RW bool lineUpEstimated;
    /** The disparity most of the scene lines up at [px], searched over twice the range (|d| up to
    max(20, 2 max(maxDisparity, -minDisparity)), at most half the width), so that a scene beyond the range
    and an exchanged pair's negative disparity show. */
    CV_PROP_RW int lineUpDisparity;
    CV_PROP_RW double lineUpScore;  //!< its correlation, -1..1
    CV_PROP_RW bool lineUpTrusted;  //!< lineUpScore >= 0.1: the events say where they line up
    /** lineUpTrusted, lineUpDisparity < 0 and below minDisparity - 1: the right camera sees the scene to the
    right of the left one; the cameras look exchanged. */
    CV_PROP_RW bool camerasExchanged;
    CV_PROP_RW bool beyondRange;  //!< lineUpTrusted and lineUpDisparity > maxDisparity: widen the range
    /** lineUpTrusted, lineUpDisparity below minDisparity - 1, and not camerasExchanged: lower minDisparity. */
    CV_PROP_RW bool belowRange;
};

/** @brief Checks whether a stereo pair is set up as StereoEventMatcher assumes, from its events: both cameras'
streams overlap in time, the rows line up (estimateRowAlignment()), and the events line up at a disparity
inside [minDisparity, maxDisparity] with the cameras the right way round (estimateDominantDisparity()).

A pair that fails any of these loses matches; the flags of the result say which, and what to change. Give it
the first seconds of a recording (two seconds with 20,000 events or more is enough), time-ordered and already
rectified when a calibration exists (StereoCalibration::rectifyEvents()). Fewer than 2000 events estimate
nothing but the counts.
@param events stereo events (camera column), time-ordered, any form getEventMat() accepts; events outside the
sensor or of other cameras are ignored by the estimates.
@param sensorSize the sensor size.
@param minDisparity, maxDisparity the disparity range the matcher will search.
*/
CV_EXPORTS_W StereoPairCheck checkStereoPair(InputArray events, Size sensorSize, int minDisparity = 0,
                                             int maxDisparity = 40);

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_STEREO_PAIR_CHECK_HPP
