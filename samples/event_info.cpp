// event_info: what is in an event recording (like ffprobe for videos).
//
//   event_info [--json] [--stats] [--sensor=WxH|NAME] [--one-based] [--left-camera-value=0|1] FILE...
//   event_info --stats --scene=NAME[,NAME...] [--sensor=DVS128|DAVIS240|DAVIS346] [--duration-ms=MS]   (the simulator's scenes)
//   event_info --devices      (the event cameras connected: what EventCapture::open("davis:...") takes)
//
// Per file: detected format, sensor size, event count (ON / OFF, and left / right for stereo files), trigger
// events by kind, first and last timestamp, duration, and the events the reader rejected (outside the sensor),
// found going back in time, or could not place in time. Exit status 1 when any file could not be read (the
// error names it).
// --stats adds, per camera, what the stream looks like (EventStatistics: event rate, ON share, events per
// pixel per edge crossing, intervals at a pixel, isolated events, pixels active in 10 ms) and ends with one
// Markdown table of every file and scene side by side: how a simulated scene compares with real recordings
// (for stereo ones also the right camera's events against the left's: pairs differ in sensitivity).

#include <opencv2/event.hpp>

#include "command_line.hpp"
#include "sample_recording_info.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

using namespace cv;
using namespace cv::event;
using namespace sample_recording_info;

namespace {

std::string jsonString(const std::string& s)
{
    std::string out = "\"";
    for (char c : s)
    {
        if (c == '"' || c == '\\')
            out += '\\';
        if ((unsigned char)c < 0x20)
        {
            char buf[8];
            std::snprintf(buf, sizeof(buf), "\\u%04x", c);
            out += buf;
            continue;
        }
        out += c;
    }
    return out + "\"";
}

void printJson(const Info& i, bool last)
{
    std::cout << "  {\"file\": " << jsonString(i.file);
    if (!i.error.empty())
        std::cout << ", \"error\": " << jsonString(i.error);
    if (!i.format.empty())  // opened: what was read, also before an error
        std::cout << ", \"format\": " << jsonString(i.format) << ", \"width\": " << i.size.width
                  << ", \"height\": " << i.size.height << ", \"stereo\": " << (i.stereo ? "true" : "false")
                  << ", \"events\": " << i.events << ", \"on\": " << i.on << ", \"off\": " << i.events - i.on
                  << ", \"left\": " << i.left << ", \"right\": " << i.events - i.left
                  << ", \"first_us\": " << i.first << ", \"last_us\": " << i.last
                  << ", \"duration_us\": " << (i.events ? i.last - i.first : 0)
                  << ", \"rejected_outside\": " << (int64)i.rejected << ", \"time_backwards\": " << (int64)i.backwards
                  << ", \"skipped\": " << (int64)i.skipped << ", \"x_min\": " << i.xMin << ", \"x_max\": " << i.xMax
                  << ", \"y_min\": " << i.yMin << ", \"y_max\": " << i.yMax << ", \"triggers\": {";
    for (int k = 0; !i.format.empty() && k <= EVENT_TRIGGER_GENERATOR_RISING; k++)
    {
        std::string name = getTriggerKindName(k);
        std::replace(name.begin(), name.end(), ' ', '_');
        std::cout << (k ? ", " : "") << "\"" << name << "\": " << i.triggers[k]
                  << (k == EVENT_TRIGGER_GENERATOR_RISING ? "}" : "");
    }
    if (!i.cameras.empty())
    {
        std::cout << ", \"statistics\": [";
        for (size_t c = 0; c < i.cameras.size(); c++)
        {
            const EventStreamStatistics& st = i.cameras[c];
            std::cout << (c ? ", " : "") << "{\"camera\": " << c << ", \"event_rate\": " << st.eventRate
                      << ", \"on_share\": " << st.onShare << ", \"events_per_crossing\": " << st.eventsPerCrossing
                      << ", \"interval_p10_us\": " << st.intervalP10Us << ", \"interval_median_us\": "
                      << st.intervalMedianUs << ", \"interval_p90_us\": " << st.intervalP90Us
                      << ", \"isolated_share\": " << st.isolatedShare << ", \"active_pixel_share\": "
                      << st.activePixelShare << "}";
        }
        std::cout << "]";
    }
    std::cout << "}" << (last ? "" : ",") << "\n";
}

// What EVENT_CAP_PROP_SKIPPED counts for this back-end: events the file holds that cannot be delivered.
std::string skippedMeaning(const std::string& format)
{
    if (format == "AEDAT3")
        return "marked invalid by their recorder";
    if (format == "DAVIS")
        return "sent before the clock reset";
    if (format.compare(0, 13, "PROPHESEE_EVT") == 0 || format == "ROSBAG1" || format == "ROSBAG2")
        return "without time base";
    return "not deliverable";
}

void printText(const Info& i)
{
    std::cout << i.file << "\n";
    if (!i.error.empty() && i.format.empty())  // not opened
    {
        std::cout << "  error:     " << i.error << "\n";
        return;
    }
    std::cout << "  format:    " << i.format << (i.stereo ? " (stereo)" : "") << "\n";
    if (i.size.empty())
        std::cout << "  sensor:    not recorded in this file (give the tools --sensor=WxH)\n";
    else
        std::cout << "  sensor:    " << i.size.width << " x " << i.size.height << "\n";
    std::cout << "  events:    " << i.events << " (ON " << i.on << ", OFF " << i.events - i.on << ")\n";
    if (i.events)
        std::cout << "  pixels:    x " << i.xMin << ".." << i.xMax << ", y " << i.yMin << ".." << i.yMax << "\n";
    if (i.stereo)
        std::cout << "  cameras:   left " << i.left << ", right " << i.events - i.left << "\n";
    int64 triggers = 0;
    std::string kinds;
    for (int k = 0; k <= EVENT_TRIGGER_GENERATOR_RISING; k++)
        if (i.triggers[k] > 0)
        {
            kinds += (triggers ? ", " : " (") + getTriggerKindName(k) + " " + std::to_string(i.triggers[k]);
            triggers += i.triggers[k];
        }
    std::cout << "  triggers:  " << triggers << (triggers ? kinds + ")" : std::string()) << "\n";
    std::cout << "  time:      " << i.first << " .. " << i.last << " us, duration "
              << (i.events ? (i.last - i.first) / 1e6 : 0.0) << " s\n"
              << "  rejected:  " << (int64)i.rejected << " outside the sensor, " << (int64)i.backwards
              << " going back in time, " << (int64)i.skipped << " " << skippedMeaning(i.format) << "\n";
    if (i.rejected > 0)
        std::cout << "             (outside the sensor: "
                  << outsideEventsAdvice(i.format == "TEXT", i.oneBased, i.events > 0 && (i.xMin == 0 || i.yMin == 0))
                  << ")\n";
    if (i.statisticsNeedSensor)
        std::cout << "  --stats:   needs the sensor size, which this file does not record: give --sensor=WxH"
                  << (i.events ? cv::format(" (at least %d x %d for these events)", i.xMax + 1, i.yMax + 1) : std::string())
                  << "\n";
    for (size_t c = 0; c < i.cameras.size(); c++)
    {
        const EventStreamStatistics& st = i.cameras[c];
        std::cout << "  " << (i.stereo ? (c == 0 ? "left:      " : "right:     ") : "stream:    ") << st.eventRate / 1e3
                  << " kev/s, ON " << 100 * st.onShare << " %, " << st.eventsPerCrossing
                  << " events per pixel per edge crossing, interval at a pixel " << st.intervalP10Us / 1e3 << " / "
                  << st.intervalMedianUs / 1e3 << " / " << st.intervalP90Us / 1e3 << " ms (p10 / median / p90), "
                  << 100 * st.isolatedShare << " % isolated, " << 100 * st.activePixelShare
                  << " % of pixels active in 10 ms\n";
    }
    if (!i.error.empty())  // read up to there: the figures above are what came before it
        std::cout << "  error:     " << i.error << "\n";
}

// --stats: every file's and scene's cameras side by side.
void printStatisticsTable(const std::vector<Info>& infos)
{
    // "events / left's": a stereo pair's cameras differ in sensitivity, and so in how many events they fire.
    std::cout << "\n| recording | camera | kev/s | events / left's | ON share | events per crossing "
                 "| interval p10 / median / p90 [ms] | isolated | pixels active in 10 ms |\n"
                 "|---|---|---|---|---|---|---|---|---|\n";
    for (const Info& i : infos)
        for (size_t c = 0; c < i.cameras.size(); c++)
        {
            const EventStreamStatistics& st = i.cameras[c];
            char ratio[32] = "-";
            if (i.stereo && i.cameras[0].events > 0)
                std::snprintf(ratio, sizeof(ratio), "%.2f", st.events / i.cameras[0].events);
            std::printf("| %s | %s | %.1f | %s | %.2f | %.2f | %.3f / %.1f / %.0f | %.1f %% | %.2f %% |\n", i.file.c_str(),
                        i.stereo ? (c == 0 ? "left" : "right") : "-", st.eventRate / 1e3, ratio, st.onShare,
                        st.eventsPerCrossing, st.intervalP10Us / 1e3, st.intervalMedianUs / 1e3,
                        st.intervalP90Us / 1e3, 100 * st.isolatedShare, 100 * st.activePixelShare);
        }
    std::fflush(stdout);
}

int listDevices()
{
    const std::vector<EventDeviceInfo> devices = listEventDevices();
    if (devices.empty())
        std::cout << "no event camera connected (DAVIS over USB; a camera that is plugged in but not listed needs a udev rule "
                     "granting access to USB vendor 152a, or root)\n";
    for (const EventDeviceInfo& d : devices)
    {
        std::cout << d.source << "\n  model:     " << d.model << ", serial " << d.serial << ", " << d.usbLocation
                  << "\n  firmware:  " << d.firmwareVersion;
        if (d.error.empty())
            std::cout << ", logic " << d.logicVersion << "\n  sensor:    " << d.sensorSize.width << " x "
                      << d.sensorSize.height << "\n  clock:     " << (d.master ? "master" : "slave (sync input)") << "\n";
        else
            std::cout << "\n  error:     " << d.error << "\n";
    }
    return 0;
}

}  // namespace

const char* const keys =
    "{help h            | false | print this message}"
    "{@files            |       | one or more recordings}"
    "{json              | false | print JSON instead of text}"
    "{stats             | false | add what each camera's stream looks like, and a table of all side by side}"
    "{scene             |       | simulator scenes to describe, comma separated (e.g. two_planes,cluttered)}"
    "{duration-ms       | 1000  | length of each simulated scene [ms]}"
    "{devices           | false | list the event cameras connected (what EventCapture::open(\"davis:N\") takes)}"
    "{sensor            |       | sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none; the model the scenes are simulated on (default DAVIS240)}"
    "{one-based         | false | text recordings count pixels from 1}"
    "{left-camera-value | 0     | the camera column's value that means left, in text recordings}";

int main(int argc, char** argv)
{
    bool json = false, oneBased = false, withStatistics = false;
    int leftValue = 0, sceneModel = SENSOR_DAVIS240;
    double durationMs = 0;
    Size sensor;
    std::vector<std::string> files, scenes;
    try
    {
        ProgramCommandLine cmd(argc, argv, keys,
                              "What is in an event recording: format, sensor, events, trigger events, time span, "
                              "rejected events.",
                              true);
        if (cmd.helpShown())
            return 0;
        if (cmd.has("devices"))
            return listDevices();
        json = cmd.has("json");
        withStatistics = cmd.has("stats");
        oneBased = cmd.has("one-based");
        leftValue = cmd.get<int>("left-camera-value");
        durationMs = cmd.get<double>("duration-ms");
        if (cmd.has("sensor"))
            sensor = parseSensorSize(cmd.get<std::string>("sensor"));
        scenes = commaList(cmd.get<std::string>("scene"));
        if (!scenes.empty() && cmd.has("sensor"))
            sceneModel = sceneSensorModel(cmd.get<std::string>("sensor"));
        files = cmd.positionals();
        if (files.empty() && scenes.empty())
            throw std::runtime_error("no recording given: event_info [options] FILE... (--help lists the options)");
        if (!(durationMs > 0))
            throw std::runtime_error("--duration-ms must be > 0");
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_info: " << errorText(e) << "\n";
        return 2;
    }
    bool failed = false;
    std::vector<Info> infos;
    if (json)
        std::cout << "[\n";
    const size_t total = files.size() + scenes.size();
    for (size_t k = 0; k < total; k++)
    {
        const Info info = k < files.size() ? probe(files[k], sensor, oneBased, leftValue, withStatistics)
                                           : probeScene(scenes[k - files.size()], sceneModel, durationMs, withStatistics);
        failed |= !info.error.empty();
        if (json)
            printJson(info, k + 1 == total);
        else
            printText(info);
        std::cout.flush();
        infos.push_back(info);
    }
    if (json)
        std::cout << "]\n";
    else if (withStatistics && std::any_of(infos.begin(), infos.end(), [](const Info& i) { return !i.cameras.empty(); }))
        printStatisticsTable(infos);
    return failed ? 1 : 0;
}
