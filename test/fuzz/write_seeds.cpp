// Writes AEDAT 4.0 seeds for fuzz_aedat4 with the module's own EventWriter (uncompressed, LZ4, ZSTD): the
// container is too rich to write by hand in make_seeds.py. run.sh runs it into the work corpus.
//   write_seeds <dir>

#include <opencv2/event.hpp>

#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::cerr << "usage: write_seeds <dir>\n";
        return 2;
    }
    cv::RNG rng(3);
    std::vector<cv::event::Event> events;
    int64_t t = 0;
    for (int i = 0; i < 40; i++)
    {
        t += rng.uniform(0, 300);
        events.emplace_back(t, rng.uniform(0, 346), rng.uniform(0, 260), rng.uniform(0, 2));
    }
    const struct { const char* name; int compression; } kinds[] = { { "none", 0 }, { "lz4", 1 }, { "zstd", 3 } };
    for (const auto& k : kinds)
    {
        const std::string path = std::string(argv[1]) + "/writer_" + k.name + ".aedat4";
        cv::event::EventWriter writer(path, cv::Size(346, 260));
        if (!writer.set(cv::event::EVENT_WRITER_PROP_COMPRESSION, k.compression))
            return 1;
        writer.write(std::vector<cv::event::Event>(events.begin(), events.begin() + 20));
        writer.write(std::vector<cv::event::Event>(events.begin() + 20, events.end()));
        writer.release();
    }
    return 0;
}
