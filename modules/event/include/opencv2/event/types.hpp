// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_TYPES_HPP
#define OPENCV_EVENT_TYPES_HPP

#include <opencv2/core.hpp>

#include <iosfwd>
#include <vector>

namespace cv {
namespace event {

//! @addtogroup event_types
//! @{

/** @brief Polarity of an event: the sign of the log-intensity change that triggered it. */
enum Polarity
{
    POLARITY_OFF = 0,  //!< brightness decreased
    POLARITY_ON = 1    //!< brightness increased
};

/** @brief Which sensor of a stereo pair an event comes from (Event::camera). Mono streams use CAMERA_LEFT. */
enum CameraId
{
    CAMERA_LEFT = 0,
    CAMERA_RIGHT = 1
};

/** @brief One event of a dynamic vision sensor.

The record has a fixed 16-byte layout so that packets of events travel through InputArray / OutputArray as
an N x 1 Mat of type EVENT_MAT_TYPE (CV_8UC(16)) and as `std::vector<Event>` without conversion:

| bytes | field    | type  | meaning                                                         |
|-------|----------|-------|-----------------------------------------------------------------|
| 0-7   | t        | int64 | timestamp in microseconds                                       |
| 8-9   | x        | int16 | column, 0-based                                                 |
| 10-11 | y        | int16 | row, 0-based, 0 = top row                                       |
| 12    | p        | uint8 | polarity, POLARITY_OFF (0) or POLARITY_ON (1)                   |
| 13    | camera   | uint8 | CameraId: 0 = left (or mono), 1 = right                         |
| 14-15 | reserved | -     | zero                                                            |

Why this choice: int64 microseconds never wrap (unlike the 32-bit counters of the sensors) and need no
time base; int16 coordinates cover every sensor up to 32767 px; the camera id lives in what would
otherwise be padding, so a merged stereo stream is just a packet of events and every algorithm takes the
same type. From Python the bytes of such a Mat can be viewed with the numpy dtype
`[('t','<i8'),('x','<i2'),('y','<i2'),('p','u1'),('camera','u1'),('reserved','<u2')]`, or converted with
packEvents() / unpackEvents().
*/
struct Event
{
    int64 t;          //!< timestamp [us]
    short x;          //!< column [px]
    short y;          //!< row [px]
    uchar p;          //!< polarity, see Polarity
    uchar camera;     //!< see CameraId
    ushort reserved;  //!< always 0; keeps the record at 16 bytes

    Event() : t(0), x(0), y(0), p(0), camera(0), reserved(0) {}
    Event(int64 t_, int x_, int y_, int p_, int camera_ = CAMERA_LEFT)
        : t(t_), x((short)x_), y((short)y_), p((uchar)(p_ > 0 ? 1 : 0)), camera((uchar)camera_), reserved(0) {}

    bool operator==(const Event& e) const
    { return t == e.t && x == e.x && y == e.y && p == e.p && camera == e.camera; }
    bool operator!=(const Event& e) const { return !(*this == e); }
};

/** @brief Mat type of an event packet: one 16-byte Event per element (CV_8UC(16)); packets are N x 1. */
enum { EVENT_MAT_TYPE = CV_8UC(16) };

/** @brief Known sensors, for their pixel array size. */
enum SensorModel
{
    SENSOR_DVS128 = 0,          //!< iniVation DVS128: 128 x 128
    SENSOR_DAVIS240 = 1,        //!< iniVation DAVIS240: 240 x 180
    SENSOR_DAVIS346 = 2,        //!< iniVation DAVIS346: 346 x 260
    SENSOR_DVXPLORER = 3,       //!< iniVation DVXplorer: 640 x 480
    SENSOR_DVXPLORER_LITE = 4,  //!< iniVation DVXplorer Lite: 320 x 240
    SENSOR_PROPHESEE_GEN3 = 5,  //!< Prophesee Gen3 VGA: 640 x 480
    SENSOR_PROPHESEE_GEN4 = 6   //!< Prophesee / Sony IMX636 Gen4.1 HD: 1280 x 720
};

/** @brief Pixel array size (width x height) of a known sensor model (see SensorModel). */
CV_EXPORTS_W Size getSensorSize(int model);

/** @brief Looks a sensor up by name, case-insensitively ("DVS128", "DAVIS240", "davis346", "Gen4", ...).
@return the SensorModel, or -1 when the name is unknown. */
CV_EXPORTS_W int findSensorModel(const String& name);

/** @brief The canonical name of a sensor model ("DAVIS346", ...). */
CV_EXPORTS_W String getSensorModelName(int model);

/** @brief Parses a sensor size given as "WxH" (e.g. "346x260") or as a sensor name (see findSensorModel()),
as command-line tools take it. Raises cv::Error::StsBadArg naming the text when it is neither. */
CV_EXPORTS_W Size parseSensorSize(const String& text);

/** @brief Views an event packet as an N x 1 `Mat_<Event>` without copying.

Accepts an N x 1 or 1 x N continuous Mat of type EVENT_MAT_TYPE, a `std::vector<Event>`, or an empty
array. Anything else raises cv::Error::StsUnsupportedFormat naming what was passed.
*/
CV_EXPORTS Mat_<Event> getEventMat(InputArray events);

/** @brief Copies an event packet (any form accepted by getEventMat()) into a `std::vector<Event>`. */
CV_EXPORTS std::vector<Event> toEventVector(InputArray events);

/** @brief Builds an event packet from separate columns (the Python- and numpy-friendly form).
@param t timestamps in microseconds, N elements of CV_64F (exact up to 2^53 us), CV_32S or CV_32F.
@param x columns, N elements of any integer or floating type (rounded).
@param y rows, N elements.
@param p polarities, N elements; > 0 is ON, <= 0 is OFF (so both 0/1 and -1/+1 conventions work).
@param events output, N x 1 EVENT_MAT_TYPE.
@param camera optional camera ids, N elements (CameraId); all CAMERA_LEFT when empty.
*/
CV_EXPORTS_W void packEvents(InputArray t, InputArray x, InputArray y, InputArray p, OutputArray events,
                             InputArray camera = noArray());

/** @brief Splits an event packet into columns: t (CV_64F, us), x and y (CV_32S), p (CV_8U, 0/1) and
optionally camera (CV_8U). Each output is N x 1. */
CV_EXPORTS_W void unpackEvents(InputArray events, OutputArray t, OutputArray x, OutputArray y, OutputArray p,
                               OutputArray camera = noArray());

/** @brief Merges the streams of a stereo pair into one time-ordered packet with camera ids.

Each input must be time-ordered. Every output event of @p left gets camera = CAMERA_LEFT, of @p right
CAMERA_RIGHT; on equal timestamps the left event comes first, and the order within each stream is kept
(a stable merge), so splitStereoEvents() gives the inputs back. @p rightTimeOffset (us) is added to the
right camera's timestamps first, for cameras whose clocks were not reset together.
Raises cv::Error::StsBadArg when an input is not time-ordered (the message gives the first offending index).
*/
CV_EXPORTS_W void mergeStereoEvents(InputArray left, InputArray right, OutputArray merged,
                                    double rightTimeOffset = 0);

/** @brief Splits a merged stereo packet by Event::camera, keeping the order within each camera. */
CV_EXPORTS_W void splitStereoEvents(InputArray merged, OutputArray left, OutputArray right);

/** @brief Index of the first event whose timestamp is smaller than its predecessor's, or -1 when the packet
is time-ordered (non-decreasing). */
CV_EXPORTS_W int findTimeOrderViolation(InputArray events);

/** @brief Writes an event to FileStorage as the flow sequence [ t, x, y, p, camera ].
The timestamp is stored as a double, exact for |t| < 2^53 us (285 years). */
CV_EXPORTS void write(FileStorage& fs, const String& name, const Event& event);
/** @brief Writes an event packet as a sequence of [ t, x, y, p, camera ] entries. */
CV_EXPORTS void write(FileStorage& fs, const String& name, const std::vector<Event>& events);
/** @brief Reads an event written by write(); a missing node gives @p defaultValue. */
CV_EXPORTS void read(const FileNode& node, Event& event, const Event& defaultValue);
/** @brief Reads an event packet written by write(); raises cv::Error::StsParseError on a malformed entry. */
CV_EXPORTS void read(const FileNode& node, std::vector<Event>& events, const std::vector<Event>& defaultValue);

/** @brief Prints an event as `Event(t=..., x=..., y=..., p=..., camera=...)`. */
CV_EXPORTS std::ostream& operator<<(std::ostream& out, const Event& event);

//! @}

}  // namespace event

//! @cond IGNORED
// Registers Event as a Mat element (16 x CV_8U) so that std::vector<Event> and Mat_<Event> travel through
// InputArray / OutputArray.
template<> class DataType<event::Event>
{
public:
    typedef event::Event value_type;
    typedef value_type work_type;
    typedef uchar channel_type;
    // fmt = 0: FileStorage then reads and writes packets element by element through
    // cv::event::read / write (named fields) instead of as 16 raw bytes.
    enum { generic_type = 0, depth = CV_8U, channels = 16, fmt = 0,
           type = CV_MAKETYPE(depth, channels) };
    typedef Vec<channel_type, channels> vec_type;
};

namespace traits {
template<> struct Depth<event::Event> { enum { value = CV_8U }; };
template<> struct Type<event::Event> { enum { value = CV_MAKETYPE(CV_8U, 16) }; };
}  // namespace traits
//! @endcond

}  // namespace cv

#endif  // OPENCV_EVENT_TYPES_HPP
