// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Runs a filter on a packet and returns its mask as a vector (255 kept, 0 removed).
std::vector<uchar> keepMask(EventFilter& f, const std::vector<Event>& ev)
{
    std::vector<Event> kept;
    Mat mask;
    f.filter(ev, kept, mask);
    std::vector<uchar> m(mask.begin<uchar>(), mask.end<uchar>());
    EXPECT_EQ((size_t)std::count(m.begin(), m.end(), (uchar)255), kept.size());
    return m;
}

int keptCount(const std::vector<uchar>& mask) { return (int)std::count(mask.begin(), mask.end(), (uchar)255); }

// A vertical edge spanning rows 0..h-1, stepping one column right every stepUs, from column 0 to w-1.
std::vector<Event> sweepingEdge(int w, int h, int64 stepUs, int64 t0 = 1000)
{
    std::vector<Event> ev;
    for (int x = 0; x < w; x++)
        for (int y = 0; y < h; y++)
            ev.push_back(Event(t0 + x * stepUs, x, y, POLARITY_ON));
    return ev;
}

// A pixel alternating ON and OFF bursts of @p burst events each, one ON burst per period, for @p periods.
void addPolarityCycles(std::vector<Event>& ev, int x, int y, int64 periodUs, int periods, int burst, int64 t0 = 0)
{
    for (int k = 0; k < periods; k++)
        for (int half = 0; half < 2; half++)
            for (int b = 0; b < burst; b++)
                ev.push_back(Event(t0 + k * periodUs + half * periodUs / 2 + b * 100, x, y,
                                   half == 0 ? POLARITY_ON : POLARITY_OFF));
}

void sortByTime(std::vector<Event>& ev)
{
    std::stable_sort(ev.begin(), ev.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
}

// A filter by name; hot_pixels learns for its first 50 ms (the default second is longer than the stream).
Ptr<EventFilter> shortLearningFilter(const String& name, Size size)
{
    Ptr<EventFilter> f = createEventFilter(name, size);
    if (Ptr<HotPixelFilter> hot = f.dynamicCast<HotPixelFilter>())
        hot->setLearningTime(50000);
    return f;
}

std::vector<Ptr<EventFilter> > everyFilter(Size size)
{
    std::vector<Ptr<EventFilter> > filters;
    for (const String& name : getEventFilterNames())
        filters.push_back(createEventFilter(name, size));
    return filters;
}

TEST(Event_Filters, background_activity_removes_isolated_events_and_keeps_a_moving_edge)
{
    Ptr<BackgroundActivityFilter> f = BackgroundActivityFilter::create(Size(40, 30), 2000);
    // Column k fires 500 us after column k - 1: every event but the very first has a neighbour within 2 ms
    // (the previous column, or the row above in the same column).
    std::vector<uchar> m = keepMask(*f, sweepingEdge(20, 10, 500));
    EXPECT_EQ(0, m[0]);
    EXPECT_EQ(20 * 10 - 1, keptCount(m));

    // Isolated events: 10 ms apart and far from each other and from the edge: none has a recent neighbour.
    std::vector<Event> noise;
    for (int i = 0; i < 8; i++)
        noise.push_back(Event(20000 + i * 10000, 25 + (i % 4) * 4, 5 + (i / 4) * 10, i % 2));
    EXPECT_EQ(0, keptCount(keepMask(*f, noise)));

    // A pixel firing alone at 1 kHz does not support itself.
    std::vector<Event> hot;
    for (int i = 0; i < 50; i++)
        hot.push_back(Event(200000 + i * 1000, 35, 25, POLARITY_ON));
    EXPECT_EQ(0, keptCount(keepMask(*f, hot)));
    EXPECT_EQ(200.0 + 8 + 50, f->getProcessedCount());
    EXPECT_EQ(199.0, f->getKeptCount());

    // A neighbour older than the correlation time does not count either.
    f->reset();
    std::vector<Event> pair{ Event(0, 5, 5, 1), Event(2001, 6, 5, 1), Event(3000, 7, 5, 1) };
    EXPECT_EQ((std::vector<uchar>{ 0, 0, 255 }), keepMask(*f, pair));
}

TEST(Event_Filters, trail_keeps_the_first_event_of_each_burst_and_every_polarity_change)
{
    Ptr<TrailFilter> f = TrailFilter::create(Size(8, 8), 5000);
    std::vector<Event> ev;
    for (int i = 0; i < 5; i++)
        ev.push_back(Event(1000 + i * 1000, 3, 3, POLARITY_ON));   // one burst: only the first passes
    ev.push_back(Event(5500, 3, 3, POLARITY_OFF));                   // polarity change: a new edge
    ev.push_back(Event(6000, 3, 3, POLARITY_OFF));                   // its trail
    ev.push_back(Event(11001, 3, 3, POLARITY_OFF));                  // more than 5 ms later: a new burst
    ev.push_back(Event(11002, 4, 3, POLARITY_OFF));                  // another pixel: its own first event
    EXPECT_EQ((std::vector<uchar>{ 255, 0, 0, 0, 0, 255, 0, 255, 255 }), keepMask(*f, ev));
    // Exactly the threshold apart is still the same burst.
    EXPECT_EQ((std::vector<uchar>{ 0 }), keepMask(*f, std::vector<Event>{ Event(16001, 3, 3, POLARITY_OFF) }));
}

TEST(Event_Filters, refractory_keeps_one_event_per_period_and_pixel)
{
    Ptr<RefractoryFilter> f = RefractoryFilter::create(Size(8, 8), 1000);
    // A pixel firing every 300 us for 30 events: kept at 0, 1200, 2400, ... (the first multiple of 300 at
    // least 1000 after the last kept one), so 30 * 300 / 1200 = 8 (rounded up) events pass.
    std::vector<Event> ev;
    for (int i = 0; i < 30; i++)
        ev.push_back(Event(i * 300, 2, 2, i % 2));
    std::vector<uchar> m = keepMask(*f, ev);
    EXPECT_EQ(8, keptCount(m));
    for (int i = 0; i < 30; i++)
        EXPECT_EQ(i % 4 == 0 ? 255 : 0, (int)m[i]) << "event " << i;
}

TEST(Event_Filters, hot_pixel_at_1khz_is_found_masked_saved_and_loaded)
{
    const Size size(64, 48);
    // One second: background activity at 1 Hz per pixel, an edge sweeping the sensor, and pixel (10, 20)
    // firing at 1 kHz.
    RNG rng(7);
    std::vector<Event> ev = sweepingEdge(64, 48, 15000, 10000);
    for (int i = 0; i < size.area(); i++)
        ev.push_back(Event(rng.uniform(0, 1000000), rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2)));
    for (int i = 0; i < 1000; i++)
        ev.push_back(Event(i * 1000 + 500, 10, 20, POLARITY_ON));
    sortByTime(ev);

    Ptr<HotPixelFilter> f = HotPixelFilter::create(size);
    f->learn(ev);
    EXPECT_EQ(1, f->detect());
    Mat mask;
    f->getMask(mask);
    EXPECT_EQ(1, countNonZero(mask));
    EXPECT_EQ(255, (int)mask.at<uchar>(20, 10));
    std::vector<Event> kept;
    f->filter(ev, kept);
    const size_t atHotPixel = (size_t)std::count_if(ev.begin(), ev.end(), [](const Event& e) { return e.x == 10 && e.y == 20; });
    EXPECT_LE(1001u, atHotPixel);  // its own 1000, the edge's, and any background event that fell there
    EXPECT_EQ(ev.size() - atHotPixel, kept.size());
    for (const Event& e : kept)
        ASSERT_FALSE(e.x == 10 && e.y == 20);

    // The mask travels with the parameters through FileStorage.
    const std::string path = cv::tempfile(".yml");
    f->save(path);
    Ptr<HotPixelFilter> g = Algorithm::load<HotPixelFilter>(path);
    std::remove(path.c_str());
    ASSERT_FALSE(g.empty());
    EXPECT_EQ(1, g->getHotPixelCount());
    EXPECT_EQ(f->getMinRate(), g->getMinRate());
    std::vector<Event> keptAgain;
    g->filter(ev, keptAgain);
    EXPECT_EQ(kept.size(), keptAgain.size());

    // Learning from the stream itself: the first 0.5 s pass, then the pixel is masked.
    Ptr<HotPixelFilter> live = HotPixelFilter::create(size);
    live->setLearningTime(500000);
    std::vector<uchar> m = keepMask(*live, ev);
    EXPECT_EQ(1, live->getHotPixelCount());
    for (size_t i = 0; i < ev.size(); i++)
        ASSERT_EQ(ev[i].x == 10 && ev[i].y == 20 && ev[i].t >= 500000 ? 0 : 255, (int)m[i]) << "event " << i;

    EXPECT_THROW(f->setMask(Mat::zeros(size.height + 1, size.width, CV_8U)), cv::Exception);
    f->clearMasks();
    EXPECT_EQ(0, f->getHotPixelCount());
}

TEST(Event_Filters, hot_pixels_stand_out_from_their_neighbours_busy_scene_parts_do_not)
{
    // One second at 1 Hz background activity, and four things firing at 500 Hz: a 5 x 5 patch (a fan's
    // hub), a one-pixel-wide track of 12 pixels (a thin edge going back and forth), a pair of adjacent pixels
    // and a lone pixel. Against the mean count of its 8 neighbours (about 1 event where they are quiet), a
    // busy pixel with b busy neighbours stands 8 / b times out: the lone pixel about 500 times, the pair's
    // and the track's ends 8 times, the track's inside 4, the patch's corners 2.7, the rest of it less.
    const Size size(64, 48);
    RNG rng(11);
    std::vector<Event> ev;
    for (int i = 0; i < size.area(); i++)
        ev.push_back(Event(rng.uniform(0, 1000000), rng.uniform(0, size.width), rng.uniform(0, size.height), rng.uniform(0, 2)));
    auto busy = [&](int x, int y) {
        for (int i = 0; i < 500; i++)
            ev.push_back(Event(i * 2000 + x + y, x, y, POLARITY_ON));
    };
    for (int y = 10; y < 15; y++)
        for (int x = 10; x < 15; x++)
            busy(x, y);
    for (int x = 30; x < 42; x++)
        busy(x, 30);
    busy(50, 40);
    busy(51, 40);
    busy(20, 40);
    sortByTime(ev);
    auto hotPixels = [&](double relativeRate) {
        // 50 Hz: well above the background activity, which at 5 Hz and a low ratio would let a few chance
        // pixels among quiet neighbours through.
        Ptr<HotPixelFilter> f = HotPixelFilter::create(size, 50, relativeRate);
        f->learn(ev);
        f->detect();
        Mat mask;
        f->getMask(mask);
        std::vector<Point> hot;
        findNonZero(mask, hot);
        return hot;
    };
    EXPECT_EQ((std::vector<Point>{ Point(20, 40) }), hotPixels(10));
    EXPECT_EQ((std::vector<Point>{ Point(30, 30), Point(41, 30), Point(20, 40), Point(50, 40), Point(51, 40) }), hotPixels(5));
}

TEST(Event_Filters, anti_flicker_removes_100hz_flicker_and_keeps_3hz_motion)
{
    const Size size(16, 16);
    // Rows 0..3 flicker at 100 Hz (an ON and an OFF burst of 2 events per 10 ms period) for 0.2 s; rows 8..11
    // see an edge go back and forth 3 times a second (a period of 333 ms) for 2 s.
    std::vector<Event> ev;
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < size.width; x++)
            addPolarityCycles(ev, x, y, 10000, 20, 2);
    for (int y = 8; y < 12; y++)
        for (int x = 0; x < size.width; x++)
            addPolarityCycles(ev, x, y, 333333, 6, 2);
    sortByTime(ev);
    Ptr<AntiFlickerFilter> f = AntiFlickerFilter::create(size, 80, 150);
    std::vector<uchar> m = keepMask(*f, ev);
    // A flickering pixel's burst starts at 0 (ON), 5 (OFF), 10 (ON: 1 period in the band), 15 (2), 20 ms (3 =
    // minCycles): the bursts from 20 ms on are removed, the four before pass, 2 events each.
    int flickerKept = 0, motionKept = 0, motion = 0;
    for (size_t i = 0; i < ev.size(); i++)
    {
        if (ev[i].y < 4)
            flickerKept += m[i] != 0;
        else
        {
            motion++;
            motionKept += m[i] != 0;
        }
    }
    EXPECT_EQ(4 * size.width * 4 * 2, flickerKept);
    EXPECT_EQ(motion, motionKept);

    // When the flicker stops, the pixel's next edge passes: its first burst start comes after the longest
    // period of the band.
    std::vector<Event> after{ Event(2500000, 0, 0, POLARITY_ON), Event(2500100, 0, 0, POLARITY_ON) };
    EXPECT_EQ((std::vector<uchar>{ 255, 255 }), keepMask(*f, after));
}

TEST(Event_Filters, anti_flicker_removes_a_simulated_lamp_after_three_periods_and_keeps_a_moving_edge)
{
    // A lamp flickering at 100 Hz in front of an edge sweeping at 80 px/s. Its pixels' bursts start at about
    // 0 (ON), 2.5 (OFF), 7.5, 12.5 and 17.5 ms; the fifth follows three periods in the band, so from 17.5 ms
    // on every flicker event goes. The simulator's flags say which events are the flicker's.
    std::vector<SimulatedPlane> scene = sweepingEdgeScene(1.0, 0.4, -0.1);
    SimulatedPlane lamp;
    lamp.center = Vec3d(0, -0.05, 0.8);
    lamp.halfSize = Vec2d(0.1, 0.02);
    lamp.texture = TEXTURE_UNIFORM;
    lamp.intensity = 2;
    lamp.flickerDepth = 0.6;
    scene.push_back(lamp);
    SimulatorSettings s = idealSmallSensor();
    s.flickerFrequencyHz = 100;
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene, s);
    std::vector<Event> ev;
    Mat truth;
    sim->generate(300000, ev, truth);
    Ptr<AntiFlickerFilter> f = AntiFlickerFilter::create(s.resolution);
    const std::vector<uchar> m = keepMask(*f, ev);
    int flicker = 0, flickerKeptLate = 0, motion = 0, motionKept = 0;
    for (size_t i = 0; i < ev.size(); i++)
    {
        if ((int)truth.at<float>((int)i, GT_FLAGS) & GT_FLAG_FLICKER)
        {
            flicker++;
            flickerKeptLate += m[i] && ev[i].t >= 17500;
        }
        else
        {
            motion++;
            motionKept += m[i] != 0;
        }
    }
    ASSERT_GT(flicker, 10000);
    ASSERT_GT(motion, 5000);
    EXPECT_EQ(0, flickerKeptLate);
    EXPECT_EQ(motion, motionKept);
}

// Cutting a stream into packets does not change what a filter keeps, on either camera.
TEST(Event_Filters, packets_and_cameras_do_not_change_the_decisions)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("boxes");
    Mat events, gt;
    sim->generate(150000, events, gt);
    const std::vector<Event> ev = toEventVector(events);
    ASSERT_GT(ev.size(), 5000u);
    const Size size = sim->getSensorSize();
    for (const String& name : getEventFilterNames())
    {
        SCOPED_TRACE(name);
        Ptr<EventFilter> whole = shortLearningFilter(name, size), cut = shortLearningFilter(name, size);
        const std::vector<uchar> expected = keepMask(*whole, ev);
        std::vector<uchar> got;
        RNG rng(3);
        for (size_t i = 0; i < ev.size();)
        {
            const size_t n = std::min(ev.size() - i, (size_t)rng.uniform(0, 3000));
            std::vector<uchar> m = keepMask(*cut, std::vector<Event>(ev.begin() + i, ev.begin() + i + n));
            got.insert(got.end(), m.begin(), m.end());
            i += n;
        }
        EXPECT_EQ(expected, got);
        EXPECT_EQ(whole->getKeptCount(), (double)keptCount(expected));

        // Each camera alone: the same decisions as in the merged stream (the cameras do not share state).
        for (int camera = 0; camera < 2; camera++)
        {
            if (name == "hot_pixels" && camera == 1)
                continue;  // its learning time starts at the stream's first event, which is a left one
            Ptr<EventFilter> one = shortLearningFilter(name, size);
            std::vector<Event> part;
            std::vector<uchar> partExpected;
            for (size_t i = 0; i < ev.size(); i++)
                if (ev[i].camera == camera)
                {
                    part.push_back(ev[i]);
                    partExpected.push_back(expected[i]);
                }
            EXPECT_EQ(partExpected, keepMask(*one, part)) << "camera " << camera;
        }
    }
}

TEST(Event_Filters, bad_packets_raise_and_leave_the_filter_unchanged)
{
    const Size size(20, 10);
    for (const Ptr<EventFilter>& f : everyFilter(size))
    {
        SCOPED_TRACE(f->getDefaultName());
        const std::vector<Event> good{ Event(100, 1, 1, 1), Event(200, 2, 1, 1), Event(300, 3, 1, 0) };
        const std::vector<Event> outside{ Event(400, 1, 1, 1), Event(500, 20, 1, 1) };
        const std::vector<Event> backwards{ Event(400, 1, 1, 1), Event(250, 2, 1, 1) };
        Event badCamera(400, 1, 1, 1);
        badCamera.camera = 2;
        std::vector<Event> kept;
        f->filter(good, kept);
        const double processed = f->getProcessedCount();
        EXPECT_THROW(f->filter(outside, kept), cv::Exception);
        EXPECT_THROW(f->filter(backwards, kept), cv::Exception);
        EXPECT_THROW(f->filter(std::vector<Event>{ badCamera }, kept), cv::Exception);
        EXPECT_THROW(f->filter(std::vector<Event>{ Event(300, 0, 0, 0), Event(299, 0, 0, 0) }, kept), cv::Exception);
        EXPECT_EQ(processed, f->getProcessedCount());
        try
        {
            f->filter(outside, kept);
        }
        catch (const cv::Exception& e)
        {
            EXPECT_NE(std::string::npos, e.msg.find("outside the 20 x 10 sensor")) << e.msg;
        }
        // Time order is per camera: the right camera may start earlier than the left one is now.
        Event right(50, 1, 1, 1);
        right.camera = CAMERA_RIGHT;
        EXPECT_NO_THROW(f->filter(std::vector<Event>{ right }, kept));
    }
    EXPECT_THROW(BackgroundActivityFilter::create(size, 0), cv::Exception);
    EXPECT_THROW(RefractoryFilter::create(size, -5), cv::Exception);
    EXPECT_THROW(AntiFlickerFilter::create(size, 120, 100), cv::Exception);
    EXPECT_THROW(createEventFilter("median", size), cv::Exception);
    EXPECT_THROW(TrailFilter::create(Size(0, 10)), cv::Exception);
}

TEST(Event_Filters, output_may_alias_the_input_and_parameters_round_trip)
{
    const Size size(40, 30);
    const std::vector<Event> edge = sweepingEdge(20, 10, 500);
    for (const Ptr<EventFilter>& f : everyFilter(size))
    {
        SCOPED_TRACE(f->getDefaultName());
        std::vector<Event> separate;
        f->filter(edge, separate);
        f->reset();
        std::vector<Event> inPlace = edge;
        f->filter(inPlace, inPlace);
        ASSERT_EQ(separate.size(), inPlace.size());
        for (size_t i = 0; i < inPlace.size(); i++)
            ASSERT_EQ(separate[i].t, inPlace[i].t);

        FileStorage fs("filter.yml", FileStorage::WRITE | FileStorage::MEMORY);
        f->write(fs);
        const std::string text = fs.releaseAndGetString();
        EXPECT_NE(std::string::npos, text.find("sensorWidth: 40")) << text;
    }
    Ptr<BackgroundActivityFilter> ba = BackgroundActivityFilter::create(size, 1234);
    FileStorage fs("filter.yml", FileStorage::WRITE | FileStorage::MEMORY);
    ba->write(fs);
    FileStorage in(fs.releaseAndGetString(), FileStorage::READ | FileStorage::MEMORY);
    Ptr<BackgroundActivityFilter> other = BackgroundActivityFilter::create();
    other->read(in.root());
    EXPECT_EQ(1234.0, other->getCorrelationTime());
    EXPECT_EQ(size, other->getSensorSize());
}

}}  // namespace
