// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Fixtures follow doc/formats.md, "AEDAT 3.1" (little-endian packets).
void appendLE(std::string& s, uint32_t v, int bytes)
{
    for (int i = 0; i < bytes; i++)
        s.push_back((char)((v >> (8 * i)) & 0xFF));
}

void packetHeader(std::string& s, int type, int eventSize, int tsOffset, int overflow, int capacity)
{
    appendLE(s, (uint32_t)type, 2);
    appendLE(s, 1, 2);  // source id
    appendLE(s, (uint32_t)eventSize, 4);
    appendLE(s, (uint32_t)tsOffset, 4);
    appendLE(s, (uint32_t)overflow, 4);
    appendLE(s, (uint32_t)capacity, 4);
    appendLE(s, (uint32_t)capacity, 4);  // number
    appendLE(s, (uint32_t)capacity, 4);  // valid
}

void polarity(std::string& s, int x, int y, int on, bool valid, int32_t t)
{
    appendLE(s, ((uint32_t)x << 17) | ((uint32_t)y << 2) | ((uint32_t)on << 1) | (valid ? 1u : 0u), 4);
    appendLE(s, (uint32_t)t, 4);
}

const char* kHeader = "#!AER-DAT3.1\r\n#Format: RAW\r\n#Source 1: DAVIS346B\r\n#Start-Time: 2020-01-01 00:00:00 (TZ+0000)\r\n#!END-HEADER\r\n";

TEST(Event_Capture_Aedat3, polarity_packets_overflow_and_skipped_types)
{
    std::string f = kHeader;
    packetHeader(f, 1, 8, 4, 0, 3);
    polarity(f, 0, 0, 1, true, 100);
    polarity(f, 345, 259, 0, true, 200);
    polarity(f, 10, 10, 1, false, 250);          // invalidated by its producer
    packetHeader(f, 2, 16, 12, 0, 2);            // a frame packet: skipped by length
    f += std::string(32, '\x7f');
    packetHeader(f, 1, 8, 4, 1, 1);              // tsOverflow 1: + 2^31 us
    polarity(f, 7, 8, 1, true, 5);
    const std::string path = writeTempFile(f, ".aedat");
    EXPECT_EQ("AEDAT3", detectEventFileFormat(path));
    EventCapture cap(path);
    EXPECT_EQ("AEDAT3", cap.getBackendName());
    EXPECT_EQ(Size(346, 260), cap.getSensorSize());
    std::vector<Event> ev = readAllEvents(cap, 100);
    ASSERT_EQ(3u, ev.size());
    EXPECT_EQ(Event(100, 0, 0, POLARITY_ON), ev[0]);
    EXPECT_EQ(Event(200, 345, 259, POLARITY_OFF), ev[1]);
    EXPECT_EQ(Event((1LL << 31) + 5, 7, 8, POLARITY_ON), ev[2]);
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_SKIPPED));
    std::remove(path.c_str());
}

void special(std::string& s, int type, bool valid, int32_t t)
{
    appendLE(s, ((uint32_t)type << 1) | (valid ? 1u : 0u), 4);
    appendLE(s, (uint32_t)t, 4);
}

TEST(Event_Capture_Aedat3, special_events_of_the_external_inputs_are_triggers)
{
    // libcaer's special event types: 2 / 3 / 4 rising / falling / pulse on input 0, 6..8 on input 1, 9..11 on
    // input 2, 12 / 13 the generator's rising / falling edge; 0 / 1 (time wrap / reset), 5 (row only) and
    // 14..17 (APS markers) are not triggers, nor is an invalidated event.
    std::string f = kHeader;
    packetHeader(f, 1, 8, 4, 0, 1);
    polarity(f, 1, 2, 1, true, 50);
    packetHeader(f, 0, 8, 4, 1, 11);              // tsOverflow 1: + 2^31 us
    special(f, 1, true, 10);
    special(f, 3, true, 100);
    special(f, 2, true, 110);
    special(f, 4, false, 120);
    special(f, 8, true, 130);
    special(f, 9, true, 140);
    special(f, 13, true, 150);
    special(f, 5, true, 160);
    special(f, 14, true, 170);
    special(f, 12, true, 180);
    special(f, 7, true, 190);
    const std::string path = writeTempFile(f, ".aedat");
    EventCapture cap(path);
    const int64 o = 1LL << 31;
    const std::vector<EventTrigger> expected = {
        EventTrigger(o + 100, EVENT_TRIGGER_FALLING), EventTrigger(o + 110, EVENT_TRIGGER_RISING),
        EventTrigger(o + 130, EVENT_TRIGGER_PULSE, 1), EventTrigger(o + 140, EVENT_TRIGGER_RISING, 2),
        EventTrigger(o + 150, EVENT_TRIGGER_GENERATOR_FALLING), EventTrigger(o + 180, EVENT_TRIGGER_GENERATOR_RISING),
        EventTrigger(o + 190, EVENT_TRIGGER_FALLING, 1) };
    EXPECT_EQ(expected, readAllTriggers(cap));
    std::remove(path.c_str());
}

TEST(Event_Capture_Aedat3, absurd_and_truncated_packets_are_errors)
{
    // A packet that claims 2^31 - 1 events must be refused without allocating them.
    std::string f = kHeader;
    const size_t at = f.size();
    packetHeader(f, 1, 8, 4, 0, 0x7FFFFFFF);
    polarity(f, 1, 1, 1, true, 1);
    std::string path = writeTempFile(f, ".aedat");
    {
        EventCapture cap(path);
        std::vector<Event> ev;
        try { cap.read(ev); FAIL() << "absurd packet accepted"; }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(std::string::npos, e.err.find(path)) << e.err;
            EXPECT_NE(std::string::npos, e.err.find("byte " + std::to_string(at))) << e.err;
            EXPECT_NE(std::string::npos, e.err.find("only")) << e.err;
        }
    }
    std::remove(path.c_str());

    std::string g = kHeader;
    packetHeader(g, 1, 8, 4, 0, 1);
    polarity(g, 1, 1, 1, true, 1);
    g += "\x01\x00\x01";  // 3 bytes of a next packet header
    path = writeTempFile(g, ".aedat");
    EventCapture cap(path);
    std::vector<Event> ev;
    try
    {
        while (cap.read(ev)) {}
        FAIL() << "truncated header accepted";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find("truncated")) << e.err;
    }
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_EVENTS_DELIVERED));  // the event before the damage got through
    std::remove(path.c_str());

    const std::string noEnd = writeTempFile("#!AER-DAT3.1\r\n#Format: RAW\r\n", ".aedat");
    EXPECT_THROW(EventCapture c(noEnd), cv::Exception);
    std::remove(noEnd.c_str());
}

}} // namespace
