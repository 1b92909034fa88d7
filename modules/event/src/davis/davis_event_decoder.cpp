// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "davis/davis_event_decoder.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

// Word layout: bit 15 = timestamp word (bits 14..0 = us since the last wrap); otherwise bits 14..12 = code,
// bits 11..0 = data.
enum WordCode { CODE_SPECIAL = 0, CODE_Y = 1, CODE_X_OFF = 2, CODE_X_ON = 3, CODE_APS = 4, CODE_MISC8 = 5,
                CODE_MISC10 = 6, CODE_WRAP = 7 };
const int kSpecialTimestampReset = 1;

// Special words of the external-input and generator modules, as trigger kinds (-1: not a trigger).
int triggerKindOfSpecial(int value)
{
    switch (value)
    {
    case 2: return EVENT_TRIGGER_FALLING;
    case 3: return EVENT_TRIGGER_RISING;
    case 4: return EVENT_TRIGGER_PULSE;
    case 16: return EVENT_TRIGGER_GENERATOR_FALLING;
    case 17: return EVENT_TRIGGER_GENERATOR_RISING;
    default: return -1;
    }
}
const int64 kWrapUs = 0x8000;

}  // namespace

DavisEventDecoder::DavisEventDecoder(int rawColumns, int rawRows, bool invertXY, bool waitForTimestampReset)
    : rawColumns_(rawColumns), rawRows_(rawRows), invertXY_(invertXY), synchronised_(!waitForTimestampReset),
      armed_(waitForTimestampReset)
{
    CV_Assert(rawColumns > 0 && rawRows > 0);
}

void DavisEventDecoder::arm(int64 epochUs)
{
    armed_ = true;
    armedEpoch_ = epochUs;
}

void DavisEventDecoder::disarm()
{
    armed_ = false;
    synchronised_ = false;
}

void DavisEventDecoder::takeTriggers(std::vector<EventTrigger>& out)
{
    out.insert(out.end(), triggers_.begin(), triggers_.end());
    triggers_.clear();
}

void DavisEventDecoder::decode(const uint8_t* data, size_t size, std::vector<Event>& out, int camera)
{
    const size_t words = size / 2;
    counters_.oddBytes += (int64)(size & 1);
    counters_.words += (int64)words;
    for (size_t i = 0; i < words; i++)
    {
        const unsigned w = (unsigned)data[2 * i] | ((unsigned)data[2 * i + 1] << 8);
        if (w & 0x8000u)
        {
            current_ = epochOffset_ + wrapBase_ + (int64)(w & 0x7FFFu);
            continue;
        }
        const int code = (int)((w >> 12) & 7u);
        const int value = (int)(w & 0xFFFu);
        switch (code)
        {
        case CODE_SPECIAL:
            if (value == kSpecialTimestampReset)
            {
                counters_.timestampResets++;
                if (armed_)
                {
                    epochOffset_ = armedEpoch_;  // the reset we asked for
                    armed_ = false;
                    synchronised_ = true;
                }
                else if (synchronised_)  // a reset nobody here asked for: time goes on, never back
                    epochOffset_ = unarmedEpoch_ ? std::max(current_, unarmedEpoch_(current_)) : current_;
                else
                    counters_.staleResets++;
                wrapBase_ = 0;
                current_ = epochOffset_;
                lastRow_ = -1;
            }
            else if (triggerKindOfSpecial(value) >= 0)
            {
                counters_.triggers++;
                if (synchronised_)
                    triggers_.push_back(EventTrigger(current_, triggerKindOfSpecial(value), 0, camera));
            }
            else
                counters_.otherWords++;
            break;
        case CODE_Y:
            if (value < rawRows_)
                lastRow_ = value;
            else
            {
                lastRow_ = -1;
                counters_.invalidAddresses++;
            }
            break;
        case CODE_X_OFF:
        case CODE_X_ON:
            if (value >= rawColumns_ || lastRow_ < 0)
            {
                counters_.invalidAddresses++;
                break;
            }
            if (!synchronised_)
            {
                counters_.eventsBeforeReset++;
                break;
            }
            if (invertXY_)
                out.emplace_back(current_, lastRow_, value, code & 1, camera);
            else
                out.emplace_back(current_, value, lastRow_, code & 1, camera);
            counters_.events++;
            break;
        case CODE_WRAP:
            counters_.wraps++;
            wrapBase_ += (int64)value * kWrapUs;
            current_ = epochOffset_ + wrapBase_;
            break;
        default:  // APS samples, IMU bytes, exposure info: not events
            counters_.otherWords++;
            break;
        }
    }
}

}  // namespace detail
}  // namespace event
}  // namespace cv
