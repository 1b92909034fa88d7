// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"
#include "test_simulator_helpers.hpp"

namespace opencv_test { namespace {

std::vector<Event> exchangeCameras(std::vector<Event> ev)
{
    for (Event& e : ev)
        e.camera = (uchar)(1 - e.camera);
    return ev;
}

TEST(Event_DominantDisparity, finds_the_plane_disparity_and_an_exchanged_pair)
{
    // plane: one surface at 1 m, disparity f B / Z = 200 * 0.1 / 1 = 20 px everywhere. Exchanging the cameras
    // mirrors every disparity: the correlation curve reversed, the peak at -20 px with the same score.
    const std::vector<Event> ev = misalignedScene("plane", 0, 0, 100000);
    Mat r, swapped;
    double score = 0, swappedScore = 0;
    EXPECT_EQ(20, estimateDominantDisparity(ev, Size(240, 180), 40, r, &score));
    EXPECT_EQ(-20, estimateDominantDisparity(exchangeCameras(ev), Size(240, 180), 40, swapped, &swappedScore));
    ASSERT_EQ(81, (int)r.total());
    ASSERT_EQ(CV_64F, r.type());
    EXPECT_NEAR(score, r.at<double>(0, 20 + 40), 1e-12);
    EXPECT_GT(score, 0.5);
    EXPECT_NEAR(score, swappedScore, 1e-9);
    for (int d = -40; d <= 40; d++)
        EXPECT_NEAR(r.at<double>(0, d + 40), swapped.at<double>(0, -d + 40), 1e-9) << "d = " << d;
}

TEST(Event_DominantDisparity, holds_a_pixel_off_rectification_and_on_a_walking_figure)
{
    // A right camera 1 px low (the images spread over three rows absorb it).
    EXPECT_EQ(20, estimateDominantDisparity(misalignedScene("plane", 1.0, 0, 100000), Size(240, 180), 40));
    // walking_near: the figure at 1.5 m, 13.3 px (limbs 12.3-14.5 px), sparse ragged edges and noise.
    double score = 0;
    const int d = estimateDominantDisparity(misalignedScene("walking_near", 0.5, 0.004, 300000), Size(240, 180),
                                            40, noArray(), &score);
    EXPECT_LE(std::abs(d - 13), 1) << d;
    EXPECT_GT(score, 0.1);
}

TEST(Event_DominantDisparity, bad_input)
{
    std::vector<Event> ev = misalignedScene("plane", 0, 0, 20000);
    EXPECT_THROW(estimateDominantDisparity(ev, Size(240, 180), 0), cv::Exception);
    EXPECT_THROW(estimateDominantDisparity(ev, Size(240, 180), 121), cv::Exception);
    EXPECT_THROW(estimateDominantDisparity(ev, Size(1, 180), 1), cv::Exception);
    EXPECT_THROW(estimateDominantDisparity(ev, Size(240, 180), 40, noArray(), 0, 0), cv::Exception);
    // Events outside the sensor or of a third camera are ignored, not fatal.
    std::vector<Event> extra = ev;
    extra.back().x = 1000;
    extra[extra.size() / 2].camera = 7;
    EXPECT_EQ(20, estimateDominantDisparity(extra, Size(240, 180), 40));
    // Time going backwards names the event.
    std::vector<Event> backwards = ev;
    std::swap(backwards[10], backwards[backwards.size() - 10]);
    try
    {
        estimateDominantDisparity(backwards, Size(240, 180), 40);
        ADD_FAILURE() << "no exception for time going backwards";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find("back in time")) << e.err;
    }
    // Nothing to compare: one camera only, or no events at all.
    std::vector<Event> left;
    for (const Event& e : ev)
        if (e.camera == CAMERA_LEFT)
            left.push_back(e);
    double score = -1;
    EXPECT_EQ(0, estimateDominantDisparity(left, Size(240, 180), 40, noArray(), &score));
    EXPECT_EQ(0, score);
    EXPECT_EQ(0, estimateDominantDisparity(std::vector<Event>(), Size(240, 180), 40, noArray(), &score));
    EXPECT_EQ(0, score);
}

}}  // namespace
