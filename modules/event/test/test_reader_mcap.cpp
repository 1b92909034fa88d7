// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include "opencv2/core/utils/filesystem.hpp"

#ifdef OPENCV_EVENT_HAVE_LZ4
#include <lz4frame.h>
#endif
#ifdef OPENCV_EVENT_HAVE_ZSTD
#include <zstd.h>
#endif

namespace opencv_test { namespace {

// An MCAP file as a ROS 2 recorder writes one (the layout in doc/reading_recordings.md's sources): records of
// {u8 opcode, u64 length, content}, little-endian.
struct McapFile
{
    std::string bytes = std::string("\x89MCAP0\r\n", 8);

    template<typename T> static std::string le(T v) { return std::string(reinterpret_cast<const char*>(&v), sizeof v); }
    static std::string str(const std::string& s) { return le<uint32_t>((uint32_t)s.size()) + s; }
    static std::string record(uint8_t opcode, const std::string& content)
    {
        return std::string(1, (char)opcode) + le<uint64_t>(content.size()) + content;
    }
    static std::string schema(uint16_t id, const std::string& type)
    {
        return record(0x03, le(id) + str(type) + str("ros2msg") + le<uint32_t>(0));
    }
    static std::string channel(uint16_t id, uint16_t schemaId, const std::string& topic)
    {
        return record(0x04, le(id) + le(schemaId) + str(topic) + str("cdr") + le<uint32_t>(0));
    }
    static std::string message(uint16_t channelId, uint32_t sequence, const std::string& data)
    {
        return record(0x05, le(channelId) + le(sequence) + le<uint64_t>(1000 + sequence) + le<uint64_t>(1000 + sequence) + data);
    }
    // A chunk of @p records, stored as @p compression gives them.
    static std::string chunk(const std::string& records, const std::string& compression)
    {
        std::string stored = records;
#ifdef OPENCV_EVENT_HAVE_LZ4
        if (compression == "lz4")
        {
            stored.resize(LZ4F_compressFrameBound(records.size(), nullptr));
            stored.resize(LZ4F_compressFrame(&stored[0], stored.size(), records.data(), records.size(), nullptr));
        }
#endif
#ifdef OPENCV_EVENT_HAVE_ZSTD
        if (compression == "zstd")
        {
            stored.resize(ZSTD_compressBound(records.size()));
            stored.resize(ZSTD_compress(&stored[0], stored.size(), records.data(), records.size(), 3));
        }
#endif
        return record(0x06, le<uint64_t>(1000) + le<uint64_t>(2000) + le<uint64_t>(records.size()) + le<uint32_t>(0) +
                                str(compression) + le<uint64_t>(stored.size()) + stored);
    }
    // The data end, a summary section holding @p summary (none when empty), the footer and the magic.
    void finish(const std::string& summary)
    {
        bytes += record(0x0F, le<uint32_t>(0));
        const uint64_t summaryStart = summary.empty() ? 0 : bytes.size();
        bytes += summary;
        bytes += record(0x02, le(summaryStart) + le<uint64_t>(0) + le<uint32_t>(0));
        bytes += std::string("\x89MCAP0\r\n", 8);
    }
};

uint16_t word(int code, int payload) { return (uint16_t)((code << 12) | payload); }

// libcaer_cmp words (event_camera_codecs' compact libcaer): time high 1 (4096 us) + low 10, column 7, row 5 ON;
// then a vector base at row 8 OFF and a vector with bits 0 and 2: rows 8 and 10.
const std::vector<uint16_t> kLeftWords = { word(0, 1), word(1, 10), word(2, 7), word(3, (1 << 11) | 5), word(4, 8),
                                           word(5, 0x5) };
// A second packet of the left camera (time base 5 ms later): the column carries over.
const std::vector<uint16_t> kLeftWords2 = { word(1, 3), word(3, 2) };
const std::vector<uint16_t> kRightWords = { word(1, 20), word(2, 339), word(3, (1 << 11) | 259) };

// The events those packets hold, as a stereo recording of two topics (time base 5 ms, then 10 ms).
const std::vector<Event> kExpected = { Event(5000 + 4106, 7, 5, POLARITY_ON, CAMERA_LEFT),
                                       Event(5000 + 4106, 7, 8, POLARITY_OFF, CAMERA_LEFT),
                                       Event(5000 + 4106, 7, 10, POLARITY_OFF, CAMERA_LEFT),
                                       Event(5000 + 20, 339, 259, POLARITY_ON, CAMERA_RIGHT),
                                       Event(10000 + 3, 7, 2, POLARITY_OFF, CAMERA_LEFT) };

// The schema, both channels and the three messages in the order the expected events have them.
std::string definitions()
{
    return McapFile::schema(1, "event_camera_msgs/msg/EventPacket") + McapFile::channel(3, 1, "/cam_left/events") +
           McapFile::channel(4, 1, "/cam_right/events");
}
std::string messages()
{
    return McapFile::message(3, 0, eventPacket(346, 260, "libcaer_cmp", 5000000, kLeftWords)) +
           McapFile::message(4, 1, eventPacket(346, 260, "libcaer_cmp", 5000000, kRightWords)) +
           McapFile::message(3, 2, eventPacket(346, 260, "libcaer_cmp", 10000000, kLeftWords2));
}

std::vector<Event> sortedByTime(std::vector<Event> ev)
{
    std::stable_sort(ev.begin(), ev.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
    return ev;
}

// The same messages unchunked, in one chunk (stored, LZ4, ZSTD), split over two chunks, with and without a
// summary section (or one that lacks the channels): the same events, as a stereo pair of the topics sorted by
// name.
TEST(Event_Capture_Mcap, every_storage_layout_gives_the_same_events)
{
    struct Layout { const char* name; std::string data; std::string summary; };
    std::vector<Layout> layouts = {
        { "unchunked", definitions() + messages(), "" },
        { "one chunk", McapFile::chunk(definitions() + messages(), ""), definitions() },
        { "one chunk, no summary", McapFile::chunk(definitions() + messages(), ""), "" },
        { "a summary without the channels", McapFile::chunk(definitions() + messages(), ""),
          McapFile::record(0x0B, std::string(46, '\0')) },
        { "two chunks", McapFile::chunk(definitions() + McapFile::message(3, 0, eventPacket(346, 260, "libcaer_cmp", 5000000, kLeftWords)), "") +
                        McapFile::chunk(McapFile::message(4, 1, eventPacket(346, 260, "libcaer_cmp", 5000000, kRightWords)) +
                                        McapFile::message(3, 2, eventPacket(346, 260, "libcaer_cmp", 10000000, kLeftWords2)), ""), "" },
    };
#ifdef OPENCV_EVENT_HAVE_LZ4
    layouts.push_back({ "LZ4 chunk", McapFile::chunk(definitions() + messages(), "lz4"), definitions() });
#endif
#ifdef OPENCV_EVENT_HAVE_ZSTD
    layouts.push_back({ "ZSTD chunk", McapFile::chunk(definitions() + messages(), "zstd"), "" });
#endif
    for (const Layout& layout : layouts)
    {
        McapFile f;
        f.bytes += McapFile::record(0x01, McapFile::str("ros2") + McapFile::str("opencv_event test"));
        f.bytes += layout.data;
        f.finish(layout.summary);
        const std::string path = writeTempFile(f.bytes, ".mcap");
        EXPECT_EQ("ROSBAG2", detectEventFileFormat(path)) << layout.name;
        EventCapture cap(path);
        EXPECT_EQ(Size(346, 260), cap.getSensorSize()) << layout.name;
        EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_STEREO)) << layout.name;
        EXPECT_EQ(sortedByTime(kExpected), readAllEvents(cap)) << layout.name;
        std::remove(path.c_str());
    }
}

// A ROS 2 bag folder: metadata.yaml lists the storage file, whatever its storage_identifier says.
TEST(Event_Capture_Mcap, a_bag_folder_whatever_its_storage_identifier)
{
    McapFile f;
    f.bytes += McapFile::record(0x01, McapFile::str("ros2") + McapFile::str(""));
    f.bytes += definitions() + messages();
    f.finish("");
    const std::string dir = cv::tempfile("_bag");
    ASSERT_TRUE(cv::utils::fs::createDirectory(dir));
    std::ofstream(dir + "/bag_0.mcap", std::ios::binary) << f.bytes;
    std::ofstream(dir + "/metadata.yaml") << "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: \"\"\n"
                                             "  relative_file_paths:\n    - bag_0.mcap\n";
    EventCapture cap(dir);
    EXPECT_EQ("ROSBAG2", cap.getBackendName());
    EXPECT_EQ(sortedByTime(kExpected), readAllEvents(cap));
    cv::utils::fs::remove_all(dir);
}

// Bad files name themselves and what is wrong; a file cut off inside a record gives the messages before it.
TEST(Event_Capture_Mcap, bad_files_are_refused_naming_the_file_and_the_problem)
{
    auto error = [](const std::string& bytes) -> std::string {
        const std::string path = writeTempFile(bytes, ".mcap");
        std::string what;
        try
        {
            EventCapture cap(path);
            readAllEvents(cap);
        }
        catch (const cv::Exception& e)
        {
            what = e.err;
            EXPECT_NE(std::string::npos, what.find(path)) << what;
        }
        std::remove(path.c_str());
        return what;
    };
    McapFile noEvents;
    noEvents.bytes += McapFile::schema(1, "sensor_msgs/msg/Image") + McapFile::channel(2, 1, "/image");
    noEvents.finish("");
    EXPECT_NE(std::string::npos, error(noEvents.bytes).find("no event_camera_msgs/msg/EventPacket")) << error(noEvents.bytes);

    McapFile unknown;
    unknown.bytes += McapFile::chunk(definitions() + messages(), "brotli");
    unknown.finish(definitions());
    EXPECT_NE(std::string::npos, error(unknown.bytes).find("\"brotli\""));

    McapFile whole;
    whole.bytes += definitions() + messages();
    whole.finish("");
    const std::string cut = whole.bytes.substr(0, whole.bytes.size() - 60);  // inside the last message
    const std::string path = writeTempFile(cut, ".mcap");
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
    ASSERT_TRUE(cap.open(path));
    std::vector<Event> all, packet;
    while (cap.read(packet))
        all.insert(all.end(), packet.begin(), packet.end());
    EXPECT_EQ(4u, all.size()) << "the events of the two whole messages";
    EXPECT_NE(std::string::npos, cap.getLastError().find("past the end of the file")) << cap.getLastError();
    std::remove(path.c_str());
}

// The data README: a ROS 2 bag in MCAP storage, 100 EventPacket messages (libcaer_cmp) on one topic,
// 571,266 events (211,043 ON / 360,223 OFF), DAVIS346.
TEST(Event_Capture_Real, rosbag2_mcap)
{
    const std::string dir = requireSharedData("format_samples/ecpy_test_events_2_mcap");
    for (const std::string& source : { dir, dir + "/test_events_2_0.mcap" })
    {
        EventCapture cap(source);
        EXPECT_EQ("ROSBAG2", cap.getBackendName()) << source;
        EXPECT_EQ(Size(346, 260), cap.getSensorSize()) << source;
        const std::vector<Event> ev = readAllEvents(cap);
        ASSERT_EQ(571266u, ev.size()) << source;
        size_t on = 0;
        for (const Event& e : ev)
            on += e.p;
        EXPECT_EQ(211043u, on) << source;
        EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS)) << source;
        EXPECT_NEAR(1.0e6, (double)(ev.back().t - ev.front().t), 0.01e6) << source;
    }
}

}} // namespace
