// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_stereo_scene_runs.hpp"

namespace opencv_test { namespace {

SceneRun runWithRowStep(const std::string& scene, int rowStep)
{
    return runScene(scene, 400, [rowStep](StereoEventMatcher& m) { m.setCostRowStep(rowStep); });
}

// Cost windows that read every other row, against the simulator's truth on a rigid and an articulated scene:
// the matching rate stays within a point of every row's and above 95 %. A sampling that paired different rows
// of the two sensors, or weighed "no counterpart" over other rows than the candidates, would fall well below.
TEST(StereoEventMatcher_CostRowStep, every_other_row_matches_as_well_as_every_row)
{
    for (const char* scene : { "boxes", "walking" })
    {
        const double every = matchingRate(runWithRowStep(scene, 1));
        const double half = matchingRate(runWithRowStep(scene, 2));
        EXPECT_GE(half, 95.0) << scene;
        EXPECT_NEAR(half, every, 1.0) << scene;
    }
}

// The step changes the costs, nothing the candidates come from: in DECOUPLED mode, where each sensor's
// lifetimes (and so which events are active in the descriptors) are its own plane fits', the events without a
// counterpart and every lifetime stay the same event by event, while a fourth of the rows decides some
// disparities differently and still matches most events.
TEST(StereoEventMatcher_CostRowStep, changes_the_costs_and_not_the_candidates)
{
    const auto decoupled = [](int rowStep) {
        return runScene("boxes", 400, [rowStep](StereoEventMatcher& m) {
            m.setMode(STEREO_DECOUPLED);
            m.setCostRowStep(rowStep);
        });
    };
    const SceneRun every = decoupled(1);
    const SceneRun sparse = decoupled(4);
    ASSERT_EQ(every.flags.size(), sparse.flags.size());
    int64 differing = 0;
    for (size_t i = 0; i < every.flags.size(); i++)
    {
        ASSERT_EQ(every.flags[i] & STEREO_NO_COUNTERPART, sparse.flags[i] & STEREO_NO_COUNTERPART) << "event " << i;
        ASSERT_EQ(every.lifetime[i], sparse.lifetime[i]) << "event " << i;
        differing += every.disparity[i] != sparse.disparity[i];
    }
    EXPECT_GT(differing, 0);
    EXPECT_GE(matchingRate(sparse), 90.0);
}

}}  // namespace
