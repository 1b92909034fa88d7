// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_IO_EVENT_READER_HPP
#define OPENCV_EVENT_SRC_IO_EVENT_READER_HPP

// The interface between EventCapture (batching, bounds, time order, properties) and the format back-ends
// (decoding only). A back-end decodes its file in order and never holds more than one chunk.

#include "opencv2/event.hpp"

namespace cv {
namespace event {
namespace detail {

/** Options EventCapture passes to a back-end when opening (from properties set before open()). */
struct ReaderOptions
{
    Size sensorSize;               // user-given sensor size; empty = take it from the file
    int textTimeUnit = EVENT_TIME_UNIT_AUTO;
    bool textOneBased = false;
    int textColumnT = 0, textColumnX = 1, textColumnY = 2, textColumnP = 3;
    int textColumnCamera = -2;     // -2: the 5th column when present, -1: none
    int textLeftCameraValue = 0;
    int cameraFilter = -1;         // >= 0: deliver only the events of this CameraId (one side of a stereo file)
    int liveQueueCapacity = 512;   // live cameras: USB transfers buffered between the reader thread and read()
    std::vector<std::pair<int, double> > deviceSettings;  // live cameras: EVENT_CAP_PROP_DEVICE_* set before open
};

class EventReader
{
public:
    virtual ~EventReader() {}
    /** Back-end name as EventCapture::getBackendName() reports it. */
    virtual String name() const = 0;
    /** Decodes the next events in file order and appends them to @p out. Returns false once the stream is
    exhausted (then nothing was appended). Raises cv::Exception on corrupt data. */
    virtual bool next(std::vector<Event>& out) = 0;
    /** Sensor size the file declares; empty when it does not. */
    virtual Size sensorSize() const = 0;
    /** Recording length when the format tells it without decoding everything, else -1. */
    virtual int64 durationUs() const { return -1; }
    /** Events the file holds but that cannot be delivered (e.g. CD events before the first time base). */
    virtual int64 skippedEvents() const { return 0; }
    /** Share of the file decoded so far, in [0, 1]; -1 when unknown (e.g. a pipe). */
    virtual double progress() const { return -1; }
    /** With a camera filter on a one-file stereo recording: the share of the file's bytes read so far that
    hold this reader's camera, so that the two cameras' readers add up to the file's progress (each one alone
    may have skipped far ahead over the other camera's records); -1 when the back-end does not tell. */
    virtual double ownShare() const { return -1; }
    /** True when the file holds both cameras of a stereo pair (a camera column / two streams). */
    virtual bool isStereo() const { return false; }
    /** True for a camera: next() may return nothing yet (it waits a little, not for data). */
    virtual bool isLive() const { return false; }
    /** Live sources: no event older than this [us] can come any more (the device clock as last reported);
    a merge uses it to go on while one camera is silent. Files: INT64_MIN (unknown). */
    virtual int64 timeHorizon() const { return INT64_MIN; }
    /** Why next() returned false when that was not the end of a file (e.g. "camera unplugged"), else empty. */
    virtual String endMessage() const { return String(); }
    /** Source-specific properties (live cameras' EVENT_CAP_PROP_DEVICE_*, counters); false when not supported. */
    virtual bool setProperty(int /*propId*/, double /*value*/) { return false; }
    virtual bool getProperty(int /*propId*/, double& /*value*/) const { return false; }
    /** Moves the trigger events decoded so far (by next() calls) to the end of @p out, in decoding order. */
    virtual void takeTriggers(std::vector<EventTrigger>& out)
    {
        out.insert(out.end(), triggers_.begin(), triggers_.end());
        triggers_.clear();
    }

protected:
    std::vector<EventTrigger> triggers_;  // decoded, not yet taken
};

Ptr<EventReader> openTextReader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openDatReader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openPropheseeRawReader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openAedat2Reader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openAedat3Reader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openAedat4Reader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openRosBag1Reader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openRosBag2Reader(const String& path, const ReaderOptions& options);
Ptr<EventReader> openHdf5Reader(const String& path, const ReaderOptions& options);
/** A reader's figure (progress, ownShare) measured before and after it decoded a chunk, told at the @p taken
of the chunk's @p size events handed on so far: a chunk may span much of a small file. @p now when either
figure is unknown (< 0) or the chunk is used up. */
inline double progressThroughChunk(double atStart, double atEnd, size_t taken, size_t size, double now)
{
    if (atStart < 0 || atEnd < 0 || taken >= size)
        return now;
    return atStart + (atEnd - atStart) * (double)taken / (double)size;
}

/** A ROS2 bag: a folder with metadata.yaml, an sqlite3 database file or an MCAP file. */
bool isRosBag2(const String& path);
/** A file that starts with MCAP's magic. */
bool isMcapFile(const String& path);
/** A ROS2 bag in MCAP storage: @p files, in order (one bag, @p bag names it in messages). */
Ptr<EventReader> openMcapReader(const String& bag, const std::vector<std::string>& files, const ReaderOptions& options);
/** Merges a left and a right stream in time order (left first on ties), setting Event::camera and adding
@p rightTimeOffset to the right stream's timestamps. Each side is read in chunks: memory stays bounded.
@p oneFile: both read the same file, one camera each (their progress adds up, see ownShare()). */
Ptr<EventReader> openStereoMerge(const Ptr<EventReader>& left, const Ptr<EventReader>& right, int64 rightTimeOffset,
                                 bool oneFile = false);

/** Live DAVIS camera: @p selector is an index ("0") or a serial number; @p source names it in messages. */
Ptr<EventReader> openDavisReader(const String& source, const String& selector, const ReaderOptions& options);
/** Two live DAVIS cameras on a sync cable, merged with one time base (the master's clock reset once both run). */
Ptr<EventReader> openDavisStereo(const String& leftSource, const String& leftSelector, const String& rightSource,
                                 const String& rightSelector, const ReaderOptions& options, int64 rightTimeOffset);

/** Events a back-end decodes per next() call: large enough to amortise the call, small enough for cache. */
static const size_t kReaderChunk = 16384;

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_IO_EVENT_READER_HPP
