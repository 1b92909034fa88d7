// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Random, time-ordered events with every field exercised (repeated timestamps, both polarities, the
// sensor's corners, Unix-epoch-sized timestamps).
std::vector<Event> randomStream(int n, Size size, int camera, uint64 seed)
{
    RNG rng(seed);
    std::vector<Event> ev(n);
    int64 t = 1605507430438338LL;
    for (int i = 0; i < n; i++)
    {
        t += rng.uniform(0, 3);
        ev[i] = Event(t, rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2), camera);
    }
    ev.front().x = 0; ev.front().y = 0;
    ev.back().x = (short)(size.width - 1); ev.back().y = (short)(size.height - 1);
    return ev;
}

std::vector<Event> readBack(const std::string& path)
{
    EventCapture cap(path);
    const std::vector<Event> all = readAllEvents(cap, 777);  // batches that do not line up with the packets
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE));
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS));
    return all;
}

void expectIdentical(const std::vector<Event>& expected, const std::vector<Event>& actual, const std::string& what)
{
    ASSERT_EQ(expected.size(), actual.size()) << what;
    for (size_t i = 0; i < expected.size(); i++)
        ASSERT_EQ(expected[i], actual[i]) << what << ": event " << i;
}

struct WriterCase
{
    const char* ext;
    int format;
    int compression;
};

const WriterCase kCases[] = {
    { ".txt", EVENT_FILE_TEXT, 0 },
    { ".aedat4", EVENT_FILE_AEDAT4, 0 },  // no compression
    { ".aedat4", EVENT_FILE_AEDAT4, 1 },  // LZ4
    { ".aedat4", EVENT_FILE_AEDAT4, 2 },  // LZ4 high
    { ".aedat4", EVENT_FILE_AEDAT4, 3 },  // ZSTD
    { ".aedat4", EVENT_FILE_AEDAT4, 4 },  // ZSTD high
};

TEST(Event_Writer, mono_round_trip_is_exact_for_every_format)
{
    const Size size(346, 260);
    const std::vector<Event> ev = randomStream(20000, size, CAMERA_LEFT, 1);
    for (const WriterCase& c : kCases)
    {
        const std::string path = cv::tempfile(c.ext);
        const std::string what = std::string(c.ext) + " compression " + std::to_string(c.compression);
        {
            EventWriter w;
            w.set(EVENT_WRITER_PROP_COMPRESSION, c.compression);
            w.set(EVENT_WRITER_PROP_PACKET_EVENTS, 1000);
            ASSERT_TRUE(w.open(path, size, c.format));
            w.write(std::vector<Event>(ev.begin(), ev.begin() + 12345));
            w.write(std::vector<Event>(ev.begin() + 12345, ev.end()));
            EXPECT_EQ(20000.0, w.get(EVENT_WRITER_PROP_EVENTS_WRITTEN));
        }  // the destructor flushes and closes
        EventCapture probe(path);
        EXPECT_EQ(size, probe.getSensorSize()) << what;
        EXPECT_EQ(c.format == EVENT_FILE_TEXT ? "TEXT" : "AEDAT4", probe.getBackendName()) << what;
        expectIdentical(ev, readBack(path), what);
        std::remove(path.c_str());
    }
}

TEST(Event_Writer, stereo_round_trip_is_exact_for_every_format)
{
    const Size size(240, 180);
    std::vector<Event> merged;
    mergeStereoEvents(randomStream(5000, size, CAMERA_LEFT, 2), randomStream(7000, size, CAMERA_RIGHT, 3), merged);
    for (const WriterCase& c : kCases)
    {
        const std::string path = cv::tempfile(c.ext);
        EventWriter w;
        w.set(EVENT_WRITER_PROP_STEREO, 1);
        w.set(EVENT_WRITER_PROP_COMPRESSION, c.compression);
        w.set(EVENT_WRITER_PROP_PACKET_EVENTS, 500);
        ASSERT_TRUE(w.open(path, size, c.format));
        w.write(merged);
        w.release();
        EventCapture probe(path);
        EXPECT_EQ(1.0, probe.get(EVENT_CAP_PROP_STEREO)) << c.ext;
        expectIdentical(merged, readBack(path), std::string(c.ext) + " stereo, compression " + std::to_string(c.compression));
        std::remove(path.c_str());
    }
}

TEST(Event_Writer, rejects_what_could_not_be_read_back)
{
    const std::string path = cv::tempfile(".aedat4");
    EventWriter w(path, Size(10, 10));
    EXPECT_THROW(w.write(std::vector<Event>(1, Event(5, 10, 0, 1))), cv::Exception);                // outside
    EXPECT_THROW(w.write(std::vector<Event>(1, Event(5, 1, 1, 1, CAMERA_RIGHT))), cv::Exception);    // not stereo
    w.write(std::vector<Event>(1, Event(5, 1, 1, 1)));
    EXPECT_THROW(w.write(std::vector<Event>(1, Event(4, 1, 1, 1))), cv::Exception);                  // backwards
    w.release();
    EXPECT_EQ(1u, readBack(path).size());
    std::remove(path.c_str());

    const std::string dir = cv::tempfile("_no_such_dir");
    try { EventWriter bad(dir + "/x.txt", Size(10, 10)); FAIL() << "created a file in a missing directory"; }
    catch (const cv::Exception& e) { EXPECT_NE(std::string::npos, e.err.find(dir)) << e.err; }
}

}} // namespace
