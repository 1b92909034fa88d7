// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// jAER AEDAT 1.0 / 2.0 (layouts: doc/formats.md, "AEDAT 1.0 / 2.0"). '#' header lines ("#!AER-DAT2.0" for 2.0,
// "# AEChip: <class>" for the sensor), then big-endian records: 2.0 = {int32 address, int32 t_us},
// 1.0 = {int16 address, int32 t_us}. Address layouts: DVS128 (bit 0 = OFF!) and DAVIS (240/346/640);
// jAER's origin is bottom-left with x mirrored, so both coordinates are flipped to top-left.
// APS and IMU samples are not DVS events: they are not delivered and not counted as lost. External / sync
// events become trigger events (pulses: the record has no edge). Timestamps are 32-bit: a drop of more than 2^31 us is a wrap.

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/file_input.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

enum class AddressLayout { DVS128, DAVIS };

class Aedat2Reader CV_FINAL : public EventReader
{
public:
    Aedat2Reader(const String& path, const ReaderOptions& options) : in_(path)
    {
        std::string line, chip;
        bool first = true;
        while (in_.peek() == '#')
        {
            in_.readLine(line);
            if (first && line.compare(0, 9, "#!AER-DAT") == 0)
            {
                const std::string v = line.substr(9);
                if (v.compare(0, 1, "2") == 0)
                    recordSize_ = 8;
                else if (v.compare(0, 1, "1") == 0)
                    recordSize_ = 6;
                else
                    formatError(path, 0, "AEDAT version \"" + v + "\" is not read by the AEDAT 1/2 back-end");
            }
            first = false;
            const size_t k = line.find("AEChip:");
            if (k != std::string::npos)
            {
                chip = line.substr(k + 7);
                chip.erase(0, chip.find_first_not_of(' '));
            }
        }
        // Without a chip line (jAER's MATLAB export writes none) the sensor the user names chooses the layout.
        const Size given = options.sensorSize;
        if (chip.empty() && recordSize_ == 8)
        {
            if (given == Size(128, 128))
                chip = "DVS128 (as given)";
            else if (given == Size(240, 180) || given == Size(346, 260) || given == Size(640, 480))
                chip = cv::format("DAVIS%d (as given)", given.width);
            else
                formatError(path, 0, given.empty()
                    ? std::string("no \"# AEChip:\" header line: the address layout is unknown; give the sensor "
                                  "(--sensor=DVS128, DAVIS240, DAVIS346 or DAVIS640; EVENT_CAP_PROP_SENSOR_WIDTH / "
                                  "_HEIGHT)")
                    : cv::format("no \"# AEChip:\" header line, and a %d x %d sensor is none of DVS128, DAVIS240, "
                                 "DAVIS346, DAVIS640: the address layout is unknown", given.width, given.height));
        }
        const std::string lower = toLowerAscii(chip);
        if (lower.find("dvs128") != std::string::npos || (chip.empty() && recordSize_ == 6))
        {
            layout_ = AddressLayout::DVS128;
            size_ = Size(128, 128);
        }
        else if (lower.find("davis240") != std::string::npos)
            size_ = Size(240, 180);
        else if (lower.find("davis346") != std::string::npos)
            size_ = Size(346, 260);
        else if (lower.find("davis640") != std::string::npos)
            size_ = Size(640, 480);
        else
            formatError(path, 0, chip.empty() ? std::string("no \"# AEChip:\" header line: the address layout is unknown")
                                              : "AEChip \"" + chip + "\" is not a known DVS128 / DAVIS sensor");
        if (!options.sensorSize.empty() && options.sensorSize != size_)
            CV_Error_(Error::StsBadArg, ("%s: the file is from a %d x %d sensor (%s); a different sensor size was set",
                                         path.c_str(), size_.width, size_.height, chip.c_str()));
    }

    String name() const CV_OVERRIDE { return "AEDAT2"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    double progress() const CV_OVERRIDE { return in_.progress(); }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        const size_t before = out.size();
        unsigned char buf[8 * 8192];
        while (out.size() == before)
        {
            const size_t got = in_.readRecords(buf, sizeof(buf) / 8 * recordSize_, (size_t)recordSize_, "AEDAT record");
            if (got == 0)
                return false;
            for (size_t i = 0; i + recordSize_ <= got; i += recordSize_)
            {
                const unsigned char* r = buf + i;
                uint32_t address, t32;
                if (recordSize_ == 8)
                {
                    address = be32(r);
                    t32 = be32(r + 4);
                }
                else
                {
                    address = (uint32_t)(r[0] << 8 | r[1]);
                    t32 = be32(r + 2);
                }
                if (haveLast_ && t32 < last32_ && last32_ - t32 > 0x80000000u)
                    high_ += (int64)1 << 32;
                haveLast_ = true;
                last32_ = t32;
                decode(address, high_ + t32, out);
            }
        }
        return true;
    }

private:
    static uint32_t be32(const unsigned char* p)
    {
        return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | (uint32_t)p[3];
    }

    void decode(uint32_t a, int64 t, std::vector<Event>& out)
    {
        if (layout_ == AddressLayout::DVS128)
        {
            if (a & 0x8000u)  // external / sync event: jAER records no edge
            {
                triggers_.push_back(EventTrigger(t, EVENT_TRIGGER_PULSE));
                return;
            }
            const int rawY = (a >> 8) & 0x7F, rawX = (a >> 1) & 0x7F;
            out.push_back(Event(t, 127 - rawX, 127 - rawY, (a & 1u) ? POLARITY_OFF : POLARITY_ON));
            return;
        }
        if (a & 0x80000000u)  // APS / IMU sample
            return;
        if (a & 0x400u)  // external input event: jAER records no edge
        {
            triggers_.push_back(EventTrigger(t, EVENT_TRIGGER_PULSE));
            return;
        }
        const int rawY = (a >> 22) & 0x1FF, rawX = (a >> 12) & 0x3FF;
        // A raw address beyond the array flips to a negative coordinate: EventCapture counts it as outside.
        out.push_back(Event(t, size_.width - 1 - rawX, size_.height - 1 - rawY,
                            (a >> 11) & 1u ? POLARITY_ON : POLARITY_OFF));
    }

    FileInput in_;
    Size size_;
    AddressLayout layout_ = AddressLayout::DAVIS;
    int recordSize_ = 6;  // no "#!AER-DAT" line: version 1.0
    int64 high_ = 0;
    uint32_t last32_ = 0;
    bool haveLast_ = false;
};

}  // namespace

Ptr<EventReader> openAedat2Reader(const String& path, const ReaderOptions& options)
{
    return makePtr<Aedat2Reader>(path, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
