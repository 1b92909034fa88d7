// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Prophesee .dat (decoded CD events): "% " header lines (optional "% Width W" / "% Height H"), one byte of
// event type, one byte of event size (8), then little-endian records {u32 t_us; u32 x:14 | y:14 << 14 | p:4 << 28}.
// The 32-bit timestamps are unwrapped: a drop of more than 2^31 us is a wrap, smaller drops are delivered
// as they are (EventCapture counts them and applies its time-order policy).

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/file_input.hpp"

#include <cstdlib>

namespace cv {
namespace event {
namespace detail {

namespace {

class DatReader CV_FINAL : public EventReader
{
public:
    DatReader(const String& path, const ReaderOptions& options) : in_(path)
    {
        std::string line;
        while (in_.peek() == '%')
        {
            in_.readLine(line);
            int value = 0;
            if (std::sscanf(line.c_str(), "%% Width %d", &value) == 1)
                size_.width = value;
            else if (std::sscanf(line.c_str(), "%% Height %d", &value) == 1)
                size_.height = value;
        }
        if (size_.width <= 0 || size_.height <= 0)
            size_ = Size();
        if (!options.sensorSize.empty())
            size_ = options.sensorSize;
        unsigned char typeAndSize[2];
        in_.readExact(typeAndSize, 2, "the event type and size bytes after the header");
        if (typeAndSize[1] != 8)
            formatError(in_.path(), in_.offset() - 1,
                        format("event size %d; only 8-byte CD event records are supported", typeAndSize[1]));
    }

    String name() const CV_OVERRIDE { return "PROPHESEE_DAT"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    double progress() const CV_OVERRIDE { return in_.progress(); }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        uint32_t words[2 * 4096];
        const size_t n = in_.readRecords(words, sizeof(words), 8, "event record") / 8;
        for (size_t i = 0; i < n; i++)
        {
            const uint32_t t32 = words[2 * i], data = words[2 * i + 1];
            if (haveLast_ && t32 < last32_ && last32_ - t32 > 0x80000000u)
                high_ += (int64)1 << 32;
            haveLast_ = true;
            last32_ = t32;
            out.push_back(Event(high_ + t32, (int)(data & 0x3FFF), (int)((data >> 14) & 0x3FFF),
                                (data >> 28) ? POLARITY_ON : POLARITY_OFF));
        }
        return n > 0;
    }

private:
    FileInput in_;
    Size size_;
    int64 high_ = 0;
    uint32_t last32_ = 0;
    bool haveLast_ = false;
};

}  // namespace

Ptr<EventReader> openDatReader(const String& path, const ReaderOptions& options)
{
    return makePtr<DatReader>(path, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
