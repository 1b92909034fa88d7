// event_info: what is in an event recording (like ffprobe for videos).
//
//   event_info [--json] [--sensor=WxH|NAME] [--one-based] [--left-camera-value=0|1] FILE...
//   event_info --devices      (the event cameras connected: what EventCapture::open("davis:...") takes)
//
// Per file: detected format, sensor size, event count (ON / OFF, and left / right for stereo files), first
// and last timestamp, duration, and the events the reader rejected (outside the sensor), found going back in
// time, or could not place in time. Exit status 1 when any file could not be read (the error names it).

#include <opencv2/event.hpp>

#include "sample_command_line.hpp"

#include <cstdio>
#include <iostream>
#include <sstream>

using namespace cv;
using namespace cv::event;

namespace {

struct Info
{
    std::string file, format, error;
    Size size;
    bool stereo = false;
    int64 events = 0, on = 0, left = 0, first = -1, last = -1;
    double rejected = 0, backwards = 0, skipped = 0;
};

Info probe(const std::string& path, Size sensor, bool oneBased, int leftValue)
{
    Info info;
    info.file = path;
    try
    {
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, sensor.width);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, sensor.height);
        cap.set(EVENT_CAP_PROP_TEXT_ONE_BASED, oneBased);
        cap.set(EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, leftValue);
        cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 65536);
        cap.open(path);
        info.format = cap.getBackendName();
        info.size = cap.getSensorSize();
        info.stereo = cap.get(EVENT_CAP_PROP_STEREO) != 0;
        std::vector<Event> packet;
        while (cap.read(packet))
        {
            for (const Event& e : packet)
            {
                info.on += e.p;
                info.left += e.camera == CAMERA_LEFT;
            }
            info.events += (int64)packet.size();
            if (info.first < 0)
                info.first = packet.front().t;
            info.last = packet.back().t;
        }
        info.rejected = cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE);
        info.backwards = cap.get(EVENT_CAP_PROP_TIME_BACKWARDS);
        info.skipped = cap.get(EVENT_CAP_PROP_SKIPPED);
    }
    catch (const cv::Exception& e)
    {
        info.error = e.err;
    }
    return info;
}

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
    else
        std::cout << ", \"format\": " << jsonString(i.format) << ", \"width\": " << i.size.width
                  << ", \"height\": " << i.size.height << ", \"stereo\": " << (i.stereo ? "true" : "false")
                  << ", \"events\": " << i.events << ", \"on\": " << i.on << ", \"off\": " << i.events - i.on
                  << ", \"left\": " << i.left << ", \"right\": " << i.events - i.left
                  << ", \"first_us\": " << i.first << ", \"last_us\": " << i.last
                  << ", \"duration_us\": " << (i.events ? i.last - i.first : 0)
                  << ", \"rejected_outside\": " << (int64)i.rejected << ", \"time_backwards\": " << (int64)i.backwards
                  << ", \"skipped\": " << (int64)i.skipped;
    std::cout << "}" << (last ? "" : ",") << "\n";
}

void printText(const Info& i)
{
    std::cout << i.file << "\n";
    if (!i.error.empty())
    {
        std::cout << "  error:     " << i.error << "\n";
        return;
    }
    std::cout << "  format:    " << i.format << (i.stereo ? " (stereo)" : "") << "\n"
              << "  sensor:    " << i.size.width << " x " << i.size.height << "\n"
              << "  events:    " << i.events << " (ON " << i.on << ", OFF " << i.events - i.on << ")\n";
    if (i.stereo)
        std::cout << "  cameras:   left " << i.left << ", right " << i.events - i.left << "\n";
    std::cout << "  time:      " << i.first << " .. " << i.last << " us, duration "
              << (i.events ? (i.last - i.first) / 1e6 : 0.0) << " s\n"
              << "  rejected:  " << (int64)i.rejected << " outside the sensor, " << (int64)i.backwards
              << " going back in time, " << (int64)i.skipped << " without time base\n";
}

int listDevices()
{
    const std::vector<EventDeviceInfo> devices = listEventDevices();
    if (devices.empty())
        std::cout << "no event camera connected (DAVIS over USB; see doc/live_davis.md for permissions)\n";
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
    "{devices           | false | list the event cameras connected (what EventCapture::open(\"davis:N\") takes)}"
    "{sensor            |       | sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none}"
    "{one-based         | false | text recordings count pixels from 1}"
    "{left-camera-value | 0     | the camera column's value that means left, in text recordings}";

int main(int argc, char** argv)
{
    bool json = false, oneBased = false;
    int leftValue = 0;
    Size sensor;
    std::vector<std::string> files;
    try
    {
        SampleCommandLine cmd(argc, argv, keys,
                              "What is in an event recording: format, sensor, events, time span, rejected events.",
                              true);
        if (cmd.helpShown())
            return 0;
        if (cmd.has("devices"))
            return listDevices();
        json = cmd.has("json");
        oneBased = cmd.has("one-based");
        leftValue = cmd.get<int>("left-camera-value");
        if (cmd.has("sensor"))
            sensor = parseSensorSize(cmd.get<std::string>("sensor"));
        files = cmd.positionals();
        if (files.empty())
            throw std::runtime_error("no recording given: event_info [options] FILE... (--help lists the options)");
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "event_info: " << e.err << "\n";
        return 2;
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_info: " << e.what() << "\n";
        return 2;
    }
    bool failed = false;
    if (json)
        std::cout << "[\n";
    for (size_t k = 0; k < files.size(); k++)
    {
        const Info info = probe(files[k], sensor, oneBased, leftValue);
        failed |= !info.error.empty();
        if (json)
            printJson(info, k + 1 == files.size());
        else
            printText(info);
    }
    if (json)
        std::cout << "]\n";
    return failed ? 1 : 0;
}
