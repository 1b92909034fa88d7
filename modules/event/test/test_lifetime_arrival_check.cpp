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
