// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// AEDAT 4.0 (DV / dv-processing; layout: doc/formats.md, "AEDAT 4.0"): magic line, size-prefixed IOHeader
// FlatBuffer (compression, data-table position, XML info node), then packets {int32 stream id, int32 size,
// compressed size-prefixed FlatBuffer}. The event (EVTS) and trigger (TRIG) streams are decoded; frames and
// IMU packets are skipped by length. A file with two event streams is a stereo recording: the first is the
// left camera, the second the right one. Reading stops at the data table (or the end of the file).

#include "precomp.hpp"
#include "io/aedat4_codec.hpp"
#include "io/event_reader.hpp"
#include "io/file_input.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

// A corrupt packet must not make the reader allocate without bound; real packets are far below this.
const size_t kMaxPacketBytes = (size_t)1 << 28;

class Aedat4Reader CV_FINAL : public EventReader
{
public:
    Aedat4Reader(const String& path, const ReaderOptions& options) : in_(path)
    {
        char magic[kAedat4MagicSize];
        in_.readExact(magic, kAedat4MagicSize, "the AEDAT 4.0 magic line");
        if (std::memcmp(magic, kAedat4Magic, kAedat4MagicSize) != 0)
            formatError(path, 0, "not an AEDAT 4.0 file (no \"#!AER-DAT4.0\" line)");
        uint32_t headerSize;
        in_.readExact(&headerSize, 4, "the IOHeader size");
        if (in_.size() >= 0 && headerSize > in_.size() - in_.offset())
            formatError(path, kAedat4MagicSize, format("IOHeader claims %u bytes, more than the file holds", headerSize));
        std::vector<uchar> header(headerSize);
        in_.readExact(header.data(), headerSize, "the IOHeader");
        const FlatTable io = FlatTable::root(header.data(), header.size(), path, kAedat4MagicSize + 4);
        compression_ = io.int32Field(0, AEDAT4_NONE);
        dataTable_ = io.int64Field(1, -1);
        const std::string info = io.stringField(2);
        if (compression_ < AEDAT4_NONE || compression_ > AEDAT4_ZSTD_HIGH)
            formatError(path, kAedat4MagicSize + 4, format("unknown compression code %d in the IOHeader", compression_));
        if (!aedat4CompressionSupported(compression_))
            formatError(path, kAedat4MagicSize + 4, format("%s compression is not available in this build",
                                                           aedat4CompressionName(compression_)));
        const std::vector<Aedat4Stream> streams = aedat4Streams(info, "EVTS");
        if (streams.empty())
            formatError(path, kAedat4MagicSize + 4, "the info node lists no event (EVTS) stream");
        stereo_ = options.cameraFilter < 0 && streams.size() >= 2;
        const int pick = std::max(0, options.cameraFilter);
        if (pick >= (int)streams.size())
            formatError(path, kAedat4MagicSize + 4, format("no event stream for camera %d", pick));
        stream_ = streams[pick].id;
        // Trigger streams: one per camera when there are as many as event streams, else all for the first.
        const std::vector<Aedat4Stream> triggers = aedat4Streams(info, "TRIG");
        for (size_t i = 0; i < triggers.size(); i++)
            if (options.cameraFilter < 0 || (triggers.size() == streams.size() ? (int)i == pick : pick == 0))
                triggerStreams_.push_back(triggers[i].id);
        size_ = streams[pick].size;
        if (!options.sensorSize.empty())
            size_ = options.sensorSize;
        if (dataTable_ >= 0)
            readDataTable();
    }

    String name() const CV_OVERRIDE { return "AEDAT4"; }
    int64 durationUs() const CV_OVERRIDE { return duration_; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    double progress() const CV_OVERRIDE { return in_.progress(); }
    bool isStereo() const CV_OVERRIDE { return stereo_; }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        for (;;)
        {
            const int64 at = in_.offset();
            if (dataTable_ >= 0 && at >= dataTable_)
                return false;
            int32_t head[2];
            const size_t got = in_.read(head, sizeof(head));
            if (got == 0)
                return false;
            if (got != sizeof(head))
                formatError(in_.path(), at, format("truncated: packet header needs 8 bytes, only %zu left", got));
            const int32_t streamId = head[0], size = head[1];
            if (size < 0 || (in_.size() >= 0 && size > in_.size() - in_.offset()))
                formatError(in_.path(), at, format("packet of stream %d claims %d bytes, only %lld left in the file",
                                                   streamId, size, (long long)(in_.size() - in_.offset())));
            const bool triggers = std::find(triggerStreams_.begin(), triggerStreams_.end(), streamId) !=
                                  triggerStreams_.end();
            if (streamId != stream_ && !triggers)
            {
                in_.seek(in_.offset() + size);
                continue;
            }
            packet_.resize((size_t)size);
            in_.readExact(packet_.data(), (size_t)size, "packet payload");
            if (triggers)
                decodeTriggers(at);
            else if (decode(at, out) > 0)
                return true;
        }
    }

private:
    // The optional FileDataTable (per packet: stream, byte offset, element count, first / last timestamp) gives
    // the recording's duration without decoding it. It is a convenience: a damaged table leaves the duration
    // unknown but does not stop the events from being read.
    void readDataTable()
    {
        const int64 back = in_.offset();
        try
        {
            if (in_.size() < 0 || dataTable_ > in_.size() || in_.size() - dataTable_ > (int64)kMaxPacketBytes)
                return;
            in_.seek(dataTable_);
            std::vector<uchar> raw((size_t)(in_.size() - dataTable_));
            in_.readExact(raw.data(), raw.size(), "the data table");
            const std::vector<uchar> fb = aedat4Decompress(compression_, raw.data(), raw.size(), in_.path(),
                                                           dataTable_, kMaxPacketBytes);
            uint32_t prefix = 0;
            if (fb.size() >= 12)
                std::memcpy(&prefix, fb.data(), 4);
            if (fb.size() < 12 || prefix > fb.size() - 4 || std::memcmp(fb.data() + 8, "FTAB", 4) != 0)
                throw std::runtime_error("not a FileDataTable");
            int64 first = INT64_MAX, last = INT64_MIN;
            for (const FlatTable& entry : FlatTable::root(fb.data() + 4, prefix, in_.path(), dataTable_).tableVectorField(0))
            {
                const uchar* info = entry.structField(1, 8);  // PacketHeader {int32 stream, int32 size}
                int32_t streamId = -1;
                if (info)
                    std::memcpy(&streamId, info, 4);
                if (streamId != stream_ || entry.int64Field(2, 0) <= 0)
                    continue;
                first = std::min(first, entry.int64Field(3, INT64_MAX));
                last = std::max(last, entry.int64Field(4, INT64_MIN));
            }
            if (first <= last)
                duration_ = last - first;
        }
        catch (const std::exception&)
        {
            duration_ = -1;
        }
        in_.seek(back);
    }

    // The packet's size-prefixed FlatBuffer, decompressed, checked to carry @p identifier; its root table.
    FlatTable unpack(int64 at, const char* identifier, const char* what)
    {
        fb_ = aedat4Decompress(compression_, packet_.data(), packet_.size(), in_.path(), at, kMaxPacketBytes);
        if (fb_.size() < 12)
            formatError(in_.path(), at, format("%s shorter than a FlatBuffer header", what));
        uint32_t prefix;
        std::memcpy(&prefix, fb_.data(), 4);
        if (prefix > fb_.size() - 4)
            formatError(in_.path(), at, format("%s size prefix %u exceeds its %zu bytes", what, prefix, fb_.size() - 4));
        if (std::memcmp(fb_.data() + 8, identifier, 4) != 0)
            formatError(in_.path(), at, format("%s does not hold its kind of FlatBuffer (identifier is not %s)", what, identifier));
        return FlatTable::root(fb_.data() + 4, prefix, in_.path(), at);
    }

    // TriggerPacket {[Trigger {int64 timestamp; int8 type}]}: DV's external-signal and generator types are
    // trigger events; its timestamp resets and APS frame / exposure markers are not.
    void decodeTriggers(int64 at)
    {
        for (const FlatTable& trigger : unpack(at, "TRIG", "packet of a trigger stream").tableVectorField(0))
        {
            static const int kinds[] = { -1, EVENT_TRIGGER_RISING, EVENT_TRIGGER_FALLING, EVENT_TRIGGER_PULSE,
                                         EVENT_TRIGGER_GENERATOR_RISING, EVENT_TRIGGER_GENERATOR_FALLING };
            const int type = trigger.int8Field(1, 0);
            if (type >= 1 && type <= 5)
                triggers_.push_back(EventTrigger(trigger.int64Field(0, 0), kinds[type]));
        }
    }

    size_t decode(int64 at, std::vector<Event>& out)
    {
        const FlatTable table = unpack(at, "EVTS", "packet of the event stream");
        size_t count = 0;
        const uchar* e = table.vectorField(0, 16, count);
        for (size_t i = 0; i < count; i++, e += 16)
        {
            int64 t;
            int16_t x, y;
            std::memcpy(&t, e, 8);
            std::memcpy(&x, e + 8, 2);
            std::memcpy(&y, e + 10, 2);
            out.push_back(Event(t, x, y, e[12] ? POLARITY_ON : POLARITY_OFF));
        }
        return count;
    }

    FileInput in_;
    Size size_;
    int compression_ = AEDAT4_NONE;
    int64 dataTable_ = -1;
    int stream_ = 0;
    bool stereo_ = false;
    int64 duration_ = -1;
    std::vector<int> triggerStreams_;
    std::vector<uchar> packet_, fb_;
};

}  // namespace

Ptr<EventReader> openAedat4Reader(const String& path, const ReaderOptions& options)
{
    return makePtr<Aedat4Reader>(path, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
