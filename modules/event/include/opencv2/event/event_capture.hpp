// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_EVENT_CAPTURE_HPP
#define OPENCV_EVENT_EVENT_CAPTURE_HPP

#include "opencv2/event/types.hpp"
#include "opencv2/event/event_trigger.hpp"

namespace cv {
namespace event {

//! @addtogroup event_io
//! @{

/** @brief Back-ends of EventCapture (apiPreference). EVENT_CAP_ANY picks one from the file's first bytes. */
enum EventCaptureAPIs
{
    EVENT_CAP_ANY = 0,      //!< detect from the content (magic bytes), then the extension
    EVENT_CAP_TEXT = 1,     //!< text, one event per line (RPG ECD `t x y p`, TUM `t x y p camera`, ...)
    EVENT_CAP_PROPHESEE_DAT = 2, //!< Prophesee .dat (decoded CD events)
    EVENT_CAP_PROPHESEE_RAW = 3, //!< Prophesee .raw, EVT 2.0 and EVT 3.0 encodings
    EVENT_CAP_AEDAT2 = 4,        //!< jAER AEDAT 1.0 / 2.0 (DVS128, DAVIS240/346/640 address layouts)
    EVENT_CAP_AEDAT3 = 5,        //!< cAER / libcaer AEDAT 3.1 (polarity packets)
    EVENT_CAP_AEDAT4 = 6,        //!< DV AEDAT 4.0 (LZ4 / ZSTD packets; two event streams = stereo)
    EVENT_CAP_ROSBAG1 = 7,       //!< ROS1 bag v2.0, dvs_msgs/EventArray or event_camera_msgs/EventPacket (evt3, libcaer); two event topics = stereo
    EVENT_CAP_ROSBAG2 = 8,       //!< ROS2 bag (MCAP or sqlite3 storage; folder, .mcap or .db3), event_camera_msgs/msg/EventPacket (evt3, libcaer, libcaer_cmp)
    EVENT_CAP_HDF5 = 9,          //!< MVSEC-style HDF5 (/davis/left|right/events), when built with libhdf5
    EVENT_CAP_DAVIS = 10         //!< live iniVation DAVIS240 / DAVIS346 over libusb-1.0: source "davis:0" (index), "davis:<serial>", or "0" / "<serial>" with this apiPreference
};

/** @brief Properties of EventCapture (get / set; those marked "before open" are read by open()). */
enum EventCaptureProperties
{
    EVENT_CAP_PROP_SENSOR_WIDTH = 1,       //!< sensor width [px]; 0 when the source does not say (settable before open)
    EVENT_CAP_PROP_SENSOR_HEIGHT = 2,      //!< sensor height [px]; 0 when unknown (settable before open)
    EVENT_CAP_PROP_WINDOW_US = 3,          //!< read() delivers the events of consecutive windows of this length [us] (default 10000)
    EVENT_CAP_PROP_BATCH_EVENTS = 4,       //!< when > 0, read() delivers batches of this many events instead of time windows
    EVENT_CAP_PROP_POS_US = 5,             //!< start of the next time window, or the timestamp of the last delivered event [us]; set() seeks (any format: by decoding, reopening for a backward seek, which restarts the counters)
    EVENT_CAP_PROP_EVENTS_DELIVERED = 6,   //!< events delivered by read()/retrieve() so far
    EVENT_CAP_PROP_DURATION_US = 7,        //!< duration of the recording when the format tells it without reading it all, else -1
    EVENT_CAP_PROP_FIRST_TIMESTAMP_US = 8, //!< timestamp of the first event (after open), or -1 when the source is empty
    EVENT_CAP_PROP_REJECTED_OUTSIDE = 9,   //!< events outside the sensor: counted, never delivered
    EVENT_CAP_PROP_TIME_BACKWARDS = 10,    //!< events older than their predecessor (handled by EVENT_CAP_PROP_TIME_ORDER_POLICY)
    EVENT_CAP_PROP_TIME_ORDER_POLICY = 11, //!< see EventTimeOrderPolicy (default EVENT_TIME_ORDER_CLAMP)
    EVENT_CAP_PROP_EXCEPTION_MODE = 12,    //!< 1 (default): errors raise cv::Exception; 0: open()/read() return false, see getLastError()
    EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US = 13, //!< stereo, before open: added to the right camera's timestamps [us]
    EVENT_CAP_PROP_STEREO = 14,            //!< 1 when the source delivers both cameras of a stereo pair (read-only)
    EVENT_CAP_PROP_SKIPPED = 15,           //!< events in the file that cannot be delivered, e.g. before the first time base (read-only)
    EVENT_CAP_PROP_PROGRESS = 16,          //!< share of the file decoded so far, 0..1 (read ahead by one chunk); -1 when unknown
    EVENT_CAP_PROP_DROPPED_EVENTS = 17,    //!< live: events decoded but lost because read() did not keep up (the queue was full); read-only
    EVENT_CAP_PROP_DROPPED_TRANSFERS = 18, //!< live: USB transfers that failed (their data is lost); read-only
    EVENT_CAP_PROP_INVALID_ADDRESSES = 19, //!< live: event words with an address beyond the pixel array (skipped); read-only
    EVENT_CAP_PROP_QUEUE_CAPACITY = 20,    //!< live, before open: USB transfers buffered between the camera's reader thread and read() (default 512, about 0.5 s at full rate)
    EVENT_CAP_PROP_TRIGGERS = 21,          //!< trigger events decoded so far (all of the recording's once read() has returned false); read-only
    EVENT_CAP_PROP_TEXT_TIME_UNIT = 100,   //!< text, before open: EventTimeUnit of the t column (default EVENT_TIME_UNIT_AUTO)
    EVENT_CAP_PROP_TEXT_ONE_BASED = 101,   //!< text, before open: 1 when x and y start at 1 (TUM stereo recordings)
    EVENT_CAP_PROP_TEXT_COLUMN_T = 102,    //!< text, before open: 0-based column of t (default 0)
    EVENT_CAP_PROP_TEXT_COLUMN_X = 103,    //!< text, before open: column of x (default 1)
    EVENT_CAP_PROP_TEXT_COLUMN_Y = 104,    //!< text, before open: column of y (default 2)
    EVENT_CAP_PROP_TEXT_COLUMN_P = 105,    //!< text, before open: column of the polarity (default 3; > 0 is ON)
    EVENT_CAP_PROP_TEXT_COLUMN_CAMERA = 106, //!< text, before open: column of the camera id, -1 = none (default: the 5th column when there is one)
    EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE = 107, //!< text, before open: value of the camera column that means the left camera (default 0; 1 for TUM's Fan recording)
    EVENT_CAP_PROP_DEVICE_BIAS_PRESET = 200,      //!< live: 0 = the vendor's default biases for the chip (set uploads them again)
    EVENT_CAP_PROP_DEVICE_BIAS_SELECT = 201,      //!< live: index of the bias EVENT_CAP_PROP_DEVICE_BIAS_VALUE reads / writes
    EVENT_CAP_PROP_DEVICE_BIAS_VALUE = 202,       //!< live: raw 16-bit word of the selected bias, in the chip's encoding of that bias (coarse/fine current: bits 4..11 fine, 12..14 coarse; VDAC: bits 0..5 voltage, 6..8 current; shifted source)
    EVENT_CAP_PROP_DEVICE_BA_FILTER = 203,        //!< live: background-activity (noise) filter on the camera, 1 = on (default 1)
    EVENT_CAP_PROP_DEVICE_BA_FILTER_TIME_US = 204, //!< live: its support time [us], rounded to 250 us steps (default 2000)
    EVENT_CAP_PROP_DEVICE_ROI_X = 205,            //!< live: region of interest on the camera (events outside are not sent); left column
    EVENT_CAP_PROP_DEVICE_ROI_Y = 206,            //!< live: ROI top row
    EVENT_CAP_PROP_DEVICE_ROI_WIDTH = 207,        //!< live: ROI width (default: the sensor)
    EVENT_CAP_PROP_DEVICE_ROI_HEIGHT = 208,       //!< live: ROI height (default: the sensor)
    EVENT_CAP_PROP_DEVICE_TIMESTAMP_RESET = 209,  //!< live: set 1 to reset the camera clock to 0 now (the master resets its slave too)
    EVENT_CAP_PROP_DEVICE_IS_MASTER = 210,        //!< live, read-only: 1 when the camera drives the timestamp clock (no sync input)
    EVENT_CAP_PROP_DEVICE_LOGIC_VERSION = 211,    //!< live, read-only: FPGA logic version
    EVENT_CAP_PROP_DEVICE_FIRMWARE_VERSION = 212, //!< live, read-only: USB firmware version
    EVENT_CAP_PROP_DEVICE_CHIP_ID = 213,          //!< live, read-only: chip identifier (0..2 DAVIS240A/B/C, 4/5/9 DAVIS346A/B/C, ...)
    EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT = 214    //!< live: 1 = the rising and falling edges on the camera's external (trigger) input become trigger events, see EventCapture::retrieveTriggers() (default 0)
};

/** @brief What EventCapture does with an event older than the one before it (a sensor reset, a bad file). */
enum EventTimeOrderPolicy
{
    EVENT_TIME_ORDER_KEEP = 0,   //!< deliver it as it is (the stream is then not time-ordered)
    EVENT_TIME_ORDER_CLAMP = 1,  //!< deliver it with the previous timestamp: nothing lost, output stays ordered
    EVENT_TIME_ORDER_DROP = 2,   //!< do not deliver it (counted in EVENT_CAP_PROP_TIME_BACKWARDS)
    EVENT_TIME_ORDER_ERROR = 3   //!< raise an error naming the file and the event
};

/** @brief Unit of the time column of text recordings. */
enum EventTimeUnit
{
    EVENT_TIME_UNIT_AUTO = 0,     //!< seconds when the first timestamp has a decimal point or exponent, else microseconds
    EVENT_TIME_UNIT_SECONDS = 1,
    EVENT_TIME_UNIT_MILLISECONDS = 2,
    EVENT_TIME_UNIT_MICROSECONDS = 3,
    EVENT_TIME_UNIT_NANOSECONDS = 4
};

/** @brief Reads event recordings (and, with the live back-ends, cameras), like cv::VideoCapture for frames.

@code
cv::event::EventCapture cap("recording.aedat4");
cap.set(cv::event::EVENT_CAP_PROP_WINDOW_US, 10000);   // 10 ms packets
cv::Mat events;                                          // N x 1 EVENT_MAT_TYPE, or std::vector<Event>
while (cap.read(events))
    process(events);
@endcode

read() returns consecutive time windows (an empty packet for a window without events) or, with
EVENT_CAP_PROP_BATCH_EVENTS, fixed-size batches; it returns false at the end of the stream. Memory stays
bounded by one chunk of the file plus one batch, whatever the length of the recording.

Errors (missing file, unknown format, truncated or corrupt data) raise cv::Exception with a message that
names the file, the byte offset where it applies and what is wrong. This differs from cv::VideoCapture on
purpose: a recording that silently stops early looks like a short recording. With
EVENT_CAP_PROP_EXCEPTION_MODE = 0 open() / read() return false instead and getLastError() holds the
message.

Events outside the sensor are never delivered; they are counted (EVENT_CAP_PROP_REJECTED_OUTSIDE).
Events that go back in time are counted and handled by EVENT_CAP_PROP_TIME_ORDER_POLICY.
*/
class CV_EXPORTS_W EventCapture
{
public:
    CV_WRAP EventCapture();
    /** @brief Opens @p source (see open()). */
    CV_WRAP explicit EventCapture(const String& source, int apiPreference = EVENT_CAP_ANY);
    virtual ~EventCapture();

    /** @brief Opens a recording or a live camera.
    @param source a file path, or a live camera: "davis:0" (the first DAVIS, see listEventDevices()),
    "davis:<serial>". A camera is configured with the vendor's default biases, events only (APS and IMU off),
    its clock reset to 0 at the start; read() then waits for its events. When the camera is unplugged read()
    returns false and getLastError() says so (no exception: like cv::VideoCapture losing a camera).
    @param apiPreference an EventCaptureAPIs value; EVENT_CAP_ANY detects the format from the content.
    @return true on success (errors raise cv::Exception unless the exception mode is off).
    Options set with set() before open() (sensor size, text columns, ...) apply to it. */
    CV_WRAP virtual bool open(const String& source, int apiPreference = EVENT_CAP_ANY);

    /** @brief Opens a stereo pair stored as two single-camera recordings, or two live cameras.
    For two DAVIS cameras ("davis:0", "davis:1") joined by a sync cable, exactly one must report itself master;
    the master's clock is reset once both run, so that both streams share one time base. Both reporting
    master means the cable is missing: an error says so.
    read() then delivers both streams merged in time order (left first on equal timestamps) with
    Event::camera set, the right timestamps shifted by EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US.
    A single file holding both cameras (e.g. a text file with a camera column) is opened with open() and
    merged the same way. */
    CV_WRAP virtual bool openStereo(const String& leftSource, const String& rightSource,
                                    int apiPreference = EVENT_CAP_ANY);

    /** @brief Opens a recording with options given as (property id, value) pairs, like cv::VideoCapture. */
    CV_WRAP virtual bool open(const String& source, int apiPreference, const std::vector<int>& params);

    CV_WRAP virtual bool isOpened() const;

    /** @brief Closes the source; the options set before open stay. Always returns promptly. */
    CV_WRAP virtual void release();

    /** @brief Reads the next packet into an internal buffer. @return false at the end of the stream. */
    CV_WRAP virtual bool grab();

    /** @brief The packet of the last grab(): N x 1 EVENT_MAT_TYPE (or a std::vector<Event>). */
    CV_WRAP virtual bool retrieve(OutputArray events);

    /** @brief The trigger events of the last grab()'s packet: N x 1 EVENT_TRIGGER_MAT_TYPE (or a
    `std::vector<EventTrigger>`), in time order, empty when there were none; may be called before or after
    retrieve(). A packet takes the triggers stamped before its end (a time window's end; for a batch, up to
    its last event's time); the first packet also takes those before it, the last one those after it.
    Triggers are read where the format stores them: Prophesee EVT 2.0 / 3.0 external triggers (also inside
    ROS bags of evt3 packets), AEDAT 4.0 trigger streams, AEDAT 3.1 special events, AEDAT 1.0 / 2.0 external
    events (as pulses), live DAVIS cameras' external-input events (once EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT
    is 1); other formats have none. APS frame and exposure markers and timestamp resets are not
    triggers. A stereo source stamps each with its camera (EventTrigger::camera) and shifts the right camera's
    by EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US.
    @return false when no packet was grabbed. */
    CV_WRAP virtual bool retrieveTriggers(OutputArray triggers);

    /** @brief grab() + retrieve(). @return false, with an empty packet, at the end of the stream. */
    CV_WRAP virtual bool read(OutputArray events);

    CV_WRAP virtual double get(int propId) const;
    CV_WRAP virtual bool set(int propId, double value);

    /** @brief Name of the back-end in use ("TEXT", "AEDAT4", ...), empty when closed. */
    CV_WRAP String getBackendName() const;

    /** @brief The source passed to open(). */
    CV_WRAP String getSource() const;

    /** @brief Message of the last error (useful when the exception mode is off), empty if none. */
    CV_WRAP String getLastError() const;

    /** @brief Sensor size (width x height), empty when the source does not tell it. */
    CV_WRAP Size getSensorSize() const;

    class Impl;
protected:
    Ptr<Impl> impl;
};

/** @brief A camera connected to this computer, as listEventDevices() reports it. */
struct CV_EXPORTS EventDeviceInfo
{
    String source;       //!< what EventCapture::open() takes for it: "davis:<serial>" (or "davis:<index>" without a serial)
    String model;        //!< "DAVIS346B", "DAVIS240C", ... ("DAVIS" when it could not be opened)
    String serial;       //!< USB serial number
    String usbLocation;  //!< "usb <bus>:<address>"
    int firmwareVersion; //!< USB firmware version
    int logicVersion;    //!< FPGA logic version; -1 when it could not be opened
    Size sensorSize;     //!< events' sensor size; empty when it could not be opened
    bool master;         //!< drives the timestamp clock (false: a slave on a sync cable)
    String error;        //!< why the camera could not be opened (permissions, in use, ...); empty when it could
};

/** @brief Lists the event cameras connected (DAVIS over USB), opening each briefly to identify it.
Returns an empty list when there is none (or when the module was built without libusb-1.0); never raises. */
CV_EXPORTS std::vector<EventDeviceInfo> listEventDevices();

/** @brief Names the format of a recording from its first bytes (and its extension when the content is
ambiguous): "TEXT", "PROPHESEE_DAT", ...; empty when it is not recognised or cannot be opened. */
CV_EXPORTS_W String detectEventFileFormat(const String& path);

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_EVENT_CAPTURE_HPP
