// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The algorithms at the edges of their input: noise only, every event at one pixel, a single event,
// timestamps near the int64 limits and across 32-bit wraps, and state that stays O(sensor pixels) however
// many events go through.

#include "test_precomp.hpp"

#include <limits>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace opencv_test { namespace {


// Uniform background activity on both sensors: every pixel fires at random, independently of the others.
std::vector<Event> uniformNoise(Size size, int count, double meanGapUs, int64 t0, uint64 seed, bool stereo)
{
    RNG rng(seed);
    std::vector<Event> ev;
    ev.reserve((size_t)count);
    double t = (double)t0;
    for (int i = 0; i < count; i++)
    {
        t += rng.uniform(0.0, 2 * meanGapUs);
        ev.push_back(Event(t0 + (int64)(t - (double)t0), rng.uniform(0, size.width), rng.uniform(0, size.height),
                           rng.uniform(0, 2), stereo ? rng.uniform(0, 2) : CAMERA_LEFT));
    }
    return ev;
}

// A vertical ON edge sweeping right at 500 px/s (2000 us per pixel) over a rectified pair, right sensor
// `disparity` px to the left; the first event at t0. Closed form: lifetime 2000 us, disparity `disparity`.
std::vector<Event> sweepingEdge(Size size, int disparity, int64 t0, bool stereo)
{
    std::vector<Event> ev;
    for (int x = 0; x < size.width; x++)
        for (int y = 0; y < size.height; y++)
        {
            const int64 t = t0 + (int64)x * 2000 + y;  // y: distinct, ordered timestamps within a column
            ev.push_back(Event(t, x, y, POLARITY_ON, CAMERA_LEFT));
            if (stereo && x - disparity >= 0)
                ev.push_back(Event(t, x - disparity, y, POLARITY_ON, CAMERA_RIGHT));
        }
    return ev;
}

std::vector<Event> shifted(std::vector<Event> ev, int64 by)
{
    for (Event& e : ev)
        e.t += by;
    return ev;
}

void expectFinite(const Mat& m, const std::string& what)
{
    ASSERT_FALSE(m.empty()) << what << " is empty: nothing to check";
    Mat f = m.reshape(1);
    ASSERT_EQ(f.depth(), CV_32F) << what;
    EXPECT_TRUE(cv::checkRange(f, true)) << what << " has a NaN or an infinity";
}

// Every output of the matcher is finite and within its documented range.
void expectSaneStereoOutputs(const std::vector<Event>& ev, const Mat& d, const Mat& lt, const Mat& flags,
                             const Mat& depth, const Mat& flow, int minDisparity, int maxDisparity,
                             const std::string& what)
{
    ASSERT_EQ(d.rows, (int)ev.size()) << what;
    expectFinite(d, what + ": disparity");
    expectFinite(lt, what + ": lifetime");
    expectFinite(depth, what + ": depth");
    expectFinite(flow, what + ": flow");
    for (int i = 0; i < d.rows; i++)
    {
        const float di = d.at<float>(i);
        const int fl = flags.at<int>(i);
        ASSERT_TRUE(di == (float)StereoEventMatcher::NO_DISPARITY ||
                    (di >= minDisparity - 1 && di <= maxDisparity + 1)) << what << ": event " << i << " disparity " << di;
        ASSERT_EQ(di >= 0, (fl & STEREO_HAS_DISPARITY) != 0) << what << ": event " << i;
        ASSERT_GE(lt.at<float>(i), 0.f) << what << ": event " << i;
        ASSERT_EQ(lt.at<float>(i) > 0, (fl & STEREO_HAS_LIFETIME) != 0) << what << ": event " << i;
    }
}

TEST(Event_Extremes, noise_only_input_gives_finite_outputs_and_mostly_noise)
{
    const Size size(240, 180);
    // 200 kev/s over a DAVIS240: each pixel fires about 5 times a second, so a 5x5 window holds about 12
    // events in the 100 ms fitting window, scattered in time: no plane should be found for most of them.
    const std::vector<Event> mono = uniformNoise(size, 40000, 5.0, 1000, 7, false);
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(size);
    Mat lt, flow, status;
    est->process(mono, lt, flow, status);
    expectFinite(lt, "lifetime");
    expectFinite(flow, "flow");
    int noise = 0;
    for (int i = 0; i < lt.rows; i++)
    {
        ASSERT_GE(lt.at<float>(i), 0.f);
        ASSERT_EQ(lt.at<float>(i) == 0, status.at<uchar>(i) == LIFETIME_NOISE) << "event " << i;
        noise += status.at<uchar>(i) == LIFETIME_NOISE;
    }
    EXPECT_GE(noise, 0.9 * lt.rows) << "uniform noise should mostly stay without a plane";

    const std::vector<Event> stereo = uniformNoise(size, 40000, 5.0, 1000, 8, true);
    for (int method : kStereoMethods)
    {
        StereoMethod m(size, method);
        m.setCalibration(StereoCalibration::fromRectified(size, 200, 0.1));
        Mat d, slt, flags, depth, sflow;
        m.process(stereo, d, slt, flags, depth, sflow);
        expectSaneStereoOutputs(stereo, d, slt, flags, depth, sflow, 0, 40, m.name());
        for (int i = 0; i < d.rows; i++)
        {
            if (d.at<float>(i) > 0)
            {
                ASSERT_GT(depth.at<float>(i), 0.f) << m.name() << ": event " << i;
            }
        }
    }
}

TEST(Event_Extremes, all_events_at_one_pixel)
{
    // 5000 events at one pixel, some sharing a timestamp: the surface keeps only the latest per pixel, so a
    // plane can never be fitted (a plane needs three pixels) and every event is noise.
    const Size size(64, 48);
    std::vector<Event> mono;
    for (int i = 0; i < 5000; i++)
        mono.push_back(Event(1000 + i / 3, 20, 10, i % 2));
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(size);
    Mat lt, flow, status;
    est->process(mono, lt, flow, status);
    EXPECT_EQ(countNonZero(lt), 0);
    EXPECT_EQ(est->getStatusCount(LIFETIME_NOISE), 5000.0);
    expectFinite(flow, "flow");

    Ptr<EventSurface> surface = EventSurface::create(size);
    surface->update(mono);
    Mat counts;
    surface->renderEventCount(counts);
    ASSERT_EQ(counts.type(), CV_32S);
    EXPECT_EQ(countNonZero(counts), 1) << "only the one pixel has events";
    EXPECT_EQ(counts.at<int>(10, 20), 5000);
    EXPECT_EQ(surface->getEventCount(), 5000.0);
    Mat on;
    surface->getSurface(POLARITY_ON, on, CV_64F, 0);
    EXPECT_EQ(on.at<double>(10, 20), (double)mono.back().t);  // the last event (i = 4999) is ON

    // Stereo: the left pixel (20, 10) and the right pixel (14, 10) fire together, every 100 us for 300 ms.
    // With a fixed activity interval the only candidate with structure is d = 6. With lifetimes no event gets
    // one (all noise): only the cold start (the plane fit's first 100 ms) keeps them active, for 2.5 fixed
    // intervals, so they match there and never after it (+ the 25 ms the last of them stays active).
    std::vector<Event> stereo;
    const int64 firstTime = 1000, coldEnd = firstTime + 100000 + 25000;
    for (int i = 0; i < 3000; i++)
    {
        stereo.push_back(Event(firstTime + 100 * i, 20, 10, POLARITY_ON, CAMERA_LEFT));
        stereo.push_back(Event(firstTime + 100 * i, 14, 10, POLARITY_ON, CAMERA_RIGHT));
    }
    for (int mode : kStereoMethods)
    {
        StereoMethod m(size, mode);
        if (m.matcher)
        {
            m.matcher->setLookAhead(0);  // decided on arrival: an event sees only the events before it
            m.matcher->setNoiseActiveTime(0);  // the paper: an event without a lifetime is inactive after the cold start
        }
        Mat d, slt, flags, depth, sflow;
        m.process(stereo, d, slt, flags, depth, sflow);
        const std::string name = m.name();
        expectSaneStereoOutputs(stereo, d, slt, flags, depth, sflow, 0, 40, name);
        int matched = 0, matchedAfterColdStart = 0;
        for (int i = 0; i < d.rows; i++)
            if (d.at<float>(i) >= 0)
            {
                matched++;
                matchedAfterColdStart += stereo[(size_t)i].t >= coldEnd;
                ASSERT_NEAR(d.at<float>(i), 6.0, 0.5) << name << ": event " << i;
            }
        if (mode == STEREO_COUPLED || mode == STEREO_DECOUPLED)
        {
            EXPECT_GE(matched, 1000) << name << ": the cold start keeps events active for the fixed interval";
            EXPECT_EQ(matchedAfterColdStart, 0) << name << ": after the cold start no event is ever active";
        }
        if (mode == STEREO_FIXED_INTERVAL)
        {
            EXPECT_GE(matched, d.rows / 2) << name << ": the one candidate should match";
        }
        EXPECT_EQ(countNonZero(slt), 0) << name << ": no plane through one pixel";
    }
    // With look-ahead each pixel's events that have arrived but are not decided yet stay visible: after the
    // cold start every event with a later one of the other sensor within the look-ahead matches, at d = 6.
    Ptr<StereoEventMatcher> ahead = StereoEventMatcher::create(size, STEREO_COUPLED);
    ahead->setLookAhead(1000);
    Mat d;
    ahead->process(stereo, d);
    int matchedAfterColdStart = 0;
    for (int i = 0; i < d.rows; i++)
        if (d.at<float>(i) >= 0 && stereo[(size_t)i].t >= coldEnd)
        {
            matchedAfterColdStart++;
            ASSERT_NEAR(d.at<float>(i), 6.0, 0.5) << "event " << i;
        }
    EXPECT_GE(matchedAfterColdStart, 2 * (int)std::count_if(stereo.begin(), stereo.end(), [&](const Event& e) {
                  return e.camera == CAMERA_LEFT && e.t >= coldEnd && e.t + 1000 <= stereo.back().t; }) * 9 / 10);
}

TEST(Event_Extremes, single_event_and_empty_packets)
{
    const Size size(240, 180);
    const Event one(123456, 100, 50, POLARITY_OFF, CAMERA_LEFT);
    Ptr<LifetimeEstimator> est = LifetimeEstimator::create(size);
    Vec2f flow(7, 7);
    int status = -1;
    EXPECT_EQ(est->processEvent(one, flow, status), 0.f);
    EXPECT_EQ(status, (int)LIFETIME_NOISE);
    EXPECT_EQ(flow, Vec2f(0, 0));
    Mat img;
    est->renderActiveEvents(123456, img);
    EXPECT_EQ(countNonZero(img), 0) << "a noise event is never active";

    for (int mode : kStereoMethods)
    {
        StereoMethod m(size, mode);
        const std::string name = m.name();
        Mat d, lt, flags;
        m.process(std::vector<Event>(), d, lt, flags);
        EXPECT_EQ(d.rows, 0) << name;
        m.process(std::vector<Event>(1, one), d, lt, flags);
        ASSERT_EQ(d.rows, 1) << name;
        EXPECT_EQ(lt.at<float>(0), 0.f) << name;
        Mat render;
        m.renderDisparity(123456, render, CAMERA_LEFT, false);
        EXPECT_EQ(render.size(), size) << name;
        if (m.frames)
        {
            // The baseline is StereoSGBM as users run it: against an empty right frame every disparity costs
            // the same and SGBM returns its first one, minDisparity. Kept as it is, so that the comparison
            // with the event methods is honest.
            EXPECT_EQ(d.at<float>(0), (float)m.frames->getMinDisparity()) << name;
            continue;
        }
        EXPECT_EQ(d.at<float>(0), (float)StereoEventMatcher::NO_DISPARITY) << name;
        EXPECT_NE(flags.at<int>(0) & STEREO_NO_COUNTERPART, 0) << name << ": the right sensor has shown nothing";
        EXPECT_EQ(countNonZero(render.reshape(1)), 0) << name;
    }
}

// The closed-form edge gives the same lifetimes, flow and disparities wherever it lies on the time axis:
// at 0, near the largest int64 timestamp, near the smallest, and just after a 32-bit microsecond wrap.
TEST(Event_Extremes, results_do_not_depend_on_where_time_starts)
{
    const Size size(48, 16);
    const std::vector<Event> mono = sweepingEdge(size, 0, 0, false);
    const std::vector<Event> stereo = sweepingEdge(size, 5, 0, true);
    const int64 span = mono.back().t + 1;
    // Multiples of the frame baseline's 33 ms window, so that its windows cut the edge where they cut it at 0.
    const int64 w = 33000;
    const int64 starts[] = {
        (std::numeric_limits<int64>::max() - span) / w * w,  // the last representable microseconds
        std::numeric_limits<int64>::min() / w * w,           // negative, at the other end
        (((int64)1 << 32) - span / 2) / w * w,                // straddles a 32-bit wrap of a sensor clock
        -(span / 2) / w * w - w                               // straddles zero
    };

    Mat lt0, flow0, status0;
    LifetimeEstimator::create(size)->process(mono, lt0, flow0, status0);
    ASSERT_GT(countNonZero(lt0), (int)mono.size() / 2) << "the reference run should find planes";
    Mat d0[4], slt0[4];
    for (int k = 0; k < 4; k++)
        StereoMethod(size, kStereoMethods[k]).process(stereo, d0[k], slt0[k]);

    for (int64 start : starts)
    {
        SCOPED_TRACE(cv::format("first timestamp %lld", (long long)start));
        Mat lt, flow, status;
        Ptr<LifetimeEstimator> est = LifetimeEstimator::create(size);
        est->process(shifted(mono, start), lt, flow, status);
        EXPECT_EQ(cvtest::norm(lt, lt0, NORM_INF), 0.0);
        EXPECT_EQ(cvtest::norm(flow, flow0, NORM_INF), 0.0);
        EXPECT_EQ(cvtest::norm(status, status0, NORM_INF), 0.0);
        Mat img;
        est->renderActiveEvents((double)(start + span / 2), img);  // double time near the limits: no crash

        Ptr<EventSurface> surface = EventSurface::create(size);
        surface->update(shifted(mono, start));
        Mat s;
        surface->getSurface(POLARITY_ON, s, CV_64F, (double)start);
        EXPECT_TRUE(cv::checkRange(s, true));
        EXPECT_NEAR(s.at<double>(3, size.width - 1), (double)((size.width - 1) * 2000 + 3), 4096.0)
            << "relative to its origin the surface keeps the edge's timing (double precision near 2^63 is 1-2 ks)";

        for (int k = 0; k < 4; k++)
        {
            Mat d, slt;
            StereoMethod m(size, kStereoMethods[k]);
            m.process(shifted(stereo, start), d, slt);
            EXPECT_EQ(cvtest::norm(d, d0[k], NORM_INF), 0.0) << m.name();
            EXPECT_EQ(cvtest::norm(slt, slt0[k], NORM_INF), 0.0) << m.name();
        }
    }
}

// INT64_MIN is EventSurface::NO_EVENT: an event stamped with it would be invisible, so it is refused by name.
TEST(Event_Extremes, the_reserved_no_event_time_is_refused)
{
    const Event reserved(EventSurface::NO_EVENT, 3, 4, POLARITY_ON, CAMERA_LEFT);
    Ptr<EventSurface> surface = EventSurface::create(Size(8, 8));
    try
    {
        surface->update(std::vector<Event>(1, reserved));
        FAIL() << "EventSurface accepted t = INT64_MIN";
    }
    catch (const cv::Exception& ex)
    {
        EXPECT_NE(ex.msg.find("NO_EVENT"), std::string::npos) << ex.msg;
    }
    EXPECT_EQ(surface->getEventCount(), 0.0) << "a refused packet leaves the surface as it was";
    Vec2f flow;
    int status;
    EXPECT_THROW(LifetimeEstimator::create(Size(8, 8))->processEvent(reserved, flow, status), cv::Exception);
    Mat d;
    EXPECT_THROW(StereoEventMatcher::create(Size(8, 8), STEREO_COUPLED)->process(std::vector<Event>(1, reserved), d),
                 cv::Exception);
}

// A jump forward by far more than any time window (a camera unplugged for an hour, a 32-bit wrap unrolled
// into a 2^32 us step) leaves nothing active from before the jump; the stream goes on after it as a new one
// (with the matcher's cold start, see StereoEventMatcher).
TEST(Event_Extremes, a_long_gap_forgets_the_past)
{
    const Size size(48, 16);
    const std::vector<Event> edge = sweepingEdge(size, 5, 0, true);
    std::vector<Event> twice = edge;
    const int64 gap = (edge.back().t + ((int64)1 << 32)) / 33000 * 33000;  // the frame baseline's windows line up
    const std::vector<Event> later = shifted(edge, gap);
    twice.insert(twice.end(), later.begin(), later.end());
    for (int mode : kStereoMethods)
    {
        const std::string name = StereoMethod(size, mode).name();
        Mat dOnce, ltOnce, dTwice, ltTwice;
        StereoMethod(size, mode).process(edge, dOnce, ltOnce);
        StereoMethod(size, mode).process(twice, dTwice, ltTwice);
        const Range second((int)edge.size(), (int)twice.size());
        EXPECT_EQ(cvtest::norm(dTwice.rowRange(second), dOnce, NORM_INF), 0.0) << name;
        EXPECT_EQ(cvtest::norm(ltTwice.rowRange(second), ltOnce, NORM_INF), 0.0) << name;
    }
}

#if defined(__GLIBC__) && defined(__GLIBC_PREREQ)
#if __GLIBC_PREREQ(2, 33) && !defined(__SANITIZE_ADDRESS__)
#define OPENCV_EVENT_HEAP_PROBE 1
size_t heapInUse()
{
    return mallinfo2().uordblks;
}
#endif
#endif

// State is O(sensor pixels): almost seven times more events leave the heap where it was.
TEST(Event_Extremes, state_does_not_grow_with_the_number_of_events)
{
#ifndef OPENCV_EVENT_HEAP_PROBE
    throw SkipTestException("needs glibc's mallinfo2 and no AddressSanitizer (its allocator is not glibc's)");
#else
    const Size size(240, 180);
    const int packet = 10000;
    for (int mode : kStereoMethods)
    {
        StereoMethod m(size, mode);
        const std::string name = m.name();
        Ptr<EventSurface> surface = EventSurface::create(size);
        Mat d, lt, flags;
        size_t afterFew = 0;
        int64 t0 = 1000;
        for (int k = 0; k < 20; k++)
        {
            // Noise on both sensors: every packet activates, matches and expires events all over the sensor.
            std::vector<Event> ev = uniformNoise(size, packet, 2.0, t0, (uint64)k + 1, true);
            t0 = ev.back().t + 1;
            m.process(ev, d, lt, flags);
            surface->update(ev);
            if (k == 2)
                afterFew = heapInUse();
        }
        const size_t afterMany = heapInUse();
        EXPECT_LE((double)afterMany, (double)afterFew + 256 * 1024)
            << name << ": the heap grew from " << afterFew << " to " << afterMany << " bytes between 30 k and 200 k events";
    }
#endif
}

}}  // namespace
