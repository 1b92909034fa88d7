// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#include "opencv2/calib3d.hpp"

namespace opencv_test { namespace {

// A distorted, slightly rotated pair: camera 2 is 0.12 m to the right with a small rotation.
struct RawPair
{
    Size size = Size(240, 180);
    Mat K1 = (Mat_<double>(3, 3) << 210, 0, 118, 0, 208, 92, 0, 0, 1);
    Mat K2 = (Mat_<double>(3, 3) << 205, 0, 122, 0, 206, 88, 0, 0, 1);
    Mat D1 = (Mat_<double>(1, 5) << -0.28, 0.09, 0.001, -0.0005, 0);
    Mat D2 = (Mat_<double>(1, 5) << -0.26, 0.08, -0.0008, 0.0004, 0);
    Mat R, T = (Mat_<double>(3, 1) << -0.12, 0.002, 0.001);
    RawPair() { Rodrigues(Vec3d(0.01, -0.02, 0.005), R); }
};

// Projects 3-D points (left camera frame) into both raw cameras, rectifies them and checks that
// corresponding points share a row and that f B / disparity gives back their depth.
void checkRectification(const StereoCalibration& c, const RawPair& pair)
{
    std::vector<Point3d> world;
    for (double z : { 1.0, 2.0, 4.0 })
        for (double u = -0.3; u <= 0.3; u += 0.15)
            for (double v = -0.2; v <= 0.2; v += 0.1)
                world.push_back(Point3d(u * z, v * z, z));
    std::vector<Point2d> raw1, raw2;
    projectPoints(world, Vec3d(0, 0, 0), Vec3d(0, 0, 0), pair.K1, pair.D1, raw1);
    Vec3d rvec;
    Rodrigues(pair.R, rvec);
    projectPoints(world, rvec, Vec3d(pair.T), pair.K2, pair.D2, raw2);
    Mat p1(raw1, true), p2(raw2, true), r1, r2;
    p1.convertTo(p1, CV_32FC2);
    p2.convertTo(p2, CV_32FC2);
    c.rectifyPoints(p1, r1, CAMERA_LEFT);
    c.rectifyPoints(p2, r2, CAMERA_RIGHT);
    const double fB = c.focalLength() * c.baseline();
    for (size_t i = 0; i < world.size(); i++)
    {
        const Vec2f a = r1.at<Vec2f>((int)i), b = r2.at<Vec2f>((int)i);
        EXPECT_NEAR(a[1], b[1], 0.05) << "point " << world[i] << " is not on one rectified row";
        const double depth = fB / (a[0] - b[0]);
        EXPECT_NEAR(depth, world[i].z, 0.01 * world[i].z) << "point " << world[i];
    }
}

TEST(StereoCalibration, fromRectified_is_identity_and_gives_fB_over_d)
{
    const StereoCalibration c = StereoCalibration::fromRectified(Size(240, 180), 200, 0.1);
    EXPECT_DOUBLE_EQ(c.focalLength(), 200);
    EXPECT_DOUBLE_EQ(c.baseline(), 0.1);
    Mat pts = (Mat_<Vec2f>(3, 1) << Vec2f(0, 0), Vec2f(119.5f, 89.5f), Vec2f(239, 179)), out;
    for (int cam = 0; cam < 2; cam++)
    {
        c.rectifyPoints(pts, out, cam);
        EXPECT_LE(cvtest::norm(pts, out, NORM_INF), 1e-3);
    }
    EXPECT_THROW(StereoCalibration::fromRectified(Size(240, 180), 200, 0), cv::Exception);
}

TEST(StereoCalibration, rectifyEvents_moves_each_camera_by_its_own_map)
{
    // No distortion, no rotation: P K^-1 moves the left camera's pixels by (+5, +3) and the right one's by
    // (-2, +1).
    StereoCalibration c = StereoCalibration::fromRectified(Size(240, 180), 200, 0.1);
    c.P1.at<double>(0, 2) += 5;
    c.P1.at<double>(1, 2) += 3;
    c.P2.at<double>(0, 2) -= 2;
    c.P2.at<double>(1, 2) += 1;
    std::vector<Event> ev = { Event(10, 0, 0, 1, CAMERA_LEFT), Event(20, 0, 0, 0, CAMERA_RIGHT),
                              Event(30, 239, 179, 1, CAMERA_LEFT), Event(30, 100, 50, 0, CAMERA_RIGHT) };
    const std::vector<Event> expected = { Event(10, 5, 3, 1, CAMERA_LEFT), Event(20, -2, 1, 0, CAMERA_RIGHT),
                                          Event(30, 244, 182, 1, CAMERA_LEFT), Event(30, 98, 51, 0, CAMERA_RIGHT) };
    c.rectifyEvents(ev, ev);  // in place
    ASSERT_EQ(expected.size(), ev.size());
    for (size_t i = 0; i < ev.size(); i++)
        EXPECT_EQ(expected[i], ev[i]) << i;
    std::vector<Event> none;
    c.rectifyEvents(std::vector<Event>(), none);
    EXPECT_TRUE(none.empty());
    ev[2].camera = 2;
    EXPECT_THROW(c.rectifyEvents(ev, none), cv::Exception);
}

TEST(StereoCalibration, opencv_file_with_R_T_rectifies_a_distorted_pair)
{
    RawPair pair;
    const std::string path = cv::tempfile(".yml");
    {
        FileStorage fs(path, FileStorage::WRITE);
        fs << "imageSize" << pair.size << "M1" << pair.K1 << "D1" << pair.D1 << "M2" << pair.K2 << "D2" << pair.D2
           << "R" << pair.R << "T" << pair.T;
    }
    const StereoCalibration c = readStereoCalibration(path);
    EXPECT_EQ(c.imageSize, pair.size);
    EXPECT_NEAR(c.baseline(), 0.12, 0.002);
    checkRectification(c, pair);

    // Written back with R1 R2 P1 P2, it reads back the same and rectifies the same.
    const std::string again = cv::tempfile(".yml");
    writeStereoCalibration(again, c);
    const StereoCalibration d = readStereoCalibration(again);
    EXPECT_LE(cvtest::norm(c.P2, d.P2, NORM_INF), 1e-9);
    EXPECT_LE(cvtest::norm(c.R1, d.R1, NORM_INF), 1e-9);
    checkRectification(d, pair);
    std::remove(path.c_str());
    std::remove(again.c_str());
}

TEST(StereoCalibration, kalibr_camchain_rectifies_a_distorted_pair)
{
    RawPair pair;
    // Kalibr: radtan [k1 k2 p1 p2], intrinsics [fu fv pu pv], T_cn_cnm1 = cam0 -> cam1; no %YAML header.
    std::ostringstream y;
    auto cam = [&](const char* name, const Mat& K, const Mat& D) {
        y << name << ":\n  camera_model: pinhole\n  intrinsics: [" << K.at<double>(0, 0) << ", " << K.at<double>(1, 1)
          << ", " << K.at<double>(0, 2) << ", " << K.at<double>(1, 2) << "]\n  distortion_model: radtan\n"
          << "  distortion_coeffs: [" << D.at<double>(0) << ", " << D.at<double>(1) << ", " << D.at<double>(2) << ", "
          << D.at<double>(3) << "]\n  resolution: [240, 180]\n  rostopic: /davis/" << name << "/events\n";
    };
    cam("cam0", pair.K1, pair.D1);
    cam("cam1", pair.K2, pair.D2);
    y << "  T_cn_cnm1:\n";
    for (int r = 0; r < 4; r++)
    {
        y << "  - [";
        for (int col = 0; col < 4; col++)
        {
            const double v = r < 3 ? (col < 3 ? pair.R.at<double>(r, col) : pair.T.at<double>(r)) : (col == 3 ? 1.0 : 0.0);
            y << std::setprecision(17) << v << (col < 3 ? ", " : "]\n");
        }
    }
    const std::string path = writeTempFile(y.str(), ".yaml");
    const StereoCalibration c = readStereoCalibration(path);
    EXPECT_FALSE(c.fisheye);
    checkRectification(c, pair);
    std::remove(path.c_str());
}

TEST(StereoCalibration, bad_files_name_the_file_and_the_problem)
{
    auto message = [](const std::string& path) -> std::string {
        try
        {
            readStereoCalibration(path);
        }
        catch (const cv::Exception& e)
        {
            return e.what();
        }
        return "";
    };
    const std::string missing = cv::tempfile(".yml");
    EXPECT_NE(message(missing).find(missing), std::string::npos);

    const std::string noKeys = writeTempFile("%YAML:1.0\nfoo: 1\n", ".yml");
    const std::string m1 = message(noKeys);
    EXPECT_NE(m1.find(noKeys), std::string::npos) << m1;
    EXPECT_NE(m1.find("K1"), std::string::npos) << m1;

    const std::string fisheyeCam = writeTempFile("cam0:\n  camera_model: omni\n  intrinsics: [1, 1, 1, 1]\n"
                                                 "cam1:\n  camera_model: pinhole\n", ".yaml");
    const std::string m2 = message(fisheyeCam);
    EXPECT_NE(m2.find("omni"), std::string::npos) << m2;

    const std::string shortT = writeTempFile("cam0:\n  intrinsics: [200, 200, 120, 90]\n  resolution: [240, 180]\n"
                                             "cam1:\n  intrinsics: [200, 200, 120, 90]\n  resolution: [240, 180]\n"
                                             "  T_cn_cnm1:\n  - [1, 0, 0, -0.1]\n", ".yaml");
    const std::string m3 = message(shortT);
    EXPECT_NE(m3.find("T_cn_cnm1"), std::string::npos) << m3;
    for (const std::string& p : { noKeys, fisheyeCam, shortT })
        std::remove(p.c_str());
}

}}  // namespace
