// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_EVENT_WRITER_HPP
#define OPENCV_EVENT_EVENT_WRITER_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_io
//! @{

/** @brief File formats EventWriter can write. */
enum EventFileFormat
{
    EVENT_FILE_AUTO = 0,   //!< from the extension: .aedat4 -> AEDAT 4.0, anything else -> text
    EVENT_FILE_TEXT = 1,   //!< text: a `# ...` comment, a `width height` line, then `t_us x y p [camera]` lines
    EVENT_FILE_AEDAT4 = 2  //!< AEDAT 4.0 (readable by DV, dv-processing, aedat, tonic, ...)
};

/** @brief Properties of EventWriter (set before open(), except where noted). */
enum EventWriterProperties
{
    EVENT_WRITER_PROP_STEREO = 1,         //!< 1: the events carry both cameras (text: a camera column; AEDAT4: two event streams)
    EVENT_WRITER_PROP_COMPRESSION = 2,    //!< AEDAT4: 0 none, 1 LZ4 (default), 2 LZ4 high, 3 ZSTD, 4 ZSTD high
    EVENT_WRITER_PROP_PACKET_EVENTS = 3,  //!< AEDAT4: events per packet (default 4096)
    EVENT_WRITER_PROP_EVENTS_WRITTEN = 4  //!< events written so far (read-only)
};

/** @brief Writes event packets to a recording that EventCapture (and other tools) read back.

Every event written is read back identical (t, x, y, p, camera) by EventCapture: the tests check the round
trip for every format. Events must be time-ordered per camera; a camera id other than left needs
EVENT_WRITER_PROP_STEREO. Errors (cannot create the file, a write failure, events outside the declared
sensor) raise cv::Exception naming the file.
@code
cv::event::EventWriter writer("out.aedat4", cv::Size(346, 260));
writer.write(events);
writer.release();   // also done by the destructor
@endcode
*/
class CV_EXPORTS_W EventWriter
{
public:
    CV_WRAP EventWriter();
    /** @brief Opens @p path for writing (see open()). */
    CV_WRAP EventWriter(const String& path, Size sensorSize, int format = EVENT_FILE_AUTO);
    virtual ~EventWriter();

    /** @brief Creates @p path (truncating it) for a sensor of @p sensorSize pixels. */
    CV_WRAP virtual bool open(const String& path, Size sensorSize, int format = EVENT_FILE_AUTO);
    CV_WRAP virtual bool isOpened() const;
    /** @brief Appends a packet (any form getEventMat() accepts). */
    CV_WRAP virtual void write(InputArray events);
    /** @brief Flushes and closes the file. */
    CV_WRAP virtual void release();
    CV_WRAP virtual bool set(int propId, double value);
    CV_WRAP virtual double get(int propId) const;

    class Impl;
protected:
    Ptr<Impl> impl;
};

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_EVENT_WRITER_HPP
