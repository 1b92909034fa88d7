// libFuzzer target for one EventCapture file back-end (chosen at compile time: FUZZ_API, FUZZ_EXTENSION).
// The input becomes a file and is read to the end. What must hold for any input:
//  - the only way to fail is a cv::Exception (anything else escapes and libFuzzer reports it);
//  - no crash, leak, out-of-bounds access or undefined behaviour (ASan + UBSan);
//  - no allocation beyond libFuzzer's -malloc_limit_mb, whatever sizes a header claims;
//  - delivered events lie inside the sensor (when it is known) and in time order (the default CLAMP policy).

#include <opencv2/event.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

#ifndef FUZZ_API
#error "FUZZ_API must name an EventCaptureAPIs value"
#endif

namespace {

std::string inputPath()
{
    const char* dir = std::getenv("TMPDIR");
    return cv::format("%s/opencv_event_fuzz_%d.%s", dir && *dir ? dir : "/tmp", (int)getpid(), FUZZ_EXTENSION);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    static const std::string path = inputPath();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f)
        std::abort();
    if (size && std::fwrite(data, 1, size, f) != size)
        std::abort();
    std::fclose(f);
    try
    {
        cv::event::EventCapture cap;
        cap.set(cv::event::EVENT_CAP_PROP_BATCH_EVENTS, 4096);
        cap.open(path, cv::event::FUZZ_API);
        const cv::Size sensor = cap.getSensorSize();
        std::vector<cv::event::Event> events;
        std::vector<cv::event::EventTrigger> triggers;
        int64_t last = INT64_MIN, lastTrigger = INT64_MIN, triggerCount = 0;
        while (cap.read(events))
        {
            for (const cv::event::Event& e : events)
            {
                if (!sensor.empty() && (e.x < 0 || e.y < 0 || e.x >= sensor.width || e.y >= sensor.height))
                    std::abort();  // EventCapture promises never to deliver these
                if (e.t < last)
                    std::abort();
                last = e.t;
            }
            cap.retrieveTriggers(triggers);  // in time order, each a known kind, each delivered once
            for (const cv::event::EventTrigger& t : triggers)
            {
                if (t.t < lastTrigger || t.kind > cv::event::EVENT_TRIGGER_GENERATOR_RISING)
                    std::abort();
                lastTrigger = t.t;
            }
            triggerCount += (int64_t)triggers.size();
            if (triggerCount > (int64_t)cap.get(cv::event::EVENT_CAP_PROP_TRIGGERS))
                std::abort();
        }
    }
    catch (const cv::Exception&)
    {
        // the documented way to reject a file
    }
    return 0;
}
