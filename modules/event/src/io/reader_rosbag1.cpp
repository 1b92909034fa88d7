// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// ROS1 bag v2.0 without ROS (layout: doc/formats.md, "ROS1 bag"). Records {u32 header length, header fields
// "name=value", u32 data length, data}; chunks (op 5) hold compressed records (none / bz2 / lz4 frames).
// The connection records at the index position name the topics; event topics are those of type
// dvs_msgs/EventArray or event_camera_msgs/EventPacket (or its former name event_array_msgs/EventArray),
// sorted by name: the first is the left camera,
// a second one makes the bag a stereo recording. The walk goes chunk by chunk: memory is one chunk.

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/file_input.hpp"
#include "io/ros_event_decoder.hpp"

#include <map>

#ifdef OPENCV_EVENT_HAVE_LZ4
#include <lz4frame.h>
#endif
#ifdef OPENCV_EVENT_HAVE_BZIP2
#include <bzlib.h>
#endif

namespace cv {
namespace event {
namespace detail {

namespace {

const char kBagMagic[] = "#ROSBAG V2.0\n";
const size_t kMaxRecordBytes = (size_t)1 << 30;  // a corrupt length must not be allocated

const char* kDvsEventArray = "dvs_msgs/EventArray";
const char* kEventPacket = "event_camera_msgs/EventPacket";
const char* kLegacyEventArray = "event_array_msgs/EventArray";  // EventPacket before its 2023 rename: same layout
const char* kDvsMd5 = "5e8beee5a6c107e504c2e78903c224b8";             // Header, height, width, events
const char* kDvsForkMd5 = "732c9cc0676a970b9aa2873b0d444ac2";         // Header, events, height, width

bool isEventPacket(const std::string& type) { return type == kEventPacket || type == kLegacyEventArray; }
/** A connection of one of the message types read as events. */
bool isEventType(const std::string& type) { return type == kDvsEventArray || isEventPacket(type); }

typedef std::map<std::string, std::string> Fields;

// Parses "u32 length, name=value" fields.
Fields parseFields(const uchar* p, size_t n, const String& path, int64 offset)
{
    Fields f;
    size_t i = 0;
    while (i < n)
    {
        if (n - i < 4)
            formatError(path, offset, "truncated record header field");
        uint32_t len;
        std::memcpy(&len, p + i, 4);
        i += 4;
        if (len > n - i)
            formatError(path, offset, format("record header field of %u bytes overruns its header", len));
        const std::string kv(reinterpret_cast<const char*>(p + i), len);
        const size_t eq = kv.find('=');
        if (eq == std::string::npos)
            formatError(path, offset, "record header field without '='");
        f[kv.substr(0, eq)] = kv.substr(eq + 1);
        i += len;
    }
    return f;
}

template<typename T>
T fieldAs(const Fields& f, const char* name, const String& path, int64 offset)
{
    auto it = f.find(name);
    if (it == f.end() || it->second.size() != sizeof(T))
        formatError(path, offset, format("record header lacks a %zu-byte \"%s\" field", sizeof(T), name));
    T v;
    std::memcpy(&v, it->second.data(), sizeof(T));
    return v;
}

struct Connection
{
    std::string topic, type, md5;
};

class RosBag1Reader CV_FINAL : public EventReader
{
public:
    RosBag1Reader(const String& path, const ReaderOptions& options) : in_(path)
    {
        char magic[sizeof(kBagMagic) - 1];
        in_.readExact(magic, sizeof(magic), "the ROS bag magic line");
        if (std::memcmp(magic, kBagMagic, sizeof(magic)) != 0)
            formatError(path, 0, "not a ROS bag v2.0 (no \"#ROSBAG V2.0\" line)");
        Fields h;
        std::vector<uchar> data;
        const int64 at = in_.offset();
        if (!readRecord(h, data) || op(h, at) != 3)
            formatError(path, at, "the first record is not the bag header");
        const uint64_t indexPos = fieldAs<uint64_t>(h, "index_pos", path, at);
        dataStart_ = in_.offset();

        // The connections at the index position tell the event topics up front (stereo needs both).
        std::map<std::string, bool> eventTopics;
        if (indexPos > 0 && (in_.size() < 0 || (int64)indexPos < in_.size()))
        {
            in_.seek((int64)indexPos);
            for (;;)
            {
                const int64 pos = in_.offset();
                if (!readRecord(h, data))
                    break;
                if (op(h, pos) == 7)
                {
                    const Connection c = connection(h, data, pos);
                    if (isEventType(c.type))
                        eventTopics[c.topic] = true;
                }
            }
            in_.seek(dataStart_);
        }
        std::vector<std::string> topics;
        for (const auto& kv : eventTopics)
            topics.push_back(kv.first);
        if (indexPos > 0 && topics.empty())
            formatError(path, (int64)indexPos, "the bag has no dvs_msgs/EventArray or event_camera_msgs/EventPacket (or event_array_msgs/EventArray) topic");
        stereo_ = options.cameraFilter < 0 && topics.size() >= 2;
        const int pick = std::max(0, options.cameraFilter);
        if (!topics.empty())
        {
            if (pick >= (int)topics.size())
                formatError(path, (int64)indexPos, format("no event topic for camera %d", pick));
            topic_ = topics[pick];  // unindexed bags: the first event topic met
        }
        size_ = options.sensorSize;
        if (size_.empty())
            size_ = probeSize();
    }

    String name() const CV_OVERRIDE { return "ROSBAG1"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    double progress() const CV_OVERRIDE { return in_.progress(); }
    bool isStereo() const CV_OVERRIDE { return stereo_; }
    int64 skippedEvents() const CV_OVERRIDE { return decoder_.skipped(); }
    void takeTriggers(std::vector<EventTrigger>& out) CV_OVERRIDE { decoder_.takeTriggers(out); }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        const size_t before = out.size();
        while (out.size() == before)
        {
            if (chunkPos_ < chunk_.size())
            {
                walkChunkRecord(out);
                continue;
            }
            Fields h;
            const int64 at = in_.offset();
            if (!readRecord(h, record_))
                return false;
            const int o = op(h, at);
            if (o == 5)
                openChunk(h, at);
            else if (o == 7)
                remember(h, record_, at);
            else if (o == 2)
                message(h, record_.data(), record_.size(), at, out);
        }
        return true;
    }

private:
    // Reads one record at the current position; false at the end of the file.
    bool readRecord(Fields& h, std::vector<uchar>& data)
    {
        const int64 at = in_.offset();
        uint32_t len;
        const size_t got = in_.read(&len, 4);
        if (got == 0)
            return false;
        if (got != 4)
            formatError(in_.path(), at, "truncated record: no header length");
        checkLength(len, at, "record header");
        headerBuf_.resize(len);
        in_.readExact(headerBuf_.data(), len, "record header");
        h = parseFields(headerBuf_.data(), len, in_.path(), at);
        in_.readExact(&len, 4, "record data length");
        checkLength(len, at, "record data");
        data.resize(len);
        in_.readExact(data.data(), len, "record data");
        return true;
    }

    void checkLength(uint32_t len, int64 at, const char* what) const
    {
        if (len > kMaxRecordBytes || (in_.size() >= 0 && (int64)len > in_.size() - in_.offset()))
            formatError(in_.path(), at, format("%s claims %u bytes, more than the file holds", what, len));
    }

    int op(const Fields& h, int64 at) const { return fieldAs<uint8_t>(h, "op", in_.path(), at); }

    Connection connection(const Fields& h, const std::vector<uchar>& data, int64 at) const
    {
        Connection c;
        auto t = h.find("topic");
        c.topic = t == h.end() ? std::string() : t->second;
        const Fields d = parseFields(data.data(), data.size(), in_.path(), at);
        auto ty = d.find("type");
        auto md = d.find("md5sum");
        c.type = ty == d.end() ? std::string() : ty->second;
        c.md5 = md == d.end() ? std::string() : md->second;
        return c;
    }

    void remember(const Fields& h, const std::vector<uchar>& data, int64 at)
    {
        const uint32_t id = fieldAs<uint32_t>(h, "conn", in_.path(), at);
        const Connection c = connection(h, data, at);
        if (topic_.empty() && isEventType(c.type))
            topic_ = c.topic;  // unindexed bag: the first event topic
        connections_[id] = c;
    }

    void openChunk(const Fields& h, int64 at)
    {
        auto it = h.find("compression");
        const std::string compression = it == h.end() ? std::string("none") : it->second;
        const uint32_t size = fieldAs<uint32_t>(h, "size", in_.path(), at);
        if (size > kMaxRecordBytes)
            formatError(in_.path(), at, format("chunk claims %u uncompressed bytes", size));
        chunkAt_ = at;
        chunkPos_ = 0;
        if (compression == "none")
            chunk_.swap(record_);
        else if (compression == "lz4")
        {
#ifdef OPENCV_EVENT_HAVE_LZ4
            chunk_.resize(size);
            LZ4F_dctx* ctx = nullptr;
            LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION);
            size_t dst = size, src = record_.size();
            const size_t r = LZ4F_decompress(ctx, chunk_.data(), &dst, record_.data(), &src, nullptr);
            LZ4F_freeDecompressionContext(ctx);
            if (LZ4F_isError(r) || dst != size)
                formatError(in_.path(), at, format("corrupt lz4 chunk (%zu of %u bytes decoded)", dst, size));
#else
            formatError(in_.path(), at, "lz4 chunks need liblz4, not available in this build");
#endif
        }
        else if (compression == "bz2")
        {
#ifdef OPENCV_EVENT_HAVE_BZIP2
            chunk_.resize(size);
            unsigned int dst = size;
            const int r = BZ2_bzBuffToBuffDecompress(reinterpret_cast<char*>(chunk_.data()), &dst,
                                                     reinterpret_cast<char*>(record_.data()),
                                                     (unsigned int)record_.size(), 0, 0);
            if (r != BZ_OK || dst != size)
                formatError(in_.path(), at, format("corrupt bz2 chunk (libbz2 error %d)", r));
#else
            formatError(in_.path(), at, "bz2 chunks need libbz2, not available in this build");
#endif
        }
        else
            formatError(in_.path(), at, "unknown chunk compression \"" + compression + "\"");
    }

    // Walks one record inside the current chunk.
    void walkChunkRecord(std::vector<Event>& out)
    {
        const uchar* p = chunk_.data() + chunkPos_;
        const size_t left = chunk_.size() - chunkPos_;
        uint32_t hl, dl;
        if (left < 4 || (std::memcpy(&hl, p, 4), hl > left - 4) || left - 4 - hl < 4)
            formatError(in_.path(), chunkAt_, format("corrupt chunk: record at chunk byte %zu overruns the chunk", chunkPos_));
        const Fields h = parseFields(p + 4, hl, in_.path(), chunkAt_);
        std::memcpy(&dl, p + 4 + hl, 4);
        if (dl > left - 8 - hl)
            formatError(in_.path(), chunkAt_, format("corrupt chunk: record data at chunk byte %zu overruns the chunk", chunkPos_));
        const uchar* data = p + 8 + hl;
        chunkPos_ += 8 + hl + dl;
        const int o = op(h, chunkAt_);
        if (o == 7)
            remember(h, std::vector<uchar>(data, data + dl), chunkAt_);
        else if (o == 2)
            message(h, data, dl, chunkAt_, out);
    }

    void message(const Fields& h, const uchar* data, size_t n, int64 at, std::vector<Event>& out)
    {
        const uint32_t id = fieldAs<uint32_t>(h, "conn", in_.path(), at);
        auto it = connections_.find(id);
        if (it == connections_.end() || it->second.topic != topic_)
            return;
        const Connection& c = it->second;
        MessageCursor m(data, n, in_.path(), at);
        m.read<uint32_t>("header seq");
        m.read<uint32_t>("header stamp");
        m.read<uint32_t>("header stamp");
        m.string("header frame_id", false);
        if (isEventPacket(c.type))
        {
            const uint32_t height = m.read<uint32_t>("height"), width = m.read<uint32_t>("width");
            note(width, height);
            m.read<uint64_t>("seq");
            const uint64_t timeBase = m.read<uint64_t>("time_base");
            const std::string encoding = m.string("encoding", false);
            m.read<uint8_t>("is_bigendian");
            const uint32_t len = m.read<uint32_t>("events length");
            decoder_.decodePacket(encoding, m.bytes(len, "events"), len, timeBase, out, in_.path(), at);
            return;
        }
        if (c.md5 == kDvsMd5)
        {
            const uint32_t height = m.read<uint32_t>("height"), width = m.read<uint32_t>("width");
            note(width, height);
            const uint32_t count = m.read<uint32_t>("event count");
            if (count > m.remaining() / 13)
                formatError(in_.path(), at, format("EventArray claims %u events, more than the message holds", count));
            RosEventDecoder::decodeDvsEvents(m.bytes((size_t)count * 13, "events"), count, out);
        }
        else if (c.md5 == kDvsForkMd5)
        {
            const uint32_t count = m.read<uint32_t>("event count");
            if (count > m.remaining() / 13)
                formatError(in_.path(), at, format("EventArray claims %u events, more than the message holds", count));
            RosEventDecoder::decodeDvsEvents(m.bytes((size_t)count * 13, "events"), count, out);
            const uint32_t height = m.read<uint32_t>("height"), width = m.read<uint32_t>("width");
            note(width, height);
        }
        else
            formatError(in_.path(), at, "dvs_msgs/EventArray with unknown definition (md5 " + c.md5 + ")");
    }

    void note(uint32_t width, uint32_t height)
    {
        if (size_.empty() && width > 0 && height > 0 && width <= 32768 && height <= 32768)
            size_ = Size((int)width, (int)height);
    }

    // Decodes up to the first event message of the topic for its width / height, then rewinds.
    Size probeSize()
    {
        std::vector<Event> scratch;
        for (int k = 0; k < 100000 && size_.empty() && scratch.empty(); k++)
            if (!next(scratch))
                break;
        const Size s = size_;
        in_.seek(dataStart_);
        chunk_.clear();
        chunkPos_ = 0;
        connections_.clear();
        decoder_ = RosEventDecoder();
        return s;
    }

    FileInput in_;
    Size size_;
    bool stereo_ = false;
    std::string topic_;
    int64 dataStart_ = 0;
    std::map<uint32_t, Connection> connections_;
    std::vector<uchar> headerBuf_, record_, chunk_;
    size_t chunkPos_ = 0;
    int64 chunkAt_ = 0;
    RosEventDecoder decoder_;
};

}  // namespace

Ptr<EventReader> openRosBag1Reader(const String& path, const ReaderOptions& options)
{
    return makePtr<RosBag1Reader>(path, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
