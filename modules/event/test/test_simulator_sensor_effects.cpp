// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The simulator's sensor and rig non-idealities, each against its closed form.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// The edge at 80 px/s (f = 200 px), starting 20 px left of the image centre.
std::vector<SimulatedPlane> sweepingEdge()
{
    return sweepingEdgeScene(1.0, 0.4, -0.1);
}

// A scene where nothing moves: every event is the sensor's own.
std::vector<SimulatedPlane> staticScene()
{
    SimulatedPlane back;
    back.center = Vec3d(0, 0, 2);
    back.halfSize = Vec2d(10, 10);
    back.texture = TEXTURE_UNIFORM;
    back.intensity = 0.3;
    return { back };
}

typedef std::map<std::tuple<int, int, int>, std::vector<int64>> PixelTimes;  // (camera, y, x) -> stamps

PixelTimes simulate(const std::vector<SimulatedPlane>& scene, const SimulatorSettings& s, double untilUs,
                    Mat* truth = nullptr, std::vector<Event>* events = nullptr)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene, s);
    std::vector<Event> ev;
    Mat gt;
    sim->generate(untilUs, ev, gt);
    PixelTimes out;
    for (size_t i = 0; i < ev.size(); i++)
    {
        if (i > 0)
        {
            EXPECT_LE(ev[i - 1].t, ev[i].t) << "the stream is in time order, event " << i;
        }
        out[std::make_tuple((int)ev[i].camera, (int)ev[i].y, (int)ev[i].x)].push_back(ev[i].t);
    }
    if (truth)
        *truth = gt;
    if (events)
        *events = ev;
    return out;
}

// Delay of every event against the same simulation without delays (the firing is the same: the delays draw
// from their own random sequences), the first events of each pixel up to the undelayed run's count.
std::vector<std::pair<double, std::tuple<int, int, int>>> delays(const SimulatorSettings& delayed, double untilUs)
{
    const PixelTimes base = simulate(sweepingEdge(), idealSmallSensor(), untilUs);
    const PixelTimes late = simulate(sweepingEdge(), delayed, untilUs + 20000);
    std::vector<std::pair<double, std::tuple<int, int, int>>> out;
    for (const auto& kv : base)
    {
        const auto it = late.find(kv.first);
        EXPECT_TRUE(it != late.end());
        if (it == late.end())
            continue;
        EXPECT_GE(it->second.size(), kv.second.size());
        for (size_t k = 0; k < kv.second.size() && k < it->second.size(); k++)
            out.push_back(std::make_pair((double)(it->second[k] - kv.second[k]), kv.first));
    }
    return out;
}

TEST(Event_SimulatorSensor, latency_is_a_fixed_delay_per_pixel_with_the_set_mean_and_spread)
{
    SimulatorSettings s = idealSmallSensor();
    s.latencyUs = 500;
    s.latencySigmaUs = 150;
    const auto d = delays(s, 500000);
    ASSERT_GT(d.size(), 5000u);
    // Per pixel, one delay (stamps are whole microseconds: within 1 us).
    std::map<std::tuple<int, int, int>, std::pair<double, double>> range;
    for (const auto& e : d)
    {
        auto it = range.find(e.second);
        if (it == range.end())
            range[e.second] = std::make_pair(e.first, e.first);
        else
        {
            it->second.first = std::min(it->second.first, e.first);
            it->second.second = std::max(it->second.second, e.first);
        }
    }
    double sum = 0, sumSq = 0;
    for (const auto& kv : range)
    {
        EXPECT_LE(kv.second.second - kv.second.first, 1.0);
        sum += kv.second.first;
        sumSq += kv.second.first * kv.second.first;
    }
    const double n = (double)range.size(), mean = sum / n, sd = std::sqrt(sumSq / n - mean * mean);
    ASSERT_GT(n, 1000);
    EXPECT_NEAR(500, mean, 3 * 150 / std::sqrt(n) + 1);  // the mean of n normal draws, +-1 us of rounding
    EXPECT_NEAR(150, sd, 0.06 * 150);
}

TEST(Event_SimulatorSensor, jitter_is_an_exponential_delay_per_event)
{
    SimulatorSettings s = idealSmallSensor();
    s.jitterUs = 300;
    // One event per pixel and crossing (threshold above half the contrast): no two of a pixel's events
    // close enough for the order rule to move one.
    SimulatorSettings base = idealSmallSensor();
    s.thresholdOn = s.thresholdOff = base.thresholdOn = base.thresholdOff = 2.0;
    const PixelTimes ideal = simulate(sweepingEdge(), base, 500000);
    const PixelTimes late = simulate(sweepingEdge(), s, 520000);
    std::vector<double> d;
    for (const auto& kv : ideal)
    {
        ASSERT_EQ(1u, kv.second.size());
        d.push_back((double)(late.at(kv.first)[0] - kv.second[0]));
    }
    ASSERT_GT(d.size(), 2000u);
    std::sort(d.begin(), d.end());
    const double mean = std::accumulate(d.begin(), d.end(), 0.0) / (double)d.size();
    // Exponential with mean J: mean J, median J ln 2, 90th percentile J ln 10 (stamps floored: -0.5 us).
    const double n = (double)d.size();
    EXPECT_NEAR(300 - 0.5, mean, 4 * 300 / std::sqrt(n));
    EXPECT_NEAR(300 * std::log(2.0), d[d.size() / 2], 0.08 * 300 * std::log(2.0));
    EXPECT_NEAR(300 * std::log(10.0), d[d.size() * 9 / 10], 0.08 * 300 * std::log(10.0));
    EXPECT_GE(d.front(), 0.0);
}

TEST(Event_SimulatorSensor, refractory_period_spaces_a_pixels_events)
{
    // The edge's 10 levels are crossed within one render step (about 3 ms): without a refractory period a
    // pixel fires all 10; with 1 ms at most one per millisecond.
    SimulatorSettings s = idealSmallSensor();
    s.refractoryUs = 1000;
    const PixelTimes times = simulate(sweepingEdge(), s, 500000);
    ASSERT_GT(times.size(), 1000u);
    size_t events = 0;
    for (const auto& kv : times)
    {
        for (size_t k = 1; k < kv.second.size(); k++)
            EXPECT_GE(kv.second[k] - kv.second[k - 1], 999) << "pixel events closer than the refractory period";
        events += kv.second.size();
    }
    const PixelTimes free = simulate(sweepingEdge(), idealSmallSensor(), 500000);
    size_t freeEvents = 0;
    for (const auto& kv : free)
        freeEvents += kv.second.size();
    EXPECT_LT(events * 2, freeEvents) << "the refractory period removes most of a fast edge's events";
}

TEST(Event_SimulatorSensor, threshold_mismatch_gives_the_expected_mean_count)
{
    // Per pixel the edge fires floor(C / c) events, c ~ N(0.2, sigma): the mean count over pixels is
    // sum_k k P(C / (k + 1) < c <= C / k).
    const double C = std::log(0.9 / 0.1), mu = 0.2, sigma = 0.04;
    auto Phi = [&](double c) { return 0.5 * std::erfc(-(c - mu) / (sigma * std::sqrt(2.0))); };
    double expected = 0;
    for (int k = 1; k < 200; k++)
        expected += k * (Phi(C / k) - Phi(C / (k + 1)));
    SimulatorSettings s = idealSmallSensor();
    s.thresholdSigma = sigma;
    const PixelTimes times = simulate(sweepingEdge(), s, 500000);
    double sum = 0, n = 0;
    for (const auto& kv : times)
        if (std::get<0>(kv.first) == CAMERA_LEFT && std::get<2>(kv.first) >= 30 && std::get<2>(kv.first) < 66)
        {
            sum += (double)kv.second.size();
            n++;
        }
    ASSERT_GT(n, 1000);
    EXPECT_NEAR(expected, sum / n, 0.03 * expected);
    EXPECT_GT(std::abs(expected - std::floor(C / mu)), 0.3) << "the mismatch must move the mean for this test to mean anything";
}

TEST(Event_SimulatorSensor, flicker_fires_every_threshold_level_within_the_swing_at_its_frequency)
{
    // A steady lamp whose intensity is I (1 + d sin(2 pi f t)). Without mismatch every pixel's reference
    // stays on the levels log I + k C, so each half period fires at the levels within the log swing
    // [log(1 - d), log(1 + d)] but the one the last burst ended on: n - 1 events, n the levels in the swing.
    const double d = 0.53, C = 0.2, f = 100;
    int levels = 0;
    for (int k = -20; k <= 20; k++)
        levels += k * C >= std::log(1 - d) && k * C <= std::log(1 + d);
    ASSERT_EQ(6, levels) << "levels well inside the swing: no level sits at a peak";
    std::vector<SimulatedPlane> lamp = staticScene();
    lamp[0].flickerDepth = d;
    SimulatorSettings s = idealSmallSensor();
    s.thresholdOn = s.thresholdOff = C;
    s.flickerFrequencyHz = f;
    Mat truth;
    std::vector<Event> ev;
    const PixelTimes times = simulate(lamp, s, 100000, &truth, &ev);
    ASSERT_EQ((size_t)2 * s.resolution.area(), times.size()) << "every pixel of both cameras flickers";
    // From the first peak at 2.5 ms to the ninth at 82.5 ms: 8 periods of 2 (n - 1) events.
    for (const auto& kv : times)
    {
        const auto inPeriods = std::count_if(kv.second.begin(), kv.second.end(), [](int64 t) { return t >= 2500 && t < 82500; });
        ASSERT_EQ(8 * 2 * (levels - 1), (int)inPeriods) << "camera " << std::get<0>(kv.first) << ", pixel ("
                                                         << std::get<2>(kv.first) << ", " << std::get<1>(kv.first) << ")";
    }
    for (size_t i = 0; i < ev.size(); i++)
    {
        // ON events while the intensity rises, OFF while it falls; every one is the flicker's.
        const double rising = std::cos(2 * CV_PI * f * (double)ev[i].t * 1e-6);
        ASSERT_GT(ev[i].p == POLARITY_ON ? rising : -rising, 0.0) << "event " << i << " at " << ev[i].t << " us";
        ASSERT_TRUE((int)truth.at<float>((int)i, GT_FLAGS) & GT_FLAG_FLICKER) << i;
        ASSERT_FLOAT_EQ(2.f, truth.at<float>((int)i, GT_DEPTH)) << "the lamp is a real scene point, 2 m away";
    }
}

TEST(Event_SimulatorSensor, flicker_and_motion_at_one_pixel_are_told_apart)
{
    // An edge of log contrast ln 9 under a lamp whose log swing w = log(1.25 / 0.75) = 0.51 is over two
    // thresholds: every pixel fires at least one level per half period, before and after the edge. The
    // edge's step (uniform planes: one render to the next) fires (ln 9 +- w) / C levels at once, the flicker's
    // phase deciding the +-: those are the motion's, all ON. The flicker's alternate, so they never add up to
    // more than the swing's levels, before and after the edge.
    const double depth = 0.25, swing = std::log((1 + depth) / (1 - depth));
    std::vector<SimulatedPlane> scene = sweepingEdge();
    for (SimulatedPlane& p : scene)
        p.flickerDepth = depth;
    SimulatorSettings s = idealSmallSensor();
    s.flickerFrequencyHz = 100;
    Mat truth;
    std::vector<Event> ev;
    simulate(scene, s, 400000, &truth, &ev);
    const double perPixel = std::log(9.0) / s.thresholdOn;
    std::map<std::tuple<int, int, int>, int> motionOn, flickerNet;
    int flickerEvents = 0;
    for (size_t i = 0; i < ev.size(); i++)
    {
        const auto key = std::make_tuple((int)ev[i].camera, (int)ev[i].y, (int)ev[i].x);
        if ((int)truth.at<float>((int)i, GT_FLAGS) & GT_FLAG_FLICKER)
        {
            flickerNet[key] += ev[i].p == POLARITY_ON ? 1 : -1;
            flickerEvents++;
        }
        else
        {
            ASSERT_EQ(POLARITY_ON, (int)ev[i].p) << "the edge brightens every pixel it crosses; event " << i;
            motionOn[key]++;
        }
    }
    ASSERT_GT(motionOn.size(), 1000u);
    // Both cameras, 80 half periods of at least one level each (the first one may fall short).
    EXPECT_GE(flickerEvents, 2 * s.resolution.area() * 79) << "every pixel follows the flicker";
    const int swingLevels = (int)std::ceil(swing / s.thresholdOn);
    for (const auto& kv : motionOn)
    {
        ASSERT_GE(kv.second, (int)std::floor(perPixel - swing / s.thresholdOn));
        ASSERT_LE(kv.second, (int)std::ceil(perPixel + swing / s.thresholdOn));
        ASSERT_LE(std::abs(flickerNet[kv.first]), 2 * swingLevels) << "flicker crossings go both ways";
    }
}

TEST(Event_SimulatorSensor, threshold_noise_makes_the_count_a_renewal_process)
{
    // A very dark background: the edge's log contrast ln(0.9 / 0.001) = 6.8 spans 34 thresholds of 0.2. With
    // a fresh N(0.2, 0.05^2) threshold per crossing the count is a renewal process: mean C / mu - 1/2 +
    // sigma^2 / (2 mu^2) and standard deviation sqrt(C sigma^2 / mu^3); without the noise every pixel fires 34.
    std::vector<SimulatedPlane> scene = sweepingEdge();
    scene[0].intensity = 0.001;
    const double C = std::log(0.9 / 0.001), mu = 0.2, sigma = 0.05;
    for (double noise : { 0.0, sigma })
    {
        SimulatorSettings s = idealSmallSensor();
        s.thresholdNoise = noise;
        const PixelTimes times = simulate(scene, s, 500000);
        double sum = 0, sumSq = 0, n = 0;
        for (const auto& kv : times)
            if (std::get<0>(kv.first) == CAMERA_LEFT && std::get<2>(kv.first) >= 30 && std::get<2>(kv.first) < 66)
            {
                const double k = (double)kv.second.size();
                sum += k;
                sumSq += k * k;
                n++;
            }
        ASSERT_GT(n, 1000);
        const double mean = sum / n, sd = std::sqrt(std::max(0.0, sumSq / n - mean * mean));
        if (noise == 0)
        {
            EXPECT_EQ(std::floor(C / mu), mean);
            EXPECT_EQ(0.0, sd);
            continue;
        }
        EXPECT_NEAR(C / mu - 0.5 + sigma * sigma / (2 * mu * mu), mean, 0.3);
        EXPECT_NEAR(std::sqrt(C * sigma * sigma / (mu * mu * mu)), sd, 0.2 * std::sqrt(C * sigma * sigma / (mu * mu * mu)));
    }
}

TEST(Event_SimulatorSensor, lens_blur_fires_an_edge_early_by_the_gaussians_quantile)
{
    // Through a Gaussian blur of sigma px a step edge from I0 to I1 reaches a pixel's first level, I0 e^c,
    // while still sigma * Phi^-1((e^c - 1) I0 / (I1 - I0)) px away: 1.916 sigma for 0.1 -> 0.9 and c = 0.2.
    // At 80 px/s and sigma = 1 px the first event of every pixel comes 24 ms before the sharp image's.
    const double v = 80, blur = 1.0, I0 = 0.1, I1 = 0.9, c = 0.2;
    const double p = (std::exp(c) - 1) * I0 / (I1 - I0);
    // Phi^-1 by bisection on erfc.
    double lo = -6, hi = 0;
    for (int k = 0; k < 60; k++)
    {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
    }
    const double expectedLeadUs = -lo * blur / v * 1e6;
    SimulatorSettings s = idealSmallSensor();
    const PixelTimes sharp = simulate(sweepingEdge(), s, 500000);
    s.blurSigmaPx = blur;
    const PixelTimes blurred = simulate(sweepingEdge(), s, 500000);
    std::vector<double> lead;
    for (const auto& kv : sharp)
        if (std::get<0>(kv.first) == CAMERA_LEFT && std::get<1>(kv.first) >= 4 && std::get<1>(kv.first) < 28 &&
            std::get<2>(kv.first) >= 30 && std::get<2>(kv.first) < 60 && blurred.count(kv.first))
            lead.push_back((double)(kv.second[0] - blurred.at(kv.first)[0]));
    ASSERT_GT(lead.size(), 500u);
    std::sort(lead.begin(), lead.end());
    EXPECT_NEAR(expectedLeadUs, lead[lead.size() / 2], 0.1 * expectedLeadUs);
}

TEST(Event_SimulatorSensor, through_a_lens_blur_the_true_lifetimes_say_when_the_next_pixel_fires)
{
    // walking_pair's figure over a wall of posters, through its lens blur (0.8 px) and nothing else of a real
    // sensor: the blurred pattern at a pixel moves with the surface that changes it, along that pixel's own
    // gradient. Lifetimes that are right are what LifetimeArrivalCheck finds: the edge reaches the next pixel
    // after one of them (median), and rarely much sooner. Taken along the gradient at the surface's pixel
    // instead, the rounded corners and the limbs' ends made them over a quarter too long (median 0.78, p25 0.44).
    Ptr<StereoEventSimulator> base = StereoEventSimulator::create("walking_pair");
    SimulatorSettings s = base->getSettings();
    ASSERT_GT(s.blurSigmaPx, 0.5);
    s.thresholdSigma = 0;
    s.thresholdNoise = 0;
    s.noiseRateHz = 0;
    s.refractoryUs = 0;
    s.latencyUs = 0;
    s.latencySigmaUs = 0;
    s.jitterUs = 0;
    s.hotPixelShare = 0;
    s.leakRateHz = 0;
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(base->getPlanes(), s);
    const LeftCameraEvents run = generateLeftCamera(*sim, 1000000);
    Mat lifetimes, flow;
    perfectLifetimes(run.groundTruth, run.truthRows, lifetimes, flow);
    Ptr<LifetimeArrivalCheck> check = LifetimeArrivalCheck::create(sim->getSensorSize());
    check->update(run.events, lifetimes, flow);
    ASSERT_GT(check->getSampleCount(), 3000);
    EXPECT_NEAR(1.0, check->getRatioQuantile(0.5), 0.06);
    EXPECT_GT(check->getRatioQuantile(0.25), 0.8);
}

TEST(Event_SimulatorSensor, through_a_lens_blur_a_turning_surfaces_true_lifetime_is_its_motion_where_its_contour_passes)
{
    // The fan's blades turn in their plane, each point at omega times its distance from the hub. Through a blur
    // of 0.8 px a pixel fires for a blade up to 3 px away: its truth must be the blade's motion where the edge
    // passes the pixel, not that of any blade pixel within the blur's reach (up to 3 px nearer the hub or further).
    Ptr<StereoEventSimulator> base = StereoEventSimulator::create("fan");
    SimulatorSettings s = base->getSettings();
    s.blurSigmaPx = 0.8;
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(base->getPlanes(), s);
    const std::vector<double> ratios = fanSideEdgeLifetimeRatios(generateLeftCamera(*sim, 200000), s);
    ASSERT_GT(ratios.size(), 1000u);
    EXPECT_NEAR(1.0, ratios[ratios.size() / 2], 0.02);
    EXPECT_NEAR(1.0, ratios[ratios.size() / 4], 0.04);
    EXPECT_NEAR(1.0, ratios[ratios.size() * 3 / 4], 0.04);
}

TEST(Event_SimulatorSensor, hot_pixels_and_leak_events_at_their_rates)
{
    SimulatorSettings s = SimulatorSettings::preset(SENSOR_DAVIS240);
    s.hotPixelShare = 0.005;
    s.hotPixelRateHz = 400;
    s.leakRateHz = 0.5;
    const double seconds = 1.0;
    Mat gt;
    std::vector<Event> ev;
    const PixelTimes times = simulate(staticScene(), s, seconds * 1e6, &gt, &ev);
    // Nothing moves: every event is noise, and the leak's are ON.
    for (int i = 0; i < gt.rows; i++)
        ASSERT_EQ((float)GT_FLAG_NOISE, gt.at<float>(i, GT_FLAGS)) << i;
    // Hot pixels: about 0.5 % of each camera's pixels, each at 400 Hz, in one polarity. A pixel with more
    // than 100 events in 1 s is hot (a leak-only pixel has 0.5 on average).
    std::map<std::tuple<int, int, int>, std::pair<int, int>> polarity;  // pixel -> (ON, OFF)
    for (const Event& e : ev)
    {
        std::pair<int, int>& c = polarity[std::make_tuple((int)e.camera, (int)e.y, (int)e.x)];
        (e.p ? c.first : c.second)++;
    }
    const double area = s.resolution.area();
    for (int camera = 0; camera < 2; camera++)
    {
        double hot = 0, hotEvents = 0, otherEvents = 0, otherOff = 0;
        for (const auto& kv : polarity)
        {
            if (std::get<0>(kv.first) != camera)
                continue;
            const int count = kv.second.first + kv.second.second;
            if (count > 100)
            {
                hot++;
                // Its own polarity, plus at most a few leak events (ON).
                EXPECT_TRUE(kv.second.second == 0 || kv.second.first <= 10) << "a hot pixel fires one polarity";
                hotEvents += count;
            }
            else
            {
                otherEvents += count;
                otherOff += kv.second.second;
            }
        }
        // Binomial count of hot pixels: mean 216, standard deviation 14.7.
        EXPECT_NEAR(0.005 * area, hot, 4 * std::sqrt(0.005 * area));
        EXPECT_NEAR(400 * seconds, hotEvents / hot, 0.03 * 400 * seconds);
        EXPECT_EQ(0, otherOff) << "leak events are ON";
        const double expectedLeak = 0.5 * seconds * (area - hot);
        EXPECT_NEAR(expectedLeak, otherEvents, 4 * std::sqrt(expectedLeak));
    }
}

// Normalised correlation of two equally sized event-count images.
double correlation(const Mat& a, const Mat& b)
{
    Mat za, zb;
    subtract(a, mean(a), za);
    subtract(b, mean(b), zb);
    return za.dot(zb) / std::sqrt(za.dot(za) * zb.dot(zb));
}

// The (dx, dy) that maps a strip of the left camera's event counts onto the right camera's best.
Point bestShift(const Mat& left, const Mat& right, int x0, int x1)
{
    Point best;
    double bestScore = -2;
    for (int dy = -4; dy <= 4; dy++)
        for (int dx = 0; dx <= 40; dx++)
        {
            if (x0 - dx < 0)
                continue;
            const Rect l(x0, 8, x1 - x0, left.rows - 16), r(x0 - dx, 8 + dy, x1 - x0, left.rows - 16);
            const double score = correlation(left(l), right(r));
            if (score > bestScore)
            {
                bestScore = score;
                best = Point(dx, dy);
            }
        }
    return best;
}

TEST(Event_SimulatorSensor, imperfect_rectification_moves_the_right_cameras_rows_and_columns)
{
    for (int variant = 0; variant < 5; variant++)
    {
        Ptr<StereoEventSimulator> ideal = StereoEventSimulator::create("plane");
        SimulatorSettings s = ideal->getSettings();
        if (variant == 1)
            s.rightRowOffset = 2.0;
        if (variant == 2)
            s.rightRollRad = 0.02;  // 2 px at 100 px from the centre
        if (variant == 3)
            s.rightColumnOffset = 3.0;
        if (variant == 4)
            s.rightScale = -0.02;  // 2 px at 100 px from the centre
        Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(ideal->getPlanes(), s);
        std::vector<Event> ev;
        Mat gt;
        sim->generate(60000, ev, gt);
        Mat counts[2] = { Mat::zeros(s.resolution, CV_32F), Mat::zeros(s.resolution, CV_32F) };
        for (size_t i = 0; i < ev.size(); i++)
        {
            ASSERT_NEAR(20.0, gt.at<float>((int)i, GT_DISPARITY), 1e-3) << "the truth stays the ideal f B / Z";
            counts[ev[i].camera].at<float>(ev[i].y, ev[i].x) += 1;
        }
        // Three strips of the left camera, seen 20 px further left by the right one: there centred 100 px left
        // of the image centre, on it, and 50 px right of it.
        const Point leftStrip = bestShift(counts[0], counts[1], 20, 60);
        const Point middle = bestShift(counts[0], counts[1], 120, 160);
        const Point rightStrip = bestShift(counts[0], counts[1], 170, 210);
        // Columns: the disparity 20 less the column offset, less the scale times the right camera's distance from
        // the centre (cx = 119.5; the strips' centres 40, 140 and 190 are seen around 20, 120 and 170): -2, 0, +1
        // px with the scale.
        const int columns[5][3] = { { 20, 20, 20 }, { 20, 20, 20 }, { 20, 20, 20 }, { 17, 17, 17 }, { 18, 20, 21 } };
        // Rows: 0 everywhere; +2 everywhere with the offset; with the roll, sin(roll) * (x - cx) in the right
        // camera: -2, 0 and +1 px. The scale moves rows by at most 1 px at the strips' ends, 0 on the whole.
        const int rows[5][3] = { { 0, 0, 0 }, { 2, 2, 2 }, { -2, 0, 1 }, { 0, 0, 0 }, { 0, 0, 0 } };
        const Point found[3] = { leftStrip, middle, rightStrip };
        for (int k = 0; k < 3; k++)
            EXPECT_EQ(Point(columns[variant][k], rows[variant][k]), found[k])
                << "variant " << variant << ", strip " << k << ": " << leftStrip << middle << rightStrip;
    }
}

TEST(Event_SimulatorSensor, the_right_cameras_true_flow_is_the_ideal_one_turned_and_stretched_as_its_grid_is)
{
    // sweepingEdge(): a vertical edge 1 m away moving right at 0.4 m/s, f x 0.4 px/s on the ideal grid. The
    // right camera's grid, rolled by 0.05 rad and scaled by 1.05, sees it move 1.05 times as fast, turned by the roll.
    SimulatorSettings s = idealSmallSensor();
    s.rightRollRad = 0.05;
    s.rightScale = 0.05;
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(sweepingEdge(), s);
    std::vector<Event> ev;
    Mat gt;
    sim->generate(150000, ev, gt);
    const double speed = s.focalLength * 0.4;
    int counted[2] = { 0, 0 };
    for (size_t i = 0; i < ev.size(); i++)
    {
        const int c = ev[i].camera;
        const float fx = gt.at<float>((int)i, GT_FLOW_X), fy = gt.at<float>((int)i, GT_FLOW_Y);
        const double expected = c == CAMERA_RIGHT ? 1.05 * speed : speed, angle = c == CAMERA_RIGHT ? 0.05 : 0.0;
        ASSERT_NEAR(expected, std::hypot(fx, fy), 0.01 * expected) << "camera " << c << ", event " << i;
        ASSERT_NEAR(angle, std::atan2(fy, fx), 0.015) << "camera " << c << ", event " << i;  // within 0.9 degrees
        ASSERT_NEAR(1e6 / expected, gt.at<float>((int)i, GT_LIFETIME), 0.01 * 1e6 / expected) << "camera " << c;
        counted[c]++;
    }
    EXPECT_GT(counted[0], 500);
    EXPECT_GT(counted[1], 500);
}

TEST(Event_SimulatorSensor, swinging_plane_moves_as_its_pivot_and_swing_rate_say)
{
    // A bar hanging from a pivot, swinging about the optical axis: its ground-truth flow at the lower end is
    // the swing rate times the distance to the pivot, across the bar.
    SimulatedPlane back;
    back.center = Vec3d(0, 0, 3);
    back.halfSize = Vec2d(10, 10);
    back.texture = TEXTURE_UNIFORM;
    back.intensity = 0.1;
    SimulatedPlane bar = back;
    bar.center = Vec3d(0, 0.1, 1);
    bar.halfSize = Vec2d(0.02, 0.2);
    bar.intensity = 0.9;
    bar.swingAxis = Vec3d(0, 0, 1);
    bar.swingPivot = Vec2d(0, -0.2);   // the top end, at (0, -0.1, 1)
    bar.swingAmplitude = 0.3;
    bar.swingFrequency = 1.0;
    SimulatorSettings s = idealSmallSensor();
    s.resolution = Size(160, 120);
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create({ back, bar }, s);
    std::vector<Event> ev;
    Mat gt;
    sim->generate(100000, ev, gt);
    ASSERT_GT(ev.size(), 200u);
    // At t, the angle is 0.3 sin(2 pi t) and the rate 0.3 * 2 pi cos(2 pi t) rad/s. An event at image row y
    // (below the pivot's row) lies (y - y_pivot) / cos(angle) px from the pivot along the bar; the bar's long
    // edges move across the bar, along their own normal, at |rate| times that radius [px/s].
    const double f = s.focalLength, cy = 0.5 * (s.resolution.height - 1), pivotRow = cy + (-0.1) * f;
    int checked = 0;
    for (size_t i = 0; i < ev.size(); i++)
    {
        if (ev[i].camera != CAMERA_LEFT || gt.at<float>((int)i, GT_DEPTH) == 0)
            continue;
        const double t = ev[i].t * 1e-6, angle = 0.3 * std::sin(2 * CV_PI * t), rate = 0.3 * 2 * CV_PI * std::cos(2 * CV_PI * t);
        const double radiusPx = (ev[i].y - pivotRow) / std::cos(angle);
        if (radiusPx < 20 || std::abs(gt.at<float>((int)i, GT_FLOW_Y)) > 0.2 * std::abs(gt.at<float>((int)i, GT_FLOW_X)))
            continue;  // near the pivot, or on the bar's end (a horizontal edge)
        const double flow = std::hypot(gt.at<float>((int)i, GT_FLOW_X), gt.at<float>((int)i, GT_FLOW_Y));
        EXPECT_NEAR(std::abs(rate) * radiusPx, flow, 0.05 * std::abs(rate) * radiusPx + 2) << i;
        checked++;
    }
    EXPECT_GT(checked, 100);
}

// A bright bar (0.9) 0.1 m wide at 1 m crossing a dark background (0.1) at 80 px/s: each pixel it passes gets
// its leading edge (ON, log contrast ln 9) and then its trailing edge (OFF).
std::vector<SimulatedPlane> crossingBar()
{
    std::vector<SimulatedPlane> scene = sweepingEdgeScene(1.0, 0.4, -0.1);
    scene[1].center[0] = -0.15;
    scene[1].halfSize[0] = 0.05;
    return scene;
}

typedef std::map<std::tuple<int, int, int>, std::vector<Event>> PixelEvents;  // (camera, y, x) -> events

PixelEvents eventsPerPixel(const std::vector<Event>& events)
{
    PixelEvents out;
    for (const Event& e : events)
        out[std::make_tuple((int)e.camera, (int)e.y, (int)e.x)].push_back(e);
    return out;
}

TEST(Event_SimulatorSensor, extra_latency_delays_each_camera_and_polarity_by_its_own_amount)
{
    const Vec4d extra(100, 300, 700, 1300);  // left ON, left OFF, right ON, right OFF
    SimulatorSettings s = idealSmallSensor();
    std::vector<Event> base, late;
    simulate(crossingBar(), s, 500000, nullptr, &base);
    s.extraLatencyUs = extra;
    simulate(crossingBar(), s, 502000, nullptr, &late);
    const PixelEvents a = eventsPerPixel(base), b = eventsPerPixel(late);
    int compared[4] = { 0, 0, 0, 0 };
    for (const auto& kv : a)
    {
        const std::vector<Event>& before = kv.second;
        const std::vector<Event>& after = b.at(kv.first);
        ASSERT_GE(after.size(), before.size());
        for (size_t k = 0; k < before.size(); k++)
        {
            const int which = 2 * before[k].camera + (before[k].p == POLARITY_ON ? 0 : 1);
            ASSERT_EQ(before[k].p, after[k].p);
            // Whole microseconds added to the crossing time before it is floored: exact.
            EXPECT_EQ((int64)extra[which], after[k].t - before[k].t) << "camera " << (int)before[k].camera << " p " << (int)before[k].p;
            compared[which]++;
        }
    }
    for (int which = 0; which < 4; which++)
        EXPECT_GT(compared[which], 500) << "events of camera " << which / 2 << (which % 2 ? " OFF" : " ON");
}

TEST(Event_SimulatorSensor, right_clock_offset_and_drift_restamp_every_right_event)
{
    SimulatorSettings s = idealSmallSensor();
    s.latencyUs = 50;
    s.latencySigmaUs = 20;
    s.jitterUs = 30;
    s.noiseRateHz = 2;
    s.hotPixelShare = 0.01;
    s.hotPixelRateHz = 200;
    s.leakRateHz = 1;
    std::vector<Event> base;
    simulate(crossingBar(), s, 400000, nullptr, &base);
    for (const Vec2d& clock : { Vec2d(3000, 0), Vec2d(-4500, 0), Vec2d(2500, 300), Vec2d(-1000, -200) })
    {
        SimulatorSettings shifted = s;
        shifted.rightClockOffsetUs = clock[0];
        shifted.rightClockDriftPpm = clock[1];
        std::vector<Event> events;
        simulate(crossingBar(), shifted, 400000, nullptr, &events);  // checks the stream is in time order
        const auto restamp = [&](int64 t) { return t + (int64)std::llround(clock[0] + clock[1] * 1e-6 * (double)t); };
        // The events each clock stamps before 300 ms: left ones as they were, right ones restamped.
        const int64 end = 300000;
        std::vector<Event> expected, got;
        for (const Event& e : base)
        {
            Event r = e;
            if (e.camera == CAMERA_RIGHT)
                r.t = restamp(e.t);
            if (e.t < end)
                expected.push_back(r);
        }
        for (const Event& e : events)
            if (e.t < (e.camera == CAMERA_RIGHT ? restamp(end) : end))
                got.push_back(e);
        const auto order = [](const Event& x, const Event& y) {
            return std::make_tuple(x.camera, x.t, x.y, x.x, x.p) < std::make_tuple(y.camera, y.t, y.y, y.x, y.p);
        };
        std::sort(expected.begin(), expected.end(), order);
        std::sort(got.begin(), got.end(), order);
        ASSERT_GT(expected.size(), 4000u);
        ASSERT_EQ(expected.size(), got.size()) << "offset " << clock[0] << " us, drift " << clock[1] << " ppm";
        for (size_t i = 0; i < expected.size(); i++)
            ASSERT_EQ(expected[i], got[i]) << i << ", offset " << clock[0] << " us, drift " << clock[1] << " ppm";
    }
}

TEST(Event_SimulatorSensor, thresholds_per_camera_and_polarity_give_their_closed_form_counts)
{
    // Log contrast L = ln 9 up, then down again: floor(L / C_on) ON events from the dark level, then OFF
    // events from the last ON level down to the dark level: floor(n_on C_on / C_off).
    SimulatorSettings s = idealSmallSensor();
    s.thresholdOn = 0.3;
    s.thresholdOff = 0.22;
    s.rightThresholdScale = 0.8;
    std::vector<Event> events;
    simulate(crossingBar(), s, 500000, nullptr, &events);
    const double L = std::log(9.0);
    for (int c = 0; c < 2; c++)
    {
        const double on = s.thresholdOn * (c == CAMERA_RIGHT ? s.rightThresholdScale : 1.0);
        const double off = s.thresholdOff * (c == CAMERA_RIGHT ? s.rightThresholdScale : 1.0);
        const int nOn = (int)std::floor(L / on), nOff = (int)std::floor(nOn * on / off);
        int crossed = 0;
        for (const auto& kv : eventsPerPixel(events))
        {
            if (std::get<0>(kv.first) != c || kv.second.front().p != POLARITY_ON)
                continue;  // another camera, or under the bar from the start
            int countOn = 0, countOff = 0;
            for (const Event& e : kv.second)
                (e.p == POLARITY_ON ? countOn : countOff)++;
            EXPECT_EQ(nOn, countOn) << "camera " << c;
            if (countOff > 0)  // the trailing edge has passed
            {
                EXPECT_EQ(nOff, countOff) << "camera " << c;
                crossed++;
            }
        }
        EXPECT_GE(crossed, 15 * 32) << "camera " << c;  // 20 columns are crossed in 500 ms
    }
}

TEST(Event_SimulatorSensor, every_effect_on_streams_alike_in_any_chunks)
{
    SimulatorSettings s = idealSmallSensor();
    s.latencyUs = 300;
    s.latencySigmaUs = 200;
    s.jitterUs = 150;
    s.hotPixelShare = 0.01;
    s.hotPixelRateHz = 200;
    s.leakRateHz = 1;
    s.noiseRateHz = 2;
    s.rightRowOffset = 0.7;
    s.rightRollRad = 0.01;
    s.thresholdSigma = 0.03;
    s.refractoryUs = 200;
    s.blurSigmaPx = 0.7;
    s.flickerFrequencyHz = 120;
    s.extraLatencyUs = Vec4d(10, 40, 70, 130);
    s.rightClockOffsetUs = -3000;  // stamps before the simulated time: generate() must simulate ahead
    s.rightClockDriftPpm = 150;
    std::vector<SimulatedPlane> scene = sweepingEdge();
    scene[0].flickerDepth = 0.3;  // the background flickers, the edge does not
    Ptr<StereoEventSimulator> whole = StereoEventSimulator::create(scene, s);
    Ptr<StereoEventSimulator> chunked = StereoEventSimulator::create(scene, s);
    std::vector<Event> all, part, joined;
    Mat gtAll, gtPart;
    whole->generate(200000, all, gtAll);
    std::vector<Mat> truths;
    for (double t = 7000; t < 200000 + 7000; t += 7000)
    {
        chunked->generate(std::min(t, 200000.0), part, gtPart);
        joined.insert(joined.end(), part.begin(), part.end());
        truths.push_back(gtPart.clone());
    }
    ASSERT_GT(all.size(), 3000u);
    ASSERT_EQ(all.size(), joined.size());
    for (size_t i = 0; i < all.size(); i++)
        ASSERT_EQ(all[i], joined[i]) << i;
    Mat gtJoined;
    vconcat(truths, gtJoined);
    EXPECT_EQ(0, cvtest::norm(gtAll, gtJoined, NORM_INF));
}

}}  // namespace
