// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Prophesee RAW recordings, EVT 2.0 and EVT 3.0 encodings (layouts: doc/formats.md, "Prophesee RAW").
// Header: "% key value" lines, optionally closed by "% end". The sensor size comes from "% format ...;
// width=W;height=H", "% geometry WxH", or else the plugin name (Gen3 640x480, Gen4.1 / IMX636 1280x720,
// GenX320 320x320). CD events before the first TIME_HIGH word have no time base: they are skipped and
// counted (EVENT_CAP_PROP_SKIPPED). External trigger words become trigger events.

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/evt3_decoder.hpp"
#include "io/file_input.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

class PropheseeRawReader CV_FINAL : public EventReader
{
public:
    PropheseeRawReader(const String& path, const ReaderOptions& options) : in_(path)
    {
        std::string line, plugin;
        while (in_.peek() == '%')
        {
            in_.readLine(line);
            if (line == "% end")
                break;
            int w = 0, h = 0;
            if (line.compare(0, 6, "% evt ") == 0)
                version_ = line.substr(6) == "3.0" ? 3 : line.substr(6) == "2.0" ? 2 : -1;
            else if (line.compare(0, 9, "% format ") == 0)
            {
                const std::string f = line.substr(9);
                const std::string encoding = f.substr(0, f.find(';'));
                version_ = encoding == "EVT3" ? 3 : encoding == "EVT2" ? 2 : -1;
                const size_t wp = f.find("width="), hp = f.find("height=");
                if (wp != std::string::npos && hp != std::string::npos)
                    size_ = Size(std::atoi(f.c_str() + wp + 6), std::atoi(f.c_str() + hp + 7));
                if (version_ < 0)
                    formatError(path, in_.offset(), "unsupported RAW encoding \"" + f + "\" (EVT2 and EVT3 are read)");
            }
            else if (std::sscanf(line.c_str(), "%% geometry %dx%d", &w, &h) == 2)
                size_ = Size(w, h);
            else if (line.compare(0, 14, "% plugin_name ") == 0)
                plugin = line.substr(14);
        }
        if (version_ < 0)
            formatError(path, in_.offset(), "the RAW header names no supported encoding (\"% evt 2.0\" / \"% evt 3.0\")");
        if (size_.empty())
        {
            if (plugin.find("gen3") != std::string::npos)
                size_ = Size(640, 480);
            else if (plugin.find("gen4") != std::string::npos || plugin.find("imx636") != std::string::npos)
                size_ = Size(1280, 720);
            else if (plugin.find("genx320") != std::string::npos)
                size_ = Size(320, 320);
        }
        if (!options.sensorSize.empty())
            size_ = options.sensorSize;
    }

    String name() const CV_OVERRIDE { return version_ == 3 ? "PROPHESEE_EVT3" : "PROPHESEE_EVT2"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    double progress() const CV_OVERRIDE { return in_.progress(); }
    int64 skippedEvents() const CV_OVERRIDE { return skipped_ + evt3_.skipped(); }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        const size_t before = out.size();
        while (out.size() == before)
        {
            const size_t got = in_.readRecords(buffer_, sizeof(buffer_), version_ == 3 ? 2 : 4, "EVT word");
            if (got == 0)
                return false;
            if (version_ == 2)
                decodeEvt2(reinterpret_cast<const uint32_t*>(buffer_), got / 4, out);
            else
                evt3_.decode(reinterpret_cast<const uint16_t*>(buffer_), got / 2, out, triggers_);
        }
        return true;
    }

private:
    void decodeEvt2(const uint32_t* w, size_t n, std::vector<Event>& out)
    {
        for (size_t i = 0; i < n; i++)
        {
            const uint32_t word = w[i];
            const uint32_t type = word >> 28;
            if (type == 0x8)  // EVT_TIME_HIGH: timestamp bits 33..6
            {
                timeHigh_ = (int64)(word & 0x0FFFFFFF) << 6;
                haveTimeHigh_ = true;
            }
            else if (type <= 0x1)  // CD_OFF / CD_ON
            {
                if (!haveTimeHigh_)
                {
                    skipped_++;
                    continue;
                }
                const int64 t = timeHigh_ | ((word >> 22) & 0x3F);
                out.push_back(Event(t, (int)((word >> 11) & 0x7FF), (int)(word & 0x7FF), (int)type));
            }
            else if (type == 0xA && haveTimeHigh_)  // EXT_TRIGGER: bit 0 the edge, bits 12..8 the channel
                triggers_.push_back(EventTrigger(timeHigh_ | ((word >> 22) & 0x3F),
                                                 (word & 1) ? EVENT_TRIGGER_RISING : EVENT_TRIGGER_FALLING,
                                                 (int)((word >> 8) & 0x1F)));
            // 0xD IMU, 0xE others, 0xF continued: not CD events
        }
    }

    FileInput in_;
    Size size_;
    int version_ = -1;
    alignas(8) char buffer_[1 << 16];
    // EVT 2.0 state
    int64 skipped_ = 0;
    bool haveTimeHigh_ = false;
    int64 timeHigh_ = 0;
    Evt3Decoder evt3_;
};

}  // namespace

Ptr<EventReader> openPropheseeRawReader(const String& path, const ReaderOptions& options)
{
    return makePtr<PropheseeRawReader>(path, options);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
