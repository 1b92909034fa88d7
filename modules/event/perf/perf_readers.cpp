// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Reading 1 M events through EventCapture, per writable format (files written once by EventWriter, on a
// DAVIS346-sized sensor at 1 Mev/s). perf/event_io_bench also covers the real sample of every format.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

enum { READ_TEXT, READ_AEDAT4_RAW, READ_AEDAT4_LZ4, READ_AEDAT4_ZSTD };
CV_ENUM(ReadFormat, READ_TEXT, READ_AEDAT4_RAW, READ_AEDAT4_LZ4, READ_AEDAT4_ZSTD)

typedef TestBaseWithParam<ReadFormat> Event_Reader;

PERF_TEST_P(Event_Reader, one_million_events, ReadFormat::all())
{
    const int format = GetParam();
    const int n = 1000000;
    const Size size(346, 260);
    const std::string path = cv::tempfile(format == READ_TEXT ? ".txt" : ".aedat4");
    {
        EventWriter writer;
        if (format != READ_TEXT)
            writer.set(EVENT_WRITER_PROP_COMPRESSION, format == READ_AEDAT4_RAW ? 0 : format == READ_AEDAT4_LZ4 ? 1 : 3);
        ASSERT_TRUE(writer.open(path, size));
        RNG rng(3);
        std::vector<Event> packet(10000);
        for (int i = 0; i < n; i += (int)packet.size())
        {
            for (int k = 0; k < (int)packet.size(); k++)
                packet[(size_t)k] = Event(i + k, rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2));
            writer.write(packet);
        }
    }
    size_t events = 0;
    std::vector<Event> batch;
    while (next())
    {
        EventCapture cap;
        startTimer();
        cap.open(path);
        events = 0;
        while (cap.read(batch))
            events += batch.size();
        stopTimer();
    }
    std::remove(path.c_str());
    ASSERT_EQ((size_t)n, events);
    SANITY_CHECK_NOTHING();
}

}} // namespace
