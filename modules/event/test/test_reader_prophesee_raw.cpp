// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

template<typename Word>
void appendWord(std::string& s, Word w)
{
    for (size_t i = 0; i < sizeof(Word); i++)
        s.push_back((char)((w >> (8 * i)) & 0xFF));
}

uint32_t evt2Cd(int p, int tLow, int x, int y)
{
    return ((uint32_t)p << 28) | ((uint32_t)tLow << 22) | ((uint32_t)x << 11) | (uint32_t)y;
}

TEST(Event_Capture_Raw, evt2_words_from_the_documented_layout)
{
    std::string f = "% date 2020-01-01\n% evt 2.0\n% geometry 640x480\n";
    appendWord<uint32_t>(f, evt2Cd(1, 3, 1, 1));                 // before any time base: skipped
    appendWord<uint32_t>(f, (0x8u << 28) | 1000u);               // TIME_HIGH: t = 1000 << 6
    appendWord<uint32_t>(f, evt2Cd(1, 5, 100, 200));
    appendWord<uint32_t>(f, evt2Cd(0, 63, 639, 479));
    appendWord<uint32_t>(f, (0xAu << 28) | (1u << 8) | 1u);      // external trigger: not a CD event
    appendWord<uint32_t>(f, (0x8u << 28) | 0x0FFFFFFFu);         // largest TIME_HIGH: 34-bit time
    appendWord<uint32_t>(f, evt2Cd(0, 2, 0, 0));
    const std::string path = writeTempFile(f, ".raw");
    EXPECT_EQ("PROPHESEE_RAW", detectEventFileFormat(path));
    EventCapture cap(path);
    EXPECT_EQ("PROPHESEE_EVT2", cap.getBackendName());
    EXPECT_EQ(Size(640, 480), cap.getSensorSize());
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(3u, ev.size());
    EXPECT_EQ(Event((1000 << 6) + 5, 100, 200, POLARITY_ON), ev[0]);
    EXPECT_EQ(Event((1000 << 6) + 63, 639, 479, POLARITY_OFF), ev[1]);
    EXPECT_EQ(Event(((int64)0x0FFFFFFF << 6) + 2, 0, 0, POLARITY_OFF), ev[2]);
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_SKIPPED));
    std::remove(path.c_str());
}

TEST(Event_Capture_Raw, evt2_and_evt3_external_triggers_on_the_event_clock)
{
    // EVT 2.0: type 0xA, bits 27..22 the time's low 6 bits, 12..8 the channel, bit 0 the edge (1 rising).
    std::string f2 = "% evt 2.0\n% geometry 640x480\n";
    appendWord<uint32_t>(f2, (0xAu << 28) | 1u);                          // before any time base: dropped
    appendWord<uint32_t>(f2, (0x8u << 28) | 1000u);
    appendWord<uint32_t>(f2, evt2Cd(1, 5, 100, 200));
    appendWord<uint32_t>(f2, (0xAu << 28) | (7u << 22) | (31u << 8) | 1u);  // rising, channel 31, t = 64007
    appendWord<uint32_t>(f2, (0xAu << 28) | (9u << 22) | (2u << 8));        // falling, channel 2, t = 64009
    // EVT 3.0: type 0xA, bits 11..8 the channel, bit 0 the edge, at the current TIME_HIGH / TIME_LOW.
    std::string f3 = "% format EVT3;height=720;width=1280\n% end\n";
    auto w = [&](int type, int payload) { appendWord<uint16_t>(f3, (uint16_t)((type << 12) | payload)); };
    w(0xA, 1);                         // before any TIME_HIGH: dropped
    w(0x8, 1); w(0x6, 10);             // t = 4106
    w(0x0, 5); w(0x2, 7);              // an event
    w(0xA, (15 << 8) | 1);             // rising, channel 15
    w(0x6, 20); w(0xA, 3 << 8);        // falling, channel 3, t = 4116
    const std::string path2 = writeTempFile(f2, ".raw"), path3 = writeTempFile(f3, ".raw");
    EventCapture cap2(path2), cap3(path3);
    const std::vector<EventTrigger> expected2 = { EventTrigger((1000 << 6) + 7, EVENT_TRIGGER_RISING, 31),
                                                  EventTrigger((1000 << 6) + 9, EVENT_TRIGGER_FALLING, 2) };
    const std::vector<EventTrigger> expected3 = { EventTrigger(4106, EVENT_TRIGGER_RISING, 15),
                                                  EventTrigger(4116, EVENT_TRIGGER_FALLING, 3) };
    EXPECT_EQ(expected2, readAllTriggers(cap2));
    EXPECT_EQ(expected3, readAllTriggers(cap3));
    EXPECT_EQ(2.0, cap2.get(EVENT_CAP_PROP_TRIGGERS));
    EXPECT_EQ(2.0, cap3.get(EVENT_CAP_PROP_TRIGGERS));
    std::remove(path2.c_str());
    std::remove(path3.c_str());
}

// An EVT 2.0 recording: events at @p eventTimes (x = their index) and rising triggers at @p triggerTimes on
// channel @p channel, in time order (times below 64 share the first TIME_HIGH).
std::string evt2Recording(const std::vector<int>& eventTimes, const std::vector<int>& triggerTimes, int channel)
{
    std::string f = "% evt 2.0\n% geometry 640x480\n";
    std::vector<std::pair<int, int> > items;  // (time, -1 trigger / event index)
    for (size_t i = 0; i < eventTimes.size(); i++)
        items.push_back(std::make_pair(eventTimes[i], (int)i));
    for (int t : triggerTimes)
        items.push_back(std::make_pair(t, -1));
    std::stable_sort(items.begin(), items.end(),
                     [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.first < b.first; });
    int high = -1;
    for (const auto& item : items)
    {
        if (item.first >> 6 != high)
        {
            high = item.first >> 6;
            appendWord<uint32_t>(f, (0x8u << 28) | (uint32_t)high);
        }
        const uint32_t low = (uint32_t)(item.first & 63);
        if (item.second < 0)
            appendWord<uint32_t>(f, (0xAu << 28) | (low << 22) | ((uint32_t)channel << 8) | 1u);
        else
            appendWord<uint32_t>(f, evt2Cd(1, (int)low, item.second, 0));
    }
    return f;
}

std::vector<int64> triggerTimesOf(const std::vector<EventTrigger>& triggers)
{
    std::vector<int64> t;
    for (const EventTrigger& x : triggers)
        t.push_back(x.t);
    return t;
}

TEST(Event_Capture_Triggers, each_packet_takes_the_triggers_of_its_time)
{
    // Events at 100..400 us; triggers before the first event, inside, on a window's end and after the last one.
    const std::string path = writeTempFile(evt2Recording({ 100, 150, 250, 400 }, { 20, 120, 200, 260, 900 }, 0), ".raw");
    EventCapture windows(path);
    windows.set(EVENT_CAP_PROP_WINDOW_US, 100);  // windows [100, 200), [200, 300), [300, 400), [400, 500)
    std::vector<Event> packet;
    std::vector<EventTrigger> triggers;
    const std::vector<std::vector<int64> > expected = { { 20, 120 }, { 200, 260 }, {}, { 900 } };
    for (const std::vector<int64>& times : expected)
    {
        ASSERT_TRUE(windows.read(packet));
        EXPECT_TRUE(windows.retrieveTriggers(triggers));
        EXPECT_EQ(times, triggerTimesOf(triggers));
    }
    EXPECT_FALSE(windows.read(packet));
    EXPECT_FALSE(windows.retrieveTriggers(triggers));
    EXPECT_TRUE(triggers.empty());
    EXPECT_EQ(5.0, windows.get(EVENT_CAP_PROP_TRIGGERS));

    // Batches of two events: up to the batch's last event, the last batch takes the rest.
    EventCapture batches(path);
    batches.set(EVENT_CAP_PROP_BATCH_EVENTS, 2);
    ASSERT_TRUE(batches.read(packet));
    batches.retrieveTriggers(triggers);
    EXPECT_EQ(std::vector<int64>({ 20, 120 }), triggerTimesOf(triggers));
    ASSERT_TRUE(batches.read(packet));
    batches.retrieveTriggers(triggers);
    EXPECT_EQ(std::vector<int64>({ 200, 260, 900 }), triggerTimesOf(triggers));

    // A seek skips the triggers before its target, with the events.
    EventCapture seeking(path);
    seeking.set(EVENT_CAP_PROP_WINDOW_US, 100);
    ASSERT_TRUE(seeking.set(EVENT_CAP_PROP_POS_US, 250));
    ASSERT_TRUE(seeking.read(packet));
    seeking.retrieveTriggers(triggers);
    EXPECT_EQ(std::vector<int64>({ 260 }), triggerTimesOf(triggers));
    std::remove(path.c_str());
}

TEST(Event_Capture_Triggers, a_stereo_pair_stamps_each_trigger_with_its_camera_and_the_right_offset)
{
    const std::string left = writeTempFile(evt2Recording({ 100, 300 }, { 150 }, 1), ".raw");
    const std::string right = writeTempFile(evt2Recording({ 100, 300 }, { 120, 250 }, 2), ".raw");
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US, 50);
    ASSERT_TRUE(cap.openStereo(left, right));
    const std::vector<EventTrigger> expected = { EventTrigger(150, EVENT_TRIGGER_RISING, 1, CAMERA_LEFT),
                                                 EventTrigger(170, EVENT_TRIGGER_RISING, 2, CAMERA_RIGHT),
                                                 EventTrigger(300, EVENT_TRIGGER_RISING, 2, CAMERA_RIGHT) };
    EXPECT_EQ(expected, readAllTriggers(cap, 1));
    std::remove(left.c_str());
    std::remove(right.c_str());
}

TEST(Event_Capture_Raw, evt3_vectors_time_rules_and_24bit_loop)
{
    std::string f = "% format EVT3;height=720;width=1280\n% end\n";
    auto w = [&](int type, int payload) { appendWord<uint16_t>(f, (uint16_t)((type << 12) | payload)); };
    w(0x2, 5);                       // ADDR_X before any TIME_HIGH: skipped
    w(0x8, 1);                       // TIME_HIGH 1 -> base 4096
    w(0x6, 10);                      // TIME_LOW 10
    w(0x0, 5);                       // ADDR_Y 5
    w(0x2, (1 << 11) | 7);           // ADDR_X 7, ON -> (4106, 7, 5, ON)
    w(0x3, 100);                     // VECT_BASE_X 100, OFF
    w(0x4, 0x005);                   // VECT_12: bits 0 and 2 -> x 100, 102; base -> 112
    w(0x5, 0x80);                    // VECT_8: bit 7 -> x 119
    w(0x6, 4);                       // TIME_LOW decreases: NOT a wrap -> t = 4100
    w(0x2, 8);
    w(0x8, 4095);                    // TIME_HIGH 4095 -> base 4095 << 12, low reset
    w(0x2, 9);                       // t = 4095 << 12
    w(0x8, 0);                       // TIME_HIGH back to 0: 24-bit loop -> 2^24
    w(0x6, 1);
    w(0x0, 719);
    w(0x2, 1279);                    // (2^24 + 1, 1279, 719, OFF)
    const std::string path = writeTempFile(f, ".raw");
    EventCapture cap(path);
    EXPECT_EQ("PROPHESEE_EVT3", cap.getBackendName());
    EXPECT_EQ(Size(1280, 720), cap.getSensorSize());
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(7u, ev.size());
    EXPECT_EQ(Event(4106, 7, 5, POLARITY_ON), ev[0]);
    EXPECT_EQ(Event(4106, 100, 5, POLARITY_OFF), ev[1]);
    EXPECT_EQ(Event(4106, 102, 5, POLARITY_OFF), ev[2]);
    EXPECT_EQ(Event(4106, 119, 5, POLARITY_OFF), ev[3]);
    // TIME_LOW 4 after 10 is a step back in time, not a wrap: the default policy clamps it and counts it.
    EXPECT_EQ(Event(4106, 8, 5, POLARITY_OFF), ev[4]);
    EXPECT_EQ(Event(4095 << 12, 9, 5, POLARITY_OFF), ev[5]);
    EXPECT_EQ(Event((1 << 24) + 1, 1279, 719, POLARITY_OFF), ev[6]);
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_SKIPPED));
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS));
    std::remove(path.c_str());
}

TEST(Event_Capture_Raw, unsupported_encoding_and_truncation_are_errors)
{
    const std::string evt21 = writeTempFile("% format EVT21;height=720;width=1280\n% end\n", ".raw");
    try { EventCapture cap(evt21); FAIL() << "EVT21 accepted"; }
    catch (const cv::Exception& e) { EXPECT_NE(std::string::npos, e.err.find("EVT21")) << e.err; }
    std::remove(evt21.c_str());

    std::string f = "% evt 2.0\n";
    appendWord<uint32_t>(f, (0x8u << 28) | 1u);
    f += "\x01\x02";  // half a word
    const std::string cut = writeTempFile(f, ".raw");
    try { EventCapture cap(cut); readAllEvents(cap); FAIL() << "truncated EVT2 accepted"; }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find(cut)) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("byte 14")) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("truncated")) << e.err;
    }
    std::remove(cut.c_str());
}

// shared/data/README.md: Gen3 640x480; 539,481 CD events, 50.0 ms; x 60..599, y 18..475.
TEST(Event_Capture_Real, evt2_sample_counts_and_ranges)
{
    EventCapture cap(requireSharedData("format_samples/evt2_sample.raw"));
    EXPECT_EQ("PROPHESEE_EVT2", cap.getBackendName());
    EXPECT_EQ(Size(640, 480), cap.getSensorSize());
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(539481u, ev.size());
    int minX = INT_MAX, maxX = 0, minY = INT_MAX, maxY = 0;
    for (const Event& e : ev)
    {
        minX = std::min(minX, (int)e.x); maxX = std::max(maxX, (int)e.x);
        minY = std::min(minY, (int)e.y); maxY = std::max(maxY, (int)e.y);
    }
    EXPECT_EQ(60, minX); EXPECT_EQ(599, maxX);
    EXPECT_EQ(18, minY); EXPECT_EQ(475, maxY);
    EXPECT_NEAR(50000, (double)(ev.back().t - ev.front().t), 500);
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE));
}

// The data README gives the sensor (Gen4.1 1280x720), 219,596 CD events and 8.8 ms. The largest x / y
// (1279 / 719: the events reach the sensor's last column and row) are a regression pin measured on this file
// with this reader, not a fact the README states.
TEST(Event_Capture_Real, evt3_sample_counts_and_ranges)
{
    EventCapture cap(requireSharedData("format_samples/evt3_sample.raw"));
    EXPECT_EQ("PROPHESEE_EVT3", cap.getBackendName());
    EXPECT_EQ(Size(1280, 720), cap.getSensorSize());
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(219596u, ev.size());
    int maxX = 0, maxY = 0;
    for (const Event& e : ev)
    {
        maxX = std::max(maxX, (int)e.x);
        maxY = std::max(maxY, (int)e.y);
    }
    EXPECT_EQ(1279, maxX);
    EXPECT_EQ(719, maxY);
    EXPECT_NEAR(8800, (double)(ev.back().t - ev.front().t), 150);
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE));
}

}} // namespace
