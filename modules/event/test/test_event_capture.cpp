// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include <iomanip>
#include <sstream>

namespace opencv_test { namespace {

// Asserts that a cv::Exception is raised whose message contains every fragment.
template<typename F>
void expectErrorMentioning(F f, const std::vector<std::string>& fragments)
{
    try
    {
        f();
        ADD_FAILURE() << "no exception";
    }
    catch (const cv::Exception& e)
    {
        for (const std::string& frag : fragments)
            EXPECT_NE(std::string::npos, e.err.find(frag)) << "'" << frag << "' not in: " << e.err;
    }
}

TEST(Event_Capture_Text, rpg_seconds_with_comments_in_time_windows)
{
    const std::string path = writeTempFile(
        "# RPG-style events.txt\n"
        "0.000100000 10 20 1\n"
        "0.000250000 11 20 0\n"
        "\n"
        "0.012000000 12 21 1\r\n"   // CRLF line, second window
        "0.035500000 13 22 0\n",    // fourth window (the third is empty)
        ".txt");
    EventCapture cap(path);
    ASSERT_TRUE(cap.isOpened());
    EXPECT_EQ("TEXT", cap.getBackendName());
    EXPECT_EQ(100.0, cap.get(EVENT_CAP_PROP_FIRST_TIMESTAMP_US));
    cap.set(EVENT_CAP_PROP_WINDOW_US, 10000);

    std::vector<Event> w;
    ASSERT_TRUE(cap.read(w));  // [100, 10100)
    ASSERT_EQ(2u, w.size());
    EXPECT_EQ(Event(100, 10, 20, POLARITY_ON), w[0]);
    EXPECT_EQ(Event(250, 11, 20, POLARITY_OFF), w[1]);
    ASSERT_TRUE(cap.read(w));  // [10100, 20100)
    ASSERT_EQ(1u, w.size());
    EXPECT_EQ(12000, w[0].t);
    ASSERT_TRUE(cap.read(w));  // [20100, 30100): no events, still a window
    EXPECT_TRUE(w.empty());
    EXPECT_EQ(30100.0, cap.get(EVENT_CAP_PROP_POS_US));
    ASSERT_TRUE(cap.read(w));
    ASSERT_EQ(1u, w.size());
    EXPECT_EQ(Event(35500, 13, 22, POLARITY_OFF), w[0]);
    EXPECT_FALSE(cap.read(w));
    EXPECT_TRUE(w.empty());
    EXPECT_EQ(4.0, cap.get(EVENT_CAP_PROP_EVENTS_DELIVERED));
    std::remove(path.c_str());
}

TEST(Event_Capture_Text, seconds_convert_to_microseconds_exactly)
{
    // Decimal seconds are converted digit by digit (no binary floating-point rounding); exponents work too.
    const std::string path = writeTempFile("0.123456789 1 1 1\n2.5e-1 3 1 1\n1.0000005 2 1 0\n86400.000001 4 1 0\n", ".txt");
    EventCapture cap(path);
    const std::vector<Event> ev = readAllEvents(cap);
    ASSERT_EQ(4u, ev.size());
    EXPECT_EQ(123457, ev[0].t);       // 123456.789 us rounds up
    EXPECT_EQ(250000, ev[1].t);
    EXPECT_EQ(1000001, ev[2].t);      // 1000000.5 us: half away from zero
    EXPECT_EQ(86400000001LL, ev[3].t);
    std::remove(path.c_str());
}

// The reader parses digits eight at a time from its buffer; every length of integer and of fraction, lines
// that cross the 1 MiB buffer refills, separators of every kind and a last line without a newline must
// give the numbers a byte-wise reading gives (computed here from the integers that were printed).
TEST(Event_Capture_Text, numbers_of_every_length_parse_exactly)
{
    RNG rng(77);
    std::ostringstream text;
    std::vector<Event> expected;
    int64 t = 0;
    const char* separators[] = { " ", "\t", ",", " , ", ";" };
    for (int i = 0; i < 120000; i++)
    {
        // Timestamps with 1 to 17 digits (a jump to the next length now and then), coordinates 1 to 5 digits.
        const int digits = 1 + (i / 7000) % 17;
        int64 low = 1;
        for (int k = 1; k < digits; k++)
            low *= 10;
        t = std::max(t + rng.uniform(0, 3), digits == 1 ? 0 : low);
        const int x = rng.uniform(0, 32767), y = rng.uniform(0, 32767), p = rng.uniform(0, 2);
        const char* sep = separators[rng.uniform(0, 5)];
        text << t << sep << x << sep << y << sep << p << (i + 1 < 120000 ? "\n" : "");  // the last without newline
        expected.push_back(Event(t, x, y, p));
    }
    const std::string path = writeTempFile("32767 32767\n" + text.str(), ".txt");
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_TEXT_TIME_UNIT, EVENT_TIME_UNIT_MICROSECONDS);
    ASSERT_TRUE(cap.open(path));
    const std::vector<Event> ev = readAllEvents(cap, 4099);
    ASSERT_EQ(expected.size(), ev.size());
    for (size_t i = 0; i < ev.size(); i++)
        ASSERT_EQ(expected[i], ev[i]) << "line " << i + 2;
    std::remove(path.c_str());

    // Seconds with 1 to 12 fraction digits: microseconds by exact decimal rounding, half away from zero.
    std::ostringstream secs;
    std::vector<int64> micros;
    for (int i = 0; i < 20000; i++)
    {
        const int fd = 1 + i % 12;
        const int64 whole = 1000 + i;
        int64 frac = 0, scale = 1;
        for (int k = 0; k < fd; k++)
        {
            frac = frac * 10 + rng.uniform(0, 10);
            scale *= 10;
        }
        secs << whole << "." << std::setw(fd) << std::setfill('0') << frac << " 1 1 1\n";
        // whole s + frac / scale s in us: frac * 10^6 / scale, rounded half up (all positive).
        micros.push_back(whole * 1000000 + (int64)((frac * 1000000 * 2 + scale) / (2 * scale)));
    }
    const std::string spath = writeTempFile(secs.str(), ".txt");
    EventCapture scap(spath);
    const std::vector<Event> sev = readAllEvents(scap);
    ASSERT_EQ(micros.size(), sev.size());
    for (size_t i = 0; i < sev.size(); i++)
        ASSERT_EQ(micros[i], sev[i].t) << "line " << i + 1;
    std::remove(spath.c_str());
}

TEST(Event_Capture_Text, plain_integer_lines_and_signed_lines_read_alike)
{
    // Lines of plain unsigned integers take the reader's integer path; a sign anywhere sends a line through the
    // general parser. Mixed at random in one stereo, one-based file, both must give the events written.
    RNG rng(78);
    std::ostringstream text;
    std::vector<Event> expected;
    int64 t = 5;
    for (int i = 0; i < 20000; i++)
    {
        t += rng.uniform(1, 1000);  // strictly increasing: the stereo merge puts the left one first on a tie
        const int x = rng.uniform(0, 346), y = rng.uniform(0, 260), p = rng.uniform(0, 2), c = rng.uniform(0, 2);
        const int retina = c == CAMERA_LEFT ? 1 : 0;  // TUM: retina 1 is the left camera
        if (rng.uniform(0, 2))
            text << t << ' ' << x + 1 << ' ' << y + 1 << ' ' << p << ' ' << retina << '\n';
        else
            text << '+' << t << ' ' << '+' << x + 1 << ' ' << y + 1 << ' ' << (p ? "+1" : "-1") << ' ' << retina << '\n';
        expected.push_back(Event(t, x, y, p, c));
    }
    const std::string path = writeTempFile(text.str(), ".dat");
    EventCapture cap;
    std::vector<int> params = { EVENT_CAP_PROP_TEXT_ONE_BASED, 1, EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, 1,
                                EVENT_CAP_PROP_SENSOR_WIDTH, 346, EVENT_CAP_PROP_SENSOR_HEIGHT, 260 };
    ASSERT_TRUE(cap.open(path, EVENT_CAP_TEXT, params));
    const std::vector<Event> ev = readAllEvents(cap, 777);
    ASSERT_EQ(expected.size(), ev.size());
    for (size_t i = 0; i < ev.size(); i++)
        ASSERT_EQ(expected[i], ev[i]) << "line " << i + 1;
    std::remove(path.c_str());
}

TEST(Event_Capture_Text, stereo_camera_column_one_based_and_batches)
{
    // TUM layout: t_us x y p retina, retina 1 = left; 1-based coordinates as an option.
    const std::string path = writeTempFile("1000 1 1 1 1\n1005 128 128 0 0\n1010 5 7 -1 1\n", ".dat");
    EventCapture cap;
    std::vector<int> params = { EVENT_CAP_PROP_TEXT_ONE_BASED, 1, EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, 1,
                                EVENT_CAP_PROP_SENSOR_WIDTH, 128, EVENT_CAP_PROP_SENSOR_HEIGHT, 128,
                                EVENT_CAP_PROP_BATCH_EVENTS, 2 };
    ASSERT_TRUE(cap.open(path, EVENT_CAP_TEXT, params));
    EXPECT_EQ(Size(128, 128), cap.getSensorSize());
    std::vector<Event> b;
    ASSERT_TRUE(cap.read(b));
    ASSERT_EQ(2u, b.size());
    EXPECT_EQ(Event(1000, 0, 0, POLARITY_ON, CAMERA_LEFT), b[0]);
    EXPECT_EQ(Event(1005, 127, 127, POLARITY_OFF, CAMERA_RIGHT), b[1]);
    ASSERT_TRUE(cap.read(b));
    ASSERT_EQ(1u, b.size());
    EXPECT_EQ(Event(1010, 4, 6, POLARITY_OFF, CAMERA_LEFT), b[0]);
    EXPECT_FALSE(cap.read(b));
    std::remove(path.c_str());
}

TEST(Event_Capture_Text, size_header_line_and_out_of_sensor_events_are_counted)
{
    const std::string path = writeTempFile("4 3\n0.1 0 0 1\n0.2 4 0 1\n0.3 3 2 0\n0.4 1 3 1\n", ".txt");
    EventCapture cap(path);
    EXPECT_EQ(Size(4, 3), cap.getSensorSize());
    std::vector<Event> all = readAllEvents(cap);
    ASSERT_EQ(2u, all.size());
    EXPECT_EQ(Event(100000, 0, 0, POLARITY_ON), all[0]);
    EXPECT_EQ(Event(300000, 3, 2, POLARITY_OFF), all[1]);
    EXPECT_EQ(2.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE));
    std::remove(path.c_str());
}

TEST(Event_Capture_Text, time_order_policies)
{
    const std::string path = writeTempFile("100 0 0 1\n300 1 0 1\n200 2 0 1\n400 3 0 1\n", ".txt");
    const int policies[] = { EVENT_TIME_ORDER_KEEP, EVENT_TIME_ORDER_CLAMP, EVENT_TIME_ORDER_DROP };
    const int64 expectedT[3][4] = { { 100, 300, 200, 400 }, { 100, 300, 300, 400 }, { 100, 300, 400, -1 } };
    for (int k = 0; k < 3; k++)
    {
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_TIME_ORDER_POLICY, policies[k]);
        cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 100);
        ASSERT_TRUE(cap.open(path));
        std::vector<Event> all = readAllEvents(cap);
        ASSERT_EQ(k == 2 ? 3u : 4u, all.size()) << "policy " << policies[k];
        for (size_t i = 0; i < all.size(); i++)
            EXPECT_EQ(expectedT[k][i], all[i].t) << "policy " << policies[k] << " event " << i;
        EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS));
    }
    EventCapture strict;
    strict.set(EVENT_CAP_PROP_TIME_ORDER_POLICY, EVENT_TIME_ORDER_ERROR);
    ASSERT_TRUE(strict.open(path));
    expectErrorMentioning([&]() { readAllEvents(strict); }, { path, "back in time" });
    std::remove(path.c_str());
}

TEST(Event_Capture_Text, malformed_line_names_file_offset_and_line)
{
    const std::string path = writeTempFile("0.1 1 2 1\n0.2 1 x 0\n", ".txt");
    EventCapture cap(path);
    std::vector<Event> b;
    expectErrorMentioning([&]() { readAllEvents(cap); }, { path, "byte 10", "line 2", "not a number" });

    EventCapture quiet;
    quiet.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
    ASSERT_TRUE(quiet.open(path));
    ASSERT_TRUE(quiet.read(b));  // the line before the bad one is delivered first
    EXPECT_EQ(std::vector<Event>{ Event(100000, 1, 2, 1) }, b);
    EXPECT_FALSE(quiet.read(b));
    EXPECT_NE(std::string::npos, quiet.getLastError().find("line 2"));
    std::remove(path.c_str());
}

TEST(Event_Capture, missing_directory_empty_and_unknown_inputs)
{
    const std::string missing = cv::tempfile(".txt");
    expectErrorMentioning([&]() { EventCapture cap(missing); }, { missing, "cannot open" });

    const std::string dir = cv::tempfile("_dir");
    ASSERT_EQ(0, mkdir(dir.c_str(), 0700));
    expectErrorMentioning([&]() { EventCapture cap(dir); }, { dir, "directory" });
    rmdir(dir.c_str());

    const std::string empty = writeTempFile("", ".txt");
    expectErrorMentioning([&]() { EventCapture cap(empty); }, { empty, "empty" });
    std::remove(empty.c_str());

    const std::string binary = writeTempFile(std::string("\x01\x02\x03\x00\xff garbage", 12), ".bin");
    expectErrorMentioning([&]() { EventCapture cap(binary); }, { binary, "unknown event file format" });
    EventCapture quiet;
    quiet.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
    EXPECT_FALSE(quiet.open(binary));
    EXPECT_FALSE(quiet.isOpened());
    EXPECT_NE(std::string::npos, quiet.getLastError().find(binary));
    std::remove(binary.c_str());
}

TEST(Event_Capture_Text, stereo_file_grouped_by_camera_is_merged_in_time)
{
    // Right camera first, then left: each camera ordered, the file as a whole not.
    const std::string path = writeTempFile("10 1 0 1 1\n30 2 0 1 1\n50 3 0 1 1\n"
                                           "20 4 0 1 0\n30 5 0 1 0\n60 6 0 1 0\n", ".txt");
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 4);
    cap.set(EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US, 1);
    ASSERT_TRUE(cap.open(path));
    std::vector<Event> all = readAllEvents(cap);
    ASSERT_EQ(6u, all.size());
    const int x[] = { 1, 4, 5, 2, 3, 6 };           // right times shifted by +1: 11, 31, 51
    const int64 t[] = { 11, 20, 30, 31, 51, 60 };
    const int cam[] = { 1, 0, 0, 1, 1, 0 };
    for (int i = 0; i < 6; i++)
    {
        EXPECT_EQ(x[i], all[i].x) << i;
        EXPECT_EQ(t[i], all[i].t) << i;
        EXPECT_EQ(cam[i], all[i].camera) << i;
    }
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS));
    std::remove(path.c_str());
}

TEST(Event_Capture_Text, progress_of_a_one_file_stereo_recording_follows_delivery)
{
    // One file read by two readers, one camera each: each reads a chunk far ahead (the other camera's lines
    // skipped over), so the read position says nothing about what was delivered. Every line has the same
    // length, so the share of the file delivered is the share of its events, whether the cameras alternate or
    // come one after the other. Each camera has more events than a reader's chunk (16384).
    const int n = 80000;
    for (bool grouped : { false, true })
    {
        SCOPED_TRACE(grouped ? "cameras one after the other" : "cameras alternating");
        std::ostringstream text;
        for (int i = 0; i < n; i++)
        {
            const int camera = grouped ? (i < n / 2 ? 1 : 0) : i % 2;
            const int k = grouped ? i % (n / 2) : i / 2;
            text << cv::format("%07d %03d %03d 1 %d\n", 1000 + 10 * k, k % 128, (k / 128) % 128, camera);
        }
        const std::string path = writeTempFile(text.str(), ".txt");
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 2000);
        ASSERT_TRUE(cap.open(path));
        EXPECT_NEAR(0.0, cap.get(EVENT_CAP_PROP_PROGRESS), 0.01);
        std::vector<Event> packet;
        size_t delivered = 0;
        while (cap.read(packet))
        {
            delivered += packet.size();
            ASSERT_NEAR((double)delivered / n, cap.get(EVENT_CAP_PROP_PROGRESS), 0.01) << delivered << " delivered";
        }
        EXPECT_EQ((size_t)n, delivered);
        EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_PROGRESS));
        std::remove(path.c_str());
    }
}

TEST(Event_Capture_Text, two_files_open_as_a_stereo_pair)
{
    const std::string l = writeTempFile("100 1 1 1\n300 2 2 0\n", ".txt");
    const std::string r = writeTempFile("200 3 3 1\n300 4 4 1\n", ".txt");
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 10);
    ASSERT_TRUE(cap.openStereo(l, r));
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_STEREO));
    std::vector<Event> all = readAllEvents(cap);
    ASSERT_EQ(4u, all.size());
    EXPECT_EQ(Event(100, 1, 1, 1, CAMERA_LEFT), all[0]);
    EXPECT_EQ(Event(200, 3, 3, 1, CAMERA_RIGHT), all[1]);
    EXPECT_EQ(Event(300, 2, 2, 0, CAMERA_LEFT), all[2]);  // left first on equal timestamps
    EXPECT_EQ(Event(300, 4, 4, 1, CAMERA_RIGHT), all[3]);
    std::remove(l.c_str());
    std::remove(r.c_str());
}

TEST(Event_Capture_Text, two_files_of_different_sensor_sizes_are_refused_naming_both)
{
    const std::string l = writeTempFile("8 6\n100 1 1 1\n", ".txt");
    const std::string r = writeTempFile("10 6\n200 3 3 1\n", ".txt");
    EventCapture cap;
    expectErrorMentioning([&]() { cap.openStereo(l, r); }, { l, r, "8 x 6", "10 x 6" });
    EXPECT_FALSE(cap.isOpened());
    std::remove(l.c_str());
    std::remove(r.c_str());
}

TEST(Event_Capture_Text, seek_by_time_forward_and_backward)
{
    std::string content;
    for (int k = 0; k < 100; k++)
        content += std::to_string(k * 1000) + " " + std::to_string(k % 50) + " 1 1\n";  // one event per ms
    const std::string path = writeTempFile(content, ".txt");
    EventCapture cap(path);
    cap.set(EVENT_CAP_PROP_WINDOW_US, 10000);
    std::vector<Event> w;
    ASSERT_TRUE(cap.read(w));
    ASSERT_EQ(10u, w.size());
    ASSERT_TRUE(cap.set(EVENT_CAP_PROP_POS_US, 55000));   // forward
    ASSERT_TRUE(cap.read(w));
    ASSERT_EQ(10u, w.size());
    EXPECT_EQ(55000, w.front().t);
    EXPECT_EQ(64000, w.back().t);
    ASSERT_TRUE(cap.set(EVENT_CAP_PROP_POS_US, 20500));   // backward: reopens
    ASSERT_TRUE(cap.read(w));
    ASSERT_EQ(10u, w.size());
    EXPECT_EQ(21000, w.front().t);
    EXPECT_EQ(30000, w.back().t);
    ASSERT_TRUE(cap.set(EVENT_CAP_PROP_POS_US, 1e9));     // past the end
    EXPECT_FALSE(cap.read(w));
    std::remove(path.c_str());
}

// ---- Prophesee .dat ---------------------------------------------------------------------------------

std::string datRecord(uint32_t t, int x, int y, int p)
{
    const uint32_t data = (uint32_t)x | ((uint32_t)y << 14) | ((uint32_t)p << 28);
    std::string r(8, '\0');
    for (int i = 0; i < 4; i++)
    {
        r[i] = (char)((t >> (8 * i)) & 0xFF);
        r[4 + i] = (char)((data >> (8 * i)) & 0xFF);
    }
    return r;
}

TEST(Event_Capture_Dat, decodes_records_and_unwraps_32bit_time)
{
    std::string content = "% Data file containing Event2D events.\n% Version 2\n% Width 640\n% Height 480\n";
    content += std::string("\x00\x08", 2);
    content += datRecord(10, 5, 6, 1);
    content += datRecord(0xFFFFFFF0u, 639, 479, 0);
    content += datRecord(0x00000005u, 7, 8, 1);  // after a wrap: 2^32 + 5
    const std::string path = writeTempFile(content, ".dat");
    EXPECT_EQ("PROPHESEE_DAT", detectEventFileFormat(path));
    EventCapture cap(path);
    EXPECT_EQ("PROPHESEE_DAT", cap.getBackendName());
    EXPECT_EQ(Size(640, 480), cap.getSensorSize());
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 10);
    std::vector<Event> all = readAllEvents(cap);
    ASSERT_EQ(3u, all.size());
    EXPECT_EQ(Event(10, 5, 6, POLARITY_ON), all[0]);
    EXPECT_EQ(Event(0xFFFFFFF0LL, 639, 479, POLARITY_OFF), all[1]);
    EXPECT_EQ(Event((1LL << 32) + 5, 7, 8, POLARITY_ON), all[2]);
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS));
    std::remove(path.c_str());
}

TEST(Event_Capture_Dat, a_file_cut_off_mid_record_delivers_the_records_before_then_names_the_byte)
{
    std::string content = "% Data file containing Event2D events.\n";
    const size_t header = content.size() + 2;
    content += std::string("\x00\x08", 2) + datRecord(1, 1, 1, 1) + datRecord(2, 2, 2, 0).substr(0, 5);
    const std::string path = writeTempFile(content, ".dat");
    EventCapture cap(path);
    std::vector<Event> delivered;
    expectErrorMentioning([&]() { readAllEventsInto(cap, delivered); },
                          { path, "byte " + std::to_string(header + 8), "truncated: the file ends 5 bytes into" });
    EXPECT_EQ(1u, delivered.size());
    std::remove(path.c_str());
}

// ---- real recordings (../shared/data; skipped when absent) --------------------------------------------

TEST(Event_Capture_Real, tum_fan_stereo_text_counts)
{
    const std::string path = requireSharedData("stereo_dvs128_tum/Fan_disp8.dat");
    EventCapture cap;
    // shared/data/README.md calls the coordinates 1-based (1..128), but the file holds x = 0 and y = 0
    // (11 events) and never 128: it is 0-based, and with that every event lies on the 128 x 128 sensor.
    std::vector<int> params = { EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, 1,
                                EVENT_CAP_PROP_SENSOR_WIDTH, 128, EVENT_CAP_PROP_SENSOR_HEIGHT, 128,
                                EVENT_CAP_PROP_WINDOW_US, 100000 };
    ASSERT_TRUE(cap.open(path, EVENT_CAP_ANY, params));
    EXPECT_EQ("TEXT", cap.getBackendName());
    int64 n = 0, left = 0, first = -1, last = -1;
    std::vector<Event> packet;
    while (cap.read(packet))
        for (const Event& e : packet)
        {
            n++;
            left += e.camera == CAMERA_LEFT;
            if (first < 0) first = e.t;
            last = e.t;
        }
    EXPECT_EQ(136233, n);  // shared/data/README.md
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE));
    // The file stores retina 1 then retina 0, each time-ordered: the stereo merge delivers one ordered stream.
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_STEREO));
    EXPECT_EQ(0.0, cap.get(EVENT_CAP_PROP_TIME_BACKWARDS));
    EXPECT_EQ(72746, left);  // retina 1 lines in the file
    EXPECT_NEAR(9.8e6, (double)(last - first), 0.1e6);
}

TEST(Event_Capture_Real, ncars_dat_counts_and_ranges)
{
    const std::string path = requireSharedData("format_samples/tonic_sample_ncars.dat");
    EventCapture cap(path);
    EXPECT_EQ("PROPHESEE_DAT", cap.getBackendName());
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 1000);
    std::vector<Event> all = readAllEvents(cap);
    ASSERT_EQ(2009u, all.size());  // shared/data/README.md: 2,009 events, 0.1 s, x 0..77, y 0..41
    int maxX = 0, maxY = 0, minX = 1 << 20, minY = 1 << 20;
    for (const Event& e : all)
    {
        maxX = std::max(maxX, (int)e.x); maxY = std::max(maxY, (int)e.y);
        minX = std::min(minX, (int)e.x); minY = std::min(minY, (int)e.y);
    }
    EXPECT_EQ(0, minX); EXPECT_EQ(77, maxX);
    EXPECT_EQ(0, minY); EXPECT_EQ(41, maxY);
    EXPECT_NEAR(1e5, (double)(all.back().t - all.front().t), 1e4);
}

}} // namespace
