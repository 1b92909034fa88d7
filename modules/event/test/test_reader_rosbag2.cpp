// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#ifdef OPENCV_EVENT_HAVE_SQLITE3
#include <sqlite3.h>
#endif

namespace opencv_test { namespace {

#ifdef OPENCV_EVENT_HAVE_SQLITE3
void writeBag(const std::string& db, const std::vector<std::pair<std::string, std::string>>& topicMessages)
{
    sqlite3* h = nullptr;
    ASSERT_EQ(SQLITE_OK, sqlite3_open(db.c_str(), &h));
    sqlite3_exec(h, "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT, type TEXT, serialization_format TEXT, "
                    "offered_qos_profiles TEXT);"
                    "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER, timestamp INTEGER, data BLOB);",
                 nullptr, nullptr, nullptr);
    std::vector<std::string> names;
    for (const auto& tm : topicMessages)
        if (std::find(names.begin(), names.end(), tm.first) == names.end())
            names.push_back(tm.first);
    for (size_t i = 0; i < names.size(); i++)
    {
        const std::string sql = "INSERT INTO topics VALUES(" + std::to_string(i + 1) + ", '" + names[i] +
                                "', 'event_camera_msgs/msg/EventPacket', 'cdr', '');";
        sqlite3_exec(h, sql.c_str(), nullptr, nullptr, nullptr);
    }
    int64 stamp = 1000;
    for (const auto& tm : topicMessages)
    {
        sqlite3_stmt* s = nullptr;
        sqlite3_prepare_v2(h, "INSERT INTO messages(topic_id, timestamp, data) VALUES(?, ?, ?)", -1, &s, nullptr);
        const int topic = (int)(std::find(names.begin(), names.end(), tm.first) - names.begin()) + 1;
        sqlite3_bind_int(s, 1, topic);
        sqlite3_bind_int64(s, 2, stamp++);
        sqlite3_bind_blob(s, 3, tm.second.data(), (int)tm.second.size(), SQLITE_TRANSIENT);
        ASSERT_EQ(SQLITE_DONE, sqlite3_step(s));
        sqlite3_finalize(s);
    }
    sqlite3_close(h);
}

uint16_t w(int type, int payload) { return (uint16_t)((type << 12) | payload); }
#endif

TEST(Event_Capture_RosBag2, evt3_packets_in_cdr_and_two_topics_make_stereo)
{
#ifndef OPENCV_EVENT_HAVE_SQLITE3
    throw SkipTestException("built without sqlite3");
#else
    // EVT3 words (doc/formats.md, "Prophesee RAW"): TIME_HIGH 1 -> 4096 us; TIME_LOW; ADDR_Y; ADDR_X (bit 11 = ON).
    const std::string left1 = eventPacket(640, 480, "evt3", 0, { w(0x8, 1), w(0x6, 10), w(0x0, 5), w(0x2, (1 << 11) | 7) });
    const std::string left2 = eventPacket(640, 480, "evt3", 0, { w(0x6, 30), w(0x0, 6), w(0x2, 8) });  // decoder state carries over
    const std::string right = eventPacket(640, 480, "evt3", 0, { w(0x8, 1), w(0x6, 20), w(0x0, 9), w(0x2, 639) });
    const std::string db = cv::tempfile(".db3");
    writeBag(db, { { "/cam_left/events", left1 }, { "/cam_right/events", right }, { "/cam_left/events", left2 } });
    EXPECT_EQ("ROSBAG2", detectEventFileFormat(db));
    EventCapture cap(db);
    EXPECT_EQ(Size(640, 480), cap.getSensorSize());
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_STEREO));
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(3u, ev.size());
    EXPECT_EQ(Event(4106, 7, 5, POLARITY_ON, CAMERA_LEFT), ev[0]);
    EXPECT_EQ(Event(4116, 639, 9, POLARITY_OFF, CAMERA_RIGHT), ev[1]);
    EXPECT_EQ(Event(4126, 8, 6, POLARITY_OFF, CAMERA_LEFT), ev[2]);
    std::remove(db.c_str());

    // An unsupported encoding names the file and the encoding.
    const std::string other = cv::tempfile(".db3");
    writeBag(other, { { "/events", eventPacket(8, 8, "mono", 0, { 0, 0, 0, 0 }) } });
    try { EventCapture c(other); readAllEvents(c); FAIL() << "encoding mono accepted"; }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find(other)) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("\"mono\"")) << e.err;
    }
    std::remove(other.c_str());
#endif
}

// shared/data/README.md: ROS2 sqlite3 bag, EventPacket with libcaer encoding, 640x480, 334,331 events; the
// int32 microsecond timestamp wraps once: the stream must stay time-ordered across it.
TEST(Event_Capture_Real, rosbag2_libcaer_rollover)
{
    const std::string dir = requireSharedData("format_samples/ros2_libcaer_rollover");
    const std::string sources[] = { dir, dir + "/libcaer_rollover_0.db3" };  // the folder or the database
    for (const std::string& source : sources)
    {
        EXPECT_EQ("ROSBAG2", detectEventFileFormat(source));
        EventCapture cap(source);
        EXPECT_EQ("ROSBAG2", cap.getBackendName());
        EXPECT_EQ(Size(640, 480), cap.getSensorSize());
        cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 100000);
        std::vector<Event> packet;
        size_t n = 0;
        int64 first = -1, last = -1, maxStep = 0;
        while (cap.read(packet))
            for (const Event& e : packet)
            {
                if (first < 0) first = e.t;
                if (last >= 0) maxStep = std::max(maxStep, e.t - last);
                last = e.t;
                n++;
            }
        EXPECT_EQ(334331u, n) << source;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS)) << source;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE)) << source;
        // The metadata gives 1.99 s between the first and last message; a mishandled wrap would show as a
        // jump of about 2^31 us (36 minutes) or as time going backwards.
        EXPECT_NEAR(2.0e6, (double)(last - first), 0.05e6) << source;
        EXPECT_LT(maxStep, 100000) << source;
    }
}

// The data README: a ROS2 sqlite3 bag whose topics table names event_array_msgs/msg/EventArray (EventPacket's
// name before its 2023 rename; its metadata.yaml says EventPacket): 378,266 events (139,584 ON / 238,682 OFF).
TEST(Event_Capture_Real, rosbag2_legacy_event_array_name)
{
    EventCapture cap(requireSharedData("format_samples/ecpy_legacy_eventarray_ros2"));
    EXPECT_EQ("ROSBAG2", cap.getBackendName());
    const std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(378266u, ev.size());
    size_t on = 0;
    for (const Event& e : ev)
        on += e.p;
    EXPECT_EQ(139584u, on);
}

// The data README: 18 rising and 18 falling trigger events; event_camera_py's test of this bag
// (tests/test_ros2_1.py): the sum of every event's and trigger's time is 6024891770230 us.
TEST(Event_Capture_Real, rosbag2_legacy_event_array_triggers)
{
    EventCapture cap(requireSharedData("format_samples/ecpy_legacy_eventarray_ros2"));
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 30000);
    const EventAndTriggerTally tally = tallyEventsAndTriggers(cap);
    EXPECT_EQ(6024891770230LL, tally.timeSum);
    const std::map<std::pair<int, int>, int64> expected = { { { EVENT_TRIGGER_FALLING, 6 }, 18 },
                                                            { { EVENT_TRIGGER_RISING, 6 }, 18 } };
    EXPECT_EQ(expected, tally.triggers);
}

}} // namespace
