// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_IO_EVT3_DECODER_HPP
#define OPENCV_EVENT_SRC_IO_EVT3_DECODER_HPP

// Prophesee EVT 3.0 word-stream decoder (doc/formats.md, "Prophesee RAW"), shared by the RAW reader and the ROS
// bag reader (event_camera_msgs/EventPacket with encoding "evt3" carries the same words). Stateful: a
// stream split into packets decodes as one when the packets are fed in order.

#include "opencv2/event.hpp"

namespace cv {
namespace event {
namespace detail {

class Evt3Decoder
{
public:
    /** Decodes @p n 16-bit words, appending CD events to @p out and external triggers to @p triggers. CD
    events before the first TIME_HIGH have no time base: they are counted in skipped() (triggers then are
    dropped). */
    void decode(const uint16_t* w, size_t n, std::vector<Event>& out, std::vector<EventTrigger>& triggers)
    {
        for (size_t i = 0; i < n; i++)
        {
            const uint16_t word = w[i];
            switch (word >> 12)
            {
            case 0x0: y_ = word & 0x7FF; break;                                   // EVT_ADDR_Y
            case 0x2: emit(word & 0x7FF, (word >> 11) & 1, out); break;          // EVT_ADDR_X
            case 0x3: baseX_ = word & 0x7FF; vectorPolarity_ = (word >> 11) & 1; break;  // VECT_BASE_X
            case 0x4:                                                            // VECT_12
            case 0x5:                                                            // VECT_8
            {
                const int bits = (word >> 12) == 0x4 ? 12 : 8;
                const uint32_t mask = word & ((1u << bits) - 1);
                for (int b = 0; b < bits; b++)
                    if (mask & (1u << b))
                        emit(baseX_ + b, vectorPolarity_, out);
                baseX_ += bits;
                break;
            }
            case 0x6: timeLow_ = word & 0xFFF; break;                            // EVT_TIME_LOW
            case 0x8:                                                            // EVT_TIME_HIGH
            {
                const int high = word & 0xFFF;
                // 24-bit time base: a TIME_HIGH far below the previous one is a loop (OpenEB's rule); a
                // TIME_LOW decrease alone is not.
                if (haveTimeHigh_ && timeHigh_ >= high + 2048)
                    loops_++;
                if (!haveTimeHigh_ || high != timeHigh_)
                    timeLow_ = 0;
                timeHigh_ = high;
                haveTimeHigh_ = true;
                timeBase_ = (loops_ << 24) + ((int64)high << 12);
                break;
            }
            case 0xA:                                                            // EXT_TRIGGER
                if (haveTimeHigh_)
                    triggers.push_back(EventTrigger(timeBase_ + timeLow_, (word & 1) ? EVENT_TRIGGER_RISING
                                                                                    : EVENT_TRIGGER_FALLING,
                                                    (word >> 8) & 0xF));
                break;
            default: break;  // IMU, others, continued words: not CD events
            }
        }
    }

    int64 skipped() const { return skipped_; }

private:
    void emit(int x, int p, std::vector<Event>& out)
    {
        if (!haveTimeHigh_)
        {
            skipped_++;
            return;
        }
        out.push_back(Event(timeBase_ + timeLow_, x, y_, p));
    }

    bool haveTimeHigh_ = false;
    int y_ = 0, baseX_ = 0, vectorPolarity_ = 0, timeHigh_ = 0;
    int64 timeLow_ = 0, timeBase_ = 0, loops_ = 0, skipped_ = 0;
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_IO_EVT3_DECODER_HPP
