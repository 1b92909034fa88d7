// What event_info reads of a recording or a simulated scene: format, sensor, counts, the pixels and times its
// events span, what the reader rejected or skipped, and with --stats each camera's EventStatistics.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_RECORDING_INFO_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_RECORDING_INFO_HPP

#include <opencv2/event.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace sample_recording_info {

using namespace cv;
using namespace cv::event;

// What event_info found in one recording or simulated scene.
struct Info
{
    std::string file, format, error;
    Size size;
    bool stereo = false;
    int64 events = 0, on = 0, left = 0, first = -1, last = -1;
    int xMin = -1, xMax = -1, yMin = -1, yMax = -1;  // the pixels the events lie on (-1: no events)
    bool statisticsNeedSensor = false;  // --stats asked for, but neither the format nor --sensor gives the size
    bool oneBased = false;              // --one-based (for the advice on events outside the sensor)
    double rejected = 0, backwards = 0, skipped = 0;
    int64 triggers[EVENT_TRIGGER_GENERATOR_RISING + 1] = {};  // trigger events by EventTriggerKind
    std::vector<EventStreamStatistics> cameras;  // --stats: per camera (left, right), or one for mono
};

// --stats: one EventStatistics per camera, created once the sensor size is known.
class CameraStatistics
{
public:
    explicit CameraStatistics(bool enabled) : enabled_(enabled) {}

    void add(const std::vector<Event>& packet, Size size)
    {
        if (!enabled_ || packet.empty() || size.empty())
            return;
        if (stats_.empty())
            for (int c = 0; c < 2; c++)
                stats_.push_back(EventStatistics::create(size));
        split_[0].clear();
        split_[1].clear();
        for (const Event& e : packet)
            split_[e.camera == CAMERA_LEFT ? 0 : 1].push_back(e);
        for (int c = 0; c < 2; c++)
            stats_[c]->update(split_[c]);
    }

    std::vector<EventStreamStatistics> result(bool stereo) const
    {
        std::vector<EventStreamStatistics> out;
        for (size_t c = 0; c < stats_.size() && c < (stereo ? 2u : 1u); c++)
            out.push_back(stats_[c]->getStatistics());
        return out;
    }

private:
    bool enabled_;
    std::vector<Ptr<EventStatistics>> stats_;
    std::vector<Event> split_[2];
};

// Adds a packet (not empty) to the counts and, with --stats, to the statistics.
inline void countPacket(Info& info, const std::vector<Event>& packet, CameraStatistics& statistics)
{
    if (info.xMin < 0)
    {
        info.xMin = info.xMax = packet.front().x;
        info.yMin = info.yMax = packet.front().y;
    }
    for (const Event& e : packet)
    {
        info.on += e.p;
        info.left += e.camera == CAMERA_LEFT;
        info.xMin = std::min(info.xMin, (int)e.x);
        info.xMax = std::max(info.xMax, (int)e.x);
        info.yMin = std::min(info.yMin, (int)e.y);
        info.yMax = std::max(info.yMax, (int)e.y);
    }
    info.events += (int64)packet.size();
    if (info.first < 0)
        info.first = packet.front().t;
    info.last = packet.back().t;
    statistics.add(packet, info.size);
}

inline Info probe(const std::string& path, Size sensor, bool oneBased, int leftValue, bool withStatistics)
{
    Info info;
    CameraStatistics statistics(withStatistics);
    info.file = path;
    EventCapture cap;
    try
    {
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, sensor.width);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, sensor.height);
        cap.set(EVENT_CAP_PROP_TEXT_ONE_BASED, oneBased);
        cap.set(EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, leftValue);
        cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 65536);
        cap.open(path);
        info.format = cap.getBackendName();
        info.size = cap.getSensorSize();
        info.stereo = cap.get(EVENT_CAP_PROP_STEREO) != 0;
        info.statisticsNeedSensor = withStatistics && info.size.empty();
        info.oneBased = oneBased;
        std::vector<Event> packet;
        std::vector<EventTrigger> triggers;
        while (cap.read(packet))
        {
            countPacket(info, packet, statistics);
            cap.retrieveTriggers(triggers);
            for (const EventTrigger& t : triggers)
                info.triggers[t.kind]++;
        }
    }
    catch (const cv::Exception& e)
    {
        info.error = e.err;  // after the events read before it (a file cut off mid-record: the user's data)
    }
    if (!info.format.empty())
    {
        info.cameras = statistics.result(info.stereo);
        info.rejected = cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE);
        info.backwards = cap.get(EVENT_CAP_PROP_TIME_BACKWARDS);
        info.skipped = cap.get(EVENT_CAP_PROP_SKIPPED);
    }
    return info;
}

// A simulator scene on a sensor model, generated in memory in 10 ms steps (--scene).
inline Info probeScene(const std::string& scene, int sensorModel, double durationMs, bool withStatistics)
{
    Info info;
    info.file = "scene " + scene + (sensorModel == SENSOR_DAVIS240 ? "" : " on a " + getSensorModelName(sensorModel))
        + " (" + std::to_string((int)durationMs) + " ms)";
    CameraStatistics statistics(withStatistics);
    try
    {
        Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene, sensorModel);
        info.format = "simulated";
        info.size = sim->getSensorSize();
        info.stereo = true;
        std::vector<Event> packet;
        Mat truth;
        for (double t = 10000; t < durationMs * 1000 + 10000; t += 10000)
        {
            sim->generate(std::min(t, durationMs * 1000), packet, truth);
            if (packet.empty())
                continue;
            countPacket(info, packet, statistics);
        }
        info.cameras = statistics.result(true);
    }
    catch (const cv::Exception& e)
    {
        info.error = e.err;
    }
    return info;
}

}  // namespace sample_recording_info

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_RECORDING_INFO_HPP
