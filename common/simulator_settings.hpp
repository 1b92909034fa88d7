// --sensor-set=NAME=VALUE,... on the command line: the numeric cv::event::SimulatorSettings fields by name
// (jitterUs, rightScale, extraLatencyUs.rightOn, seed, ...), for the tools that simulate a scene.

#ifndef OPENCV_EVENT_COMMON_SIMULATOR_SETTINGS_HPP
#define OPENCV_EVENT_COMMON_SIMULATOR_SETTINGS_HPP

#include <opencv2/event.hpp>

#include "command_line.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

/** Sets the field @p name of @p s to @p value; throws std::runtime_error naming the fields when there is no such
    field. */
inline void applySimulatorSetting(cv::event::SimulatorSettings& s, const std::string& name, double value)
{
    const std::pair<const char*, double*> fields[] = {
        { "thresholdOn", &s.thresholdOn }, { "thresholdOff", &s.thresholdOff }, { "thresholdSigma", &s.thresholdSigma }, { "thresholdNoise", &s.thresholdNoise }, { "blurSigmaPx", &s.blurSigmaPx },
        { "rightThresholdScale", &s.rightThresholdScale }, { "refractoryUs", &s.refractoryUs },
        { "noiseRateHz", &s.noiseRateHz }, { "latencyUs", &s.latencyUs }, { "latencySigmaUs", &s.latencySigmaUs },
        { "jitterUs", &s.jitterUs }, { "hotPixelShare", &s.hotPixelShare }, { "hotPixelRateHz", &s.hotPixelRateHz },
        { "leakRateHz", &s.leakRateHz }, { "rightRowOffset", &s.rightRowOffset }, { "rightRollRad", &s.rightRollRad },
        { "rightScale", &s.rightScale }, { "rightColumnOffset", &s.rightColumnOffset },
        { "maxPixelStep", &s.maxPixelStep }, { "flickerFrequencyHz", &s.flickerFrequencyHz },
        { "rightClockOffsetUs", &s.rightClockOffsetUs }, { "rightClockDriftPpm", &s.rightClockDriftPpm },
        { "extraLatencyUs.leftOn", &s.extraLatencyUs[0] }, { "extraLatencyUs.leftOff", &s.extraLatencyUs[1] },
        { "extraLatencyUs.rightOn", &s.extraLatencyUs[2] }, { "extraLatencyUs.rightOff", &s.extraLatencyUs[3] }
    };
    for (const auto& f : fields)
        if (name == f.first)
        {
            *f.second = value;
            return;
        }
    if (name == "seed")
    {
        s.seed = (int)value;
        return;
    }
    std::string known;
    for (const auto& f : fields)
        known += std::string(known.empty() ? "" : ", ") + f.first;
    throw std::runtime_error("--sensor-set: no simulator setting \"" + name + "\" (" + known + ", seed)");
}

/** Applies "name=value,name=value" (the --sensor-set option) to @p s; throws std::runtime_error naming an item
    whose value is not a number. */
inline void applySimulatorSettings(cv::event::SimulatorSettings& s, const std::string& list)
{
    for (const std::pair<std::string, std::string>& item : parseNameValueList("--sensor-set", list))
    {
        char* end = nullptr;
        const double value = std::strtod(item.second.c_str(), &end);
        if (item.second.empty() || *end != '\0')
            throw std::runtime_error("--sensor-set: " + item.first + "=" + item.second + ": the value is not a number");
        applySimulatorSetting(s, item.first, value);
    }
}

/** The simulator of @p scene on @p sensorModel with the --sensor-set list @p list applied (as built when it is
    empty); throws as applySimulatorSettings does. */
inline cv::Ptr<cv::event::StereoEventSimulator> simulatorWithSettings(const std::string& scene, int sensorModel,
                                                                     const std::string& list)
{
    cv::Ptr<cv::event::StereoEventSimulator> sim = cv::event::StereoEventSimulator::create(scene, sensorModel);
    if (list.empty())
        return sim;
    cv::event::SimulatorSettings s = sim->getSettings();
    applySimulatorSettings(s, list);
    return cv::event::StereoEventSimulator::create(sim->getPlanes(), s);
}

#endif  // OPENCV_EVENT_COMMON_SIMULATOR_SETTINGS_HPP
