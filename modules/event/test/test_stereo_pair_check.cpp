// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_simulator_helpers.hpp"

namespace opencv_test { namespace {

const Size kSensor(240, 180);

std::vector<Event> withCameras(std::vector<Event> ev, bool exchange, int keepRightEvery = 1)
{
    std::vector<Event> out;
    int right = 0;
    for (Event e : ev)
    {
        if (exchange)
            e.camera = (uchar)(1 - e.camera);
        if (e.camera == CAMERA_RIGHT && right++ % keepRightEvery != 0)
            continue;
        out.push_back(e);
    }
    return out;
}

TEST(Event_StereoPairCheck, a_pair_set_up_right_passes_every_check)
{
    // plane: one surface at 20 px (f B / Z = 200 * 0.1 / 1), rows aligned.
    const std::vector<Event> ev = misalignedScene("plane", 0, 0, 200000);
    const StereoPairCheck c = checkStereoPair(ev, kSensor, 0, 40);
    EXPECT_TRUE(c.overlap);
    EXPECT_EQ((double)ev.size(), c.leftEvents + c.rightEvents);
    EXPECT_EQ((double)(ev.back().t - ev.front().t), c.spanUs);
    ASSERT_TRUE(c.lineUpEstimated);
    EXPECT_EQ(20, c.lineUpDisparity);
    EXPECT_TRUE(c.lineUpTrusted);
    EXPECT_FALSE(c.camerasExchanged || c.beyondRange || c.belowRange);
    ASSERT_TRUE(c.rowsEstimated);
    EXPECT_NEAR(std::abs(c.rowOffset) + std::abs(std::sin(c.roll)) * 120, c.rowsOffAtSides, 1e-12);
    EXPECT_FALSE(c.rowsOff) << c.rowOffset << " px, roll " << c.roll << ", score " << c.rowScore;
}

TEST(Event_StereoPairCheck, names_what_is_wrong_with_a_pair)
{
    const std::vector<Event> ev = misalignedScene("plane", 0, 0, 200000);
    // The cameras exchanged: every disparity mirrored.
    const StereoPairCheck exchanged = checkStereoPair(withCameras(ev, true), kSensor, 0, 40);
    EXPECT_EQ(-20, exchanged.lineUpDisparity);
    EXPECT_TRUE(exchanged.camerasExchanged);
    EXPECT_FALSE(exchanged.belowRange);
    // A range that stops short of the scene, or starts past it.
    EXPECT_TRUE(checkStereoPair(ev, kSensor, 0, 10).beyondRange);
    const StereoPairCheck below = checkStereoPair(ev, kSensor, 30, 40);
    EXPECT_TRUE(below.belowRange);
    EXPECT_FALSE(below.camerasExchanged);
    // A right camera whose rows are 1.5 px low: the rows are off by that much at the sides too.
    const StereoPairCheck low = checkStereoPair(misalignedScene("two_planes", 1.5, 0), kSensor, 0, 40);
    ASSERT_TRUE(low.rowsEstimated);
    EXPECT_NEAR(1.5, low.rowOffset, 0.25);
    EXPECT_TRUE(low.rowsTrusted);
    EXPECT_TRUE(low.rowsOff);
}

TEST(Event_StereoPairCheck, streams_that_do_not_overlap_or_too_few_events_estimate_nothing)
{
    const std::vector<Event> ev = misalignedScene("plane", 0, 0, 200000);
    // One right event in 200 kept: under 1 % of the left camera's.
    const StereoPairCheck silent = checkStereoPair(withCameras(ev, false, 200), kSensor, 0, 40);
    EXPECT_FALSE(silent.overlap);
    EXPECT_LT(silent.rightEvents * 100, silent.leftEvents);
    EXPECT_FALSE(silent.lineUpEstimated || silent.rowsEstimated);
    const StereoPairCheck none = checkStereoPair(std::vector<Event>(), kSensor, 0, 40);
    EXPECT_EQ(0.0, none.leftEvents + none.rightEvents + none.spanUs);
    EXPECT_FALSE(none.overlap || none.lineUpEstimated || none.rowsEstimated);
    const std::vector<Event> few(ev.begin(), ev.begin() + 1999);
    const StereoPairCheck small = checkStereoPair(few, kSensor, 0, 40);
    EXPECT_EQ(1999.0, small.leftEvents + small.rightEvents);
    EXPECT_FALSE(small.lineUpEstimated || small.rowsEstimated);
    // A sensor too narrow for three strips of the range: the line-up, but not the rows.
    const StereoPairCheck narrow = checkStereoPair(ev, kSensor, 0, 160);
    EXPECT_TRUE(narrow.lineUpEstimated);
    EXPECT_FALSE(narrow.rowsEstimated);
    EXPECT_THROW(checkStereoPair(ev, Size(), 0, 40), cv::Exception);
    EXPECT_THROW(checkStereoPair(ev, kSensor, 10, 5), cv::Exception);
}

}}  // namespace
