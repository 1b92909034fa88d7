// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// ROS2 bags in MCAP storage (the default of current ROS 2 releases): magic, then records of {u8 opcode, u64
// length, content}, all little-endian; strings and byte arrays carry a u32 length (a chunk's records a u64).
// Schema records name the message types, Channel records give each topic its id, Message records hold one
// CDR-serialised message, and Chunk records hold a run of such records, uncompressed, LZ4 (frame format) or
// ZSTD. The data section is read in file order, one chunk (or one message) at a time, so memory is one
// chunk; the event topics are listed first from the summary section when the file has one, else by a scan
// of the data section. Two event topics make a stereo recording (sorted by name: the first is the left
// camera).

#include "precomp.hpp"
#include "io/aedat4_codec.hpp"
#include "io/event_reader.hpp"
#include "io/ros_event_decoder.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace cv {
namespace event {
namespace detail {

namespace {

const uchar kMcapMagic[8] = { 0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n' };

enum McapOpcode
{
    MCAP_HEADER = 0x01,
    MCAP_FOOTER = 0x02,
    MCAP_SCHEMA = 0x03,
    MCAP_CHANNEL = 0x04,
    MCAP_MESSAGE = 0x05,
    MCAP_CHUNK = 0x06,
    MCAP_DATA_END = 0x0F
};

// A chunk may not claim more than this once decompressed: a corrupt length cannot make the reader allocate
// without bound (writers use chunks of a few MiB).
const uint64_t kMaxChunkBytes = (uint64_t)1 << 31;

class McapReader CV_FINAL : public EventReader
{
public:
    McapReader(const String& bag, const std::vector<std::string>& files, const ReaderOptions& options)
        : files_(files), size_(options.sensorSize)
    {
        const std::vector<std::string> topics = eventTopics();  // sorted by name
        topic_ = topics[pickRos2EventTopic(topics.size(), options.cameraFilter, bag, stereo_)];
        open(0);
        if (size_.empty())
        {
            // The first message tells the sensor size; decode it, then start again.
            std::vector<Event> scratch;
            next(scratch);
            decoder_ = RosEventDecoder();
            open(0);
        }
    }

    String name() const CV_OVERRIDE { return "ROSBAG2"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    bool isStereo() const CV_OVERRIDE { return stereo_; }
    int64 skippedEvents() const CV_OVERRIDE { return decoder_.skipped(); }
    void takeTriggers(std::vector<EventTrigger>& out) CV_OVERRIDE { decoder_.takeTriggers(out); }
    double progress() const CV_OVERRIDE
    {
        const double inFile = input_ && input_->size() > 0 ? (double)input_->offset() / (double)input_->size() : 0.0;
        return (fileIndex_ + inFile) / (double)files_.size();
    }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        const size_t before = out.size();
        while (out.size() == before)
        {
            if (chunkPos_ < chunk_.size())
            {
                nextInChunk(&out);
                continue;
            }
            uchar opcode;
            uint64_t length;
            int64 at;
            if (!nextRecord(*input_, opcode, length, at))
            {
                if (fileIndex_ + 1 >= files_.size())
                    return false;
                open(fileIndex_ + 1);
                continue;
            }
            if (opcode == MCAP_CHUNK)
                loadChunk(*input_, length, at);
            else if (opcode == MCAP_SCHEMA || opcode == MCAP_CHANNEL || opcode == MCAP_MESSAGE)
            {
                readContent(*input_, length, at, record_);
                handle(opcode, record_.data(), record_.size(), at, &out);
            }
            else
                input_->seek(at + 9 + (int64)length);
        }
        return true;
    }

private:
    void open(size_t index)
    {
        fileIndex_ = index;
        input_.reset(new FileInput(files_[index]));
        expectMagic(*input_);
        chunk_.clear();
        chunkPos_ = 0;
        schemas_.clear();
        channels_.clear();
    }

    void expectMagic(FileInput& in) const
    {
        uchar magic[8];
        if (in.read(magic, 8) != 8 || std::memcmp(magic, kMcapMagic, 8) != 0)
            formatError(in.path(), 0, "not an MCAP file (wrong magic)");
    }

    // The next record's header of the data section; false at its end (the data-end record, the footer, or
    // the end of a file cut off between records). A record cut off by the end of the file raises an error,
    // or, with @p cutEnds (the topic scan, which needs only what comes before it), ends the section.
    bool nextRecord(FileInput& in, uchar& opcode, uint64_t& length, int64& at, bool cutEnds = false) const
    {
        at = in.offset();
        uchar head[9];
        const size_t got = in.read(head, 9);
        if (got == 0)
            return false;
        opcode = head[0];
        length = 0;
        if (got == 9)
            std::memcpy(&length, head + 1, 8);
        const bool cut = got < 9 || (in.size() >= 0 && length > (uint64_t)(in.size() - at - 9));
        if (cut && cutEnds)
            return false;
        if (cut)
            formatError(in.path(), at, got < 9 ? String("truncated: MCAP record header")
                                               : format("truncated: MCAP record of %llu bytes runs past the end of "
                                                        "the file", (unsigned long long)length));
        return opcode != MCAP_DATA_END && opcode != MCAP_FOOTER;
    }

    static void readContent(FileInput& in, uint64_t length, int64 at, std::vector<uchar>& content)
    {
        if (length > kMaxChunkBytes)
            formatError(in.path(), at, format("MCAP record of %llu bytes is larger than this reader takes",
                                              (unsigned long long)length));
        content.resize((size_t)length);
        in.readExact(content.data(), content.size(), "MCAP record");
    }

    // Reads a chunk record at @p at and decompresses its records into chunk_.
    void loadChunk(FileInput& in, uint64_t length, int64 at)
    {
        readContent(in, length, at, record_);
        MessageCursor c(record_.data(), record_.size(), in.path(), at);
        c.read<uint64_t>("message start time");
        c.read<uint64_t>("message end time");
        const uint64_t uncompressed = c.read<uint64_t>("uncompressed size");
        c.read<uint32_t>("uncompressed crc");
        const std::string compression = c.string("compression", false);
        const uint64_t n = c.read<uint64_t>("records length");
        if (n > c.remaining())
            formatError(in.path(), at, "truncated MCAP chunk: its records run past the record");
        const uchar* records = c.bytes((size_t)n, "records");
        if (uncompressed > kMaxChunkBytes)
            formatError(in.path(), at, format("MCAP chunk of %llu bytes uncompressed is larger than this reader takes",
                                              (unsigned long long)uncompressed));
        if (compression.empty())
            chunk_.assign(records, records + n);
        else if (compression == "lz4" || compression == "zstd")
            chunk_ = aedat4Decompress(compression == "lz4" ? AEDAT4_LZ4 : AEDAT4_ZSTD, records, (size_t)n, in.path(), at,
                                      (size_t)uncompressed);
        else
            formatError(in.path(), at, "MCAP chunk compression \"" + compression + "\" is not supported (lz4, zstd)");
        if (chunk_.size() != uncompressed)
            formatError(in.path(), at, format("MCAP chunk decompresses to %zu bytes, its header says %llu",
                                              chunk_.size(), (unsigned long long)uncompressed));
        chunkAt_ = at;
        chunkPos_ = 0;
    }

    // The next record of the current chunk (see handle()).
    void nextInChunk(std::vector<Event>* out)
    {
        const String where = input_->path() + format(" (chunk at byte %lld)", (long long)chunkAt_);
        if (chunk_.size() - chunkPos_ < 9)
            formatError(where, (int64)chunkPos_, "truncated MCAP record header inside the chunk");
        const uchar opcode = chunk_[chunkPos_];
        uint64_t length;
        std::memcpy(&length, chunk_.data() + chunkPos_ + 1, 8);
        if (length > chunk_.size() - chunkPos_ - 9)
            formatError(where, (int64)chunkPos_, "MCAP record runs past the end of its chunk");
        const size_t content = chunkPos_ + 9;
        chunkPos_ = content + (size_t)length;
        handle(opcode, chunk_.data() + content, (size_t)length, chunkAt_, out);
        if (chunkPos_ == chunk_.size())
        {
            chunk_.clear();
            chunkPos_ = 0;
        }
    }

    // A schema, a channel or a message (of our topic: decoded into @p out when given).
    void handle(uchar opcode, const uchar* data, size_t size, int64 at, std::vector<Event>* out)
    {
        MessageCursor c(data, size, input_->path(), at);
        if (opcode == MCAP_SCHEMA)
        {
            const uint16_t id = c.read<uint16_t>("schema id");
            schemas_[id] = c.string("schema name", false);
        }
        else if (opcode == MCAP_CHANNEL)
        {
            const uint16_t id = c.read<uint16_t>("channel id");
            const uint16_t schema = c.read<uint16_t>("channel schema id");
            const std::string topic = c.string("channel topic", false);
            const std::string encoding = c.string("channel message encoding", false);
            const auto s = schemas_.find(schema);
            const bool events = s != schemas_.end() && (s->second == kRos2EventPacket || s->second == kRos2LegacyEventArray);
            channels_[id] = events ? topic : std::string();
            if (events && encoding != "cdr")
                formatError(input_->path(), at, "channel " + topic + " has message encoding \"" + encoding + "\" (cdr expected)");
        }
        else if (opcode == MCAP_MESSAGE && out)
        {
            const uint16_t channel = c.read<uint16_t>("message channel id");
            const auto ch = channels_.find(channel);
            if (ch == channels_.end() || ch->second != topic_)
                return;
            const uint32_t sequence = c.read<uint32_t>("message sequence");
            c.read<uint64_t>("message log time");
            c.read<uint64_t>("message publish time");
            const size_t n = c.remaining();
            decoder_.decodeCdrPacket(c.bytes(n, "message data"), n,
                                     input_->path() + format(" (message %u of %s)", sequence, topic_.c_str()), size_, *out);
        }
    }

    // The event topics of the first file: from its summary section when the footer points to one, else from
    // a scan of its data section.
    std::vector<std::string> eventTopics()
    {
        input_.reset(new FileInput(files_[0]));
        FileInput& in = *input_;
        expectMagic(in);
        uint64_t summaryStart = 0;
        if (in.size() >= 8 + 9 + 20 + 8)
        {
            // Footer: {0x02, u64 length 20, u64 summary start, u64 summary offset start, u32 crc}, then the magic
            // (absent from a file cut off: then the data section is scanned).
            in.seek(in.size() - 8 - 29);
            uchar tail[29 + 8];
            in.readExact(tail, sizeof tail, "MCAP footer");
            uint64_t footerLength;
            std::memcpy(&footerLength, tail + 1, 8);
            if (tail[0] == MCAP_FOOTER && footerLength == 20 && std::memcmp(tail + 29, kMcapMagic, 8) == 0)
                std::memcpy(&summaryStart, tail + 9, 8);
            if (summaryStart >= (uint64_t)in.size())
                summaryStart = 0;
        }
        scanDefinitions(in, summaryStart > 0 ? (int64)summaryStart : 8, summaryStart > 0);
        std::set<std::string> topics = channelTopics();
        if (topics.empty() && summaryStart > 0)
        {
            // A summary without the channels: they are in the data section.
            scanDefinitions(in, 8, false);
            topics = channelTopics();
        }
        return std::vector<std::string>(topics.begin(), topics.end());
    }

    // Reads the schema and channel records from @p from to the end of its section; in the data section also
    // those inside chunks (@p summary: the summary section, which holds them outside chunks).
    void scanDefinitions(FileInput& in, int64 from, bool summary)
    {
        in.seek(from);
        uchar opcode;
        uint64_t length;
        int64 at;
        for (;;)
        {
            if (chunkPos_ < chunk_.size())
            {
                nextInChunk(nullptr);
                continue;
            }
            if (!nextRecord(in, opcode, length, at, true))
                break;
            if (opcode == MCAP_SCHEMA || opcode == MCAP_CHANNEL)
            {
                readContent(in, length, at, record_);
                handle(opcode, record_.data(), record_.size(), at, nullptr);
            }
            else if (opcode == MCAP_CHUNK && !summary)
                loadChunk(in, length, at);
            else
                in.seek(at + 9 + (int64)length);
        }
    }

    std::set<std::string> channelTopics() const
    {
        std::set<std::string> topics;
        for (const auto& c : channels_)
            if (!c.second.empty())
                topics.insert(c.second);
        return topics;
    }

    std::vector<std::string> files_;
    size_t fileIndex_ = 0;
    std::unique_ptr<FileInput> input_;
    std::vector<uchar> record_, chunk_;  // the record read last; the records of the current chunk
    size_t chunkPos_ = 0;
    int64 chunkAt_ = 0;
    std::map<uint16_t, std::string> schemas_;   // id -> message type
    std::map<uint16_t, std::string> channels_;  // id -> topic, empty for topics other than event topics
    std::string topic_;
    Size size_;
    bool stereo_ = false;
    RosEventDecoder decoder_;
};

}  // namespace

bool isMcapFile(const String& path)
{
    const std::string head = readFilePrefix(path, 8);
    return head.size() == 8 && std::memcmp(head.data(), kMcapMagic, 8) == 0;
}

Ptr<EventReader> openMcapReader(const String& bag, const std::vector<std::string>& files, const ReaderOptions& options)
{
    return makePtr<McapReader>(bag, files, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
