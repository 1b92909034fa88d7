// What estimateClockOffset() finds when the right camera's clock is moved by a known amount: prints one Markdown
// table.
//
//   clock_offset_sweep [--scenes=boxes,walking,boxes_fast_pair] [--clocks-ms=-10,-5,0,5,10] [--duration-ms=3000]
//
// Each scene is simulated with its right clock moved by each amount (the simulator's rightClockOffsetUs, added
// to what the scene already has) and its first seconds go through the estimate, as event_stereo's
// --right-time-offset-ms=auto does. A clock moved by c should move the estimate by -c; where the events cannot
// tell an offset from a disparity, the estimate should say so (an uncertainty above 0.5 ms: event_stereo then
// does not apply it, nor an estimate within two uncertainties of zero).

#include "clock_offset_policy.hpp"
#include "command_line.hpp"
#include "test_simulator_helpers.hpp"

#include <opencv2/event.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

using namespace cv;
using namespace cv::event;

namespace {

// "+9.77 +- 0.05", "+8.15 +- 2.13 (not applied)" or "none" (no estimate at all).
std::string cell(double estimateUs, double uncertaintyUs)
{
    char text[64];
    if (!std::isfinite(uncertaintyUs))
        return "none";
    std::snprintf(text, sizeof(text), "%+.2f +- %.2f%s", estimateUs / 1000, uncertaintyUs / 1000,
                  sampleAppliesClockOffset(estimateUs, uncertaintyUs) ? "" : " (not applied)");
    return text;
}

}  // namespace

int main(int argc, char** argv)
{
    try
    {
        const char* keys =
            "{help h      | false                                  | print this message}"
            "{scenes      | boxes,walking,boxes_fast_pair          | simulator scenes, comma separated}"
            "{clocks-ms   | -10,-5,0,5,10                          | amounts the right clock is moved by [ms], comma separated}"
            "{duration-ms | 3000                                   | the seconds estimated on [ms] (event_stereo: 3000)}";
        ProgramCommandLine cmd(argc, argv, keys, "What estimateClockOffset() finds with the right clock moved.");
        if (cmd.helpShown())
            return 0;
        const double durationUs = cmd.get<double>("duration-ms") * 1000;
        const std::vector<std::string> scenes = commaList(cmd.get<std::string>("scenes"));
        std::vector<double> clocksMs;
        for (const std::string& c : commaList(cmd.get<std::string>("clocks-ms")))
            clocksMs.push_back(std::stod(c));

        std::cout << "| scene | right clock as simulated |";
        for (double c : clocksMs)
            std::printf(" moved %+g ms |", c);
        std::cout << "\n|---|---|";
        for (size_t i = 0; i < clocksMs.size(); i++)
            std::cout << "---|";
        std::cout << "\n";
        for (const std::string& scene : scenes)
        {
            const Ptr<StereoEventSimulator> built = StereoEventSimulator::create(scene);
            const Size size = built->getSensorSize();
            std::printf("| %s | %+.1f ms |", scene.c_str(), built->getSettings().rightClockOffsetUs / 1000);
            for (double c : clocksMs)
            {
                const std::vector<Event> events = opencv_test::simulateChangedScene(
                    scene, [&](SimulatorSettings& s) { s.rightClockOffsetUs += c * 1000; }, durationUs);
                double uncertainty = 0;
                const double estimate = estimateClockOffset(events, size, 0, 40, &uncertainty);
                std::printf(" %s |", cell(estimate, uncertainty).c_str());
                std::fflush(stdout);
            }
            std::printf("\n");
        }
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "clock_offset_sweep: " << errorText(e) << "\n";
        return 1;
    }
}
