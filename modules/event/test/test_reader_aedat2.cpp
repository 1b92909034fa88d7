// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Fixtures follow doc/formats.md, "AEDAT 1.0 / 2.0" (big-endian records, jAER bottom-left mirrored addresses).
void appendBE(std::string& s, uint32_t v, int bytes)
{
    for (int i = bytes - 1; i >= 0; i--)
        s.push_back((char)((v >> (8 * i)) & 0xFF));
}

uint32_t davisAddress(int rawX, int rawY, int on)
{
    return ((uint32_t)rawY << 22) | ((uint32_t)rawX << 12) | ((uint32_t)on << 11);
}

TEST(Event_Capture_Aedat2, davis240_records_flip_to_top_left_and_skip_non_dvs_but_external_events_are_triggers)
{
    std::string f = "#!AER-DAT2.0\r\n# This is a raw AE data file\r\n# AEChip: eu.seebetter.ini.chips.davis.DAVIS240C\r\n";
    appendBE(f, davisAddress(0, 0, 1), 4);  appendBE(f, 1000, 4);        // bottom-left raw -> (239, 179)
    appendBE(f, davisAddress(239, 179, 0), 4); appendBE(f, 1010, 4);    // -> (0, 0), OFF
    appendBE(f, 0x80000000u | davisAddress(5, 5, 0), 4); appendBE(f, 1020, 4);  // APS sample: not an event
    appendBE(f, davisAddress(3, 4, 1) | 0x400u, 4); appendBE(f, 1030, 4);       // external event: a trigger
    appendBE(f, davisAddress(9, 10, 1), 4); appendBE(f, 0xFFFFFFF0u, 4);
    appendBE(f, davisAddress(9, 11, 0), 4); appendBE(f, 0x10u, 4);      // 32-bit wrap
    appendBE(f, davisAddress(300, 0, 0), 4); appendBE(f, 0x20u, 4);     // raw x beyond 240: outside
    const std::string path = writeTempFile(f, ".aedat");
    EXPECT_EQ("AEDAT2", detectEventFileFormat(path));
    EventCapture cap(path);
    EXPECT_EQ("AEDAT2", cap.getBackendName());
    EXPECT_EQ(Size(240, 180), cap.getSensorSize());
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(4u, ev.size());
    EXPECT_EQ(Event(1000, 239, 179, POLARITY_ON), ev[0]);
    EXPECT_EQ(Event(1010, 0, 0, POLARITY_OFF), ev[1]);
    EXPECT_EQ(Event(0xFFFFFFF0LL, 230, 169, POLARITY_ON), ev[2]);
    EXPECT_EQ(Event((1LL << 32) + 0x10, 230, 168, POLARITY_OFF), ev[3]);
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE));
    EventCapture again(path);
    const std::vector<EventTrigger> expected = { EventTrigger(1030, EVENT_TRIGGER_PULSE) };  // no edge recorded
    EXPECT_EQ(expected, readAllTriggers(again));
    std::remove(path.c_str());
}

TEST(Event_Capture_Aedat2, dvs128_polarity_bit_zero_is_on_and_version_1_records)
{
    // AEDAT 2.0, DVS128 addresses: bit 0 = 0 means ON (jAER and libcaer).
    std::string f = "#!AER-DAT2.0\n# AEChip: ch.unizh.ini.jaer.chip.retina.DVS128\n";
    appendBE(f, (10u << 8) | (20u << 1) | 0u, 4); appendBE(f, 50, 4);   // raw (20, 10) ON -> (107, 117)
    appendBE(f, (0u << 8) | (127u << 1) | 1u, 4); appendBE(f, 60, 4);   // raw (127, 0) OFF -> (0, 127)
    appendBE(f, 0x8000u, 4); appendBE(f, 70, 4);                        // sync event: a trigger
    std::string path = writeTempFile(f, ".aedat");
    EventCapture cap(path);
    std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(2u, ev.size());
    EXPECT_EQ(Event(50, 107, 117, POLARITY_ON), ev[0]);
    EXPECT_EQ(Event(60, 0, 127, POLARITY_OFF), ev[1]);
    EventCapture again(path);
    const std::vector<EventTrigger> expected = { EventTrigger(70, EVENT_TRIGGER_PULSE) };
    EXPECT_EQ(expected, readAllTriggers(again));
    std::remove(path.c_str());

    // AEDAT 1.0: no version line, 6-byte records {int16 address, int32 t}.
    std::string v1 = "# AEChip: ch.unizh.ini.jaer.chip.retina.DVS128\r\n";
    appendBE(v1, (1u << 8) | (2u << 1) | 1u, 2); appendBE(v1, 123, 4);
    path = writeTempFile(v1, ".dat");
    EXPECT_EQ("AEDAT2", detectEventFileFormat(path));
    EventCapture cap1(path);
    ev = readAllEvents(cap1);
    ASSERT_EQ(1u, ev.size());
    EXPECT_EQ(Event(123, 125, 126, POLARITY_OFF), ev[0]);
    std::remove(path.c_str());
}

TEST(Event_Capture_Aedat2, without_a_chip_line_the_named_sensor_chooses_the_layout)
{
    // jAER's MATLAB export (saveaerdat.m) writes no "# AEChip:" line.
    std::string f = "#!AER-DAT2.0\n# This is a raw AE data file created by saveaerdat.m\n";
    appendBE(f, (10u << 8) | (20u << 1) | 0u, 4); appendBE(f, 50, 4);  // as a DVS128: raw (20, 10) ON -> (107, 117)
    const std::string path = writeTempFile(f, ".aedat");
    {
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
        EXPECT_FALSE(cap.open(path));
        EXPECT_NE(std::string::npos, cap.getLastError().find("give the sensor (--sensor=DVS128")) << cap.getLastError();
    }
    for (int width : { 128, 240 })
    {
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, width);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, width == 128 ? 128 : 180);
        ASSERT_TRUE(cap.open(path));
        // As a DAVIS240 address the same word is raw x = (word >> 12) & 0x3FF = 0, y = 0, bit 11 set: ON at
        // the bottom-left, (239, 179) in top-left coordinates.
        const Event expected = width == 128 ? Event(50, 107, 117, POLARITY_ON) : Event(50, 239, 179, POLARITY_ON);
        EXPECT_EQ(std::vector<Event>{ expected }, readAllEvents(cap)) << width;
    }
    {
        EventCapture odd;
        odd.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
        odd.set(EVENT_CAP_PROP_SENSOR_WIDTH, 100);
        odd.set(EVENT_CAP_PROP_SENSOR_HEIGHT, 100);
        EXPECT_FALSE(odd.open(path));
        EXPECT_NE(std::string::npos, odd.getLastError().find("a 100 x 100 sensor is none of")) << odd.getLastError();
    }
    std::remove(path.c_str());
}

TEST(Event_Capture_Aedat2, an_unknown_chip_is_refused_and_a_cut_off_file_delivers_its_whole_records_first)
{
    std::string f = "#!AER-DAT2.0\n# AEChip: some.unknown.Chip\n";
    appendBE(f, 0, 4); appendBE(f, 0, 4);
    std::string path = writeTempFile(f, ".aedat");
    try { EventCapture cap(path); FAIL() << "unknown chip accepted"; }
    catch (const cv::Exception& e) { EXPECT_NE(std::string::npos, e.err.find("some.unknown.Chip")) << e.err; }
    std::remove(path.c_str());

    std::string g = "#!AER-DAT2.0\n# AEChip: eu.seebetter.ini.chips.davis.Davis346red\n";
    const size_t header = g.size();
    appendBE(g, davisAddress(1, 1, 1), 4); appendBE(g, 5, 4);
    g += std::string("\x00\x01\x02", 3);
    path = writeTempFile(g, ".aedat");
    EventCapture cap(path);
    std::vector<Event> delivered;
    try
    {
        readAllEventsInto(cap, delivered);
        FAIL() << "truncated file read as whole";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find(path)) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("byte " + std::to_string(header + 8))) << e.err;
    }
    EXPECT_EQ(1u, delivered.size());  // the record before the cut
    std::remove(path.c_str());
}

}} // namespace
