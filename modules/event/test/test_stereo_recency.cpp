// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_stereo_scene_runs.hpp"

namespace opencv_test { namespace {

// Two vertical ON edges in the right sensor, rows 10-30: a stale one at column 25 (time `staleTime`) and a fresh
// one at column 20 (t = 9000), and one left edge at column 40 (t = 9000). All fall in the cold start, so every
// event stays active (2.5 fixed intervals, 25 ms). For the left edge the two right edges are mirror images of
// each other about the candidate: at disparity 15 the matching edge has the other one 5 px to its left, at 20
// 5 px to its right (an odd gap: no pixel between them is equally near both, where the nearest vector's tie
// would break one way), so the two candidates cost the same, at every window up to the largest (31 x 31, inside
// both images). Returns the left edge's 21 estimates.
std::vector<StereoEventEstimate> leftEdgeBetweenTwo(int recencyWeight, int64 staleTime)
{
    std::vector<Event> ev;
    for (int y = 10; y <= 30; y++)
        ev.push_back(Event(staleTime, 25, (short)y, POLARITY_ON, CAMERA_RIGHT));
    for (int y = 10; y <= 30; y++)
        ev.push_back(Event(9000, 20, (short)y, POLARITY_ON, CAMERA_RIGHT));
    for (int y = 10; y <= 30; y++)
        ev.push_back(Event(9000, 40, (short)y, POLARITY_ON, CAMERA_LEFT));
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create(Size(64, 48), STEREO_COUPLED);
    m->setRecencyWeight(recencyWeight);
    m->setPriorTolerance(0);  // the cost alone: the prior would settle a tie from the rows decided before
    Mat d, flags, confidence;
    m->process(ev, d, noArray(), flags, noArray(), noArray(), confidence);
    return estimatesOf(d, flags, confidence, 42, 21);
}

// Without the recency cost the two candidates tie: the tie goes to the smaller disparity, 15, the stale edge,
// with confidence 0 (the runner-up costs as much). With it the stale edge, 8 ms before the event, pays 8/10 of
// the full recency cost and the fresh one nothing: 20 wins. Events 1 ms apart (a tenth of the recency time)
// still tell the two apart; at the same time they tie again.
TEST(StereoEventMatcher_Recency, a_stale_trail_loses_to_the_edge_that_fires_with_the_event)
{
    const struct
    {
        int weight;
        int64 staleTime;
        float disparity;
        bool confident;
    } cases[] = { { 0, 1000, 15.f, false }, { 15, 1000, 20.f, true }, { 15, 8000, 20.f, true }, { 15, 9000, 15.f, false } };
    for (const auto& c : cases)
    {
        const std::vector<StereoEventEstimate> left = leftEdgeBetweenTwo(c.weight, c.staleTime);
        for (size_t i = 0; i < left.size(); i++)
        {
            SCOPED_TRACE(cv::format("recency weight %d, stale edge at %d us, row %d", c.weight, (int)c.staleTime,
                                    10 + (int)i));
            ASSERT_TRUE(left[i].flags & STEREO_HAS_DISPARITY);
            EXPECT_NEAR(left[i].disparity, c.disparity, 0.5);
            if (c.confident)
                EXPECT_GT(left[i].confidence, 0.f);
            else
                EXPECT_EQ(left[i].confidence, 0.f);
        }
    }
}

}}  // namespace
