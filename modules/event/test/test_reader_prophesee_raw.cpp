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
