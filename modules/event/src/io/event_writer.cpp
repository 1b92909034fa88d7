// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// EventWriter: text and AEDAT 4.0. The AEDAT 4.0 FlatBuffers are laid out by hand (fixed schemas, see
// aedat4_codec.hpp), with the alignment FlatBuffers readers verify: 8 bytes for the int64 header field
// and for the 16-byte event structs.

#include "precomp.hpp"
#include "io/aedat4_codec.hpp"
#include "io/file_input.hpp"
#include "common/sensor_bounds.hpp"

#include <cerrno>
#include <charconv>
#include <cstdio>

namespace cv {
namespace event {

using namespace detail;

namespace {

template<typename T>
void put(std::vector<uchar>& b, size_t at, T v)
{
    std::memcpy(b.data() + at, &v, sizeof(T));
}

// IOHeader {compression: int32, dataTablePosition: int64, infoNode: string}, size-prefixed.
std::vector<uchar> buildIOHeader(int compression, const std::string& info)
{
    // [0] root offset -> 24, [4] "IOHE", [8] vtable (5 x u16), [24] table: soffset, compression,
    // dataTablePosition (8-aligned at 32), uoffset to the string at 44.
    const size_t stringAt = 44;
    const size_t total = (stringAt + 4 + info.size() + 1 + 3) & ~(size_t)3;
    std::vector<uchar> b(4 + total, 0);
    const size_t o = 4;  // after the u32 size prefix
    put<uint32_t>(b, 0, (uint32_t)total);
    put<uint32_t>(b, o + 0, 24);
    std::memcpy(b.data() + o + 4, "IOHE", 4);
    put<uint16_t>(b, o + 8, 10);   // vtable size
    put<uint16_t>(b, o + 10, 20);  // table size
    put<uint16_t>(b, o + 12, 4);   // compression
    put<uint16_t>(b, o + 14, 8);   // dataTablePosition
    put<uint16_t>(b, o + 16, 16);  // infoNode
    put<int32_t>(b, o + 24, 24 - 8);
    put<int32_t>(b, o + 28, compression);
    put<int64>(b, o + 32, -1);     // no data table: readers scan the packets
    put<uint32_t>(b, o + 40, (uint32_t)(stringAt - 40));
    put<uint32_t>(b, o + stringAt, (uint32_t)info.size());
    std::memcpy(b.data() + o + stringAt + 4, info.data(), info.size());
    return b;
}

// EventPacket {elements: [Event (16-byte struct)]}, size-prefixed: prefix, root offset, "EVTS", vtable,
// table, vector (elements 8-aligned at byte 32).
std::vector<uchar> buildEventPacket(const std::vector<Event>& events)
{
    const size_t n = events.size();
    std::vector<uchar> b(32 + 16 * n, 0);
    put<uint32_t>(b, 0, (uint32_t)(b.size() - 4));
    put<uint32_t>(b, 4, 20 - 4);
    std::memcpy(b.data() + 8, "EVTS", 4);
    put<uint16_t>(b, 12, 6);
    put<uint16_t>(b, 14, 8);
    put<uint16_t>(b, 16, 4);
    put<int32_t>(b, 20, 20 - 12);
    put<uint32_t>(b, 24, 28 - 24);
    put<uint32_t>(b, 28, (uint32_t)n);
    for (size_t i = 0; i < n; i++)
    {
        const size_t at = 32 + 16 * i;
        put<int64>(b, at, events[i].t);
        put<int16_t>(b, at + 8, events[i].x);
        put<int16_t>(b, at + 10, events[i].y);
        b[at + 12] = events[i].p ? 1 : 0;
    }
    return b;
}

std::string infoNode(Size size, int compression, int streams)
{
    std::string xml = "<dv version=\"2.0\">\n    <node name=\"outInfo\" path=\"/mainloop/Recorder/outInfo/\">\n";
    for (int s = 0; s < streams; s++)
    {
        const std::string id = std::to_string(s), path = "/mainloop/Recorder/outInfo/" + id + "/";
        xml += "        <node name=\"" + id + "\" path=\"" + path + "\">\n"
               "            <attr key=\"compression\" type=\"string\">" + aedat4CompressionName(compression) + "</attr>\n"
               "            <attr key=\"originalModuleName\" type=\"string\">opencv_event</attr>\n"
               "            <attr key=\"originalOutputName\" type=\"string\">" + (s == 0 ? "events" : "events_right") + "</attr>\n"
               "            <attr key=\"typeDescription\" type=\"string\">Array of events (polarity ON/OFF).</attr>\n"
               "            <attr key=\"typeIdentifier\" type=\"string\">EVTS</attr>\n"
               "            <node name=\"info\" path=\"" + path + "info/\">\n"
               "                <attr key=\"sizeX\" type=\"int\">" + std::to_string(size.width) + "</attr>\n"
               "                <attr key=\"sizeY\" type=\"int\">" + std::to_string(size.height) + "</attr>\n"
               "                <attr key=\"source\" type=\"string\">opencv_event_" + (s == 0 ? "left" : "right") + "</attr>\n"
               "                <attr key=\"tsOffset\" type=\"long\">0</attr>\n"
               "            </node>\n"
               "        </node>\n";
    }
    return xml + "    </node>\n</dv>\n";
}

}  // namespace

class EventWriter::Impl
{
public:
    // options
    bool stereo = false;
    int compression = AEDAT4_LZ4;
    int packetEvents = 4096;

    std::FILE* file = nullptr;
    String path;
    int format = EVENT_FILE_TEXT;
    Size size;
    int64 written = 0;
    int64 lastT[2] = { 0, 0 };
    bool haveLast[2] = { false, false };
    std::vector<Event> pending[2];  // AEDAT4: events of each stream not yet in a packet
    std::string line;

    ~Impl() { close(false); }

    void open(const String& p, Size s, int fmt)
    {
        close(false);
        if (s.width <= 0 || s.height <= 0 || s.width > 32768 || s.height > 32768)
            CV_Error_(Error::StsBadArg, ("%s: sensor size %d x %d is not valid", p.c_str(), s.width, s.height));
        if (fmt == EVENT_FILE_AUTO)
        {
            fmt = fileExtension(p) == "aedat4" ? EVENT_FILE_AEDAT4 : EVENT_FILE_TEXT;
        }
        if (fmt != EVENT_FILE_TEXT && fmt != EVENT_FILE_AEDAT4)
            CV_Error_(Error::StsBadArg, ("%s: unknown EventFileFormat %d", p.c_str(), fmt));
        if (fmt == EVENT_FILE_AEDAT4 && !aedat4CompressionSupported(compression))
            CV_Error_(Error::StsBadArg, ("%s: %s compression is not available in this build", p.c_str(),
                                         aedat4CompressionName(compression)));
        file = std::fopen(p.c_str(), "wb");
        if (!file)
            CV_Error_(Error::StsError, ("%s: cannot create: %s", p.c_str(), std::strerror(errno)));
        path = p;
        format = fmt;
        size = s;
        written = 0;
        haveLast[0] = haveLast[1] = false;
        if (format == EVENT_FILE_TEXT)
        {
            const std::string head = std::string("# opencv_event events: t_us x y p") + (stereo ? " camera" : "") +
                                     "; first line: sensor width height\n" + std::to_string(s.width) + " " +
                                     std::to_string(s.height) + "\n";
            output(head.data(), head.size());
        }
        else
        {
            output(kAedat4Magic, kAedat4MagicSize);
            const std::vector<uchar> h = buildIOHeader(compression, infoNode(s, compression, stereo ? 2 : 1));
            output(h.data(), h.size());
        }
    }

    void output(const void* data, size_t n)
    {
        if (std::fwrite(data, 1, n, file) != n)
            CV_Error_(Error::StsError, ("%s: write failed: %s", path.c_str(), std::strerror(errno)));
    }

    void write(InputArray events)
    {
        if (!file)
            CV_Error(Error::StsError, "EventWriter::write: no file is open");
        Mat_<Event> ev = getEventMat(events);
        for (int i = 0; i < (int)ev.total(); i++)
        {
            const Event& e = ev(i);
            if (!onSensor(e.x, e.y, size))
                CV_Error_(Error::StsOutOfRange, ("%s: event (x=%d, y=%d, t=%lld) is outside the %d x %d sensor",
                                                 path.c_str(), e.x, e.y, (long long)e.t, size.width, size.height));
            const int c = e.camera;
            if (c > 1 || (c == CAMERA_RIGHT && !stereo))
                CV_Error_(Error::StsBadArg, ("%s: event with camera %d; set EVENT_WRITER_PROP_STEREO to write a "
                                             "stereo stream", path.c_str(), c));
            if (haveLast[c] && e.t < lastT[c])
                CV_Error_(Error::StsBadArg, ("%s: event t=%lld of camera %d goes back in time (after %lld)",
                                             path.c_str(), (long long)e.t, c, (long long)lastT[c]));
            lastT[c] = e.t;
            haveLast[c] = true;
            if (format == EVENT_FILE_TEXT)
                writeLine(e);
            else
            {
                pending[c].push_back(e);
                if ((int)pending[c].size() >= packetEvents)
                    flushPacket(c);
            }
            written++;
        }
    }

    void writeLine(const Event& e)
    {
        // std::to_chars: no locale, no format parsing; several times faster than snprintf on this hot path.
        char buf[80];
        char* p = std::to_chars(buf, buf + 24, (long long)e.t).ptr;
        *p++ = ' ';
        p = std::to_chars(p, p + 8, (int)e.x).ptr;
        *p++ = ' ';
        p = std::to_chars(p, p + 8, (int)e.y).ptr;
        *p++ = ' ';
        *p++ = (char)('0' + e.p);
        if (stereo)
        {
            *p++ = ' ';
            *p++ = (char)('0' + e.camera);
        }
        *p++ = '\n';
        output(buf, (size_t)(p - buf));
    }

    void flushPacket(int stream)
    {
        if (pending[stream].empty())
            return;
        const std::vector<uchar> fb = buildEventPacket(pending[stream]);
        const std::vector<uchar> payload = aedat4Compress(compression, fb.data(), fb.size());
        const int32_t head[2] = { stream, (int32_t)payload.size() };
        output(head, sizeof(head));
        output(payload.data(), payload.size());
        pending[stream].clear();
    }

    void close(bool raise)
    {
        if (!file)
            return;
        std::FILE* f = file;
        try
        {
            if (format == EVENT_FILE_AEDAT4)
            {
                flushPacket(0);
                flushPacket(1);
            }
        }
        catch (...)
        {
            std::fclose(f);
            file = nullptr;
            if (raise)
                throw;
            return;
        }
        file = nullptr;
        const bool ok = std::fclose(f) == 0;
        if (!ok && raise)
            CV_Error_(Error::StsError, ("%s: closing failed: %s", path.c_str(), std::strerror(errno)));
    }
};

EventWriter::EventWriter() : impl(makePtr<Impl>()) {}

EventWriter::EventWriter(const String& path, Size sensorSize, int format) : impl(makePtr<Impl>())
{
    open(path, sensorSize, format);
}

EventWriter::~EventWriter() {}

bool EventWriter::open(const String& path, Size sensorSize, int format)
{
    impl->open(path, sensorSize, format);
    return true;
}

bool EventWriter::isOpened() const { return impl->file != nullptr; }

void EventWriter::write(InputArray events) { impl->write(events); }

void EventWriter::release() { impl->close(true); }

bool EventWriter::set(int propId, double value)
{
    const int v = cvRound(value);
    switch (propId)
    {
    case EVENT_WRITER_PROP_STEREO: impl->stereo = v != 0; return true;
    case EVENT_WRITER_PROP_COMPRESSION:
        if (v < AEDAT4_NONE || v > AEDAT4_ZSTD_HIGH) return false;
        impl->compression = v;
        return true;
    case EVENT_WRITER_PROP_PACKET_EVENTS:
        if (v < 1) return false;
        impl->packetEvents = v;
        return true;
    default: return false;
    }
}

double EventWriter::get(int propId) const
{
    switch (propId)
    {
    case EVENT_WRITER_PROP_STEREO: return impl->stereo ? 1 : 0;
    case EVENT_WRITER_PROP_COMPRESSION: return impl->compression;
    case EVENT_WRITER_PROP_PACKET_EVENTS: return impl->packetEvents;
    case EVENT_WRITER_PROP_EVENTS_WRITTEN: return (double)impl->written;
    default: return 0;
    }
}

}  // namespace event
}  // namespace cv
