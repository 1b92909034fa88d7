// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_EVENT_TRIGGER_HPP
#define OPENCV_EVENT_EVENT_TRIGGER_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_io
//! @{

/** @brief What a trigger event reports (EventTrigger::kind). */
enum EventTriggerKind
{
    EVENT_TRIGGER_FALLING = 0,           //!< falling edge on the camera's trigger / sync input
    EVENT_TRIGGER_RISING = 1,            //!< rising edge on that input
    EVENT_TRIGGER_PULSE = 2,             //!< a pulse on that input (the camera reports the pulse, not its edges)
    EVENT_TRIGGER_GENERATOR_FALLING = 3, //!< falling edge of the signal the camera itself generates (DAVIS)
    EVENT_TRIGGER_GENERATOR_RISING = 4   //!< rising edge of that signal
};

/** @brief A trigger event: a signal on a camera's trigger input, stamped by the camera's clock.

Cameras stamp external signals (a strobe, another sensor's exposure, a sync cable) with the same clock as
their pixel events, so that event streams can be aligned with other sensors. EventCapture delivers them
beside the events (EventCapture::retrieveTriggers()). Like Event, the record has a fixed 16-byte layout, so a
packet is an N x 1 Mat of type EVENT_TRIGGER_MAT_TYPE (CV_8UC(16)) or a `std::vector<EventTrigger>`:

| bytes | field    | type  | meaning                                                   |
|-------|----------|-------|-----------------------------------------------------------|
| 0-7   | t        | int64 | timestamp in microseconds, on the clock of the events     |
| 8-9   | channel  | int16 | trigger input of the camera (Prophesee: 0-31; others 0)   |
| 10    | kind     | uint8 | EventTriggerKind                                          |
| 11    | camera   | uint8 | CameraId of the camera that stamped it                    |
| 12-15 | reserved | -     | zero                                                      |

From Python, view such a Mat with the numpy dtype
`[('t','<i8'),('channel','<i2'),('kind','u1'),('camera','u1'),('reserved','<u4')]`.
*/
struct EventTrigger
{
    int64 t;          //!< timestamp [us]
    short channel;    //!< trigger input
    uchar kind;       //!< see EventTriggerKind
    uchar camera;     //!< see CameraId
    uint reserved;    //!< always 0; keeps the record at 16 bytes

    EventTrigger() : t(0), channel(0), kind(0), camera(0), reserved(0) {}
    EventTrigger(int64 t_, int kind_, int channel_ = 0, int camera_ = CAMERA_LEFT)
        : t(t_), channel((short)channel_), kind((uchar)kind_), camera((uchar)camera_), reserved(0) {}
    bool operator==(const EventTrigger& o) const
    { return t == o.t && channel == o.channel && kind == o.kind && camera == o.camera; }
    bool operator!=(const EventTrigger& o) const { return !(*this == o); }
};

/** @brief Mat type of a trigger packet: one 16-byte EventTrigger per element (CV_8UC(16)); packets are N x 1. */
enum { EVENT_TRIGGER_MAT_TYPE = CV_8UC(16) };

/** @brief Name of an EventTriggerKind ("rising", "falling", "pulse", "generator rising", "generator falling"). */
CV_EXPORTS_W String getTriggerKindName(int kind);

//! @}

}  // namespace event

//! @cond IGNORED
// Registers EventTrigger as a Mat element (16 x CV_8U) so that std::vector<EventTrigger> travels through
// InputArray / OutputArray.
template<> class DataType<event::EventTrigger>
{
public:
    typedef event::EventTrigger value_type;
    typedef value_type work_type;
    typedef uchar channel_type;
    enum { generic_type = 0, depth = CV_8U, channels = 16, fmt = 0,
           type = CV_MAKETYPE(depth, channels) };
    typedef Vec<channel_type, channels> vec_type;
};

namespace traits {
template<> struct Depth<event::EventTrigger> { enum { value = CV_8U }; };
template<> struct Type<event::EventTrigger> { enum { value = CV_MAKETYPE(CV_8U, 16) }; };
}  // namespace traits
//! @endcond

}  // namespace cv

#endif  // OPENCV_EVENT_EVENT_TRIGGER_HPP
