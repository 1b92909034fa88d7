// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// cAER / libcaer AEDAT 3.1 (layouts: doc/formats.md, "AEDAT 3.1"): '#' header lines closed by "#!END-HEADER",
// then packets with a 28-byte little-endian header {int16 type, int16 source, int32 eventSize,
// int32 tsOffset, int32 tsOverflow, int32 capacity, int32 number, int32 valid} and capacity x eventSize
// bytes of events. Polarity events (type 1): {u32 data: valid bit 0, polarity bit 1, y bits 2..16,
// x bits 17..31; int32 t}, full time = tsOverflow << 31 | t. Special events (type 0) give the trigger
// events; other packet types are skipped by length. Polarity events marked invalid by their producer are
// counted in EVENT_CAP_PROP_SKIPPED.

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/file_input.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

Size sizeOfDevice(const std::string& name)
{
    const std::string n = toLowerAscii(name);
    if (n.find("dvs128") != std::string::npos) return Size(128, 128);
    if (n.find("davis240") != std::string::npos) return Size(240, 180);
    if (n.find("davis346") != std::string::npos) return Size(346, 260);
    if (n.find("davis640") != std::string::npos) return Size(640, 480);
    if (n.find("dvxplorer") != std::string::npos) return Size(640, 480);
    return Size();
}

class Aedat3Reader CV_FINAL : public EventReader
{
public:
    Aedat3Reader(const String& path, const ReaderOptions& options) : in_(path)
    {
        std::string line;
        bool ended = false;
        while (in_.peek() == '#')
        {
            in_.readLine(line);
            if (line == "#!END-HEADER")
            {
                ended = true;
                break;
            }
            const size_t k = line.find("#Source ");
            if (k == 0)
            {
                const size_t colon = line.find(':');
                if (colon != std::string::npos && size_.empty())
                    size_ = sizeOfDevice(line.substr(colon + 1));
            }
        }
        if (!ended)
            formatError(path, in_.offset(), "AEDAT 3.1 header without its \"#!END-HEADER\" line");
        if (!options.sensorSize.empty())
            size_ = options.sensorSize;
    }

    String name() const CV_OVERRIDE { return "AEDAT3"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    double progress() const CV_OVERRIDE { return in_.progress(); }
    int64 skippedEvents() const CV_OVERRIDE { return invalid_; }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        const size_t before = out.size();
        while (out.size() == before)
        {
            if (remaining_ == 0 && !nextPolarityPacket())
                return false;
            const int64 n = std::min<int64>(remaining_, (int64)(sizeof(buffer_) / eventSize_));
            in_.readExact(buffer_, (size_t)(n * eventSize_), "polarity events of the packet");
            remaining_ -= n;
            for (int64 i = 0; i < n; i++)
            {
                const unsigned char* e = buffer_ + i * eventSize_;
                const uint32_t data = le32(e);
                const int32_t t = (int32_t)le32(e + 4);
                if (!(data & 1u))
                {
                    invalid_++;
                    continue;
                }
                out.push_back(Event(overflow_ + t, (int)(data >> 17), (int)((data >> 2) & 0x7FFF),
                                    (data >> 1) & 1u ? POLARITY_ON : POLARITY_OFF));
            }
        }
        return true;
    }

private:
    static uint32_t le32(const unsigned char* p)
    {
        return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
    }

    // Skips packets of other types; false at the end of the file.
    bool nextPolarityPacket()
    {
        for (;;)
        {
            unsigned char h[28];
            const int64 at = in_.offset();
            const size_t got = in_.read(h, sizeof(h));
            if (got == 0)
                return false;
            if (got != sizeof(h))
                formatError(in_.path(), at, format("truncated: packet header needs 28 bytes, only %zu left", got));
            const int type = (int16_t)(h[0] | h[1] << 8);
            const int32_t size = (int32_t)le32(h + 4), tsOffset = (int32_t)le32(h + 8);
            const int32_t overflow = (int32_t)le32(h + 12), capacity = (int32_t)le32(h + 16);
            if (size <= 0 || capacity < 0)
                formatError(in_.path(), at, format("packet header with event size %d and capacity %d", size, capacity));
            if (overflow < 0)  // a counter of 2^31 us wraps: never negative (found by fuzz_aedat3)
                formatError(in_.path(), at, format("packet header with timestamp overflow counter %d", overflow));
            const int64 payload = (int64)size * capacity;
            if (in_.size() >= 0 && payload > in_.size() - in_.offset())
                formatError(in_.path(), at, format("packet claims %lld bytes of events, only %lld left in the file",
                                                   (long long)payload, (long long)(in_.size() - in_.offset())));
            if (type == 1)
            {
                if (size < 8 || size > 64 || tsOffset != 4)
                    formatError(in_.path(), at, format("polarity packet with event size %d / timestamp offset %d "
                                                       "(expected 8..64 / 4)", size, tsOffset));
                eventSize_ = size;
                remaining_ = capacity;
                overflow_ = (int64)overflow << 31;
                if (capacity > 0)
                    return true;
            }
            else if (type == 0 && size == 8 && tsOffset == 4)
                readSpecialEvents(capacity, (int64)overflow << 31);
            else
                in_.seek(in_.offset() + payload);
        }
    }

    // Special events {u32 data: valid bit 0, type bits 1..7; int32 t}: libcaer's external-input types become
    // trigger events (input 0, 1, 2 as the channel), the rest (time wraps and resets, row-only, APS
    // markers) are not triggers.
    void readSpecialEvents(int64 count, int64 overflow)
    {
        while (count > 0)
        {
            const int64 n = std::min<int64>(count, (int64)(sizeof(buffer_) / 8));
            in_.readExact(buffer_, (size_t)(n * 8), "special events of the packet");
            count -= n;
            for (int64 i = 0; i < n; i++)
            {
                const uint32_t data = le32(buffer_ + i * 8);
                const int64 t = overflow + (int32_t)le32(buffer_ + i * 8 + 4);
                const int type = (int)((data >> 1) & 0x7F);
                if (!(data & 1u))
                    continue;
                if (type >= 2 && type <= 11 && type != 5)  // input 0: 2..4, input 1: 6..8, input 2: 9..11
                {
                    const int channel = type < 5 ? 0 : (type - 3) / 3;
                    const int edge = type < 5 ? type - 2 : (type - 6) % 3;  // 0 rising, 1 falling, 2 pulse
                    static const int kinds[3] = { EVENT_TRIGGER_RISING, EVENT_TRIGGER_FALLING, EVENT_TRIGGER_PULSE };
                    triggers_.push_back(EventTrigger(t, kinds[edge], channel));
                }
                else if (type == 12 || type == 13)
                    triggers_.push_back(EventTrigger(t, type == 12 ? EVENT_TRIGGER_GENERATOR_RISING
                                                                   : EVENT_TRIGGER_GENERATOR_FALLING));
            }
        }
    }

    FileInput in_;
    Size size_;
    unsigned char buffer_[8 * 8192];
    int64 remaining_ = 0;
    int eventSize_ = 8;
    int64 overflow_ = 0;
    int64 invalid_ = 0;
};

}  // namespace

Ptr<EventReader> openAedat3Reader(const String& path, const ReaderOptions& options)
{
    return makePtr<Aedat3Reader>(path, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
