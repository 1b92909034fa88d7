// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// A vertical ON edge sweeping right at one column per @p columnUs: every pixel of column c fires
// @p eventsPerPixel events, 100 us apart, from c * columnUs on; in time order, rows ascending on ties.
std::vector<Event> sweepingEdge(Size size, int64 columnUs, int eventsPerPixel)
{
    std::vector<Event> ev;
    for (int c = 0; c < size.width; c++)
        for (int j = 0; j < eventsPerPixel; j++)
            for (int y = 0; y < size.height; y++)
                ev.push_back(Event(c * columnUs + j * 100, c, y, POLARITY_ON));
    return ev;
}

TEST(Event_Statistics, sweeping_edge_gives_its_closed_form_figures)
{
    const Size size(20, 10);
    // 200 px/s: a column every 5 ms, so every event but the very first has a neighbour within 10 ms.
    {
        Ptr<EventStatistics> stats = EventStatistics::create(size);
        const std::vector<Event> ev = sweepingEdge(size, 5000, 3);
        stats->update(std::vector<Event>(ev.begin(), ev.begin() + 250));  // packets may cut anywhere
        stats->update(std::vector<Event>(ev.begin() + 250, ev.end()));
        const EventStreamStatistics s = stats->getStatistics();
        EXPECT_EQ(600.0, s.events);
        EXPECT_EQ(19 * 5000.0 + 200, s.durationUs);
        EXPECT_NEAR(600 / 0.0952, s.eventRate, 1e-6);
        EXPECT_EQ(1.0, s.onShare);
        EXPECT_DOUBLE_EQ(3.0, s.eventsPerCrossing);
        // Every interval is 100 us; the 2 % bins give it within 1 %.
        EXPECT_NEAR(100.0, s.intervalMedianUs, 1.0);
        EXPECT_NEAR(100.0, s.intervalP10Us, 1.0);
        EXPECT_NEAR(100.0, s.intervalP90Us, 1.0);
        EXPECT_DOUBLE_EQ(1.0 / 600, s.isolatedShare);
        // Windows of 10 ms hold two columns each: 20 of 200 pixels.
        EXPECT_DOUBLE_EQ(0.1, s.activePixelShare);
    }
    // 50 px/s: a column every 20 ms, longer than the isolation window: the first event of each column
    // (row 0, its first event) has no neighbour within 10 ms before it.
    {
        Ptr<EventStatistics> stats = EventStatistics::create(size);
        stats->update(sweepingEdge(size, 20000, 3));
        const EventStreamStatistics s = stats->getStatistics();
        EXPECT_DOUBLE_EQ(20.0 / 600, s.isolatedShare);
        EXPECT_DOUBLE_EQ(3.0, s.eventsPerCrossing);
        // Column c lies in window 2c: 20 of the 39 windows (0 .. 38) hold one column of 10 pixels.
        EXPECT_DOUBLE_EQ(20.0 * 10 / (39.0 * 200), s.activePixelShare);
    }
    // A crossing gap shorter than the 100 us between a pixel's events splits every crossing into single events.
    {
        Ptr<EventStatistics> stats = EventStatistics::create(size);
        stats->setCrossingGap(99);
        stats->update(sweepingEdge(size, 5000, 3));
        EXPECT_DOUBLE_EQ(1.0, stats->getStatistics().eventsPerCrossing);
    }
}

TEST(Event_Statistics, background_activity_matches_poisson_closed_forms)
{
    // Poisson background activity at r per pixel, random polarity: the superposition of all pixels is one
    // Poisson process at area * r with uniformly drawn pixels. The recording is 300 median intervals long,
    // so that intervals cut off by its end do not bias the percentiles.
    const Size size(32, 32);
    const double r = 10.0, durationS = 20.0, isolationS = 0.01;
    RNG rng(7);
    std::vector<Event> ev;
    double t = 0;
    while (true)
    {
        t += -std::log(1.0 - rng.uniform(0.0, 1.0)) / (size.area() * r);
        if (t >= durationS)
            break;
        ev.push_back(Event((int64)std::llround(t * 1e6), rng.uniform(0, size.width), rng.uniform(0, size.height),
                           rng.uniform(0, 2)));
    }
    Ptr<EventStatistics> stats = EventStatistics::create(size);
    stats->update(ev);
    const EventStreamStatistics s = stats->getStatistics();

    EXPECT_NEAR(size.area() * r, s.eventRate, 0.02 * size.area() * r);
    EXPECT_NEAR(0.5, s.onShare, 0.01);
    // Per pixel the intervals are exponential with rate r: median ln 2 / r, 10th and 90th percentiles
    // -ln(0.9) / r and ln(10) / r.
    EXPECT_NEAR(std::log(2.0) / r * 1e6, s.intervalMedianUs, 0.03 * std::log(2.0) / r * 1e6);
    EXPECT_NEAR(-std::log(0.9) / r * 1e6, s.intervalP10Us, 0.04 * -std::log(0.9) / r * 1e6);
    EXPECT_NEAR(std::log(10.0) / r * 1e6, s.intervalP90Us, 0.03 * std::log(10.0) / r * 1e6);
    // Isolated: none of a pixel's n neighbours (8 inside, 5 on an edge, 3 at a corner) fired in the last
    // 10 ms, probability exp(-n r T), averaged over the pixels.
    double expectedIsolated = 0;
    for (int y = 0; y < size.height; y++)
        for (int x = 0; x < size.width; x++)
        {
            const int nx = (x > 0) + (x < size.width - 1) + 1, ny = (y > 0) + (y < size.height - 1) + 1;
            expectedIsolated += std::exp(-(nx * ny - 1) * r * isolationS);
        }
    expectedIsolated /= size.area();
    EXPECT_NEAR(expectedIsolated, s.isolatedShare, 0.01);
    // A run continues only with the same polarity (1/2) within the 5 ms gap (1 - exp(-r * 5 ms)).
    const double continued = 0.5 * (1 - std::exp(-r * 0.005));
    EXPECT_NEAR(1.0 / (1.0 - continued), s.eventsPerCrossing, 0.002);
    // A pixel fires in a 10 ms window with probability 1 - exp(-r * 10 ms).
    EXPECT_NEAR(1 - std::exp(-r * 0.01), s.activePixelShare, 0.03 * (1 - std::exp(-r * 0.01)));
}

TEST(Event_Statistics, bad_events_are_refused_by_name_and_leave_the_figures)
{
    Ptr<EventStatistics> stats = EventStatistics::create(Size(8, 6));
    stats->update(std::vector<Event>{ Event(100, 1, 1, 1), Event(200, 2, 1, 0) });
    try
    {
        stats->update(std::vector<Event>{ Event(300, 1, 1, 1), Event(400, 8, 1, 1) });
        FAIL() << "an event outside the sensor was accepted";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_EQ(Error::StsOutOfRange, e.code);
        EXPECT_NE(std::string::npos, e.err.find("event #1 at (x=8, y=1)")) << e.err;
    }
    try
    {
        stats->update(std::vector<Event>{ Event(150, 1, 1, 1) });
        FAIL() << "an event going back in time was accepted";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_EQ(Error::StsBadArg, e.code);
        EXPECT_NE(std::string::npos, e.err.find("goes back in time")) << e.err;
    }
    const EventStreamStatistics s = stats->getStatistics();
    EXPECT_EQ(2.0, s.events);
    EXPECT_EQ(100.0, s.durationUs);
}

TEST(Event_Statistics, windows_round_trip_through_file_storage)
{
    Ptr<EventStatistics> a = EventStatistics::create(Size(8, 6));
    a->setCrossingGap(2500);
    a->setIsolationWindow(3000);
    a->setActivityWindow(33000);
    FileStorage fs(".yml", FileStorage::WRITE | FileStorage::MEMORY);
    a->write(fs);
    const String text = fs.releaseAndGetString();
    FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
    Ptr<EventStatistics> b = EventStatistics::create(Size(8, 6));
    b->read(in.root());
    EXPECT_EQ(2500.0, b->getCrossingGap());
    EXPECT_EQ(3000.0, b->getIsolationWindow());
    EXPECT_EQ(33000.0, b->getActivityWindow());
    EXPECT_THROW(b->setActivityWindow(0), cv::Exception);
}

}}  // namespace
