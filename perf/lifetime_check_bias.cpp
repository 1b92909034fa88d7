// What LifetimeArrivalCheck says of perfect lifetimes: prints one Markdown table.
//
//   lifetime_check_bias [--scenes=boxes,walking,boxes_pair] [--sensor=DAVIS240] [--sensor-set=NAME=VALUE,...]
//                       [--duration-ms=1000] [--effects=false]
//
// The simulator's true lifetime and normal flow of every event of the left camera (0 for noise, as a perfect
// estimator would call it) go through the check, for each scene as built, for its ideal sensor (no threshold
// spread, noise, refractory period, latency, jitter, hot pixels, leak or blur), and for the ideal sensor with
// one real-sensor effect back at a time. A check without bias would give a median of 1 and a narrow spread
// everywhere; what it gives is what an estimator can at best score on recordings of that kind.

#include "command_line.hpp"
#include "simulator_settings.hpp"
#include "test_simulator_helpers.hpp"  // perfectLifetimes, shared with the unit tests and design_figures

#include <opencv2/event.hpp>

#include <cstdio>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using namespace cv;
using namespace cv::event;
using opencv_test::perfectLifetimes;

namespace {

/** The settings of a DAVIS without its departures from the ideal sensor. */
void idealSensor(SimulatorSettings& s)
{
    s.thresholdSigma = 0;
    s.thresholdNoise = 0;
    s.noiseRateHz = 0;
    s.refractoryUs = 0;
    s.latencyUs = 0;
    s.latencySigmaUs = 0;
    s.jitterUs = 0;
    s.hotPixelShare = 0;
    s.leakRateHz = 0;
    s.blurSigmaPx = 0;
}

struct Variant
{
    const char* name;
    std::function<void(SimulatorSettings&)> change;
};

struct Result
{
    double samples = 0, p25 = 0, median = 0, p75 = 0;
};

Result check(const Ptr<StereoEventSimulator>& sim, double durationUs)
{
    Ptr<LifetimeArrivalCheck> arrival = LifetimeArrivalCheck::create(sim->getSensorSize());
    std::vector<Event> packet, left;
    std::vector<int> rows;
    Mat truth, lifetimes, flow;
    for (double t = 10000; t <= durationUs; t += 10000)
    {
        sim->generate(t, packet, truth);
        left.clear();
        rows.clear();
        for (size_t i = 0; i < packet.size(); i++)
            if (packet[i].camera == CAMERA_LEFT)
            {
                left.push_back(packet[i]);
                rows.push_back((int)i);
            }
        if (left.empty())
            continue;
        perfectLifetimes(truth, rows, lifetimes, flow);
        arrival->update(left, lifetimes, flow);
    }
    Result r;
    r.samples = arrival->getSampleCount();
    r.p25 = arrival->getRatioQuantile(0.25);
    r.median = arrival->getRatioQuantile(0.5);
    r.p75 = arrival->getRatioQuantile(0.75);
    return r;
}

}  // namespace

int main(int argc, char** argv)
{
    try
    {
        const char* keys =
            "{help h      | false                   | print this message}"
            "{scenes      | boxes,walking,boxes_pair | simulator scenes, comma separated}"
            "{sensor      | DAVIS240                | the sensor model the scenes are simulated on (DVS128, DAVIS240, DAVIS346)}"
            "{sensor-set  |                         | the scenes' sensor settings NAME=VALUE before each row's change, comma separated (SimulatorSettings fields, e.g. blurSigmaPx=0.6)}"
            "{duration-ms | 1000                    | simulated time per row [ms]}"
            "{effects     | true                    | also the rows of the ideal sensor and of each effect alone (false: each scene as built only)}";
        ProgramCommandLine cmd(argc, argv, keys, "What LifetimeArrivalCheck says of the simulator's true lifetimes.");
        if (cmd.helpShown())
            return 0;
        const double durationUs = cmd.get<double>("duration-ms") * 1000;
        const int sensorModel = sceneSensorModel(cmd.get<std::string>("sensor"));
        const std::vector<std::string> scenes = commaList(cmd.get<std::string>("scenes"));
        const std::string sensorSettings = cmd.get<std::string>("sensor-set");
        const bool effects = cmd.get<bool>("effects");

        const std::vector<Variant> variants = {
            { "as built", [](SimulatorSettings&) {} },
            { "ideal sensor", idealSensor },
            { "ideal + noise 0.1 Hz", [](SimulatorSettings& s) { idealSensor(s); s.noiseRateHz = 0.1; } },
            { "ideal + refractory 0.5 ms", [](SimulatorSettings& s) { idealSensor(s); s.refractoryUs = 500; } },
            { "ideal + threshold spread 0.05 (missed firings)",
              [](SimulatorSettings& s) { idealSensor(s); s.thresholdSigma = 0.05; s.thresholdNoise = 0.05; } },
            { "ideal + latency 50 +- 30 us, jitter 30 us",
              [](SimulatorSettings& s) { idealSensor(s); s.latencyUs = 50; s.latencySigmaUs = 30; s.jitterUs = 30; } },
            { "ideal + blur 0.8 px", [](SimulatorSettings& s) { idealSensor(s); s.blurSigmaPx = 0.8; } },
        };
        std::cout << "| scene | sensor | samples | median (p25 / p75) |\n|---|---|---|---|\n";
        const size_t rows = effects ? variants.size() : 1;  // "as built" first
        for (const std::string& scene : scenes)
        {
            const std::string label = sensorSettings.empty() ? scene : scene + " (" + sensorSettings + ")";
            for (size_t k = 0; k < rows; k++)
            {
                const Variant& v = variants[k];
                const Ptr<StereoEventSimulator> built = simulatorWithSettings(scene, sensorModel, sensorSettings);
                SimulatorSettings s = built->getSettings();
                v.change(s);
                const Result r = check(StereoEventSimulator::create(built->getPlanes(), s), durationUs);
                std::printf("| %s | %s | %.0f | %.2f (%.2f / %.2f) |\n", label.c_str(), v.name, r.samples, r.median,
                            r.p25, r.p75);
                std::fflush(stdout);
            }
        }
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "lifetime_check_bias: " << errorText(e) << "\n";
        return 1;
    }
}
