// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_EVENT_STATISTICS_HPP
#define OPENCV_EVENT_EVENT_STATISTICS_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_statistics
//! @{

/** @brief What an event stream looks like, in figures that can be compared between recordings: a simulated
scene against a real recording, one sensor against another, a recording before and after a filter.

Every figure is over the events given to EventStatistics::update(); for a stereo recording keep one
EventStatistics per camera.
*/
struct CV_EXPORTS_W_SIMPLE EventStreamStatistics
{
    EventStreamStatistics()
        : events(0), durationUs(0), eventRate(0), onShare(0), eventsPerCrossing(0), intervalP10Us(0),
          intervalMedianUs(0), intervalP90Us(0), isolatedShare(0), activePixelShare(0) {}

    CV_PROP_RW double events;             //!< events counted
    CV_PROP_RW double durationUs;         //!< last minus first timestamp [us]
    CV_PROP_RW double eventRate;          //!< events per second (events / duration)
    CV_PROP_RW double onShare;            //!< share of ON events (0..1)
    /** Events per pixel per edge crossing: the mean length of the runs of same-polarity events at one pixel,
    each within EventStatistics::getCrossingGap() of the one before. An edge of contrast C crossing a pixel of
    threshold c fires about C / c events in such a run. */
    CV_PROP_RW double eventsPerCrossing;
    /** Time between consecutive events at the same pixel (any polarity) [us]: 10th percentile, median and
    90th percentile, from a histogram with 2 % wide bins. */
    CV_PROP_RW double intervalP10Us;
    CV_PROP_RW double intervalMedianUs;   //!< @copydoc intervalP10Us
    CV_PROP_RW double intervalP90Us;      //!< @copydoc intervalP10Us
    /** Share of events none of whose 8 neighbours fired within EventStatistics::getIsolationWindow() before
    them: the events a background-activity filter removes; most of them are noise. */
    CV_PROP_RW double isolatedShare;
    /** Mean over consecutive windows of EventStatistics::getActivityWindow() (from the first event to the
    last) of the share of the sensor's pixels with at least one event in the window. */
    CV_PROP_RW double activePixelShare;
};

/** @brief Accumulates EventStreamStatistics over a stream of event packets.

Streaming: packets in time order, any length; memory is O(sensor pixels) whatever the length of the stream
(a few 8-byte timestamps per pixel). Events outside the sensor raise cv::Error::StsOutOfRange naming the
event; time going backwards raises cv::Error::StsBadArg naming it. The camera id is not looked at.
*/
class CV_EXPORTS_W EventStatistics : public Algorithm
{
public:
    /** @brief Statistics for a sensor of @p sensorSize pixels, with the default windows (all empty). */
    CV_WRAP static Ptr<EventStatistics> create(Size sensorSize = Size(240, 180));

    /** @brief Adds a packet of events (any form getEventMat() accepts). */
    CV_WRAP virtual void update(InputArray events) = 0;
    /** @brief The figures of everything added since create() or reset(). */
    CV_WRAP virtual EventStreamStatistics getStatistics() const = 0;
    /** @brief Forgets every event (the settings stay). */
    CV_WRAP virtual void reset() = 0;

    CV_WRAP virtual Size getSensorSize() const = 0;
    // Setting a window forgets every event: figures over two windows would mean neither.
    /** @brief Longest gap between two events of one edge crossing at a pixel [us] (default 5000). */
    CV_WRAP virtual double getCrossingGap() const = 0;
    CV_WRAP virtual void setCrossingGap(double us) = 0;
    /** @brief How far back a neighbour's event keeps an event from being isolated [us] (default 10000). */
    CV_WRAP virtual double getIsolationWindow() const = 0;
    CV_WRAP virtual void setIsolationWindow(double us) = 0;
    /** @brief Window of the active-pixel share [us] (default 10000). */
    CV_WRAP virtual double getActivityWindow() const = 0;
    CV_WRAP virtual void setActivityWindow(double us) = 0;
};

//! @}

}  // namespace event
}  // namespace cv

#endif
