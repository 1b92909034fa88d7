// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_simulator_helpers.hpp"

namespace opencv_test { namespace {

TEST(Event_RowAlignment, finds_the_simulated_row_offset_and_roll)
{
    // two_planes: textured, edges of every direction. The offset within 0.25 px, the roll within 0.003 rad
    // (0.36 px at the image's sides).
    struct Case { double offset, roll; };
    for (const Case& c : { Case{ 0, 0 }, Case{ -1.5, 0 }, Case{ 0.5, 0.01 }, Case{ 0, -0.012 } })
    {
        double score = 0;
        const Vec2d a = estimateRowAlignment(misalignedScene("two_planes", c.offset, c.roll), Size(240, 180), 0, 40, &score);
        EXPECT_NEAR(c.offset, a[0], 0.25) << "offset " << c.offset << ", roll " << c.roll;
        EXPECT_NEAR(c.roll, a[1], 0.003) << "offset " << c.offset << ", roll " << c.roll;
        EXPECT_GT(score, 0.4);
    }
}

TEST(Event_RowAlignment, sparse_realistic_scene_and_bad_arguments)
{
    // boxes: a few edges and noise, the right camera 0.5 px low and rolled 0.004 rad by the scene itself.
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create("boxes");
    std::vector<Event> ev;
    Mat gt;
    sim->generate(600000, ev, gt);
    const Vec2d a = estimateRowAlignment(ev, sim->getSensorSize(), 0, 40);
    EXPECT_NEAR(sim->getSettings().rightRowOffset, a[0], 0.35);
    EXPECT_THROW(estimateRowAlignment(ev, Size(8, 8), 0, 40), cv::Exception);
    EXPECT_THROW(estimateRowAlignment(ev, Size(240, 180), 10, 5), cv::Exception);
}

}}  // namespace
