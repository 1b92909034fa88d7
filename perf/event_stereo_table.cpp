// The paper's Table I, reproduced: per scene, the events that keep a lifetime and the processing time of
// DECOUPLED and COUPLED stereo, measured in the same run: the lifetime estimation alone, as the paper times it
// (StereoEventMatcher::setTimeLifetimes), and the whole matcher, each with its COUPLED / DECOUPLED ratio; next
// to them FIXED_INTERVAL and frames + SGBM (FrameStereoMatcher), and, where ground truth exists, density and
// share within 1 px. A second table gives, per method, Mev/s, the per-event latency percentiles (p50 / p99, each
// event timed on its own through processEvent; SGBM: per 33 ms window, as its events wait for their window) and the
// memory the matcher added (peak resident memory during the run minus the resident memory before it).
// A third table gives COUPLED and DECOUPLED through process() in 33 ms windows on each of --threads (row
// bands, StereoEventMatcher::setNumThreads): Mev/s, the speed-up over one thread, and whether every output
// (disparity, lifetime, flags, flow) is bit for bit the one thread's.
//
//   event_stereo_table [--duration-ms=500] [--scenes=plane,two_planes,faint_line,cluttered]
//                      [--shared=DIR] [--markdown=FILE] [--soak-events=N] [--threads=1,2] [--repeat=3]
//
// Simulated scenes come with ground truth; the real TUM pairs in DIR/stereo_dvs128_tum (default
// ../shared/data) are added when present. Events are generated/read before timing: the times are the
// matcher's alone (single thread), in windows of 33 ms as a live pipeline would get them.
// Each mode runs --repeat times, the modes taking turns; each time reported is the fastest repetition's
// (a shared machine only ever adds time), the latency percentiles are those of the fastest whole run, and the
// memory is the first repetition's (later ones reuse what the first freed).
// --soak-events N streams N events through one COUPLED matcher (the first scene replayed with its time
// shifted on every pass) and prints the resident memory at every tenth: it stays flat.

#include "resident_memory.hpp"
#include "algorithm_settings.hpp"
#include "command_line.hpp"

#include <opencv2/event.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>

using namespace cv;
using namespace cv::event;

namespace {

struct Recording
{
    std::string name;
    Size size;
    std::vector<std::vector<Event>> windows;
    std::vector<Mat> truth;  // per window, N x 6 (simulated only)
    int64 events = 0;
};

struct Result
{
    double seconds = 0;
    double lifetimeSeconds = 0;  // the lifetime estimation alone (StereoEventMatcher::setTimeLifetimes)
    int64 withLifetime = 0, withDisparity = 0;
    StereoEventScores scores;  // simulated recordings only
    double p50 = 0, p99 = 0;  // latency per event [us] (SGBM: per window)
    double addedMiB = 0;      // peak resident memory during the run minus before it
};

std::string num(double v, int precision);

// Two repetitions of one mode combined: each time the smaller, the latencies of the faster whole run, the
// first one's memory and counts (every repetition's are the same).
Result fastest(const Result& first, const Result& next)
{
    if (next.withLifetime != first.withLifetime || next.withDisparity != first.withDisparity || next.scores.within1 != first.scores.within1)
        throw std::runtime_error("two runs of the same mode gave different estimates: the matcher is not deterministic");
    Result r = first;
    if (next.seconds < first.seconds)
    {
        r.seconds = next.seconds;
        r.p50 = next.p50;
        r.p99 = next.p99;
    }
    r.lifetimeSeconds = std::min(first.lifetimeSeconds, next.lifetimeSeconds);
    return r;
}

double percentile(std::vector<float>& v, double q)
{
    if (v.empty())
        return 0;
    const size_t k = std::min(v.size() - 1, (size_t)(q * (double)v.size()));
    std::nth_element(v.begin(), v.begin() + (std::ptrdiff_t)k, v.end());
    return v[k];
}

Recording simulated(const std::string& scene, double durationMs, int sensorModel)
{
    Recording r;
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene, sensorModel);
    r.name = scene + (sensorModel == SENSOR_DAVIS240 ? " (sim)" : " (sim, " + getSensorModelName(sensorModel) + ")");
    r.size = sim->getSensorSize();
    for (double t = 33000; t < durationMs * 1000 + 33000; t += 33000)
    {
        std::vector<Event> ev;
        Mat gt;
        sim->generate(std::min(t, durationMs * 1000), ev, gt);
        r.events += (int64)ev.size();
        r.windows.push_back(ev);
        r.truth.push_back(gt);
    }
    return r;
}

bool real(const std::string& path, const std::string& name, Recording& r)
{
    struct stat st;
    if (::stat(path.c_str(), &st) != 0)
        return false;
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, 1);  // TUM stereo DVS128: retina 1 is the left camera
    cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, 128);
    cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, 128);
    cap.set(EVENT_CAP_PROP_WINDOW_US, 33000);
    cap.open(path);
    r.name = name + " (real)";
    r.size = cap.getSensorSize();
    std::vector<Event> ev;
    while (cap.read(ev))
    {
        r.events += (int64)ev.size();
        r.windows.push_back(ev);
    }
    return true;
}

// A matcher of `mode` for the recording's sensor with --set's parameters.
Ptr<StereoEventMatcher> createMatcher(const Recording& rec, int mode, const std::string& settings)
{
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(rec.size, mode);
    applyMatcherSettings(m, settings);
    return m;
}

// The results' index of frames + SGBM, after the three StereoMatchModes.
const int FRAME_BASELINE = 3;

std::string methodName(int method)
{
    return method == FRAME_BASELINE ? std::string("sgbm") : getStereoModeName(method);
}

// A StereoMatchMode event by event, or FRAME_BASELINE window by window.
Result run(const Recording& rec, int method, const std::string& settings)
{
    Result r;
    Mat d, lt, fl;
    std::vector<float> latency;
    // Allocated and touched before the memory baseline, so that the matcher's memory is what is measured.
    latency.assign((size_t)rec.events, 0.f);
    latency.clear();  // keeps the capacity
    bench::resetPeakResident();
    const double before = bench::residentMiB("VmRSS:");
    Ptr<StereoEventMatcher> m;
    Ptr<FrameStereoMatcher> frames;
    if (method == FRAME_BASELINE)
        frames = FrameStereoMatcher::create(rec.size);
    else
    {
        m = createMatcher(rec, method, settings);
        m->setTimeLifetimes(true);
    }
    StereoEventEstimate est;
    for (size_t w = 0; w < rec.windows.size(); w++)
    {
        const std::vector<Event>& ev = rec.windows[w];
        if (frames)
        {
            const auto t0 = std::chrono::steady_clock::now();
            frames->process(ev, d, fl);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            r.seconds += s;
            latency.push_back((float)(s * 1e6));
        }
        else
        {
            // One event at a time, as a live loop runs it (identical results to process()).
            d.create((int)ev.size(), 1, CV_32F);
            fl.create((int)ev.size(), 1, CV_32S);
            for (size_t i = 0; i < ev.size(); i++)
            {
                const auto t0 = std::chrono::steady_clock::now();
                m->processEvent(ev[i], est);
                const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                r.seconds += s;
                latency.push_back((float)(s * 1e6));
                d.at<float>((int)i) = est.disparity;
                fl.at<int>((int)i) = est.flags;
            }
        }
        for (int i = 0; i < d.rows; i++)
        {
            const int f = fl.at<int>(i);
            r.withLifetime += (f & STEREO_HAS_LIFETIME) != 0;
            r.withDisparity += (f & STEREO_HAS_DISPARITY) != 0;
        }
        if (!rec.truth.empty())
            scoreStereoEvents(ev, d, rec.truth[w], r.scores);
    }
    r.lifetimeSeconds = m ? m->getLifetimeSeconds() : 0;
    r.p50 = percentile(latency, 0.5);
    r.p99 = percentile(latency, 0.99);
    latency = std::vector<float>();
    r.addedMiB = bench::residentMiB("VmHWM:") - before;
    return r;
}

// process() over the recording's windows with `threads` row bands: seconds, and every output in `outputs`.
double runThreads(const Recording& rec, int mode, int threads, const std::string& settings, std::vector<Mat>& outputs)
{
    Ptr<StereoEventMatcher> m = createMatcher(rec, mode, settings);
    m->setNumThreads(threads);
    outputs.clear();
    double seconds = 0;
    for (const std::vector<Event>& ev : rec.windows)
    {
        Mat d, lt, fl, flow;
        const auto t0 = std::chrono::steady_clock::now();
        m->process(ev, d, lt, fl, noArray(), flow);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        for (const Mat& o : { d, lt, fl, flow })
            outputs.push_back(o);
    }
    return seconds;
}

bool sameBits(const std::vector<Mat>& a, const std::vector<Mat>& b)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); i++)
        if (a[i].size != b[i].size || std::memcmp(a[i].data, b[i].data, a[i].total() * a[i].elemSize()) != 0)
            return false;
    return true;
}

// Streams `events` events through one COUPLED matcher, replaying the recording with its time shifted on
// every pass; prints the resident memory at every tenth.
void soak(const Recording& rec, int64 events, const std::string& settings)
{
    Ptr<StereoEventMatcher> m = createMatcher(rec, STEREO_COUPLED, settings);
    const int64 span = rec.windows.back().back().t - rec.windows.front().front().t + 33000;
    int64 done = 0, shift = 0, nextReport = 0;
    std::vector<Event> shifted;
    Mat d;
    const auto t0 = std::chrono::steady_clock::now();
    std::cout << "\nsoak: " << events << " events of " << rec.name << " through COUPLED\n\n| events | resident MiB | Mev/s so far |\n|---|---|---|\n";
    while (done < events)
    {
        for (const std::vector<Event>& w : rec.windows)
        {
            if (done >= nextReport)
            {
                const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                std::cout << "| " << done << " | " << num(bench::residentMiB("VmRSS:"), 1) << " | "
                          << num(s > 0 ? (double)done / s / 1e6 : 0, 3) << " |" << std::endl;
                nextReport += events / 10;
            }
            if (done >= events)
                break;
            shifted = w;
            for (Event& e : shifted)
                e.t += shift;
            m->process(shifted, d);
            done += (int64)w.size();
        }
        shift += span;
    }
    std::cout << "| " << done << " | " << num(bench::residentMiB("VmRSS:"), 1) << " | - |\n";
}

std::string pct(int64 a, int64 b)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(1) << (b ? 100.0 * (double)a / (double)b : 0.0) << " %";
    return s.str();
}

std::string num(double v, int precision)
{
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

}  // namespace

const char* const keys =
    "{help h      | false                                 | print this message}"
    "{duration-ms | 500                                   | length of each simulated scene [ms]}"
    "{scenes      | plane,two_planes,faint_line,cluttered | simulated scenes, comma separated}"
    "{sensor      | DAVIS240                              | the simulated scenes' sensor: DAVIS240 or DAVIS346}"
    "{set         |                                       | matcher parameters NAME=VALUE, comma separated (FileStorage names, e.g. costWindow=9)}"
    "{shared      | ../shared/data                        | folder holding stereo_dvs128_tum/ (the real pairs, when present)}"
    "{markdown    |                                       | also write the tables to this file}"
    "{soak-events | 0                                     | stream this many events through one COUPLED matcher, printing its memory}"
    "{threads     | 1,2                                   | thread counts of the row-band table, comma separated}"
    "{repeat      | 3                                     | runs of each mode; the fastest one's times are reported}";

int main(int argc, char** argv)
{
    double durationMs = 0;
    int64 soakEvents = 0;
    int repeat = 1;
    std::string scenes, shared, markdown, threadList, settings;
    int sensorModel = SENSOR_DAVIS240;
    try
    {
        ProgramCommandLine cmd(argc, argv, keys,
                              "The paper's Table I and the matcher's speed, latency, memory and row-band scaling.");
        if (cmd.helpShown())
            return 0;
        durationMs = cmd.get<double>("duration-ms");
        scenes = cmd.get<std::string>("scenes");
        shared = cmd.get<std::string>("shared");
        markdown = cmd.get<std::string>("markdown");
        soakEvents = (int64)cmd.get<double>("soak-events");
        threadList = cmd.get<std::string>("threads");
        repeat = cmd.get<int>("repeat");
        settings = cmd.get<std::string>("set");
        const std::string sensor = cmd.get<std::string>("sensor");
        sensorModel = findSensorModel(sensor);
        if (sensorModel != SENSOR_DAVIS240 && sensorModel != SENSOR_DAVIS346)
            throw std::invalid_argument("--sensor must be DAVIS240 or DAVIS346 (the simulator's presets), got " + sensor);
        if (repeat < 1)
            throw std::invalid_argument("--repeat must be at least 1, got " + std::to_string(repeat));
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_stereo_table: " << errorText(e) << "\n";
        return 2;
    }
    try
    {
        std::vector<Recording> recordings;
        for (const std::string& scene : commaList(scenes))
        {
            std::cerr << "simulating " << scene << " (" << durationMs << " ms)...\n";
            recordings.push_back(simulated(scene, durationMs, sensorModel));
        }
        for (const char* name : { "Fan_disp8", "Rotation_disp11", "Translation_disp12" })
        {
            Recording r;
            if (real(shared + "/stereo_dvs128_tum/" + std::string(name) + ".dat", name, r))
                recordings.push_back(std::move(r));
        }

        std::ostringstream table;
        table << "| recording | events | DECOUPLED: with lifetime | DECOUPLED: lifetime time / whole | COUPLED: with lifetime "
                 "| COUPLED: lifetime time / whole | COUPLED / DECOUPLED: lifetime time | whole | COUPLED Mev/s "
                 "| density / within 1 px: COUPLED | DECOUPLED | FIXED | SGBM |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        double coupledSeconds = 0, decoupledSeconds = 0, coupledLifetime = 0, decoupledLifetime = 0;
        std::ostringstream speed, bands;
        speed << "| recording | mode | Mev/s | latency p50 | latency p99 | memory added |\n|---|---|---|---|---|---|\n";
        bands << "| recording | mode | threads | Mev/s | speed-up | outputs identical to 1 thread |\n|---|---|---|---|---|---|\n";
        std::vector<int> threadCounts;
        for (const std::string& item : commaList(threadList))
            threadCounts.push_back(std::stoi(item));
        for (const Recording& rec : recordings)
        {
            std::cerr << "running " << rec.name << " (" << rec.events << " events)...\n";
            Result res[4];
            for (int k = 0; k < repeat; k++)
                for (int method = STEREO_COUPLED; method <= FRAME_BASELINE; method++)
                {
                    const Result r = run(rec, method, settings);
                    if (k == 0)
                        res[method] = r;
                    else
                        res[method] = fastest(res[method], r);
                }
            const Result& c = res[STEREO_COUPLED];
            const Result& d = res[STEREO_DECOUPLED];
            coupledSeconds += c.seconds;
            decoupledSeconds += d.seconds;
            coupledLifetime += c.lifetimeSeconds;
            decoupledLifetime += d.lifetimeSeconds;
            for (int method = STEREO_COUPLED; method <= FRAME_BASELINE; method++)
                speed << "| " << rec.name << " | " << methodName(method) << " | "
                      << num((double)rec.events / std::max(1e-12, res[method].seconds) / 1e6, 3) << " | "
                      << num(res[method].p50, 1) << (method == FRAME_BASELINE ? " us / window" : " us") << " | "
                      << num(res[method].p99, 1) << (method == FRAME_BASELINE ? " us / window" : " us") << " | "
                      << num(res[method].addedMiB, 1) << " MiB |\n";
            auto accuracy = [&](const Result& r) {
                return rec.truth.empty() ? pct(r.withDisparity, rec.events) + " of all"
                                         : num(r.scores.density(), 1) + " % / " + num(r.scores.precision(), 1) + " %";
            };
            table << "| " << rec.name << " | " << rec.events << " | " << d.withLifetime << " | " << num(d.lifetimeSeconds * 1e3, 0)
                  << " / " << num(d.seconds * 1e3, 0) << " ms | " << c.withLifetime << " | " << num(c.lifetimeSeconds * 1e3, 0)
                  << " / " << num(c.seconds * 1e3, 0) << " ms | **" << num(c.lifetimeSeconds / std::max(1e-12, d.lifetimeSeconds), 2)
                  << "** | " << num(c.seconds / std::max(1e-12, d.seconds), 2) << " | " << num((double)rec.events / c.seconds / 1e6, 3)
                  << " | " << accuracy(c) << " | " << accuracy(d) << " | " << accuracy(res[STEREO_FIXED_INTERVAL]) << " | "
                  << accuracy(res[FRAME_BASELINE]) << " |\n";
            for (int mode : { (int)STEREO_COUPLED, (int)STEREO_DECOUPLED })
            {
                std::vector<Mat> first, outputs;
                double oneThread = 0;
                for (size_t k = 0; k < threadCounts.size(); k++)
                {
                    const double s = runThreads(rec, mode, threadCounts[k], settings, k == 0 ? first : outputs);
                    if (k == 0)
                        oneThread = s;
                    bands << "| " << rec.name << " | " << getStereoModeName(mode) << " | " << threadCounts[k] << " | "
                          << num((double)rec.events / std::max(1e-12, s) / 1e6, 3) << " | " << num(oneThread / s, 2) << " | "
                          << (k == 0 ? "-" : sameBits(first, outputs) ? "yes" : "**NO**") << " |\n";
                }
            }
        }
        table << "\nCOUPLED / DECOUPLED time over all recordings: lifetime estimation "
              << num(coupledLifetime / std::max(1e-12, decoupledLifetime), 2)
              << " (the paper's Table I, which reports about 0.5), whole matcher " << num(coupledSeconds / std::max(1e-12, decoupledSeconds), 2)
              << "\n\n" << speed.str()
              << "\nPeak resident memory of the whole run (the recordings are held in memory): "
              << num(bench::residentMiB("VmHWM:"), 1) << " MiB\n\nprocess() in 33 ms windows, row bands on "
              << threadList << " threads (speed-up against the first):\n\n" << bands.str();
        std::cout << table.str();
        if (!markdown.empty())
            std::ofstream(markdown) << table.str();
        if (soakEvents > 0 && !recordings.empty())
            soak(recordings.front(), soakEvents, settings);
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_stereo_table: " << errorText(e) << "\n";
        return 1;
    }
}
