// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

struct Aedat4Facts
{
    const char* file;
    Size size;
    size_t events;
    double durationUs;
};

// shared/data/README.md
const Aedat4Facts kFacts[] = {
    { "format_samples/aestream_davis346.aedat4", Size(346, 260), 117667, 0.130e6 },
    { "format_samples/tonic_sample_dvxplorer.aedat4", Size(320, 240), 111954, 0.590e6 },
};

TEST(Event_Capture_Real, aedat4_samples_counts_sizes_and_durations)
{
    for (const Aedat4Facts& f : kFacts)
    {
        EventCapture cap(requireSharedData(f.file));
        EXPECT_EQ("AEDAT4", cap.getBackendName()) << f.file;
        EXPECT_EQ(f.size, cap.getSensorSize()) << f.file;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_STEREO)) << f.file;
        // Both files end with a FileDataTable: the duration is known before reading.
        EXPECT_NEAR(f.durationUs, cap.get(EVENT_CAP_PROP_DURATION_US), 0.01e6) << f.file;
        cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 50000);
        std::vector<Event> packet;
        size_t n = 0;
        int64 first = -1, last = -1;
        while (cap.read(packet))
        {
            n += packet.size();
            if (first < 0) first = packet.front().t;
            last = packet.back().t;
        }
        EXPECT_EQ(f.events, n) << f.file;
        EXPECT_NEAR(f.durationUs, (double)(last - first), 0.01e6) << f.file;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE)) << f.file;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS)) << f.file;
    }
}

// The DAVIS346 sample's trigger stream holds 15 APS frame and exposure markers (DV trigger types 6..9), which
// are not trigger events: it is read, and gives none.
TEST(Event_Capture_Real, aedat4_trigger_stream_of_frame_markers_gives_no_triggers)
{
    EventCapture cap(requireSharedData("format_samples/aestream_davis346.aedat4"));
    EXPECT_TRUE(readAllTriggers(cap).empty());
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TRIGGERS));
}

}} // namespace
