// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_stereo_scene_runs.hpp"

namespace opencv_test { namespace {

// Without the filling, which replaces estimates by their surface's median after the averaging.
SceneRun runAveraged(const std::string& scene, double ms, int radius)
{
    return runScene(scene, ms, [radius](StereoEventMatcher& m) {
        m.setAveragingRadius(radius);
        m.setFillRadius(0);
    });
}

// The neighbours read each event's own estimate, never the averaged one, so a run with averaging makes the
// same decisions as one without: only the output disparity differs, by at most the averaging's 1.5 px.
TEST(StereoEventMatcher_Averaging, changes_only_the_output_disparity_and_by_at_most_its_tolerance)
{
    const SceneRun own = runAveraged("boxes_pair", 400, 0);
    const SceneRun averaged = runAveraged("boxes_pair", 400, 4);
    ASSERT_EQ(own.disparity.size(), averaged.disparity.size());
    int64 moved = 0;
    for (size_t i = 0; i < own.disparity.size(); i++)
    {
        ASSERT_EQ(own.flags[i], averaged.flags[i]) << "event " << i;
        ASSERT_EQ(own.lifetime[i], averaged.lifetime[i]) << "event " << i;
        ASSERT_EQ(own.confidence[i], averaged.confidence[i]) << "event " << i;
        ASSERT_EQ(own.disparity[i] < 0, averaged.disparity[i] < 0) << "event " << i;
        if (own.disparity[i] < 0)
            continue;
        ASSERT_LE(std::abs(averaged.disparity[i] - own.disparity[i]), 1.5f + 1e-4f) << "event " << i;
        moved += averaged.disparity[i] != own.disparity[i];
    }
    EXPECT_GT(moved, (int64)own.disparity.size() / 4);  // a pair's estimates scatter: most have neighbours
}

// boxes_pair's boxes turn a little away from the cameras, so that their disparities fall between whole pixels,
// and its dotted edges leave one event's match a pixel or so off: there the mean of the neighbours' estimates
// of both cameras lies within a pixel of the simulator's truth for far more events than each event's own: the
// averaging brings at least half of the events that miss by more than a pixel to within one.
TEST(StereoEventMatcher_Averaging, brings_a_pairs_estimates_to_within_a_pixel_of_the_truth)
{
    const double own = matchingRate(runAveraged("boxes_pair", 1000, 0));
    const double averaged = matchingRate(runAveraged("boxes_pair", 1000, 4));
    EXPECT_LE(100 - averaged, (100 - own) / 2);
    EXPECT_GE(averaged, 90);
}

TEST(StereoEventMatcher_Averaging, radius_is_checked_and_stored)
{
    Ptr<StereoEventMatcher> m = StereoEventMatcher::create();
    EXPECT_EQ(m->getAveragingRadius(), 4);
    EXPECT_THROW(m->setAveragingRadius(-1), cv::Exception);
    EXPECT_THROW(m->setAveragingRadius(6), cv::Exception);
    m->setAveragingRadius(2);
    Ptr<StereoEventMatcher> b = writtenAndReadBack(*m);
    EXPECT_EQ(b->getAveragingRadius(), 2);
}

}}  // namespace
