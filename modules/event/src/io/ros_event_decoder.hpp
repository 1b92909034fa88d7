// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_IO_ROS_EVENT_DECODER_HPP
#define OPENCV_EVENT_SRC_IO_ROS_EVENT_DECODER_HPP

// Payloads of the ROS event messages, shared by the ROS1 bag and ROS2 bag readers (the serialisation of
// the surrounding message differs: ROS1 is packed little-endian, ROS2 is CDR; each reader extracts the
// fields and hands the payload here).
//  - event_camera_msgs/EventPacket, encoding "evt3": Prophesee EVT 3.0 words; the sensor time (us) is
//    delivered (the decoder state runs across packets, as the words form one stream), external triggers too;
//  - encoding "libcaer": 8-byte libcaer polarity events {u32 data, int32 t_us}; time = time_base (ns) / 1000
//    + t, + 2^31 us when t rolls over inside the packet;
//  - encoding "libcaer_cmp": event_camera_codecs' compact form of it (decodeLibcaerCompressed);
//  - dvs_msgs/EventArray events: 13-byte records {u16 x, u16 y, u32 sec, u32 nsec, u8 polarity}.

#include "io/evt3_decoder.hpp"
#include "io/file_input.hpp"

#include <algorithm>

namespace cv {
namespace event {
namespace detail {

// ROS 2's event message type, and its name before the 2023 rename (the same layout).
static const char kRos2EventPacket[] = "event_camera_msgs/msg/EventPacket";
static const char kRos2LegacyEventArray[] = "event_array_msgs/msg/EventArray";

/** ROS 2 bags (sqlite3 and MCAP): which of @p count event topics, sorted by name, a reader of camera
@p cameraFilter (-1: any) delivers, and whether the bag is a stereo recording (two topics or more, no filter).
Errors name @p where. */
inline size_t pickRos2EventTopic(size_t count, int cameraFilter, const String& where, bool& stereo)
{
    if (count == 0)
        CV_Error_(Error::StsParseError, ("%s: no %s (or %s) topic in the bag", where.c_str(), kRos2EventPacket,
                                         kRos2LegacyEventArray));
    stereo = cameraFilter < 0 && count >= 2;
    const int pick = std::max(0, cameraFilter);
    if (pick >= (int)count)
        CV_Error_(Error::StsParseError, ("%s: no event topic for camera %d", where.c_str(), pick));
    return (size_t)pick;
}

class RosEventDecoder
{
public:
    /** Decodes one EventPacket payload. Unknown encodings raise an error naming the file and offset. */
    void decodePacket(const std::string& encoding, const uchar* data, size_t n, uint64_t timeBase,
                      std::vector<Event>& out, const String& path, int64 offset)
    {
        if (encoding == "evt3")
        {
            if (n % 2 != 0)
                formatError(path, offset, format("evt3 packet of %zu bytes is not a whole number of 16-bit words", n));
            words_.resize(n / 2);
            std::memcpy(words_.data(), data, n);
            evt3_.decode(words_.data(), words_.size(), out, triggers_);
        }
        else if (encoding == "libcaer")
        {
            if (n % 8 != 0)
                formatError(path, offset, format("libcaer packet of %zu bytes is not a whole number of 8-byte events", n));
            int64 high = (int64)(timeBase / 1000);
            int64 lastLow = 0;
            for (size_t i = 0; i < n; i += 8)
            {
                uint32_t d;
                int32_t t;
                std::memcpy(&d, data + i, 4);
                std::memcpy(&t, data + i + 4, 4);
                if (t < lastLow)
                    high += (int64)1 << 31;  // the 31-bit microsecond counter rolled over inside the packet
                lastLow = t;
                out.push_back(Event(high + t, (int)((d >> 17) & 0x7FFF), (int)((d >> 2) & 0x7FFF), (d >> 1) & 1u));
            }
        }
        else if (encoding == "libcaer_cmp")
        {
            if (n % 2 != 0)
                formatError(path, offset, format("libcaer_cmp packet of %zu bytes is not a whole number of 16-bit words", n));
            decodeLibcaerCompressed(data, n / 2, timeBase, out);
        }
        else
            formatError(path, offset, "EventPacket encoding \"" + encoding + "\" is not supported (evt3, libcaer, libcaer_cmp)");
    }

    /** Decodes @p count dvs_msgs/Event records (13 bytes each). */
    static void decodeDvsEvents(const uchar* data, size_t count, std::vector<Event>& out)
    {
        for (size_t i = 0; i < count; i++, data += 13)
        {
            uint16_t x, y;
            uint32_t sec, nsec;
            std::memcpy(&x, data, 2);
            std::memcpy(&y, data + 2, 2);
            std::memcpy(&sec, data + 4, 4);
            std::memcpy(&nsec, data + 8, 4);
            out.push_back(Event((int64)sec * 1000000 + nsec / 1000, x, y, data[12] ? POLARITY_ON : POLARITY_OFF));
        }
    }

    /** Decodes one CDR-serialised event_camera_msgs/msg/EventPacket (ROS2: a 4-byte encapsulation header, then
    the fields aligned to their size relative to byte 4). The sensor size is taken into @p sensorSize when that
    is still empty. Errors name @p where. */
    void decodeCdrPacket(const uchar* data, size_t n, const String& where, Size& sensorSize, std::vector<Event>& out);

    int64 skipped() const { return evt3_.skipped(); }

    /** Moves the trigger events decoded so far (evt3 external triggers) to the end of @p out. */
    void takeTriggers(std::vector<EventTrigger>& out)
    {
        out.insert(out.end(), triggers_.begin(), triggers_.end());
        triggers_.clear();
    }

private:
    // libcaer_cmp (event_camera_codecs' compact libcaer): 16-bit words, the code in the top 4 bits. Time is
    // [us] after the packet's time base (ns): a high word sets bits 12-23, a low word bits 0-11, both 0 at the
    // start of each packet. An x word sets the column; a y word gives one event there (bit 11: polarity); a
    // vector base sets a row and a polarity, and each vector word then gives an event at each set bit i of its
    // low 8 bits, row base + i, and moves the base 8 rows on. Column, base and polarity carry over packets.
    void decodeLibcaerCompressed(const uchar* data, size_t words, uint64_t timeBase, std::vector<Event>& out)
    {
        enum { TIME_HIGH = 0, TIME_LOW = 1, ADDR_X = 2, ADDR_Y = 3, VECT_BASE_Y = 4, VECT_8 = 5 };
        const int64 base = (int64)(timeBase / 1000);
        int64 high = 0, low = 0;
        for (size_t i = 0; i < words; i++)
        {
            uint16_t w;
            std::memcpy(&w, data + 2 * i, 2);
            const int code = w >> 12;
            if (code == TIME_HIGH)
                high = (int64)(w & 0xFFF) << 12;
            else if (code == TIME_LOW)
                low = w & 0xFFF;
            else if (code == ADDR_X)
                cmpX_ = w & 0x7FF;
            else if (code == ADDR_Y)
                out.push_back(Event(base + (high | low), cmpX_, w & 0x7FF, (w >> 11) & 1));
            else if (code == VECT_BASE_Y)
            {
                cmpBaseY_ = w & 0x7FF;
                cmpPolarity_ = (w >> 11) & 1;
            }
            else if (code == VECT_8)
            {
                for (int b = 0; b < 8; b++)
                    if (w & (1 << b))
                        out.push_back(Event(base + (high | low), cmpX_, cmpBaseY_ + b, cmpPolarity_));
                cmpBaseY_ += 8;
            }
        }
    }

    int cmpX_ = 0, cmpBaseY_ = 0, cmpPolarity_ = 0;
    Evt3Decoder evt3_;
    std::vector<uint16_t> words_;
    std::vector<EventTrigger> triggers_;
};

/** Bounds-checked little-endian reading of a serialised message. */
class MessageCursor
{
public:
    MessageCursor(const uchar* data, size_t size, const String& path, int64 offset, size_t cdrOrigin = 0)
        : data_(data), size_(size), path_(path), offset_(offset), origin_(cdrOrigin) {}

    template<typename T>
    T read(const char* what)
    {
        need(sizeof(T), what);
        T v;
        std::memcpy(&v, data_ + pos_, sizeof(T));
        pos_ += sizeof(T);
        return v;
    }
    std::string string(const char* what, bool cdr)
    {
        if (cdr)
            align(4);
        const uint32_t n = read<uint32_t>(what);
        need(n, what);
        std::string s(reinterpret_cast<const char*>(data_ + pos_), n);
        pos_ += n;
        if (cdr && !s.empty() && s.back() == '\0')
            s.pop_back();  // CDR strings count their terminating NUL
        return s;
    }
    const uchar* bytes(size_t n, const char* what)
    {
        need(n, what);
        const uchar* p = data_ + pos_;
        pos_ += n;
        return p;
    }
    /** CDR alignment, relative to the start of the data after the encapsulation header. */
    void align(size_t a)
    {
        const size_t rel = pos_ - origin_;
        const size_t pad = (a - rel % a) % a;
        need(pad, "alignment");
        pos_ += pad;
    }
    size_t remaining() const { return size_ - pos_; }

private:
    void need(size_t n, const char* what) const
    {
        if (n > size_ - pos_)
            formatError(path_, offset_, format("truncated message: %s needs %zu bytes, %zu left", what, n, size_ - pos_));
    }

    const uchar* data_;
    size_t size_, pos_ = 0;
    String path_;
    int64 offset_;
    size_t origin_;
};

inline void RosEventDecoder::decodeCdrPacket(const uchar* data, size_t n, const String& where, Size& sensorSize,
                                             std::vector<Event>& out)
{
    if (n < 4 || data[0] != 0 || data[1] != 1)
        formatError(where, 0, "message is not little-endian CDR");
    MessageCursor m(data, n, where, 0, 4);
    m.bytes(4, "encapsulation");
    m.read<int32_t>("stamp sec");
    m.read<uint32_t>("stamp nanosec");
    m.string("frame_id", true);
    m.align(4);
    const uint32_t height = m.read<uint32_t>("height"), width = m.read<uint32_t>("width");
    if (sensorSize.empty() && width > 0 && height > 0 && width <= 32768 && height <= 32768)
        sensorSize = Size((int)width, (int)height);
    m.align(8);
    m.read<uint64_t>("seq");
    const uint64_t timeBase = m.read<uint64_t>("time_base");
    const std::string encoding = m.string("encoding", true);
    m.read<uint8_t>("is_bigendian");
    m.align(4);
    const uint32_t len = m.read<uint32_t>("events length");
    decodePacket(encoding, m.bytes(len, "events"), len, timeBase, out, where, 0);
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_IO_ROS_EVENT_DECODER_HPP
