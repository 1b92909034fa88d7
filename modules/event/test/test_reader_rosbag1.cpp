// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#ifdef OPENCV_EVENT_HAVE_BZIP2
#include <bzlib.h>
#endif

namespace opencv_test { namespace {

// ROS1 bag fixtures built from the documented layout (doc/formats.md, "ROS1 bag"), independently of the reader.
template<typename T>
void put(std::string& s, T v)
{
    s.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

std::string field(const std::string& name, const std::string& value)
{
    std::string f;
    put<uint32_t>(f, (uint32_t)(name.size() + 1 + value.size()));
    return f + name + "=" + value;
}

template<typename T>
std::string bin(T v)
{
    return std::string(reinterpret_cast<const char*>(&v), sizeof(T));
}

std::string record(const std::string& header, const std::string& data)
{
    std::string r;
    put<uint32_t>(r, (uint32_t)header.size());
    r += header;
    put<uint32_t>(r, (uint32_t)data.size());
    return r + data;
}

std::string connectionRecord(uint32_t conn, const std::string& topic, const std::string& type, const std::string& md5)
{
    return record(field("op", std::string(1, '\x07')) + field("conn", bin(conn)) + field("topic", topic),
                  field("topic", topic) + field("type", type) + field("md5sum", md5) +
                  field("message_definition", "# fixture"));
}

std::string messageRecord(uint32_t conn, const std::string& payload)
{
    return record(field("op", std::string(1, '\x02')) + field("conn", bin(conn)) + field("time", bin<uint64_t>(0)), payload);
}

std::string rosHeader()
{
    std::string h;
    put<uint32_t>(h, 7);  // seq
    put<uint32_t>(h, 1);  // stamp sec
    put<uint32_t>(h, 2);  // stamp nsec
    put<uint32_t>(h, 3);
    return h + "cam";
}

std::string eventArray(uint32_t width, uint32_t height, const std::vector<Event>& ev)
{
    std::string m = rosHeader();
    put<uint32_t>(m, height);
    put<uint32_t>(m, width);
    put<uint32_t>(m, (uint32_t)ev.size());
    for (const Event& e : ev)
    {
        put<uint16_t>(m, (uint16_t)e.x);
        put<uint16_t>(m, (uint16_t)e.y);
        put<uint32_t>(m, (uint32_t)(e.t / 1000000));
        put<uint32_t>(m, (uint32_t)(e.t % 1000000) * 1000 + 999);  // sub-microsecond nanoseconds are dropped
        put<uint8_t>(m, e.p);
    }
    return m;
}

const char* kDvsMd5 = "5e8beee5a6c107e504c2e78903c224b8";

uint32_t xxh32(const uchar* p, size_t n)
{
    const uint32_t P1 = 2654435761U, P2 = 2246822519U, P3 = 3266489917U, P5 = 374761393U;
    uint32_t h = P5 + (uint32_t)n;
    for (size_t i = 0; i < n; i++)
    {
        h += p[i] * P5;
        h = ((h << 11) | (h >> 21)) * P1;
    }
    h ^= h >> 15; h *= P2; h ^= h >> 13; h *= P3; h ^= h >> 16;
    return h;
}

// An LZ4 frame holding the data as one stored (uncompressed) block: valid LZ4, written by hand.
std::string lz4StoredFrame(const std::string& data)
{
    std::string f("\x04\x22\x4d\x18", 4);
    const uchar desc[2] = { 0x60, 0x70 };  // version 01, independent blocks; max block 4 MB
    f.append(reinterpret_cast<const char*>(desc), 2);
    f.push_back((char)((xxh32(desc, 2) >> 8) & 0xFF));
    put<uint32_t>(f, 0x80000000u | (uint32_t)data.size());
    f += data;
    put<uint32_t>(f, 0);  // end mark
    return f;
}

// magic, bag header, one chunk of `inner` records, then the index (the connection records).
std::string bag(const std::string& inner, const std::string& compression, const std::string& index)
{
    const std::string magic = "#ROSBAG V2.0\n";
    std::string payload = compression == "lz4" ? lz4StoredFrame(inner) : inner;
#ifdef OPENCV_EVENT_HAVE_BZIP2
    if (compression == "bz2")
    {
        std::vector<char> out(inner.size() * 2 + 600);
        unsigned int n = (unsigned int)out.size();
        std::string src = inner;
        CV_Assert(BZ2_bzBuffToBuffCompress(out.data(), &n, &src[0], (unsigned int)src.size(), 9, 0, 0) == BZ_OK);
        payload.assign(out.data(), n);
    }
#endif
    const std::string chunk = record(field("op", std::string(1, '\x05')) + field("compression", compression) +
                                     field("size", bin<uint32_t>((uint32_t)inner.size())), payload);
    // The bag header's length does not depend on index_pos: compute it with 0 first.
    auto header = [&](uint64_t indexPos) {
        return record(field("op", std::string(1, '\x03')) + field("index_pos", bin(indexPos)) +
                      field("conn_count", bin<uint32_t>(1)) + field("chunk_count", bin<uint32_t>(1)), std::string(64, ' '));
    };
    const uint64_t indexPos = magic.size() + header(0).size() + chunk.size();
    return magic + header(indexPos) + chunk + index;
}

TEST(Event_Capture_RosBag1, dvs_event_array_in_an_uncompressed_chunk)
{
    const std::vector<Event> ev = { Event(1000001, 3, 4, 1), Event(1000002, 239, 179, 0), Event(2500000, 0, 0, 1) };
    const std::string conn = connectionRecord(0, "/dvs/events", "dvs_msgs/EventArray", kDvsMd5);
    const std::string inner = conn + messageRecord(0, eventArray(240, 180, std::vector<Event>(ev.begin(), ev.begin() + 2))) +
                              messageRecord(0, eventArray(240, 180, std::vector<Event>(ev.begin() + 2, ev.end())));
    const std::string path = writeTempFile(bag(inner, "none", conn), ".bag");
    EXPECT_EQ("ROSBAG1", detectEventFileFormat(path));
    EventCapture cap(path);
    EXPECT_EQ("ROSBAG1", cap.getBackendName());
    EXPECT_EQ(Size(240, 180), cap.getSensorSize());
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_STEREO));
    std::vector<Event> back = readAllEvents(cap);
    ASSERT_EQ(ev.size(), back.size());
    for (size_t i = 0; i < ev.size(); i++)
        EXPECT_EQ(ev[i], back[i]) << i;
    std::remove(path.c_str());
}

TEST(Event_Capture_RosBag1, two_event_topics_in_an_lz4_chunk_are_a_stereo_pair)
{
    const std::string cl = connectionRecord(0, "/dvs/left/events", "dvs_msgs/EventArray", kDvsMd5);
    const std::string cr = connectionRecord(1, "/dvs/right/events", "dvs_msgs/EventArray", kDvsMd5);
    const std::vector<Event> left = { Event(10, 1, 1, 1), Event(30, 2, 1, 1) };
    const std::vector<Event> right = { Event(20, 5, 1, 0), Event(30, 6, 1, 0) };
    // The right topic's connection comes first in the file: the camera still follows the topic names.
    const std::string inner = cr + cl + messageRecord(1, eventArray(64, 48, right)) + messageRecord(0, eventArray(64, 48, left));
    const std::string path = writeTempFile(bag(inner, "lz4", cr + cl), ".bag");
    EventCapture cap(path);
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_STEREO));
    EXPECT_EQ(Size(64, 48), cap.getSensorSize());
    std::vector<Event> back = readAllEvents(cap);
    ASSERT_EQ(4u, back.size());
    EXPECT_EQ(Event(10, 1, 1, 1, CAMERA_LEFT), back[0]);
    EXPECT_EQ(Event(20, 5, 1, 0, CAMERA_RIGHT), back[1]);
    EXPECT_EQ(Event(30, 2, 1, 1, CAMERA_LEFT), back[2]);
    EXPECT_EQ(Event(30, 6, 1, 0, CAMERA_RIGHT), back[3]);
    std::remove(path.c_str());
}

TEST(Event_Capture_RosBag1, bz2_chunk)
{
#ifndef OPENCV_EVENT_HAVE_BZIP2
    throw SkipTestException("built without libbz2");
#else
    const std::vector<Event> ev = { Event(7, 1, 2, 1), Event(9, 3, 4, 0) };
    const std::string conn = connectionRecord(0, "/dvs/events", "dvs_msgs/EventArray", kDvsMd5);
    const std::string path = writeTempFile(bag(conn + messageRecord(0, eventArray(16, 16, ev)), "bz2", conn), ".bag");
    EventCapture cap(path);
    std::vector<Event> back = readAllEvents(cap);
    ASSERT_EQ(2u, back.size());
    EXPECT_EQ(ev[0], back[0]);
    EXPECT_EQ(ev[1], back[1]);
    std::remove(path.c_str());
#endif
}

TEST(Event_Capture_RosBag1, event_packet_libcaer_encoding_with_rollover)
{
    // libcaer polarity events {u32: polarity bit 1, y bits 2.., x bits 17..; int32 t_us}; time_base in ns.
    std::string events;
    auto caer = [&](int x, int y, int on, int32_t t) {
        put<uint32_t>(events, ((uint32_t)x << 17) | ((uint32_t)y << 2) | ((uint32_t)on << 1) | 1u);
        put<int32_t>(events, t);
    };
    caer(1, 2, 1, 0x7FFFFFF0);
    caer(3, 4, 0, 0x00000010);  // the 31-bit counter rolled over
    std::string msg = rosHeader();
    put<uint32_t>(msg, 260);  // height
    put<uint32_t>(msg, 346);  // width
    put<uint64_t>(msg, 1);    // seq
    put<uint64_t>(msg, 5000000000ULL);  // time_base: 5 s in ns
    put<uint32_t>(msg, 7);
    msg += "libcaer";
    put<uint8_t>(msg, 0);
    put<uint32_t>(msg, (uint32_t)events.size());
    msg += events;
    const std::string conn = connectionRecord(0, "/events", "event_camera_msgs/EventPacket", "8a6101b351a64529ac77bd8b71074e52");
    const std::string path = writeTempFile(bag(conn + messageRecord(0, msg), "none", conn), ".bag");
    EventCapture cap(path);
    EXPECT_EQ(Size(346, 260), cap.getSensorSize());
    std::vector<Event> back = readAllEvents(cap);
    ASSERT_EQ(2u, back.size());
    EXPECT_EQ(Event(5000000 + 0x7FFFFFF0LL, 1, 2, 1), back[0]);
    EXPECT_EQ(Event(5000000 + (1LL << 31) + 0x10, 3, 4, 0), back[1]);
    std::remove(path.c_str());
}

TEST(Event_Capture_RosBag1, corrupt_bags_name_file_and_offset)
{
    const std::string conn = connectionRecord(0, "/dvs/events", "dvs_msgs/EventArray", kDvsMd5);
    std::string good = bag(conn + messageRecord(0, eventArray(8, 8, { Event(1, 1, 1, 1) })), "none", conn);

    const std::string unknown = bag(conn, "zip", conn);
    std::string path = writeTempFile(unknown, ".bag");
    {
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, 8);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, 8);
        cap.open(path);
        std::vector<Event> ev;
        try { readAllEvents(cap); FAIL() << "unknown compression accepted"; }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(std::string::npos, e.err.find(path)) << e.err;
            EXPECT_NE(std::string::npos, e.err.find("\"zip\"")) << e.err;
        }
    }
    std::remove(path.c_str());

    // Cut inside the chunk record: the record claims more bytes than the file holds.
    path = writeTempFile(good.substr(0, good.size() - conn.size() - 5), ".bag");
    try { EventCapture cap(path); readAllEvents(cap); FAIL() << "truncated bag accepted"; }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find(path)) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("byte ")) << e.err;
    }
    std::remove(path.c_str());
}

// shared/data/README.md: 640x480; 343,474 events (125,183 ON / 218,291 OFF), 2.078 s.
TEST(Event_Capture_Real, rosbag1_evt3_event_packets)
{
    EventCapture cap(requireSharedData("format_samples/ecpy_test_events_1_ros1.bag"));
    EXPECT_EQ("ROSBAG1", cap.getBackendName());
    EXPECT_EQ(Size(640, 480), cap.getSensorSize());
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(343474u, ev.size());
    size_t on = 0;
    for (const Event& e : ev)
        on += e.p;
    EXPECT_EQ(125183u, on);
    EXPECT_NEAR(2.078e6, (double)(ev.back().t - ev.front().t), 1e3);
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS));
}

// event_camera_py's test of this bag (tests/test_1.py): the sum of every event's and trigger's time is
// 2885601049874 us, and 2078 triggers have edge value 0 (falling; its counter calls them rising and never
// checks the others). The evt3 triggers are a 1 kHz square wave on channel 6, starting with a rising edge.
TEST(Event_Capture_Real, rosbag1_evt3_triggers)
{
    for (const char* file : { "format_samples/ecpy_test_events_1_ros1.bag", "format_samples/ecpy_legacy_eventarray_ros1.bag" })
    {
        EventCapture cap(requireSharedData(file));
        cap.set(EVENT_CAP_PROP_WINDOW_US, 10000);
        const EventAndTriggerTally tally = tallyEventsAndTriggers(cap);
        EXPECT_EQ(2885601049874LL, tally.timeSum) << file;
        const std::map<std::pair<int, int>, int64> expected = { { { EVENT_TRIGGER_FALLING, 6 }, 2078 },
                                                                { { EVENT_TRIGGER_RISING, 6 }, 2079 } };
        EXPECT_EQ(expected, tally.triggers) << file;
        EXPECT_EQ(4157.0, cap.get(EVENT_CAP_PROP_TRIGGERS)) << file;
    }
}

// The data README: the same recording as ecpy_test_events_1_ros1.bag, recorded as event_array_msgs/EventArray,
// EventPacket's name before its 2023 rename: the same events, one for one.
TEST(Event_Capture_Real, rosbag1_legacy_event_array_name)
{
    EventCapture legacy(requireSharedData("format_samples/ecpy_legacy_eventarray_ros1.bag"));
    EventCapture renamed(requireSharedData("format_samples/ecpy_test_events_1_ros1.bag"));
    EXPECT_EQ("ROSBAG1", legacy.getBackendName());
    const std::vector<Event> ev = readAllEvents(legacy);
    EXPECT_EQ(343474u, ev.size());
    EXPECT_TRUE(ev == readAllEvents(renamed));
}

}} // namespace
