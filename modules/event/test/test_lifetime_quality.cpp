// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

struct QualityRun
{
    std::vector<Event> events;
    Mat lifetimes, flow, status, quality;
};

QualityRun runQuality(Ptr<LifetimeEstimator> est, const std::vector<Event>& events)
{
    QualityRun r;
    r.events = events;
    est->process(events, r.lifetimes, r.flow, r.status, r.quality);
    return r;
}

// On a plane that every event lies on, the refit leaves no residual: the quality is 1 / (1 + 1 / (n - 2)) for the
// n inliers it rests on, so n = 2 + q / (1 - q) comes out a whole number of the window's pixels. Timing jitter
// adds the residuals' relative error and lowers it.
TEST(Event_LifetimeQuality, an_exact_plane_has_the_quality_of_its_inlier_count)
{
    const Size size(24, 24);
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(size);
    est->setUsePrediction(false);
    // 50 px/s: 20 ms per pixel, so whole-microsecond timestamps are on the plane to 2.5e-5 of a step.
    const QualityRun exact = runQuality(est, movingEdge(size, 50.0, 0.5, 0.0, 0.0, 1));
    std::vector<double> exactQualities;
    for (int i = 0; i < (int)exact.events.size(); i++)
    {
        const float q = exact.quality.at<float>(i);
        if (exact.status.at<uchar>(i) != LIFETIME_FITTED)
        {
            EXPECT_EQ(0.f, q) << i;  // noise: no lifetime, no quality
            continue;
        }
        ASSERT_GT(q, 0.f) << i;
        ASSERT_LT(q, 1.f) << i;
        const double inliers = 2 + q / (1.0 - q);
        EXPECT_NEAR(inliers, std::round(inliers), 0.05) << i;
        EXPECT_GE(std::round(inliers), est->getMinInliers()) << i;
        EXPECT_LE(std::round(inliers), est->getWindowSize() * est->getWindowSize()) << i;
        exactQualities.push_back(q);
    }
    ASSERT_GT(exactQualities.size(), 200u);

    Ptr<LifetimeEstimator> jittered = LifetimeEstimator::create(size);
    jittered->setUsePrediction(false);
    jittered->setInlierThreshold(3.0);
    const QualityRun noisy = runQuality(jittered, movingEdge(size, 50.0, 0.5, 0.08, 0.0, 1));
    std::vector<double> noisyQualities;
    for (int i = 0; i < (int)noisy.events.size(); i++)
        if (noisy.status.at<uchar>(i) == LIFETIME_FITTED)
            noisyQualities.push_back(noisy.quality.at<float>(i));
    ASSERT_GT(noisyQualities.size(), 200u);
    EXPECT_LT(median(noisyQualities), median(exactQualities) - 0.02);
}

// A predicted event reuses a plane without fitting one: its quality is that plane's, which the event one pixel
// back along the motion (the one that predicted it) was given. A plane passed on by insertEvent (a stereo
// match) has none.
TEST(Event_LifetimeQuality, a_predicted_event_takes_the_quality_of_the_plane_that_predicted_it)
{
    const Size size(24, 24);
    const QualityRun run = runQuality(LifetimeEstimator::create(size), movingEdge(size, 200.0, 0.3, 0.01, 0.0, 5));
    int predicted = 0, traced = 0;
    for (int i = 0; i < (int)run.events.size(); i++)
    {
        if (run.status.at<uchar>(i) != LIFETIME_PREDICTED)
            continue;
        predicted++;
        const Event& e = run.events[(size_t)i];
        // The latest earlier event with a plane at an 8-neighbour of the same polarity with the same quality.
        for (int j = i - 1; j >= 0; j--)
        {
            const Event& o = run.events[(size_t)j];
            if (o.p == e.p && std::max(std::abs(o.x - e.x), std::abs(o.y - e.y)) == 1 &&
                run.lifetimes.at<float>(j) > 0 && run.quality.at<float>(j) == run.quality.at<float>(i))
            {
                traced++;
                break;
            }
        }
        EXPECT_GT(run.quality.at<float>(i), 0.f) << i;
    }
    ASSERT_GT(predicted, 100);
    EXPECT_EQ(predicted, traced);

    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(Size(32, 32));
    est->insertEvent(Event(1000000, 10, 10, 1), 1000.f, Vec2f(1000.f, 0.f));
    Vec2f flow;
    int status = -1;
    float quality = -1;
    EXPECT_NEAR(1000.f, est->processEvent(Event(1001000, 11, 10, 1), flow, status, quality), 1e-3f);
    EXPECT_EQ(LIFETIME_PREDICTED, status);
    EXPECT_EQ(0.f, quality);
}

TEST(Event_LifetimeQuality, batch_and_incremental_apis_agree)
{
    const std::vector<Event> ev = movingEdge(Size(24, 24), 150.0, 1.0, 0.05, 0.1, 7);
    const QualityRun batch = runQuality(LifetimeEstimator::create(Size(24, 24)), ev);
    Ptr<LifetimeEstimator> single = LifetimeEstimator::create(Size(24, 24));
    for (size_t i = 0; i < ev.size(); i++)
    {
        Vec2f f;
        int s;
        float q;
        ASSERT_EQ(batch.lifetimes.at<float>((int)i), single->processEvent(ev[i], f, s, q)) << i;
        ASSERT_EQ(batch.quality.at<float>((int)i), q) << i;
    }
}

// Against the simulator's true lifetimes: the quarter of the lifetimes with the highest quality is off by less
// than half as much (median relative error) as the quarter with the lowest, on a cluttered scene and on a
// DAVIS240-like pair's blurred, dotted edges.
TEST(Event_LifetimeQuality, ranks_the_lifetimes_by_their_error_against_the_simulated_truth)
{
    for (const char* scene : { "cluttered", "boxes_pair" })
    {
        Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene);
        const LeftCameraEvents run = generateLeftCamera(*sim, 600000);
        const QualityRun q = runQuality(LifetimeEstimator::create(sim->getSensorSize()), run.events);
        std::vector<std::pair<float, double>> byQuality;  // quality, relative error
        for (size_t k = 0; k < run.events.size(); k++)
        {
            const float truth = run.groundTruth.at<float>(run.truthRows[k], GT_LIFETIME);
            const float lifetime = q.lifetimes.at<float>((int)k);
            const bool noise = ((int)run.groundTruth.at<float>(run.truthRows[k], GT_FLAGS) & GT_FLAG_NOISE) != 0;
            if (lifetime > 0 && truth > 0 && !noise)
                byQuality.emplace_back(q.quality.at<float>((int)k), std::abs(lifetime - truth) / truth);
        }
        ASSERT_GT(byQuality.size(), 2000u) << scene;
        std::sort(byQuality.begin(), byQuality.end(),
                  [](const std::pair<float, double>& a, const std::pair<float, double>& b) { return a.first < b.first; });
        const size_t quarter = byQuality.size() / 4;
        std::vector<double> lowest, highest;
        for (size_t i = 0; i < quarter; i++)
        {
            lowest.push_back(byQuality[i].second);
            highest.push_back(byQuality[byQuality.size() - 1 - i].second);
        }
        EXPECT_LT(median(highest), 0.5 * median(lowest)) << scene;
    }
}

// The active events' picture at a quality threshold holds exactly the pixels whose latest event is alive and
// has a lifetime of at least that quality, as process() gave them.
TEST(Event_LifetimeQuality, the_active_events_picture_keeps_the_lifetimes_of_the_quality_asked_for)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("cluttered");
    const Size size = sim->getSensorSize();
    const LeftCameraEvents run = generateLeftCamera(*sim, 300000);
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(size);
    const QualityRun q = runQuality(est, run.events);
    const double t = (double)run.events.back().t;
    int drawn[2] = { 0, 0 };
    const double thresholds[2] = { 0, 0.75 };
    for (int k = 0; k < 2; k++)
    {
        Mat expected = Mat::zeros(size, CV_8U);
        for (size_t i = 0; i < run.events.size(); i++)
        {
            const Event& e = run.events[i];
            const float lifetime = q.lifetimes.at<float>((int)i);
            const bool alive = lifetime > 0 && q.quality.at<float>((int)i) >= thresholds[k] && (double)e.t <= t &&
                               t < (double)e.t + lifetime;
            expected.at<uchar>(e.y, e.x) = alive ? (e.p ? 255 : 128) : 0;  // the pixel's latest event decides
        }
        Mat image;
        est->renderActiveEvents(t, image, thresholds[k]);
        ASSERT_EQ(size, image.size());
        EXPECT_EQ(0, cvtest::norm(expected, image, NORM_INF)) << "minQuality " << thresholds[k];
        drawn[k] = countNonZero(image);
    }
    EXPECT_GT(drawn[1], 100);
    EXPECT_LT(drawn[1], drawn[0]);
    Mat image;
    EXPECT_THROW(est->renderActiveEvents(t, image, 1.5), cv::Exception);
    EXPECT_THROW(est->renderActiveEvents(t, image, -0.1), cv::Exception);
}

}}  // namespace
