// Reader / writer throughput and memory across formats: prints one Markdown table.
//
//   event_io_bench [--events=N] [--shared=DIR] [--tmp=DIR]
//
// For each writable format it writes N synthetic events (DAVIS346-sized, 1 Mev/s) and reads them back;
// for each real recording in DIR/format_samples and DIR/stereo_dvs128_tum it reads the file. Per row: events,
// seconds, Mev/s, and the peak resident memory while reading (VmHWM after resetting it through
// /proc/self/clear_refs), which must not grow with N: the readers stream.

#include "resident_memory.hpp"
#include "command_line.hpp"

#include <opencv2/event.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/stat.h>

using namespace cv;
using namespace cv::event;

namespace {

struct Row
{
    std::string what, format;
    int64 events = 0;
    double seconds = 0, rssMiB = 0;
};

Row readAll(const std::string& path, const std::string& label)
{
    Row r;
    r.what = label;
    bench::resetPeakResident();
    const auto t0 = std::chrono::steady_clock::now();
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 65536);
    cap.open(path);
    r.format = cap.getBackendName();
    std::vector<Event> packet;
    while (cap.read(packet))
        r.events += (int64)packet.size();
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.rssMiB = bench::residentMiB("VmHWM:");
    return r;
}

bool exists(const std::string& p)
{
    struct stat st;
    return ::stat(p.c_str(), &st) == 0;
}

}  // namespace

const char* const keys =
    "{help h | false          | print this message}"
    "{events | 20000000       | events in each synthetic recording}"
    "{shared | ../shared/data | folder holding format_samples/ and stereo_dvs128_tum/ (read when present)}"
    "{tmp    | /tmp           | where the synthetic recordings are written (and removed)}";

int main(int argc, char** argv)
{
    int64 n = 0;
    std::string shared, tmp;
    try
    {
        ProgramCommandLine cmd(argc, argv, keys, "Reading and writing speed and memory of every recording format.");
        if (cmd.helpShown())
            return 0;
        n = (int64)cmd.get<double>("events");
        shared = cmd.get<std::string>("shared");
        tmp = cmd.get<std::string>("tmp");
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_io_bench: " << errorText(e) << "\n";
        return 2;
    }
    std::vector<Row> rows;
    const Size size(346, 260);

    // Synthetic recordings written chunk by chunk (the writer streams too), then read back.
    struct Out { const char* ext; int format; int compression; const char* label; };
    const Out outs[] = { { ".txt", EVENT_FILE_TEXT, 0, "text" }, { ".aedat4", EVENT_FILE_AEDAT4, 0, "AEDAT4 none" },
                         { ".aedat4", EVENT_FILE_AEDAT4, 1, "AEDAT4 LZ4" }, { ".aedat4", EVENT_FILE_AEDAT4, 3, "AEDAT4 ZSTD" } };
    for (const Out& o : outs)
    {
        const std::string path = tmp + "/event_io_bench" + o.ext;
        RNG rng(1);
        std::vector<Event> chunk(65536);
        const auto t0 = std::chrono::steady_clock::now();
        {
            EventWriter w;
            w.set(EVENT_WRITER_PROP_COMPRESSION, o.compression);
            w.open(path, size, o.format);
            for (int64 done = 0; done < n; done += (int64)chunk.size())
            {
                const int64 k = std::min<int64>((int64)chunk.size(), n - done);
                chunk.resize((size_t)k);
                for (int64 i = 0; i < k; i++)
                    chunk[(size_t)i] = Event(done + i, rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2));
                w.write(chunk);
            }
        }
        const double writeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        struct stat st;
        ::stat(path.c_str(), &st);
        Row r = readAll(path, std::string("synthetic, ") + o.label);
        std::cerr << o.label << ": wrote " << n << " events (" << st.st_size / 1e6 << " MB) at "
                  << n / writeSeconds / 1e6 << " Mev/s\n";
        rows.push_back(r);
        std::remove(path.c_str());
    }

    const char* real[] = { "format_samples/aestream_davis346.aedat4", "format_samples/tonic_sample_dvxplorer.aedat4",
                           "format_samples/evt2_sample.raw", "format_samples/evt3_sample.raw",
                           "format_samples/tonic_sample_ncars.dat", "format_samples/ecpy_test_events_1_ros1.bag",
                           "format_samples/ros2_libcaer_rollover", "format_samples/ecpy_test_events_2_mcap",
                           "stereo_dvs128_tum/Fan_disp8.dat",
                           "stereo_dvs128_tum/pendulum_left_30cm_2.tsv.txt" };
    for (const char* f : real)
    {
        const std::string path = shared + "/" + f;
        if (!exists(path))
        {
            std::cerr << "skipped (absent): " << path << "\n";
            continue;
        }
        rows.push_back(readAll(path, f));
    }

    std::printf("\n| recording | format | events | seconds | Mev/s | peak RSS [MiB] |\n|---|---|---|---|---|---|\n");
    for (const Row& r : rows)
        std::printf("| %s | %s | %lld | %.3f | %.1f | %.1f |\n", r.what.c_str(), r.format.c_str(), (long long)r.events,
                    r.seconds, r.events / std::max(1e-9, r.seconds) / 1e6, r.rssMiB);
    return 0;
}
