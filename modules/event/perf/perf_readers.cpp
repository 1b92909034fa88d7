// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Reading 1 M events through EventCapture, per writable format (files written once by EventWriter, on a
// DAVIS346-sized sensor at 1 Mev/s); and reading the real sample of every other format in ../shared/data
// (skipped when absent). perf/event_io_bench prints the same as a table.

#include "perf_precomp.hpp"

namespace opencv_test { namespace {

// Opens path and reads it to the end in batches; returns the events read.
static size_t readAll(EventCapture& cap, const std::string& path, std::vector<Event>& batch)
{
    cap.open(path);
    size_t events = 0;
    while (cap.read(batch))
        events += batch.size();
    return events;
}

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
        events = readAll(cap, path, batch);
        stopTimer();
    }
    std::remove(path.c_str());
    ASSERT_EQ((size_t)n, events);
    SANITY_CHECK_NOTHING();
}

// The real recordings of ../shared/data/README.md, one per reader, with the event counts it documents (the
// property "events" gives Mev/s from the time). A stereo recording in one file (Fan: a camera column) is read
// by one reader per camera, each parsing the whole file, so that the merge keeps memory bounded when the file
// stores one camera after the other: its lines are parsed twice.
struct SharedRecording
{
    const char* path;
    int events;
};

static const SharedRecording sharedRecordings[] = {
    { "format_samples/aestream_davis346.aedat4", 117667 },  // AEDAT4, LZ4
    { "format_samples/tonic_sample_dvxplorer.aedat4", 111954 },
    { "format_samples/evt2_sample.raw", 539481 },            // Prophesee EVT 2.0
    { "format_samples/evt3_sample.raw", 219596 },            // Prophesee EVT 3.0
    { "format_samples/tonic_sample_ncars.dat", 2009 },       // Prophesee DAT
    { "format_samples/ecpy_test_events_1_ros1.bag", 343474 },  // ROS1 bag, evt3 packets
    { "format_samples/ros2_libcaer_rollover", 334331 },      // ROS2 bag, libcaer packets
    { "stereo_dvs128_tum/Fan_disp8.dat", 136233 },           // stereo text
};

typedef TestBaseWithParam<int> Event_ReaderSample;

PERF_TEST_P(Event_ReaderSample, shared_recording, testing::Range(0, (int)(sizeof(sharedRecordings) / sizeof(sharedRecordings[0]))))
{
    const SharedRecording& r = sharedRecordings[GetParam()];
    const std::string path = requireSharedData(r.path);
    RecordProperty("recording", r.path);
    RecordProperty("events", r.events);
    size_t events = 0;
    std::vector<Event> batch;
    while (next())
    {
        EventCapture cap;
        startTimer();
        events = readAll(cap, path, batch);
        stopTimer();
    }
    ASSERT_EQ((size_t)r.events, events) << path;
    SANITY_CHECK_NOTHING();
}

}} // namespace
