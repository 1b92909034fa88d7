// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Helpers of opencv_test_event: reading a capture whole, writing fixture files, a synthetic moving edge, a median.

#ifndef OPENCV_EVENT_TEST_EVENT_HELPERS_HPP
#define OPENCV_EVENT_TEST_EVENT_HELPERS_HPP

#include "opencv2/ts.hpp"
#include "opencv2/event.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace opencv_test {

/** The median of @p v (the upper one of an even count); @p v must not be empty. */
inline double median(std::vector<double> v)
{
    CV_Assert(!v.empty());
    std::nth_element(v.begin(), v.begin() + (std::ptrdiff_t)(v.size() / 2), v.end());
    return v[v.size() / 2];
}

/** Every event @p cap delivers appended to @p all, read in batches of @p batch events (batches that need not
line up with the file's own packets), packet by packet: when read() raises (a file cut off mid-record), @p all
holds every event delivered before the error. */
inline void readAllEventsInto(cv::event::EventCapture& cap, std::vector<cv::event::Event>& all, int batch = 1 << 20)
{
    cap.set(cv::event::EVENT_CAP_PROP_BATCH_EVENTS, batch);
    std::vector<cv::event::Event> packet;
    while (cap.read(packet))
        all.insert(all.end(), packet.begin(), packet.end());
}

/** Every event @p cap delivers (see readAllEventsInto()). */
inline std::vector<cv::event::Event> readAllEvents(cv::event::EventCapture& cap, int batch = 1 << 20)
{
    std::vector<cv::event::Event> all;
    readAllEventsInto(cap, all, batch);
    return all;
}

/** Every trigger event @p cap delivers with its packets (read in batches of @p batch events), in order. */
inline std::vector<cv::event::EventTrigger> readAllTriggers(cv::event::EventCapture& cap, int batch = 1 << 20)
{
    cap.set(cv::event::EVENT_CAP_PROP_BATCH_EVENTS, batch);
    std::vector<cv::event::Event> packet;
    std::vector<cv::event::EventTrigger> triggers, all;
    while (cap.read(packet))
    {
        cap.retrieveTriggers(triggers);
        all.insert(all.end(), triggers.begin(), triggers.end());
    }
    return all;
}

/** What event_camera_py's tests check of a bag: the sum of every event's and trigger's time [us], and the
triggers by (kind, channel). @p cap is read in the packets its properties give. */
struct EventAndTriggerTally
{
    int64 timeSum = 0;
    std::map<std::pair<int, int>, int64> triggers;  // (EventTriggerKind, channel) -> count
};

inline EventAndTriggerTally tallyEventsAndTriggers(cv::event::EventCapture& cap)
{
    EventAndTriggerTally tally;
    std::vector<cv::event::Event> packet;
    std::vector<cv::event::EventTrigger> triggers;
    while (cap.read(packet))
    {
        cap.retrieveTriggers(triggers);
        for (const cv::event::Event& e : packet)
            tally.timeSum += e.t;
        for (const cv::event::EventTrigger& t : triggers)
        {
            tally.timeSum += t.t;
            tally.triggers[std::make_pair((int)t.kind, (int)t.channel)]++;
        }
    }
    return tally;
}

// A new StereoEventMatcher that read what m wrote (FileStorage in memory).
inline cv::Ptr<cv::event::StereoEventMatcher> writtenAndReadBack(const cv::event::StereoEventMatcher& m)
{
    cv::FileStorage out(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    m.write(out);
    cv::Ptr<cv::event::StereoEventMatcher> b = cv::event::StereoEventMatcher::create();
    b->read(cv::FileStorage(out.releaseAndGetString(), cv::FileStorage::READ | cv::FileStorage::MEMORY).root());
    return b;
}

/** Writes @p content to a fresh temporary file with the given suffix and returns its path. */
inline std::string writeTempFile(const std::string& content, const std::string& suffix)
{
    const std::string path = cv::tempfile(suffix.c_str());
    std::ofstream out(path.c_str(), std::ios::binary);
    out.write(content.data(), (std::streamsize)content.size());
    return path;
}

/** A straight edge moving at `speed` px/s in direction `angle`: pixel (x, y) fires when the edge line
reaches it, t = (x cos + y sin) / speed, with Gaussian timing jitter (a fraction of the per-pixel time)
and, at a share of the pixels, an outlier firing at a random time instead. */
inline std::vector<cv::event::Event> movingEdge(cv::Size size, double speed, double angle, double jitter,
                                               double outliers, uint64 seed)
{
    cv::RNG rng(seed);
    const double c = std::cos(angle), s = std::sin(angle);
    const double pixelTime = 1e6 / speed;  // us per pixel
    double tMin = 1e18;
    std::vector<cv::event::Event> ev;
    for (int y = 0; y < size.height; y++)
        for (int x = 0; x < size.width; x++)
        {
            double t = (x * c + y * s) * pixelTime + rng.gaussian(jitter * pixelTime);
            if (rng.uniform(0.0, 1.0) < outliers)
                t += rng.uniform(-3.0, 3.0) * pixelTime;
            tMin = std::min(tMin, t);
            ev.push_back(cv::event::Event((int64)std::llround(t), x, y, cv::event::POLARITY_ON));
        }
    for (cv::event::Event& e : ev)
        e.t -= (int64)std::floor(tMin) - 1000;
    std::stable_sort(ev.begin(), ev.end(),
                     [](const cv::event::Event& a, const cv::event::Event& b) { return a.t < b.t; });
    return ev;
}

}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_EVENT_HELPERS_HPP
