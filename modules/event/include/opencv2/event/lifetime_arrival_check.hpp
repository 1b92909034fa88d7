// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_LIFETIME_ARRIVAL_CHECK_HPP
#define OPENCV_EVENT_LIFETIME_ARRIVAL_CHECK_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_lifetime
//! @{

/** @brief A check of lifetimes that needs no ground truth: does the edge reach the next pixel when the
lifetime says it will?

An event's lifetime is the time its edge needs to move one pixel, and its flow the direction it moves in. For
each event with a lifetime L and a flow, the check takes the 8-neighbour the flow points to (the direction
rounded to 45 degrees) and the time the edge should need to get there, L times the neighbour's distance
along the flow. When that neighbour next fires an event of the same polarity, the delay over the expected
time is one sample. Lifetimes that agree with the recording give a median near 1; lifetimes too short give
more, too long less. Where noise fires in between, single samples are off; the median and quartiles are the
figures to read.

A crossing's first event claims, the later events of its burst do not: an event whose pixel fired (same
polarity) within the expected time before claims nothing, as the neighbour is then already in its own burst.
An edge that skips pixels is measured at the pixel beyond the neighbour as well (twice the distance): the first
of the two to fire settles the claim, so that a neighbour missing this crossing does not make the sample a
crossing too long; the pixel beyond counts only from the time the neighbour was due on (earlier, its firing is
not this edge). When more than four events point at one pixel before it fires, the oldest claims are
dropped. Events with no lifetime claim nothing but do settle the claims on their pixel.

Streaming: packets in time order with the LifetimeEstimator outputs that belong to them; memory is O(sensor
pixels) (up to four claims and the last event's time per pixel and polarity, and a fixed histogram of ratios).
Events outside the sensor raise cv::Error::StsOutOfRange, time going backwards and outputs of another length
raise cv::Error::StsBadArg, naming the event. The camera id is not looked at: keep one check per camera.
*/
class CV_EXPORTS_W LifetimeArrivalCheck : public Algorithm
{
public:
    CV_WRAP static Ptr<LifetimeArrivalCheck> create(Size sensorSize = Size(240, 180));

    /** @brief Adds a packet of events (any form getEventMat() accepts) with their lifetimes (N x 1 CV_32F,
    us, 0 for noise) and flow (N x 2 CV_32F or N x 1 CV_32FC2, px/s), as LifetimeEstimator::process() gives them. */
    CV_WRAP virtual void update(InputArray events, InputArray lifetimes, InputArray flow) = 0;

    /** @brief Quantile @p q (0..1) of the delay until the neighbour fires over the time the lifetime
    expects, over every sample so far (0 when there is none). The histogram's bins are 1 % wide. */
    CV_WRAP virtual double getRatioQuantile(double q) const = 0;
    /** @brief Samples so far: events whose neighbour has fired since. */
    CV_WRAP virtual double getSampleCount() const = 0;
    /** @brief Forgets every event and sample. */
    CV_WRAP virtual void reset() = 0;
    CV_WRAP virtual Size getSensorSize() const = 0;
};

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_LIFETIME_ARRIVAL_CHECK_HPP
