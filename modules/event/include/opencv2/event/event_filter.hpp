// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_EVENT_FILTER_HPP
#define OPENCV_EVENT_EVENT_FILTER_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_filter
//! @{

/** @brief Common interface of the event noise filters: packets in, the kept events out.

A filter is fed a stream packet by packet; its state (per-pixel times, counters) carries over from one call
to the next, so the result does not depend on how the stream is cut into packets. Memory is a few bytes per
pixel and camera, whatever the length of the stream.

Events of both cameras of a stereo stream (Event::camera 0 and 1) can go through one filter: each camera
has its own state. Within a camera, events must come in time order.

Bad input raises, and leaves the filter as it was before the call:
- cv::Error::StsOutOfRange for an event outside the sensor or at t = INT64_MIN;
- cv::Error::StsBadArg for a camera id other than 0 or 1, or an event earlier than the previous event of
  its camera (in this packet or the ones before).
*/
class CV_EXPORTS_W EventFilter : public Algorithm
{
public:
    /** @brief Filters a packet of events (see getEventMat() for the accepted forms).
    @param events the packet, in time order per camera.
    @param kept output: the events the filter keeps, in their input order (N' x 1 EVENT_MAT_TYPE, or a
    `std::vector<Event>`). May be the same array as @p events.
    @param mask optional output: N x 1 CV_8U, 255 where the event was kept, 0 where it was removed. */
    CV_WRAP virtual void filter(InputArray events, OutputArray kept, OutputArray mask = noArray()) = 0;

    /** @brief Forgets the stream: the next event starts from an empty state (parameters are kept). */
    CV_WRAP virtual void reset() = 0;

    /** @brief Sensor size in pixels. Setting it resets the filter. */
    CV_WRAP virtual Size getSensorSize() const = 0;
    /** @copybrief getSensorSize @see getSensorSize */
    CV_WRAP virtual void setSensorSize(Size size) = 0;

    /** @brief Events filtered since the last reset(). */
    CV_WRAP virtual double getProcessedCount() const = 0;
    /** @brief Events kept since the last reset(). */
    CV_WRAP virtual double getKeptCount() const = 0;
};

/** @brief Background-activity filter: an event is kept when one of its 8 neighbours fired within the
correlation time before it.

Background activity (thermal leak, shot noise) fires isolated pixels; a moving edge fires neighbouring pixels
within a short time. Same rule as dv-processing's BackgroundActivityNoiseFilter: the event's own pixel does
not count (a hot pixel does not support itself), polarity is ignored. An edge's first event, before any
neighbour has fired, is removed: on a moving edge that is the leading pixel of a few rows at its start.
Cost: 8 timestamp reads and one write per event. */
class CV_EXPORTS_W BackgroundActivityFilter : public EventFilter
{
public:
    /** @param sensorSize pixels of the sensor.
    @param correlationTimeUs how recent a neighbour's event must be to support an event [us], > 0. */
    CV_WRAP static Ptr<BackgroundActivityFilter> create(Size sensorSize = Size(240, 180),
                                                        double correlationTimeUs = 10000);
    /** @brief How recent a neighbour's event must be [us]. Longer keeps more signal of slow edges and more
    noise (each noise event opens its 8 neighbours for this long). */
    CV_WRAP virtual double getCorrelationTime() const = 0;
    /** @copybrief getCorrelationTime @see getCorrelationTime */
    CV_WRAP virtual void setCorrelationTime(double us) = 0;
};

/** @brief Trail filter: keeps the first event of each burst at a pixel, and every polarity change.

An edge crossing a pixel makes it fire a burst of same-polarity events (one per contrast threshold the
edge spans); the later ones trail behind the edge and blur it. An event is kept when its pixel has not
fired within the threshold before it, or fired with the other polarity (the event starts a new edge). The
time since the pixel's last event counts, kept or not: a burst stays one burst however long it lasts, as
long as its events come less than the threshold apart. Prophesee's Trail filter follows this rule.
Cost: one timestamp read and write per event. */
class CV_EXPORTS_W TrailFilter : public EventFilter
{
public:
    /** @param sensorSize pixels of the sensor.
    @param thresholdUs gap that ends a burst [us], > 0. */
    CV_WRAP static Ptr<TrailFilter> create(Size sensorSize = Size(240, 180), double thresholdUs = 5000);
    /** @brief Gap between two events of a pixel that ends a burst [us]. */
    CV_WRAP virtual double getThreshold() const = 0;
    /** @copybrief getThreshold @see getThreshold */
    CV_WRAP virtual void setThreshold(double us) = 0;
};

/** @brief Refractory filter: after an event it keeps, a pixel is dead for a fixed period.

Thins bursts to at most one event per period and pixel, whatever the polarity; the dead time starts at
the last kept event, so a pixel firing continuously keeps one event per period (unlike TrailFilter, which
would keep only the first). Use it to cap the event rate of flickering or hot pixels, or to emulate a
sensor with a longer refractory period. Cost: one timestamp read and write per event. */
class CV_EXPORTS_W RefractoryFilter : public EventFilter
{
public:
    /** @param sensorSize pixels of the sensor.
    @param periodUs the dead time after a kept event [us], > 0. */
    CV_WRAP static Ptr<RefractoryFilter> create(Size sensorSize = Size(240, 180), double periodUs = 1000);
    /** @brief Dead time after a kept event [us]: an event less than this after its pixel's last kept event
    is removed. */
    CV_WRAP virtual double getPeriod() const = 0;
    /** @copybrief getPeriod @see getPeriod */
    CV_WRAP virtual void setPeriod(double us) = 0;
};

/** @brief Hot-pixel filter: removes every event of the pixels a mask marks as hot.

A hot pixel fires on its own, steadily and far more often than the scene makes its neighbours fire. The
mask comes from one of:
- learn() on a recording (or its first seconds), then detect(): a pixel is hot when its rate over the learnt
  time is at least getMinRate() and at least getRelativeRate() times the mean rate of its 8 neighbours
  (at least one event over the learnt time). Scene motion makes neighbours fire together, so a busy part of
  the scene (a fan's hub, a pendulum's pivot) is not hot, however busy;
- a learning time (setLearningTime()): filter() then learns from the first events of the stream, passing
  them all, and calls detect() once that much time has gone by;
- setMask(), e.g. a mask saved before: save() / Algorithm::load<HotPixelFilter>() store the parameters and
  the masks (FileStorage), so a camera's hot pixels are found once and reused.

reset() forgets the learnt counts and restarts the learning time; the masks stay until clearMasks().
Cost: one byte read per event. */
class CV_EXPORTS_W HotPixelFilter : public EventFilter
{
public:
    /** @param sensorSize pixels of the sensor.
    @param minRateHz see setMinRate().
    @param relativeRate see setRelativeRate(). */
    CV_WRAP static Ptr<HotPixelFilter> create(Size sensorSize = Size(240, 180), double minRateHz = 5,
                                              double relativeRate = 10);

    /** @brief Counts the events of a packet per pixel and camera for detect(); the packet is not filtered.
    Same input rules as filter(). */
    CV_WRAP virtual void learn(InputArray events) = 0;
    /** @brief Turns the counts learnt so far into the masks (replacing them) and returns the number of hot
    pixels found, both cameras together. Needs events that span some time; with none learnt, the masks
    become empty (no hot pixel). */
    CV_WRAP virtual int detect() = 0;

    /** @brief Mask of a camera: sensor-sized CV_8U, 255 at hot pixels, 0 elsewhere. */
    CV_WRAP virtual void getMask(OutputArray mask, int camera = CAMERA_LEFT) const = 0;
    /** @brief Sets the mask of a camera (sensor-sized CV_8U, non-zero = hot). */
    CV_WRAP virtual void setMask(InputArray mask, int camera = CAMERA_LEFT) = 0;
    /** @brief No pixel is hot any more, on both cameras. */
    CV_WRAP virtual void clearMasks() = 0;
    /** @brief Hot pixels in the masks, both cameras together. */
    CV_WRAP virtual int getHotPixelCount() const = 0;

    /** @brief Least rate of a hot pixel [events/s]. */
    CV_WRAP virtual double getMinRate() const = 0;
    /** @copybrief getMinRate @see getMinRate */
    CV_WRAP virtual void setMinRate(double hz) = 0;
    /** @brief Least ratio of a hot pixel's count to the mean count of its 8 neighbours (floored at one
    event). Two adjacent hot pixels of equal rates stand about 8 times out of each other's neighbourhood,
    as does the end of a thin edge's track: 10, the default, finds neither; 5 finds both. */
    CV_WRAP virtual double getRelativeRate() const = 0;
    /** @copybrief getRelativeRate @see getRelativeRate */
    CV_WRAP virtual void setRelativeRate(double ratio) = 0;
    /** @brief Time from a stream's first event during which filter() learns instead of filtering [us];
    0 (the default): filter() only applies the masks. */
    CV_WRAP virtual double getLearningTime() const = 0;
    /** @copybrief getLearningTime @see getLearningTime */
    CV_WRAP virtual void setLearningTime(double us) = 0;
};

/** @brief Anti-flicker filter: removes the events of pixels that alternate polarity at a frequency in a band.

Lamps on the mains flicker at 100 Hz (50 Hz grid) or 120 Hz (60 Hz grid); every pixel that sees them fires
an ON burst and an OFF burst per period. A pixel's polarity changes mark the starts of its bursts; the time
between two starts of the same polarity is one period. A pixel is flickering once getMinCycles() periods in
a row lie in the band [getMinFrequency(), getMaxFrequency()]; its events are removed until a period falls
outside the band or no burst starts within the band's longest period. The first cycles of a flicker pass
(they are needed to see it). Scene motion fires a pixel once per edge that crosses it, so it only looks
like flicker where edges cross a pixel at the flicker's rate (a fine grating moving fast).
Cost: one state read and write per event. */
class CV_EXPORTS_W AntiFlickerFilter : public EventFilter
{
public:
    /** @param sensorSize pixels of the sensor.
    @param minFrequencyHz lower end of the band [Hz], > 0.
    @param maxFrequencyHz upper end of the band [Hz], > minFrequencyHz. */
    CV_WRAP static Ptr<AntiFlickerFilter> create(Size sensorSize = Size(240, 180), double minFrequencyHz = 80,
                                                 double maxFrequencyHz = 150);
    /** @brief Lower end of the flicker band [Hz]. */
    CV_WRAP virtual double getMinFrequency() const = 0;
    /** @brief Upper end of the flicker band [Hz]. */
    CV_WRAP virtual double getMaxFrequency() const = 0;
    /** @brief Sets the band [Hz], 0 < min < max. */
    CV_WRAP virtual void setFrequencyBand(double minHz, double maxHz) = 0;
    /** @brief Periods in a row, inside the band, that make a pixel flickering (1 to 255). */
    CV_WRAP virtual int getMinCycles() const = 0;
    /** @copybrief getMinCycles @see getMinCycles */
    CV_WRAP virtual void setMinCycles(int cycles) = 0;
};

/** @brief Names createEventFilter() accepts: "background_activity", "trail", "refractory", "hot_pixels",
"anti_flicker". */
CV_EXPORTS_W std::vector<String> getEventFilterNames();

/** @brief A filter by name with its default parameters (see getEventFilterNames()), e.g. for a command line.
"hot_pixels" comes with a learning time of 1 s, so that it works on a stream without a mask.
Raises cv::Error::StsBadArg, listing the names, for an unknown one. */
CV_EXPORTS_W Ptr<EventFilter> createEventFilter(const String& name, Size sensorSize);

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_EVENT_FILTER_HPP
