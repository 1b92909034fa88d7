// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The bad-input matrix over every file back-end, on the fuzzers' seed files (test/fuzz/corpus, small valid
// files built from the formats' byte layouts) and an AEDAT 4.0 file from EventWriter:
//  - truncated at every byte: the events delivered are exactly the first events of the whole file (nothing
//    invented, nothing skipped), and a cut inside a record is a cv::Exception naming the file;
//  - every header byte flipped: a cv::Exception naming the file, or events inside the sensor and in time order;
//  - wrong magic, empty file, directory, absurd sizes: a cv::Exception naming the file and the problem.
// Any other exception type, a crash or (under the sanitizers ctest) a memory error fails.

#include "test_precomp.hpp"

#include <set>
#include <sstream>
#include <unistd.h>

namespace opencv_test { namespace {

std::string corpusDir()
{
    return std::string(sourceRoot()) + "/test/fuzz/corpus";
}

std::string readBytes(const std::string& path)
{
    std::ifstream in(path.c_str(), std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

struct Outcome
{
    std::vector<Event> events;
    std::string error;  // empty: the stream ended cleanly
    Size sensor;
};

// Reads @p bytes as a file of back-end @p api. Only cv::Exception may come out; anything else fails.
Outcome readAs(const std::string& bytes, int api, const std::string& suffix)
{
    Outcome o;
    const std::string path = writeTempFile(bytes, suffix);
    try
    {
        EventCapture cap;
        cap.open(path, api);
        o.sensor = cap.getSensorSize();
        readAllEventsInto(cap, o.events, 257);  // what came before an error counts too
    }
    catch (const cv::Exception& e)
    {
        o.error = e.err;
        EXPECT_NE(std::string::npos, o.error.find(path)) << "the message does not name the file: " << o.error;
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "not a cv::Exception: " << e.what();
    }
    std::remove(path.c_str());
    return o;
}

struct Sample
{
    std::string name;
    int api;
    std::string suffix;
    std::string bytes;
};

std::vector<Sample> samples()
{
    const struct { const char* file; int api; const char* suffix; } seeds[] = {
        { "text/rpg_seconds.txt", EVENT_CAP_TEXT, ".txt" },
        { "text/size_line_us.txt", EVENT_CAP_TEXT, ".txt" },
        { "text/stereo_camera_column.txt", EVENT_CAP_TEXT, ".txt" },
        { "aedat2/davis240.aedat", EVENT_CAP_AEDAT2, ".aedat" },
        { "aedat2/dvs128.aedat", EVENT_CAP_AEDAT2, ".aedat" },
        { "aedat3/davis346.aedat", EVENT_CAP_AEDAT3, ".aedat" },
        { "dat/cd.dat", EVENT_CAP_PROPHESEE_DAT, ".dat" },
        { "raw/evt2.raw", EVENT_CAP_PROPHESEE_RAW, ".raw" },
        { "raw/evt3.raw", EVENT_CAP_PROPHESEE_RAW, ".raw" },
        { "mcap/two_messages.mcap", EVENT_CAP_ROSBAG2, ".mcap" },
    };
    std::vector<Sample> out;
    for (const auto& s : seeds)
    {
        const std::string bytes = readBytes(corpusDir() + "/" + s.file);
        if (bytes.empty())
            CV_Error(cv::Error::StsError, "seed file missing: " + corpusDir() + "/" + s.file);
        out.push_back({ s.file, s.api, s.suffix, bytes });
    }
    // AEDAT 4.0 from the module's writer (LZ4 packets).
    RNG rng(9);
    std::vector<Event> ev;
    int64 t = 0;
    for (int i = 0; i < 30; i++)
        ev.emplace_back(t += rng.uniform(0, 200), rng.uniform(0, 346), rng.uniform(0, 260), rng.uniform(0, 2));
    const std::string path = cv::tempfile(".aedat4");
    {
        EventWriter w(path, Size(346, 260));
        w.write(std::vector<Event>(ev.begin(), ev.begin() + 10));
        w.write(std::vector<Event>(ev.begin() + 10, ev.end()));
    }
    out.push_back({ "writer.aedat4", EVENT_CAP_AEDAT4, ".aedat4", readBytes(path) });
    std::remove(path.c_str());
    return out;
}

/** Where a sample's records start, and the cut positions that leave whole records only: written from the
formats' layouts (header lines, record sizes, packet headers), not from the readers. */
struct Layout
{
    size_t dataStart = 0;
    std::set<size_t> wholeRecords;
};

size_t afterHeaderLines(const std::string& b, char comment)
{
    size_t pos = 0;
    while (pos < b.size() && b[pos] == comment)
    {
        const size_t nl = b.find('\n', pos);
        pos = nl == std::string::npos ? b.size() : nl + 1;
    }
    return pos;
}

int32_t int32At(const std::string& b, size_t pos)
{
    uint32_t v = 0;
    for (int i = 3; i >= 0; i--)
        v = (v << 8) | (uint8_t)b[pos + (size_t)i];
    return (int32_t)v;
}

Layout layoutOf(const Sample& s)
{
    const std::string& b = s.bytes;
    Layout l;
    auto fixedRecords = [&](size_t start, size_t record) {
        l.dataStart = start;
        for (size_t pos = start; pos <= b.size(); pos += record)
            l.wholeRecords.insert(pos);
    };
    if (s.api == EVENT_CAP_TEXT)
    {
        // From the end of the first event line (its cut prefixes "t x" read as a size line: no way to tell),
        // a cut at a line's end, before or after its newline, leaves whole lines.
        size_t pos = 0;
        for (;;)
        {
            const size_t nl = b.find('\n', pos);
            std::istringstream line(b.substr(pos, nl - pos));
            std::string token;
            int tokens = 0;
            while (line >> token)
                tokens++;
            pos = nl + 1;
            if (tokens >= 4)
                break;
        }
        l.dataStart = pos;
        for (size_t i = pos - 1; i < b.size(); i++)
            if (b[i] == '\n')
                l.wholeRecords.insert(i), l.wholeRecords.insert(i + 1);
    }
    else if (s.api == EVENT_CAP_AEDAT2)
        fixedRecords(afterHeaderLines(b, '#'), 8);
    else if (s.api == EVENT_CAP_PROPHESEE_DAT)
        fixedRecords(afterHeaderLines(b, '%') + 2, (size_t)(uint8_t)b[afterHeaderLines(b, '%') + 1]);
    else if (s.api == EVENT_CAP_PROPHESEE_RAW)
        fixedRecords(afterHeaderLines(b, '%'), b.find("evt 3.0") != std::string::npos ? 2 : 4);
    else if (s.api == EVENT_CAP_AEDAT3)
    {
        // 28-byte packet headers: event size at byte 4, capacity at byte 20.
        size_t pos = l.dataStart = afterHeaderLines(b, '#');
        l.wholeRecords.insert(pos);
        while (pos + 28 <= b.size())
        {
            pos += 28 + (size_t)int32At(b, pos + 4) * (size_t)int32At(b, pos + 20);
            l.wholeRecords.insert(pos);
        }
    }
    else if (s.api == EVENT_CAP_AEDAT4)
    {
        // The magic line, a size-prefixed IOHeader, then packets of an 8-byte header (stream, size) and their
        // payload; the file data table after them is read as one more "packet" of whatever size it gives.
        size_t pos = l.dataStart = 14 + 4 + (size_t)int32At(b, 14);
        l.wholeRecords.insert(pos);
        while (pos + 8 <= b.size())
        {
            pos += 8 + (size_t)int32At(b, pos + 4);
            l.wholeRecords.insert(pos);
        }
    }
    else if (s.api == EVENT_CAP_ROSBAG2)
    {
        // MCAP: the magic, then records of {u8 opcode, u64 length, content}; the events start with the first
        // message record (opcode 5), and past the data-end record (opcode 15) every event's record is whole.
        size_t pos = 8;
        while (pos + 9 <= b.size())
        {
            const uint8_t opcode = (uint8_t)b[pos];
            uint64_t length = 0;
            std::memcpy(&length, b.data() + pos + 1, 8);
            if (opcode == 5 && l.dataStart == 0)
                l.dataStart = pos;
            l.wholeRecords.insert(pos);
            pos += 9 + (size_t)length;
            if (opcode == 15)
            {
                for (size_t end = pos; end <= b.size(); end++)
                    l.wholeRecords.insert(end);
                break;
            }
        }
    }
    else
        CV_Error(cv::Error::StsError, "no layout for " + s.name);
    return l;
}

bool isPrefix(const std::vector<Event>& part, const std::vector<Event>& whole)
{
    return part.size() <= whole.size() && std::equal(part.begin(), part.end(), whole.begin());
}

TEST(Event_BadInput, truncated_at_every_byte_delivers_a_prefix_then_ends_or_names_the_file)
{
    for (const Sample& s : samples())
    {
        SCOPED_TRACE(s.name);
        const Outcome full = readAs(s.bytes, s.api, s.suffix);
        ASSERT_TRUE(full.error.empty()) << full.error;
        ASSERT_GE(full.events.size(), 10u);
        const Layout layout = layoutOf(s);
        ASSERT_GT(layout.dataStart, 0u);
        ASSERT_LT(layout.dataStart, s.bytes.size());
        size_t eventsOfWholeRecords = 0;  // delivered by the last cut at a record boundary
        for (size_t len = 0; len < s.bytes.size(); len++)
        {
            const Outcome o = readAs(s.bytes.substr(0, len), s.api, s.suffix);
            ASSERT_TRUE(isPrefix(o.events, full.events)) << "cut at byte " << len << ": events not a prefix";
            if (len >= layout.dataStart && layout.wholeRecords.count(len))
                eventsOfWholeRecords = o.events.size();
            // A cut inside a record must be reported, not read as a shorter recording, and only after every
            // whole record before it. (Cuts inside the header are not judged here: some headers have no end
            // marker.)
            if (len > layout.dataStart && !layout.wholeRecords.count(len))
            {
                EXPECT_FALSE(o.error.empty()) << "cut at byte " << len << " of " << s.bytes.size()
                                              << " (inside a record) read as a clean end with " << o.events.size()
                                              << " events";
                EXPECT_EQ(eventsOfWholeRecords, o.events.size())
                    << "cut at byte " << len << ": the events of the whole records before it are not all delivered";
            }
        }
    }
}

TEST(Event_BadInput, every_header_byte_flipped_is_rejected_or_read_within_bounds)
{
    for (const Sample& s : samples())
    {
        SCOPED_TRACE(s.name);
        const size_t header = std::min<size_t>(s.bytes.size(), 160);
        bool unknownCompression = false;
        for (size_t i = 0; i < header; i++)
            for (int mask : { 0x01, 0x80, 0xFF })
            {
                std::string bad = s.bytes;
                bad[i] = (char)(bad[i] ^ mask);
                const Outcome o = readAs(bad, s.api, s.suffix);
                unknownCompression |= o.error.find("unknown compression") != std::string::npos;
                if (!o.error.empty())
                    continue;
                for (size_t k = 0; k < o.events.size(); k++)
                {
                    const Event& e = o.events[k];
                    if (!o.sensor.empty())
                    {
                        ASSERT_TRUE(e.x >= 0 && e.y >= 0 && e.x < o.sensor.width && e.y < o.sensor.height)
                            << "byte " << i << " ^ " << mask << ": event outside the sensor";
                    }
                    ASSERT_TRUE(k == 0 || o.events[k - 1].t <= e.t) << "byte " << i << " ^ " << mask << ": time order";
                }
            }
        // AEDAT 4.0: some flip lands in the IOHeader's compression field, and the error says so.
        if (s.api == EVENT_CAP_AEDAT4)
        {
            EXPECT_TRUE(unknownCompression) << "no header flip gave an unknown-compression error";
        }
    }
}

TEST(Event_BadInput, wrong_magic_empty_file_and_directory_name_the_file_and_the_problem)
{
    for (const Sample& s : samples())
    {
        if (s.api == EVENT_CAP_TEXT)
            continue;  // text has no magic
        SCOPED_TRACE(s.name);
        std::string bad = s.bytes;
        bad[0] = '\x01';  // neither a header character nor text
        const Outcome detected = readAs(bad, EVENT_CAP_ANY, s.suffix);
        EXPECT_NE(std::string::npos, detected.error.find("unknown event file format")) << detected.error;
        if (s.api != EVENT_CAP_AEDAT2)  // AEDAT 1.0 has no magic: forced, such a file is records from byte 0
        {
            const Outcome forced = readAs(bad, s.api, s.suffix);
            EXPECT_FALSE(forced.error.empty()) << "a broken magic was accepted";
        }
        const Outcome empty = readAs(std::string(), s.api, s.suffix);
        EXPECT_FALSE(empty.error.empty());
    }
    const std::string dir = cv::tempfile("_dir");
    ASSERT_EQ(0, ::mkdir(dir.c_str(), 0700));
    for (int api : { EVENT_CAP_ANY, EVENT_CAP_TEXT, EVENT_CAP_AEDAT2, EVENT_CAP_AEDAT4, EVENT_CAP_PROPHESEE_RAW })
    {
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
        EXPECT_FALSE(cap.open(dir, api));
        EXPECT_NE(std::string::npos, cap.getLastError().find(dir)) << cap.getLastError();
    }
    ::rmdir(dir.c_str());
}

// Root reads any file, so where this process can read a file without permission (root with CAP_DAC_OVERRIDE)
// the test is skipped; the ctest opencv_test_event_unprivileged runs it again without that capability
// (setpriv), where the permission bits apply.
TEST(Event_BadInput, unreadable_file_names_the_file_and_the_reason)
{
    {
        // Whether permission bits stop this process: root with CAP_DAC_OVERRIDE reads any file.
        const std::string probe = writeTempFile("x", ".probe");
        ASSERT_EQ(0, ::chmod(probe.c_str(), 0));
        FILE* f = std::fopen(probe.c_str(), "rb");
        const bool readsAnyFile = f != nullptr;
        if (f)
            std::fclose(f);
        std::remove(probe.c_str());
        if (readsAnyFile)
            throw SkipTestException("this process reads files without read permission (root); ctest "
                                    "opencv_test_event_unprivileged runs this test without that capability");
    }
    for (const Sample& s : samples())
    {
        SCOPED_TRACE(s.name);
        const std::string path = writeTempFile(s.bytes, s.suffix);
        ASSERT_EQ(0, ::chmod(path.c_str(), 0));
        for (int api : { (int)EVENT_CAP_ANY, s.api })
        {
            EventCapture cap;
            cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 0);
            EXPECT_FALSE(cap.open(path, api));
            const std::string error = cap.getLastError();
            EXPECT_NE(std::string::npos, error.find(path)) << error;
            EXPECT_NE(std::string::npos, error.find("ermission denied")) << error;
            cap.set(EVENT_CAP_PROP_EXCEPTION_MODE, 1);
            EXPECT_THROW(cap.open(path, api), cv::Exception);
        }
        std::remove(path.c_str());
    }
}

TEST(Event_BadInput, absurd_sizes_in_headers_are_refused_without_allocating_them)
{
    // AEDAT 3.1 packet headers that claim 2^31 - 1 events of 2^31 bytes (and of 8 bytes): the reader must
    // check them against the file, not allocate them (the sanitizers ctest would abort on a 16 EiB request).
    const std::string header = "#!AER-DAT3.1\r\n#Format: RAW\r\n#Source 1: DAVIS346B\r\n#!END-HEADER\r\n";
    for (uint32_t eventSize : { 8u, 0x7FFFFFFFu, 0u })
    {
        std::string f = header;
        const uint32_t fields[7] = { 8 /* size, replaced */, 4, 0, 0x7FFFFFFF, 0x7FFFFFFF, 0x7FFFFFFF, 0 };
        f += std::string("\x01\x00\x01\x00", 4);  // polarity packet, source 1
        for (int k = 0; k < 6; k++)
        {
            const uint32_t v = k == 0 ? eventSize : fields[k];
            for (int b = 0; b < 4; b++)
                f.push_back((char)((v >> (8 * b)) & 0xFF));
        }
        f += std::string(64, '\0');
        const Outcome o = readAs(f, EVENT_CAP_AEDAT3, ".aedat");
        EXPECT_FALSE(o.error.empty()) << "event size " << eventSize;
    }
    // Text: a size line of 2^40 x 2^40 pixels must not become a 2^80-pixel sensor.
    const Outcome text = readAs("1099511627776 1099511627776\n0 1 1 1\n", EVENT_CAP_TEXT, ".txt");
    EXPECT_TRUE(!text.error.empty() || text.sensor.width <= 32768) << text.sensor;
}

}}  // namespace
