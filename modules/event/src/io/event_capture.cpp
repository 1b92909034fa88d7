// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// EventCapture: picks a back-end, then turns its decoded chunks into the packets read() delivers
// (time windows or fixed counts), enforcing the sensor bounds and the time-order policy on the way.

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/file_input.hpp"
#include "common/sensor_bounds.hpp"

namespace cv {
namespace event {

using namespace detail;

namespace {

bool hasPrefix(const std::string& s, const char* prefix)
{
    return s.compare(0, std::strlen(prefix), prefix) == 0;
}

// Prophesee .dat and .raw both start with "% " header lines: .dat headers name their event type, RAW headers
// their encoding; the extension decides only when neither line is there.
bool looksLikePropheseeDat(const std::string& head, const String& path)
{
    if (!hasPrefix(head, "% "))
        return false;
    if (head.find("% Data file containing") != std::string::npos)
        return true;
    return fileExtension(path) == "dat" && head.find("% evt ") == std::string::npos &&
           head.find("% format EVT") == std::string::npos;
}

bool looksLikePropheseeRaw(const std::string& head)
{
    return hasPrefix(head, "% ") && (head.find("% evt ") != std::string::npos ||
                                     head.find("% format EVT") != std::string::npos);
}

bool looksLikeText(const std::string& head)
{
    if (head.empty())
        return false;
    for (unsigned char c : head)
        if (!(std::isprint(c) || std::isspace(c)))
            return false;
    return true;
}

}  // namespace

String detectEventFileFormat(const String& path)
{
    if (isRosBag2(path))
        return "ROSBAG2";
    const std::string head = readFilePrefix(path, 4096);
    if (head.empty())
        return String();
    if (hasPrefix(head, "#!AER-DAT1") || hasPrefix(head, "#!AER-DAT2"))
        return "AEDAT2";
    if (hasPrefix(head, "#!AER-DAT3"))
        return "AEDAT3";
    if (hasPrefix(head, "#!AER-DAT4"))
        return "AEDAT4";
    if (hasPrefix(head, "#ROSBAG V2.0"))
        return "ROSBAG1";
    if (hasPrefix(head, "\x89HDF\r\n\x1a\n"))
        return "HDF5";
    if (looksLikePropheseeDat(head, path))
        return "PROPHESEE_DAT";
    if (looksLikePropheseeRaw(head))
        return "PROPHESEE_RAW";
    if (looksLikeText(head))
        return "TEXT";
    if (hasPrefix(head, "#") && head.find("AEChip") != std::string::npos)
        return "AEDAT2";  // AEDAT 1.0: '#' header lines without a version line, then binary records
    return String();
}

namespace {

// The back-ends: the name detectEventFileFormat() gives, the apiPreference, and how to open one.
struct Backend
{
    const char* name;
    int api;
    Ptr<EventReader> (*open)(const String&, const ReaderOptions&);
};

const Backend kBackends[] = {
    { "TEXT", EVENT_CAP_TEXT, openTextReader },
    { "PROPHESEE_DAT", EVENT_CAP_PROPHESEE_DAT, openDatReader },
    { "PROPHESEE_RAW", EVENT_CAP_PROPHESEE_RAW, openPropheseeRawReader },
    { "AEDAT2", EVENT_CAP_AEDAT2, openAedat2Reader },
    { "AEDAT3", EVENT_CAP_AEDAT3, openAedat3Reader },
    { "AEDAT4", EVENT_CAP_AEDAT4, openAedat4Reader },
    { "ROSBAG1", EVENT_CAP_ROSBAG1, openRosBag1Reader },
    { "ROSBAG2", EVENT_CAP_ROSBAG2, openRosBag2Reader },
    { "HDF5", EVENT_CAP_HDF5, openHdf5Reader },
};

}  // namespace

class EventCapture::Impl
{
public:
    // ---- options (survive release(); read by open()) ----
    ReaderOptions options;
    int64 windowUs = 10000;
    int64 batchEvents = 0;
    int timeOrderPolicy = EVENT_TIME_ORDER_CLAMP;
    int64 rightTimeOffset = 0;
    bool exceptionMode = true;

    // ---- state of the open source ----
    Ptr<EventReader> reader;
    String source, lastError;
    Size sensor;
    std::vector<Event> raw;       // last chunk from the back-end
    std::vector<Event> pending;   // accepted events not yet delivered
    size_t pendingPos = 0;
    // The back-end's progress before and after the chunk in `pending` was read: a chunk may span much of a
    // small file, so progress is told by how far delivery has gone through it.
    double chunkStartProgress = -1, chunkEndProgress = -1;
    bool readerDone = true;
    std::vector<Event> batch;     // the grabbed packet
    bool grabbed = false;
    int64 windowStart = 0;
    bool windowStarted = false;
    int64 firstTimestamp = -1;
    int64 lastAccepted = 0;
    bool haveLast = false;
    int64 lastDelivered = -1;
    int64 delivered = 0, rejectedOutside = 0, backwards = 0;
    // Trigger events decoded but not yet handed out with a packet (time-ordered), those of the grabbed packet,
    // and how many were decoded in all.
    std::vector<EventTrigger> pendingTriggers, batchTriggers;
    int64 triggersRead = 0;
    // A decoding error is raised when delivery reaches it, not when the chunk holding it is read ahead:
    // every event before the error is still delivered.
    String deferredError;
    int deferredCode = Error::StsOk;

    void close()
    {
        reader.release();
        source.clear();
        sensor = Size();
        raw.clear();
        pending.clear();
        pendingPos = 0;
        chunkStartProgress = chunkEndProgress = -1;
        readerDone = true;
        batch.clear();
        grabbed = false;
        windowStarted = false;
        firstTimestamp = -1;
        haveLast = false;
        lastDelivered = -1;
        delivered = rejectedOutside = backwards = 0;
        pendingTriggers.clear();
        batchTriggers.clear();
        triggersRead = 0;
        deferredError.clear();
        deferredCode = Error::StsOk;
    }

    // "davis:<selector>", or the selector alone with apiPreference EVENT_CAP_DAVIS: a live camera.
    static bool isLiveSource(const String& source, int api, String& selector)
    {
        if (hasPrefix(source, "davis:"))
        {
            selector = source.substr(6);
            return true;
        }
        selector = source;
        return api == EVENT_CAP_DAVIS;
    }

    static Ptr<EventReader> makeReader(const String& path, int api, const ReaderOptions& opt)
    {
        String selector;
        if (isLiveSource(path, api, selector))
            return openDavisReader(path, selector, opt);
        if (api != EVENT_CAP_ROSBAG2 && !isRosBag2(path))
        {
            // Whatever the back-end: a missing file, a directory or an empty file is not a recording.
            FileInput probe(path);
            if (probe.size() == 0)
                CV_Error_(Error::StsError, ("%s: empty file, not a recording", path.c_str()));
        }
        int backend = api;
        if (backend == EVENT_CAP_ANY)
        {
            const String fmt = detectEventFileFormat(path);
            for (const Backend& b : kBackends)
                if (fmt == b.name)
                    backend = b.api;
            if (backend == EVENT_CAP_ANY)
                CV_Error_(Error::StsError, ("%s: unknown event file format (first bytes match no supported "
                                            "format)", path.c_str()));
        }
        for (const Backend& b : kBackends)
            if (b.api == backend)
                return b.open(path, opt);
        CV_Error_(Error::StsBadArg, ("%s: apiPreference %d is not an available EventCapture back-end", path.c_str(), api));
    }

    // How the source was opened, to reopen it for a backward seek.
    String openedPath, openedRight;
    int openedApi = EVENT_CAP_ANY;
    bool openedStereoPair = false;

    void open(const String& path, int api)
    {
        close();
        lastError.clear();
        openedPath = path;
        openedRight.clear();
        openedApi = api;
        openedStereoPair = false;
        Ptr<EventReader> r = makeReader(path, api, options);
        if (r->isStereo())
        {
            // One file, two cameras: read each camera with its own reader and merge them in time.
            ReaderOptions left = options, right = options;
            left.cameraFilter = CAMERA_LEFT;
            right.cameraFilter = CAMERA_RIGHT;
            r = openStereoMerge(makeReader(path, api, left), makeReader(path, api, right), rightTimeOffset, true);
        }
        start(r, path);
    }

    void openStereo(const String& leftPath, const String& rightPath, int api)
    {
        close();
        lastError.clear();
        openedPath = leftPath;
        openedRight = rightPath;
        openedApi = api;
        openedStereoPair = true;
        String leftSelector, rightSelector;
        const bool leftLive = isLiveSource(leftPath, api, leftSelector);
        const bool rightLive = isLiveSource(rightPath, api, rightSelector);
        if (leftLive != rightLive)
            CV_Error_(Error::StsBadArg, ("openStereo(%s, %s): one live camera and one file cannot be merged in time",
                                         leftPath.c_str(), rightPath.c_str()));
        if (leftLive)
        {
            start(openDavisStereo(leftPath, leftSelector, rightPath, rightSelector, options, rightTimeOffset),
                  leftPath + " + " + rightPath);
            return;
        }
        Ptr<EventReader> l = makeReader(leftPath, api, options), r = makeReader(rightPath, api, options);
        if (l->isStereo() || r->isStereo())
            CV_Error_(Error::StsBadArg, ("openStereo(%s, %s): each file must hold one camera",
                                         leftPath.c_str(), rightPath.c_str()));
        const Size leftSize = l->sensorSize(), rightSize = r->sensorSize();
        if (!leftSize.empty() && !rightSize.empty() && leftSize != rightSize)
            CV_Error_(Error::StsBadArg, ("openStereo(%s, %s): the left file's sensor is %d x %d, the right one's %d x %d; "
                                         "the cameras of a stereo pair have one size", leftPath.c_str(), rightPath.c_str(),
                                         leftSize.width, leftSize.height, rightSize.width, rightSize.height));
        start(openStereoMerge(l, r, rightTimeOffset), leftPath + " + " + rightPath);
    }

    void start(const Ptr<EventReader>& r, const String& name)
    {
        reader = r;
        source = name;
        sensor = options.sensorSize.empty() ? reader->sensorSize() : options.sensorSize;
        readerDone = false;
        if (fill())
            firstTimestamp = pending[pendingPos].t;
    }

    /** How far delivery has gone through the source, 0..1 (-1 when unknown). */
    double progress() const
    {
        if (!reader)
            return -1.0;
        return progressThroughChunk(chunkStartProgress, chunkEndProgress, pendingPos, pending.size(),
                                    reader->progress());
    }

    // Moves the next decoded chunk through the bounds and time-order checks into `pending`.
    // Returns false when nothing is left; with @p wait false, also when a live source has nothing right now
    // (it is asked once, which waits a little).
    bool fill(bool wait = true)
    {
        if (pendingPos < pending.size())
            return true;
        pending.clear();
        pendingPos = 0;
        if (!readerDone)
            chunkStartProgress = reader->progress();
        for (bool first = true; pending.empty() && !readerDone && (wait || first); first = false)
        {
            raw.clear();
            try
            {
                if (!reader->next(raw))
                {
                    readerDone = true;
                    const String why = reader->endMessage();  // e.g. a camera unplugged: a status, not an error
                    if (!why.empty())
                        lastError = why;
                }
            }
            catch (const cv::Exception& e)
            {
                // The events decoded before the error (a file cut off inside a line or a record) are the user's
                // data: they are delivered, then the error is raised (raiseDeferredError).
                deferError(e);
            }
            chunkEndProgress = reader->progress();
            takeTriggers();
            try
            {
                accept();
            }
            catch (const cv::Exception& e)
            {
                deferError(e);
            }
        }
        return !pending.empty();
    }

    void takeTriggers()
    {
        const size_t before = pendingTriggers.size();
        reader->takeTriggers(pendingTriggers);
        triggersRead += (int64)(pendingTriggers.size() - before);
        auto older = [](const EventTrigger& a, const EventTrigger& b) { return a.t < b.t; };
        if (!std::is_sorted(pendingTriggers.begin(), pendingTriggers.end(), older))
            std::stable_sort(pendingTriggers.begin(), pendingTriggers.end(), older);
    }

    // How many of the pending triggers come before @p limit (or up to it, @p inclusive).
    size_t triggersBefore(int64 limit, bool inclusive) const
    {
        size_t n = 0;
        while (n < pendingTriggers.size() && (pendingTriggers[n].t < limit || (inclusive && pendingTriggers[n].t == limit)))
            n++;
        return n;
    }

    // The grabbed packet's triggers: those before @p limit (or up to it, @p inclusive), or all that are left
    // once the stream has ended.
    void takePacketTriggers(int64 limit, bool inclusive)
    {
        const bool ended = pendingPos >= pending.size() && readerDone;
        const size_t n = ended ? pendingTriggers.size() : triggersBefore(limit, inclusive);
        batchTriggers.assign(pendingTriggers.begin(), pendingTriggers.begin() + n);
        pendingTriggers.erase(pendingTriggers.begin(), pendingTriggers.begin() + n);
    }

    void deferError(const cv::Exception& e)
    {
        if (deferredError.empty())
        {
            deferredError = e.err;
            deferredCode = e.code;
        }
        readerDone = true;
    }

    void raiseDeferredError()
    {
        if (deferredCode == Error::StsOk)
            return;
        const String msg = deferredError;
        const int code = deferredCode;
        deferredError.clear();
        deferredCode = Error::StsOk;
        cv::error(code, msg, "EventCapture::read", __FILE__, __LINE__);
    }

    void accept()
    {
        const bool bounded = !sensor.empty();
        for (const Event& e0 : raw)
        {
            Event e = e0;
            if (bounded ? !onSensor(e.x, e.y, sensor)
                        : (e.x < 0 || e.y < 0))
            {
                rejectedOutside++;
                continue;
            }
            if (haveLast && e.t < lastAccepted)
            {
                backwards++;
                switch (timeOrderPolicy)
                {
                case EVENT_TIME_ORDER_KEEP: break;
                case EVENT_TIME_ORDER_CLAMP: e.t = lastAccepted; break;
                case EVENT_TIME_ORDER_DROP: continue;
                default:
                    CV_Error_(Error::StsError, ("%s: event %lld goes back in time (t=%lld us after %lld us)",
                                                source.c_str(), (long long)(delivered + (int64)(pending.size() - pendingPos)),
                                                (long long)e.t, (long long)lastAccepted));
                }
            }
            if (!haveLast || e.t > lastAccepted)
                lastAccepted = e.t;
            haveLast = true;
            pending.push_back(e);
        }
    }

    bool grab()
    {
        batch.clear();
        batchTriggers.clear();
        grabbed = false;
        if (!reader)
            return false;
        // A live camera's packet is what it has sent so far: a batch does not wait to be full, and a window
        // closes once the camera's clock has passed its end, events or not.
        const bool live = reader->isLive();
        if (batchEvents > 0)
        {
            while ((int64)batch.size() < batchEvents && fill(!live || batch.empty()))
            {
                const size_t take = std::min((size_t)(batchEvents - (int64)batch.size()), pending.size() - pendingPos);
                batch.insert(batch.end(), pending.begin() + pendingPos, pending.begin() + pendingPos + take);
                pendingPos += take;
            }
            if (batch.empty())
                raiseDeferredError();
            if (!live)
                fill();  // whether this was the last batch: then it takes the triggers after it
            grabbed = !batch.empty();
            if (grabbed)
                takePacketTriggers(batch.back().t, true);
            return grabbed;
        }
        // A file's stream ends with its last event; a camera's once it is gone (its windows may be empty).
        if ((!windowStarted || !live) ? !fill() : (pendingPos >= pending.size() && readerDone))
        {
            raiseDeferredError();
            return false;  // nothing left: the stream has ended
        }
        if (!windowStarted)
        {
            windowStart = pending[pendingPos].t;
            windowStarted = true;
        }
        const int64 end = windowStart + windowUs;
        for (;;)
        {
            if (pendingPos < pending.size())
            {
                size_t i = pendingPos;
                while (i < pending.size() && pending[i].t < end)
                    i++;
                batch.insert(batch.end(), pending.begin() + pendingPos, pending.begin() + i);
                pendingPos = i;
                if (i < pending.size())
                    break;  // an event at or after the end: the window is complete
            }
            if (live && reader->timeHorizon() >= end)
                break;
            if (!fill(!live) && readerDone)
                break;
        }
        windowStart = end;
        takePacketTriggers(end, false);
        grabbed = true;  // an empty window is still a window
        return true;
    }

    // Seeks by decoding: events before @p target are skipped (not delivered, not counted); a target before
    // the current position reopens the source first. Every format supports it; the cost is the decoding.
    void seek(int64 target)
    {
        const int64 position = windowStarted ? windowStart : (lastDelivered >= 0 ? lastDelivered + 1 : INT64_MIN);
        if (target < position)
        {
            if (openedStereoPair)
                openStereo(openedPath, openedRight, openedApi);
            else
                open(openedPath, openedApi);
        }
        while (fill() && pending[pendingPos].t < target)
            pendingPos++;
        pendingTriggers.erase(pendingTriggers.begin(), pendingTriggers.begin() + triggersBefore(target, false));
        windowStart = target;
        windowStarted = true;
    }

    void retrieve(OutputArray events)
    {
        if (batch.empty())
            events.release();
        else
            Mat(batch).copyTo(events);
        delivered += (int64)batch.size();
        if (!batch.empty())
            lastDelivered = batch.back().t;
        batch.clear();
    }
};

EventCapture::EventCapture() : impl(makePtr<Impl>()) {}

EventCapture::EventCapture(const String& source, int apiPreference) : impl(makePtr<Impl>())
{
    open(source, apiPreference);
}

EventCapture::~EventCapture() {}

namespace {

// Runs an opening step; on failure the capture is closed and, as the exception mode says, the error is raised
// or only recorded (getLastError()) and false returned.
template<typename Open>
bool guardedOpen(EventCapture::Impl& impl, Open open)
{
    try
    {
        open();
        return true;
    }
    catch (const cv::Exception& e)
    {
        impl.close();
        impl.lastError = e.err;
        if (impl.exceptionMode)
            throw;
        return false;
    }
}

// Runs a change of the open source (seek, a camera setting); on failure, as the exception mode says, the error
// is raised or only recorded (getLastError()) and false returned. The source stays open.
template<typename Change>
bool guardedChange(EventCapture::Impl& impl, Change change)
{
    try
    {
        return change();
    }
    catch (const cv::Exception& e)
    {
        impl.lastError = e.err;
        if (impl.exceptionMode)
            throw;
        return false;
    }
}

}  // namespace

bool EventCapture::open(const String& source, int apiPreference)
{
    return guardedOpen(*impl, [&]() { impl->open(source, apiPreference); });
}

bool EventCapture::openStereo(const String& leftSource, const String& rightSource, int apiPreference)
{
    return guardedOpen(*impl, [&]() { impl->openStereo(leftSource, rightSource, apiPreference); });
}

bool EventCapture::open(const String& source, int apiPreference, const std::vector<int>& params)
{
    if (params.size() % 2 != 0)
        CV_Error_(Error::StsBadArg, ("%s: EventCapture::open: params must be (property id, value) pairs", source.c_str()));
    for (size_t i = 0; i < params.size(); i += 2)
        if (!set(params[i], params[i + 1]))
            CV_Error_(Error::StsBadArg, ("%s: EventCapture::open: property %d cannot be set to %d", source.c_str(),
                                         params[i], params[i + 1]));
    return open(source, apiPreference);
}

bool EventCapture::isOpened() const { return !impl->reader.empty(); }

void EventCapture::release() { impl->close(); }

bool EventCapture::grab()
{
    try
    {
        return impl->grab();
    }
    catch (const cv::Exception& e)
    {
        impl->lastError = e.err;
        impl->readerDone = true;
        impl->pending.clear();
        impl->pendingPos = 0;
        impl->batchTriggers.clear();
        if (impl->exceptionMode)
            throw;
        return false;
    }
}

bool EventCapture::retrieve(OutputArray events)
{
    if (!impl->grabbed)
    {
        events.release();
        return false;
    }
    impl->retrieve(events);
    return true;
}

bool EventCapture::retrieveTriggers(OutputArray triggers)
{
    if (!impl->grabbed)
    {
        triggers.release();
        return false;
    }
    if (impl->batchTriggers.empty())
        triggers.release();
    else
        Mat(impl->batchTriggers).copyTo(triggers);
    return true;
}

bool EventCapture::read(OutputArray events)
{
    if (!grab())
    {
        events.release();
        return false;
    }
    return retrieve(events);
}

double EventCapture::get(int propId) const
{
    const Impl& s = *impl;
    switch (propId)
    {
    case EVENT_CAP_PROP_SENSOR_WIDTH: return s.reader ? s.sensor.width : s.options.sensorSize.width;
    case EVENT_CAP_PROP_SENSOR_HEIGHT: return s.reader ? s.sensor.height : s.options.sensorSize.height;
    case EVENT_CAP_PROP_WINDOW_US: return (double)s.windowUs;
    case EVENT_CAP_PROP_BATCH_EVENTS: return (double)s.batchEvents;
    case EVENT_CAP_PROP_POS_US:
        if (s.batchEvents == 0 && s.windowStarted)
            return (double)s.windowStart;
        return (double)(s.lastDelivered >= 0 ? s.lastDelivered : s.firstTimestamp);
    case EVENT_CAP_PROP_EVENTS_DELIVERED: return (double)s.delivered;
    case EVENT_CAP_PROP_DURATION_US: return s.reader ? (double)s.reader->durationUs() : -1.0;
    case EVENT_CAP_PROP_FIRST_TIMESTAMP_US: return (double)s.firstTimestamp;
    case EVENT_CAP_PROP_REJECTED_OUTSIDE: return (double)s.rejectedOutside;
    case EVENT_CAP_PROP_TIME_BACKWARDS: return (double)s.backwards;
    case EVENT_CAP_PROP_TIME_ORDER_POLICY: return s.timeOrderPolicy;
    case EVENT_CAP_PROP_EXCEPTION_MODE: return s.exceptionMode ? 1 : 0;
    case EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US: return (double)s.rightTimeOffset;
    case EVENT_CAP_PROP_STEREO: return s.reader && s.reader->isStereo() ? 1 : 0;
    case EVENT_CAP_PROP_SKIPPED: return s.reader ? (double)s.reader->skippedEvents() : 0.0;
    case EVENT_CAP_PROP_PROGRESS: return s.progress();
    case EVENT_CAP_PROP_TRIGGERS: return (double)s.triggersRead;
    case EVENT_CAP_PROP_TEXT_TIME_UNIT: return s.options.textTimeUnit;
    case EVENT_CAP_PROP_TEXT_ONE_BASED: return s.options.textOneBased ? 1 : 0;
    case EVENT_CAP_PROP_TEXT_COLUMN_T: return s.options.textColumnT;
    case EVENT_CAP_PROP_TEXT_COLUMN_X: return s.options.textColumnX;
    case EVENT_CAP_PROP_TEXT_COLUMN_Y: return s.options.textColumnY;
    case EVENT_CAP_PROP_TEXT_COLUMN_P: return s.options.textColumnP;
    case EVENT_CAP_PROP_TEXT_COLUMN_CAMERA: return s.options.textColumnCamera;
    case EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE: return s.options.textLeftCameraValue;
    case EVENT_CAP_PROP_QUEUE_CAPACITY: return s.options.liveQueueCapacity;
    default:
    {
        double v = 0;
        if (s.reader && s.reader->getProperty(propId, v))
            return v;
        for (const auto& setting : s.options.deviceSettings)  // set before open
            if (setting.first == propId)
                v = setting.second;
        return v;
    }
    }
}

bool EventCapture::set(int propId, double value)
{
    Impl& s = *impl;
    const int v = cvRound(value);
    auto column = [&](int& field) {
        if (v < 0 || v > 15)
            return false;
        field = v;
        return true;
    };
    switch (propId)
    {
    case EVENT_CAP_PROP_SENSOR_WIDTH:
        if (v < 0 || v > 32768) return false;
        s.options.sensorSize.width = v;
        if (s.reader && v > 0) s.sensor.width = v;
        return true;
    case EVENT_CAP_PROP_SENSOR_HEIGHT:
        if (v < 0 || v > 32768) return false;
        s.options.sensorSize.height = v;
        if (s.reader && v > 0) s.sensor.height = v;
        return true;
    case EVENT_CAP_PROP_WINDOW_US:
        if (!(value >= 1)) return false;
        s.windowUs = (int64)value;
        return true;
    case EVENT_CAP_PROP_BATCH_EVENTS:
        if (value < 0) return false;
        s.batchEvents = (int64)value;
        return true;
    case EVENT_CAP_PROP_TIME_ORDER_POLICY:
        if (v < EVENT_TIME_ORDER_KEEP || v > EVENT_TIME_ORDER_ERROR) return false;
        s.timeOrderPolicy = v;
        return true;
    case EVENT_CAP_PROP_EXCEPTION_MODE: s.exceptionMode = v != 0; return true;
    case EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US: s.rightTimeOffset = (int64)std::llround(value); return true;
    case EVENT_CAP_PROP_POS_US:
    {
        String selector;
        if (!s.reader || Impl::isLiveSource(s.openedPath, s.openedApi, selector))
            return false;  // a live camera cannot seek
        return guardedChange(s, [&]() {
            s.seek((int64)std::llround(value));
            return true;
        });
    }
    case EVENT_CAP_PROP_TEXT_TIME_UNIT:
        if (v < EVENT_TIME_UNIT_AUTO || v > EVENT_TIME_UNIT_NANOSECONDS) return false;
        s.options.textTimeUnit = v;
        return true;
    case EVENT_CAP_PROP_TEXT_ONE_BASED: s.options.textOneBased = v != 0; return true;
    case EVENT_CAP_PROP_TEXT_COLUMN_T: return column(s.options.textColumnT);
    case EVENT_CAP_PROP_TEXT_COLUMN_X: return column(s.options.textColumnX);
    case EVENT_CAP_PROP_TEXT_COLUMN_Y: return column(s.options.textColumnY);
    case EVENT_CAP_PROP_TEXT_COLUMN_P: return column(s.options.textColumnP);
    case EVENT_CAP_PROP_TEXT_COLUMN_CAMERA:
        if (v < -2 || v > 15) return false;
        s.options.textColumnCamera = v;
        return true;
    case EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE:
        if (v != 0 && v != 1) return false;
        s.options.textLeftCameraValue = v;
        return true;
    case EVENT_CAP_PROP_QUEUE_CAPACITY:
        if (v < 1) return false;
        s.options.liveQueueCapacity = v;
        return true;
    default:
        if ((propId < EVENT_CAP_PROP_DEVICE_BIAS_PRESET || propId > EVENT_CAP_PROP_DEVICE_TIMESTAMP_RESET) &&
            propId != EVENT_CAP_PROP_DEVICE_EXTERNAL_INPUT)
            return false;
        if (!s.reader)
        {
            s.options.deviceSettings.emplace_back(propId, value);  // applied by open() of a live camera
            return true;
        }
        return guardedChange(s, [&]() { return s.reader->setProperty(propId, value); });
    }
}

String EventCapture::getBackendName() const { return impl->reader ? impl->reader->name() : String(); }
String EventCapture::getSource() const { return impl->source; }
String EventCapture::getLastError() const { return impl->lastError; }
Size EventCapture::getSensorSize() const { return impl->reader ? impl->sensor : impl->options.sensorSize; }

}  // namespace event
}  // namespace cv
