// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Everything process() returns for a run, and the lifetime estimators' status counts after it.
struct RunOutputs
{
    std::vector<Mat> packets;  // per packet: disparity, lifetime, flags, depth, flow, confidence
    std::vector<double> statusCounts;
};

RunOutputs runMatcher(const std::vector<std::vector<Event>>& packets, Size size, int mode, int threads,
                      const StereoCalibration& calibration = StereoCalibration(), double lookAhead = 10000)
{
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(size, mode);
    if (!calibration.empty())
        m->setCalibration(calibration);
    m->setNumThreads(threads);
    m->setLookAhead(lookAhead);
    RunOutputs out;
    for (const std::vector<Event>& ev : packets)
    {
        Mat d, lt, fl, depth, flow, confidence;
        m->process(ev, d, lt, fl, depth, flow, confidence);
        for (const Mat& o : { d, lt, fl, depth, flow, confidence })
            out.packets.push_back(o.clone());
    }
    for (int c = 0; c < 2; c++)
        for (int s = 0; s < 4; s++)
            out.statusCounts.push_back(m->getLifetimeEstimator(c)->getStatusCount(s));
    return out;
}

int differingOutputs(const RunOutputs& a, const RunOutputs& b)
{
    int differ = a.packets.size() == b.packets.size() ? 0 : 1;
    for (size_t i = 0; i < std::min(a.packets.size(), b.packets.size()); i++)
        differ += !sameBits(a.packets[i], b.packets[i]);
    return differ + (a.statusCounts != b.statusCounts);
}

std::vector<std::vector<Event>> simulatedPackets(const std::string& scene, double ms, double packetMs)
{
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene);
    std::vector<std::vector<Event>> packets;
    Mat gt;
    for (double t = packetMs; t <= ms + 1e-9; t += packetMs)
    {
        packets.emplace_back();
        sim->generate(t * 1000, packets.back(), gt);
    }
    return packets;
}

typedef testing::TestWithParam<std::tuple<std::string, int>> StereoEventMatcher_RowBands;

// The row bands' ordering rule makes every operation that could meet another band's run in the one-thread
// order: any slip (an expiry taken late, an event that did not wait) changes descriptors and so disparities
// and lifetimes. Runs are repeated because a missed wait shows only when the threads happen to interleave.
TEST_P(StereoEventMatcher_RowBands, give_the_results_of_one_thread_bit_for_bit)
{
    const std::string scene = std::get<0>(GetParam());
    const int mode = std::get<1>(GetParam());
    const std::vector<std::vector<Event>> packets = simulatedPackets(scene, 132, 33);
    const Size size = StereoEventSimulator::create(scene)->getSensorSize();
    const RunOutputs one = runMatcher(packets, size, mode, 1);
    size_t events = 0;
    for (const std::vector<Event>& p : packets)
        events += p.size();
    ASSERT_GT(events, 4u * 1000) << "every packet must be large enough for the bands";
    for (int threads : { 2, 3, 2, 7 })
        EXPECT_EQ(differingOutputs(one, runMatcher(packets, size, mode, threads)), 0)
            << scene << ", " << getStereoModeName(mode) << ", " << threads << " threads";
    // Without look-ahead (each event decided on arrival, one operation per event).
    const RunOutputs onArrival = runMatcher(packets, size, mode, 1, StereoCalibration(), 0);
    EXPECT_GT(differingOutputs(one, onArrival), 0) << "the look-ahead must change something";
    EXPECT_EQ(differingOutputs(onArrival, runMatcher(packets, size, mode, 3, StereoCalibration(), 0)), 0)
        << scene << ", " << getStereoModeName(mode) << ", no look-ahead, 3 threads";
}

INSTANTIATE_TEST_CASE_P(/**/, StereoEventMatcher_RowBands,
                        testing::Combine(testing::Values("two_planes", "cluttered"),
                                         testing::Values((int)STEREO_COUPLED, (int)STEREO_DECOUPLED,
                                                         (int)STEREO_FIXED_INTERVAL)));

TEST(StereoEventMatcher, row_bands_follow_the_rectified_rows)
{
    // A calibration that moves rows (a vertical shift between the sensors, and pixels that leave the image):
    // bands split by rectified row, and events rectified outside are flagged without a thread touching them.
    const std::vector<std::vector<Event>> packets = simulatedPackets("two_planes", 99, 33);
    const Size size(240, 180);
    StereoCalibration cal = StereoCalibration::fromRectified(size, 200, 0.1);
    cal.K2.at<double>(1, 2) += 3;  // the right camera's rows land 3 rows higher
    cal.validate();
    const RunOutputs one = runMatcher(packets, size, STEREO_COUPLED, 1, cal);
    int outside = 0;
    // Each packet stores its outputs in runMatcher()'s order: disparity, lifetime, flags, depth, flow, confidence.
    const size_t outputsPerPacket = 6, flagsOutput = 2;
    ASSERT_EQ(0u, one.packets.size() % outputsPerPacket);
    for (size_t i = flagsOutput; i < one.packets.size(); i += outputsPerPacket)
    {
        ASSERT_EQ(CV_32S, one.packets[i].type()) << "output " << i << " is a flags Mat";
        outside += countNonZero((one.packets[i] & STEREO_OUTSIDE) != 0);
    }
    EXPECT_GT(outside, 0) << "the shift must push some events out";
    EXPECT_EQ(differingOutputs(one, runMatcher(packets, size, STEREO_COUPLED, 4, cal)), 0);
}

TEST(StereoEventMatcher, row_bands_on_a_short_sensor_and_a_bad_event_behave_like_one_thread)
{
    // 32 rows hold a single band at the defaults (each is more than the 19 rows across which two operations
    // can conflict): the band path on one thread.
    const Size small(64, 32);
    std::vector<Event> ev;
    RNG rng(7);
    for (int i = 0; i < 3000; i++)
        ev.push_back(Event(1000 + i * 20, rng.uniform(0, small.width), rng.uniform(0, small.height), rng.uniform(0, 2),
                           rng.uniform(0, 2)));
    EXPECT_EQ(differingOutputs(runMatcher({ ev }, small, STEREO_COUPLED, 1), runMatcher({ ev }, small, STEREO_COUPLED, 4)),
              0);

    // A packet that goes back in time at event 2500: both throw the same error after processing the events
    // before it, and go on alike.
    const std::vector<std::vector<Event>> packets = simulatedPackets("cluttered", 66, 33);
    std::vector<Event> bad = packets[1];
    ASSERT_GT(bad.size(), 3000u);
    bad[2500].t = bad[2499].t - 5;
    std::string messages[2];
    RunOutputs after[2];
    for (int k = 0; k < 2; k++)
    {
        Ptr<StereoEventMatcher> m = StereoEventMatcher::create(Size(240, 180), STEREO_COUPLED);
        m->setNumThreads(k == 0 ? 1 : 2);
        Mat d;
        m->process(packets[0], d);
        try
        {
            m->process(bad, d);
        }
        catch (const cv::Exception& e)
        {
            messages[k] = e.what();
        }
        // The rest of the packet, after the bad event, then the next packet.
        const std::vector<Event> rest(bad.begin() + 2501, bad.end());
        Mat lt, fl;
        for (const std::vector<Event>* p : { &rest, &packets[1] })
        {
            std::vector<Event> later = *p;
            for (Event& e : later)
                e.t += p == &rest ? 0 : 40000;
            m->process(later, d, lt, fl);
            for (const Mat& o : { d, lt, fl })
                after[k].packets.push_back(o.clone());
        }
    }
    EXPECT_NE(messages[0].find("earlier than the previous one"), std::string::npos) << messages[0];
    EXPECT_EQ(messages[0].substr(messages[0].find("StereoEventMatcher")),
              messages[1].substr(messages[1].find("StereoEventMatcher")));
    EXPECT_EQ(differingOutputs(after[0], after[1]), 0);

    Ptr<StereoEventMatcher> m = StereoEventMatcher::create();
    EXPECT_THROW(m->setNumThreads(0), cv::Exception);
    EXPECT_THROW(m->setNumThreads(65), cv::Exception);
    m->setNumThreads(3);
    EXPECT_EQ(m->getNumThreads(), 3);
}

}}  // namespace
