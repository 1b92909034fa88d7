// libFuzzer target for the live DAVIS word decoder. The first byte picks the array geometry and options, the
// second the transfer size; the rest is the byte stream, split into transfers as USB would deliver it.
// Must hold: no crash / UB / leak, and every event lies inside the array it was configured for.

#include <opencv2/event.hpp>
#include "davis/davis_event_decoder.hpp"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 2)
        return 0;
    static const int kColumns[] = { 240, 346, 180, 260, 128, 640, 1, 4095 };
    static const int kRows[] = { 180, 260, 240, 346, 128, 480, 1, 4095 };
    const int columns = kColumns[data[0] & 7], rows = kRows[(data[0] >> 3) & 7];
    const bool invertXY = (data[0] & 0x40) != 0, waitForReset = (data[0] & 0x80) != 0;
    const size_t transfer = 1 + (size_t)data[1] * 37;  // odd sizes too: words split across transfers
    cv::event::detail::DavisEventDecoder decoder(columns, rows, invertXY, waitForReset);
    const int width = invertXY ? rows : columns, height = invertXY ? columns : rows;
    std::vector<cv::event::Event> events;
    std::vector<cv::event::EventTrigger> triggers;
    for (size_t pos = 2; pos < size; pos += transfer)
    {
        events.clear();
        decoder.decode(data + pos, std::min(transfer, size - pos), events);
        for (const cv::event::Event& e : events)
            if (e.x < 0 || e.y < 0 || e.x >= width || e.y >= height || e.t < 0)
                std::abort();
        triggers.clear();
        decoder.takeTriggers(triggers);  // on the events' clock: never before zero, a known kind
        for (const cv::event::EventTrigger& t : triggers)
            if (t.t < 0 || t.kind > cv::event::EVENT_TRIGGER_GENERATOR_RISING)
                std::abort();
    }
    return 0;
}
