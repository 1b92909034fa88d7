// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Overload on the live path: a stereo DAVIS346 pair sends a 100 ms burst at 5 Mev/s (both cameras) through
// the tests' fake USB transport, paced at the burst's data rate, into EventCapture and on to COUPLED on one
// thread, which runs far below that rate. What happens is printed: events delivered and dropped (a full
// queue drops whole transfers and counts them), the latency from the moment the camera sent an event to
// the moment the matcher is done with it, and the resident memory. Only the accounting is asserted: every
// event sent is delivered or counted as dropped.

#include "perf_precomp.hpp"
#include "../test/fake_davis_usb.hpp"

#include <fstream>

namespace opencv_test { namespace {

using namespace fake_davis_usb;

// Resident memory of this process [MiB]; -1 where /proc is not there.
double residentMiB()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.compare(0, 6, "VmRSS:") == 0)
            return std::atof(line.c_str() + 6) / 1024.0;
    return -1;
}

// The burst, per camera: 500 ms of boxes_fast on a DAVIS346 (realistic noise model) played 25 times faster,
// five times over: 100 ms, about 250,000 events per camera.
struct Burst
{
    std::vector<Event> camera[2];
};

const Burst& davis346Burst()
{
    static Burst burst;
    if (burst.camera[0].empty())
    {
        Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("boxes_fast", SENSOR_DAVIS346);
        Mat ev, gt;
        sim->generate(500000, ev, gt);
        const std::vector<Event> scene = toEventVector(ev);
        for (int copy = 0; copy < 5; copy++)
            for (const Event& e : scene)
                burst.camera[e.camera].push_back(Event(copy * 20000 + e.t / 25, e.x, e.y, e.p, CAMERA_LEFT));
    }
    return burst;
}

typedef TestBaseWithParam<int> Event_LiveBurst;

PERF_TEST_P(Event_LiveBurst, davis346_stereo_5mevs_100ms_into_coupled, testing::Values(512, 32))
{
    const int queueCapacity = GetParam();
    const Burst& burst = davis346Burst();
    const size_t sent = burst.camera[0].size() + burst.camera[1].size();
    const double before = residentMiB();
    declare.iterations(1);
    size_t delivered = 0;
    double dropped = 0, peakMiB = before;
    std::vector<double> latencyMs;
    double seconds = 0;
    while (next())
    {
        FakeUsb usb;
        Ptr<FakeCamera> left = usb.add(5, 346, 260, false, false);  // slave
        Ptr<FakeCamera> right = usb.add(5, 346, 260, false, true);  // master
        right->slave = left.get();
        // Each camera sends its burst's words in 100 ms, then its clock running on for 100 ms more (a little
        // later, at the same rate).
        const double burstSeconds = 0.1;
        for (int c = 0; c < 2; c++)
        {
            FakeCamera& camera = c == CAMERA_LEFT ? *left : *right;
            camera.afterReset = davis_words::encodeEvents(burst.camera[c]);
            camera.bytesPerSecond = (double)camera.afterReset.size() / burstSeconds;
            davis_words::appendClockWords(camera.afterReset, burst.camera[c].back().t + 100000);
        }

        EventCapture cap;
        cap.set(EVENT_CAP_PROP_QUEUE_CAPACITY, queueCapacity);
        ASSERT_TRUE(cap.openStereo("davis:0", "davis:1"));
        cap.set(EVENT_CAP_PROP_WINDOW_US, 10000);
        Ptr<StereoEventMatcher> matcher = StereoEventMatcher::create(getSensorSize(SENSOR_DAVIS346), STEREO_COUPLED);
        matcher->setNumThreads(1);
        std::vector<Event> packet;
        Mat disparity, lifetime;
        delivered = 0;
        latencyMs.clear();
        startTimer();
        const auto start = std::chrono::steady_clock::now();
        while (delivered + (size_t)cap.get(EVENT_CAP_PROP_DROPPED_EVENTS) < sent &&
               std::chrono::steady_clock::now() - start < std::chrono::seconds(60) && cap.read(packet))
        {
            matcher->process(packet, disparity, lifetime);
            const auto done = std::chrono::steady_clock::now();
            delivered += packet.size();
            // The camera sent an event about its timestamp after the pacing started (the bytes go out at an
            // even rate over the burst).
            for (size_t i = 0; i < packet.size(); i += 64)
            {
                const auto sentAt = right->paceStart + std::chrono::microseconds(packet[i].t);
                latencyMs.push_back(std::chrono::duration<double, std::milli>(done - sentAt).count());
            }
            peakMiB = std::max(peakMiB, residentMiB());
        }
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stopTimer();
        dropped = cap.get(EVENT_CAP_PROP_DROPPED_EVENTS);
        EXPECT_EQ(0, cap.get(EVENT_CAP_PROP_DROPPED_TRANSFERS));
    }
    EXPECT_EQ(sent, delivered + (size_t)dropped) << "every event is delivered or counted as dropped";
    std::sort(latencyMs.begin(), latencyMs.end());
    auto quantile = [&](double q) { return latencyMs.empty() ? 0.0 : latencyMs[(size_t)(q * (double)(latencyMs.size() - 1))]; };
    printf("queue %d transfers: %d events sent in 100 ms (%.1f Mev/s), %d delivered, %d dropped (%.1f %%); "
           "matcher done %.2f s after the burst began (%.2f Mev/s delivered); latency p50 %.0f ms, p99 %.0f ms, "
           "max %.0f ms; resident memory %.0f MiB before, %.0f MiB at most\n",
           queueCapacity, (int)sent, (double)sent / 0.1 * 1e-6, (int)delivered, (int)dropped,
           100.0 * dropped / (double)sent, seconds, (double)delivered / seconds * 1e-6, quantile(0.5), quantile(0.99),
           quantile(1.0), before, peakMiB);
    SANITY_CHECK_NOTHING();
}

}}  // namespace
