// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include <fstream>
#include <iterator>

namespace opencv_test { namespace {

template<typename T>
void put(std::vector<uchar>& b, size_t at, T v)
{
    std::memcpy(b.data() + at, &v, sizeof(T));
}

// A size-prefixed DV TriggerPacket {elements: [Trigger {timestamp: int64; type: int8}]} (file identifier TRIG):
// root table, vector of table offsets, one vtable the Trigger tables share, then the 16-byte tables.
std::vector<uchar> triggerPacket(const std::vector<std::pair<int64, int> >& triggers)
{
    const size_t n = triggers.size(), vtable = 28 + 4 * n;
    const size_t first = (vtable + 8 + 7) & ~(size_t)7;
    std::vector<uchar> b(4 + first + 16 * n, 0);
    put<uint32_t>(b, 0, (uint32_t)(b.size() - 4));
    std::vector<uchar> fb(first + 16 * n, 0);
    put<uint32_t>(fb, 0, 16);                       // root table at 16
    std::memcpy(fb.data() + 4, "TRIG", 4);
    put<uint16_t>(fb, 8, 6); put<uint16_t>(fb, 10, 8); put<uint16_t>(fb, 12, 4);  // root vtable
    put<int32_t>(fb, 16, 16 - 8);
    put<uint32_t>(fb, 20, 24 - 20);                 // the vector at 24
    put<uint32_t>(fb, 24, (uint32_t)n);
    put<uint16_t>(fb, vtable, 8); put<uint16_t>(fb, vtable + 2, 16);
    put<uint16_t>(fb, vtable + 4, 8); put<uint16_t>(fb, vtable + 6, 4);  // timestamp at +8, type at +4
    for (size_t i = 0; i < n; i++)
    {
        const size_t table = first + 16 * i, slot = 28 + 4 * i;
        put<uint32_t>(fb, slot, (uint32_t)(table - slot));
        put<int32_t>(fb, table, (int32_t)(table - vtable));
        fb[table + 4] = (uchar)triggers[i].second;
        put<int64>(fb, table + 8, triggers[i].first);
    }
    std::copy(fb.begin(), fb.end(), b.begin() + 4);
    return b;
}

TEST(Event_Capture_Aedat4, trigger_stream_types_become_trigger_events)
{
    // EventWriter's stereo layout with its second stream declared a trigger (TRIG) stream instead, then one
    // trigger packet of that stream: DV types 1..5 (signal rising, falling, pulse; generator rising, falling)
    // are triggers; 0 (timestamp reset) and 6..9 (APS frame and exposure markers) are not.
    const std::string path = cv::tempfile(".aedat4");
    {
        EventWriter writer;
        writer.set(EVENT_WRITER_PROP_STEREO, 1);
        writer.set(EVENT_WRITER_PROP_COMPRESSION, 0);
        ASSERT_TRUE(writer.open(path, Size(32, 24)));
        writer.write(std::vector<Event>({ Event(100, 1, 2, 1), Event(900, 3, 4, 0) }));
        writer.release();
    }
    std::ifstream in(path.c_str(), std::ios::binary);
    std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const size_t second = file.find(">EVTS<", file.find(">EVTS<") + 1);
    ASSERT_NE(std::string::npos, second);
    file.replace(second, 6, ">TRIG<");
    const std::vector<uchar> packet = triggerPacket({ { 150, 1 }, { 160, 0 }, { 200, 2 }, { 300, 3 }, { 350, 7 },
                                                      { 400, 4 }, { 500, 5 }, { 600, 9 } });
    const int32_t head[2] = { 1, (int32_t)packet.size() };
    file.append(reinterpret_cast<const char*>(head), sizeof(head));
    file.append(packet.begin(), packet.end());
    const std::string patched = writeTempFile(file, ".aedat4");
    EventCapture cap(patched);
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_STEREO));
    const std::vector<EventTrigger> expected = {
        EventTrigger(150, EVENT_TRIGGER_RISING), EventTrigger(200, EVENT_TRIGGER_FALLING),
        EventTrigger(300, EVENT_TRIGGER_PULSE), EventTrigger(400, EVENT_TRIGGER_GENERATOR_RISING),
        EventTrigger(500, EVENT_TRIGGER_GENERATOR_FALLING) };
    EXPECT_EQ(expected, readAllTriggers(cap));
    EXPECT_EQ(5.0, cap.get(EVENT_CAP_PROP_TRIGGERS));
    std::remove(path.c_str());
    std::remove(patched.c_str());
}

}} // namespace
