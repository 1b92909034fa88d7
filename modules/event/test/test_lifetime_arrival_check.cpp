// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// The check fed with a straight edge at `speed` px/s in direction `angle` and, for every event, the lifetime
// `scale` / speed with the edge's own flow.
Ptr<LifetimeArrivalCheck> checkScaledLifetimes(double speed, double angle, double scale)
{
    const Size size(32, 32);
    const std::vector<Event> ev = movingEdge(size, speed, angle, 0, 0, 1);
    std::vector<float> lifetimes(ev.size(), (float)(scale * 1e6 / speed));
    std::vector<Vec2f> flow(ev.size(), Vec2f((float)(speed * std::cos(angle)), (float)(speed * std::sin(angle))));
    Ptr<LifetimeArrivalCheck> check = LifetimeArrivalCheck::create(size);
    check->update(ev, lifetimes, flow);
    return check;
}

TEST(Event_LifetimeArrivalCheck, a_straight_edge_arrives_after_exactly_its_lifetime)
{
    // The edge reaches the neighbour the flow points to after (offset . flow direction) / speed: the lifetime
    // times that distance. Lifetimes scaled by k give 1 / k; the bins are 1 % wide and timestamps whole us.
    for (double angleDeg : { 0.0, 30.0, 45.0, 100.0, 200.0, 290.0 })
        for (double scale : { 1.0, 2.0, 0.5 })
        {
            Ptr<LifetimeArrivalCheck> check = checkScaledLifetimes(200, angleDeg * CV_PI / 180, scale);
            EXPECT_GT(check->getSampleCount(), 500) << angleDeg << " deg";
            EXPECT_NEAR(1 / scale, check->getRatioQuantile(0.5), 0.02 / scale) << angleDeg << " deg, x" << scale;
            EXPECT_NEAR(1 / scale, check->getRatioQuantile(0.1), 0.03 / scale) << angleDeg << " deg, x" << scale;
            EXPECT_NEAR(1 / scale, check->getRatioQuantile(0.9), 0.03 / scale) << angleDeg << " deg, x" << scale;
        }
}

// Vertical edges `period` px apart moving right at 1000 px/s (lifetime 1000 us) over a 64 x 16 sensor for 40 ms:
// each crossing fires `burst` events `spacing` us apart at every pixel, except where `skip` says the pixel misses
// that crossing. Every such event gets the true lifetime and flow. With `clutterUs` > 0 every pixel also fires
// an event without a lifetime that long before each crossing (another edge, noise).
template <class Skip>
Ptr<LifetimeArrivalCheck> checkStripes(int period, int burst, int spacing, Skip skip, int clutterUs = 0)
{
    const Size size(64, 16);
    const double speed = 1000;
    std::vector<std::pair<Event, float>> fired;
    for (int x = 0; x < size.width; x++)
        for (int crossing = 0; crossing * period <= 40 + x; crossing++)
        {
            const int64 t = (int64)std::llround((x + crossing * period) * 1e6 / speed);
            for (int y = 0; y < size.height; y++)
            {
                if (clutterUs > 0 && t >= clutterUs)
                    fired.emplace_back(Event(t - clutterUs, x, y, 1), 0.f);
                if (!skip(x, y, crossing))
                    for (int j = 0; j < burst; j++)
                        fired.emplace_back(Event(t + j * spacing, x, y, 1), (float)(1e6 / speed));
            }
        }
    std::stable_sort(fired.begin(), fired.end(), [](const std::pair<Event, float>& a, const std::pair<Event, float>& b) {
        return a.first.t < b.first.t;
    });
    std::vector<Event> ev;
    std::vector<float> lifetimes;
    for (const std::pair<Event, float>& f : fired)
    {
        ev.push_back(f.first);
        lifetimes.push_back(f.second);
    }
    Ptr<LifetimeArrivalCheck> check = LifetimeArrivalCheck::create(size);
    check->update(ev, lifetimes, std::vector<Vec2f>(ev.size(), Vec2f((float)speed, 0)));
    return check;
}

TEST(Event_LifetimeArrivalCheck, a_burst_of_events_per_crossing_is_measured_from_its_first)
{
    // Three events per crossing, 600 us apart (a blurred edge fires over more than a lifetime): measured from
    // the later ones, the neighbour's next event would come 0.4 lifetimes after (in its own burst). Only each
    // crossing's first event claims, and the neighbour's first event settles it: exactly one lifetime.
    Ptr<LifetimeArrivalCheck> check = checkStripes(8, 3, 600, [](int, int, int) { return false; });
    EXPECT_GT(check->getSampleCount(), 3000);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.05), 0.01);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.95), 0.01);
}

TEST(Event_LifetimeArrivalCheck, where_the_neighbour_misses_a_crossing_the_pixel_beyond_says_when_the_edge_passed)
{
    // A fifth of the firings missed, never two neighbours along the row in one crossing: where the neighbour
    // misses, its next crossing comes 8 lifetimes later, but the pixel beyond fires after two lifetimes, as
    // expected there. Every sample is one lifetime.
    const auto missed = [](int x, int y, int crossing) { return (2 * x + 3 * y + crossing) % 5 == 0; };
    Ptr<LifetimeArrivalCheck> check = checkStripes(8, 1, 0, missed);
    EXPECT_GT(check->getSampleCount(), 2000);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.01), 0.01);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.99), 0.01);
}

TEST(Event_LifetimeArrivalCheck, the_pixel_beyond_firing_before_the_neighbour_is_due_settles_nothing)
{
    // Every pixel also fires 1700 us before each crossing: 300 us after the edge left the pixel two behind, long
    // before that pixel's claim on it is due (2000 us). Taken as the edge, it would give 0.15 and drop the
    // neighbour's sample; the neighbour settles the claim after exactly one lifetime.
    Ptr<LifetimeArrivalCheck> check = checkStripes(8, 1, 0, [](int, int, int) { return false; }, 1700);
    EXPECT_GT(check->getSampleCount(), 3000);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.01), 0.01);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.99), 0.01);
}

TEST(Event_LifetimeArrivalCheck, the_estimators_lifetimes_agree_where_the_ground_truth_says_they_are_right)
{
    // boxes: the estimator's median lifetime error against the simulator's truth is 0.5 % (benchmarks.md), so
    // the check, which sees only the events, must find the edges arriving after one lifetime.
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("boxes");
    const std::vector<Event> left = generateLeftCamera(*sim, 500000).events;
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(sim->getSensorSize());
    Mat lifetimes, flow;
    est->process(left, lifetimes, flow);
    Ptr<LifetimeArrivalCheck> check = LifetimeArrivalCheck::create(sim->getSensorSize());
    check->update(left, lifetimes, flow);
    EXPECT_GT(check->getSampleCount(), 5000);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.5), 0.05);
    // The same events with every lifetime halved: the edges now take two lifetimes.
    lifetimes *= 0.5;
    check->reset();
    EXPECT_EQ(0, check->getSampleCount());
    EXPECT_EQ(0, check->getRatioQuantile(0.5));
    check->update(left, lifetimes, flow);
    EXPECT_NEAR(2.0, check->getRatioQuantile(0.5), 0.1);
}

TEST(Event_LifetimeArrivalCheck, bad_input_is_named_and_leaves_the_check_as_it_was)
{
    Ptr<LifetimeArrivalCheck> check = checkScaledLifetimes(200, 0, 1);
    const double samples = check->getSampleCount();
    std::vector<Event> ev(2, Event(100, 1, 1, 1));
    std::vector<float> lifetimes(2, 5000.f);
    std::vector<Vec2f> flow(2, Vec2f(200, 0));
    // The edge's events end at about 160 ms: events at 100 us go back in time.
    EXPECT_THROW(check->update(ev, lifetimes, flow), cv::Exception);
    ev[0].t = ev[1].t = 10000000;
    ev[1].x = 32;  // outside the 32 x 32 sensor
    EXPECT_THROW(check->update(ev, lifetimes, flow), cv::Exception);
    ev[1].x = 2;
    EXPECT_THROW(check->update(ev, std::vector<float>(1, 5000.f), flow), cv::Exception);
    EXPECT_THROW(check->update(ev, lifetimes, std::vector<Vec2f>(3)), cv::Exception);
    EXPECT_EQ(samples, check->getSampleCount());
    EXPECT_THROW(check->getRatioQuantile(1.5), cv::Exception);
    EXPECT_THROW(LifetimeArrivalCheck::create(Size(0, 10)), cv::Exception);
    check->update(std::vector<Event>(), std::vector<float>(), std::vector<Vec2f>());  // an empty packet
    // Lifetimes so small that the ratio overflows to infinity: a sample in the histogram's open end, never an
    // out-of-range bin.
    {
        Ptr<LifetimeArrivalCheck> tiny = LifetimeArrivalCheck::create(Size(4, 1));
        std::vector<Event> row = { Event(10, 0, 0, 1), Event(20, 1, 0, 1), Event(30, 2, 0, 1), Event(40, 3, 0, 1) };
        tiny->update(row, std::vector<float>{ 1e-45f, 1e-38f, 1e-20f, 1.f }, std::vector<Vec2f>(4, Vec2f(1e6f, 0)));
        EXPECT_EQ(3, tiny->getSampleCount());
        EXPECT_GT(tiny->getRatioQuantile(0.5), 999);
    }
    check->update(ev, lifetimes, flow);  // valid: no pixel fired twice, no new sample
    EXPECT_EQ(samples, check->getSampleCount());
}

}} // namespace
