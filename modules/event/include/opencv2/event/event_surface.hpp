// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_EVENT_SURFACE_HPP
#define OPENCV_EVENT_EVENT_SURFACE_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_surface
//! @{

/** @brief Surface of Active Events (SAE): per pixel and polarity, the timestamp of the last event there.

The SAE is the state every estimator of this module reads: the lifetime estimator fits planes to it,
the stereo matcher finds nearest active events on it. It also renders the two classic pictures of an
event stream:
- a **time surface**, exp(-(t - T(x, y)) / tau), which shows recent edges bright and fades old ones;
- an **event-count frame**: the number of events per pixel since clearCounts(), i.e. the fixed-interval
  accumulation (call clearCounts() every 10 ms for the paper's FIXED_INTERVAL representation).

Cost: update() costs O(1) per event (one timestamp store and one counter increment, no allocation);
memory is 2 polarities x (8-byte timestamp + 4-byte counter) per pixel, whatever the length of the stream.
Events are expected in time order; an older event simply overwrites a newer timestamp (the surface stores
the last *arriving* event), which is what a streaming sensor delivers.
Events outside the sensor raise cv::Error::StsOutOfRange naming the event and the sensor size; nothing is
written for them.
*/
class CV_EXPORTS_W EventSurface : public Algorithm
{
public:
    /** @brief Timestamp stored where no event has arrived yet (raw surface, ptr()). */
    static const int64 NO_EVENT = (int64)0x8000000000000000ULL;  // INT64_MIN

    /** @brief Creates a surface for a sensor of the given pixel size (all pixels empty). */
    CV_WRAP static Ptr<EventSurface> create(Size sensorSize = Size(240, 180));

    /** @brief Sensor size in pixels. Setting it clears the surface. */
    CV_WRAP virtual Size getSensorSize() const = 0;
    /** @copybrief getSensorSize @see getSensorSize */
    CV_WRAP virtual void setSensorSize(Size size) = 0;

    /** @brief Adds a packet of events (see getEventMat() for the accepted forms).
    Raises cv::Error::StsOutOfRange, and writes nothing of that packet, when an event lies outside the
    sensor. The camera id of the events is not looked at: use one surface per camera. */
    CV_WRAP virtual void update(InputArray events) = 0;

    /** @brief Adds one event (same rules as update(InputArray)). */
    virtual void update(const Event& event) = 0;

    /** @brief Empties the surface (all pixels NO_EVENT) and clears the counts. */
    CV_WRAP virtual void reset() = 0;

    /** @brief Sets every event count to zero (the timestamps stay). */
    CV_WRAP virtual void clearCounts() = 0;

    /** @brief Timestamp of the last event at (x, y) with polarity @p polarity, or NO_EVENT.
    Raises cv::Error::StsOutOfRange outside the sensor. */
    virtual int64 at(int x, int y, int polarity) const = 0;

    /** @brief Latest timestamp at (x, y) over both polarities, or NO_EVENT. */
    virtual int64 latest(int x, int y) const = 0;

    /** @brief Row @p y of the raw surface of one polarity: getSensorSize().width timestamps, NO_EVENT where
    empty. Rows are contiguous (the whole polarity plane is one row-major block, so ptr(p, y) + k * width is
    row y + k): the fast path for estimators reading N x N neighbourhoods. */
    virtual const int64* ptr(int polarity, int y = 0) const = 0;

    /** @brief The raw surface of one polarity (POLARITY_OFF or POLARITY_ON), or the latest of both (-1).
    @param polarity POLARITY_OFF, POLARITY_ON or -1 for both.
    @param surface output, sensor-sized; CV_64F microseconds (exact below 2^53 us) with -infinity where no
    event arrived, or CV_32S microseconds relative to @p origin (saturated) with INT_MIN where empty.
    @param ddepth CV_64F or CV_32S.
    @param origin subtracted from every timestamp (us), e.g. the first timestamp of the recording.
    Times cross the API as double microseconds (exact below 2^53 us, 285 years): the Python bindings of
    OpenCV 4.6 cannot pass int64 arguments. */
    CV_WRAP virtual void getSurface(int polarity, OutputArray surface, int ddepth = CV_64F, double origin = 0) const = 0;

    /** @brief Renders the exponentially decaying time surface at time @p t.
    Value = exp(-(t - T) / tau) for pixels whose last event T is at or before @p t, 0 elsewhere (no event yet,
    or only later events). CV_32F gives the value in [0, 1]; CV_8U scales it to [0, 255].
    @param t time to render at [us].
    @param tau decay constant [us], > 0.
    @param dst output, sensor-sized.
    @param ddepth CV_8U or CV_32F.
    @param polarity POLARITY_OFF, POLARITY_ON, or -1 for the latest of both. */
    CV_WRAP virtual void renderTimeSurface(double t, double tau, OutputArray dst, int ddepth = CV_8U,
                                           int polarity = -1) const = 0;

    /** @brief Renders the event counts accumulated since the last clearCounts() / reset().
    @param dst output, sensor-sized, CV_32S.
    @param polarity POLARITY_OFF, POLARITY_ON, -1 for ON + OFF, or -2 for ON - OFF (signed frame). */
    CV_WRAP virtual void renderEventCount(OutputArray dst, int polarity = -1) const = 0;

    /** @brief Number of events added since the last reset(). */
    CV_WRAP virtual double getEventCount() const = 0;
};

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_EVENT_SURFACE_HPP
