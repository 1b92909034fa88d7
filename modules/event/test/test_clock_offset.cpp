// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// estimateClockOffset(): a right clock moved by a known amount moves the estimate by as much; a walking figure's
// clock is found to within half a millisecond; objects that each move at one speed, and one line at one speed, get no
// confident wrong offset.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// The first @p untilUs of a built-in scene with the right camera's clock moved by @p clockUs more.
std::vector<Event> sceneWithRightClock(const String& scene, double clockUs, double untilUs)
{
    return simulateChangedScene(scene, [&](SimulatorSettings& s) { s.rightClockOffsetUs += clockUs; }, untilUs);
}

TEST(Event_ClockOffset, a_right_clock_moved_by_a_known_amount_moves_the_estimate_by_as_much)
{
    // Boxes slid to and fro: their speeds along the rows change, so an offset is told from a disparity. The
    // scene's own offset (its clock, latencies and sensitivities together) is what the estimate at 0 is;
    // moving the right clock by c must move the estimate by -c.
    const Size size(240, 180);
    double u0 = 0;
    const double e0 = estimateClockOffset(sceneWithRightClock("boxes_fast_pair", 0, 1000000), size, 0, 40, &u0);
    ASSERT_LT(u0, 500) << "the scene's own offset is measurable";
    for (double clock : { -10000.0, 10000.0 })
    {
        double u = 0;
        const double e = estimateClockOffset(sceneWithRightClock("boxes_fast_pair", clock, 1000000), size, 0, 40, &u);
        EXPECT_LT(u, 500) << "clock moved by " << clock << " us";
        EXPECT_NEAR(-clock, e - e0, 500) << "clock moved by " << clock << " us";
    }
}

TEST(Event_ClockOffset, a_walking_figure_tells_its_clock_to_within_half_a_millisecond)
{
    // Limbs that swing: speeds along the rows change on one surface, so a clock is told from a disparity. The
    // figure moves one way, so what the matching itself does with an edge's speed (faster edges a little
    // nearer; the look-ahead's counterpart a little along the motion, opposite ways for the two cameras) looks
    // like a clock unless the estimate takes it apart: the simulated clocks agree, and moved by +-10 ms the
    // estimate must follow to within 0.5 ms of the clock itself, and say so within two of its uncertainties.
    const Size size(240, 180);
    ASSERT_EQ(0, StereoEventSimulator::create("walking")->getSettings().rightClockOffsetUs);
    for (double clock : { -10000.0, 0.0, 10000.0 })
    {
        double u = 0;
        const double e = estimateClockOffset(sceneWithRightClock("walking", clock, 5000000), size, 0, 40, &u);
        ASSERT_TRUE(std::isfinite(u)) << "clock moved by " << clock << " us";
        EXPECT_NEAR(-clock, e, 500) << "clock moved by " << clock << " us";
        EXPECT_LE(std::abs(e + clock), 2 * u) << "clock moved by " << clock << " us";
    }
}

TEST(Event_ClockOffset, objects_that_each_move_at_one_speed_get_no_confident_wrong_offset)
{
    // Fast diagonal boxes, each at one speed: an offset shifts each box's disparities by one amount, as a depth
    // would. The slope of disparity on speed vanishes again 17-18 ms past the clock, where the matches are
    // less clear-cut: with the clocks alike than at none, with the right clock 10 ms late than at offsets
    // further off (on the first three seconds, what event_stereo measures on). Whatever the clock: no
    // estimate, or one within half a millisecond of it.
    ASSERT_EQ(0, StereoEventSimulator::create("boxes_fast")->getSettings().rightClockOffsetUs);
    for (double clock : { 0.0, 10000.0 })
    {
        double uncertainty = 0;
        const double e = estimateClockOffset(sceneWithRightClock("boxes_fast", clock, 3000000), Size(240, 180), 0, 40,
                                             &uncertainty);
        if (uncertainty <= 500)
        {
            EXPECT_NEAR(-clock, e, 500) << "clock moved by " << clock << " us";
        }
    }
}

TEST(Event_ClockOffset, one_line_at_one_speed_cannot_tell_an_offset_from_a_disparity)
{
    // A vertical line moving at one speed: any offset shifts every disparity by one amount, as a depth would.
    double uncertainty = 0;
    const std::vector<Event> events = sceneWithRightClock("moving_line", 5000, 1000000);
    const double e = estimateClockOffset(events, Size(240, 180), 0, 40, &uncertainty);
    EXPECT_GT(uncertainty, 1000);
    EXPECT_EQ(0, e) << "nothing to go by: no offset";
    // Events a calibration rectified past the border are ignored: the same estimate.
    std::vector<Event> withOutside = events;
    withOutside.insert(withOutside.begin() + (long)events.size() / 2,
                       { Event(events[events.size() / 2].t, 240, 9, 1, CAMERA_LEFT),
                         Event(events[events.size() / 2].t, 3, -1, 0, CAMERA_RIGHT) });
    double withOutsideUncertainty = 0;
    EXPECT_EQ(e, estimateClockOffset(withOutside, Size(240, 180), 0, 40, &withOutsideUncertainty));
    EXPECT_EQ(uncertainty, withOutsideUncertainty);
}

TEST(Event_ClockOffset, bad_arguments_are_refused_and_one_camera_gives_nothing)
{
    const std::vector<Event> events = sceneWithRightClock("plane", 0, 20000);
    EXPECT_THROW(estimateClockOffset(events, Size(0, 180)), cv::Exception);
    EXPECT_THROW(estimateClockOffset(events, Size(240, 180), 10, 5), cv::Exception);
    EXPECT_THROW(estimateClockOffset(events, Size(240, 180), 0, 240), cv::Exception);
    std::vector<Event> left;
    for (const Event& e : events)
        if (e.camera == CAMERA_LEFT)
            left.push_back(e);
    ASSERT_FALSE(left.empty());
    double uncertainty = 0;
    EXPECT_EQ(0, estimateClockOffset(left, Size(240, 180), 0, 40, &uncertainty));
    EXPECT_TRUE(std::isinf(uncertainty));
}

}}  // namespace
