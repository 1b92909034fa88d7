// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stereo calibration: the OpenCV (stereoCalibrate + stereoRectify) and Kalibr camchain files, and the
// raw -> rectified point mapping the matcher's lookup tables are built from.

#include "precomp.hpp"
#include "stereo/rectification_table.hpp"

#include "opencv2/calib3d.hpp"

#include <fstream>
#include <iterator>
#include <sstream>

namespace cv {
namespace event {

namespace {

Mat readMat(const FileNode& root, std::initializer_list<const char*> keys, const String& path, bool required)
{
    for (const char* key : keys)
    {
        const FileNode n = root[key];
        if (n.empty())
            continue;
        Mat m;
        try
        {
            n >> m;
        }
        catch (const cv::Exception&)
        {
            m.release();
        }
        if (m.empty())
            CV_Error_(Error::StsParseError, ("%s: key '%s' is not a matrix (write it with FileStorage << Mat)",
                                             path.c_str(), key));
        Mat d;
        m.convertTo(d, CV_64F);
        return d;
    }
    if (required)
        CV_Error_(Error::StsParseError, ("%s: no '%s' entry: not a stereo calibration file (expected K1 D1 K2 D2 "
                                         "and R1 R2 P1 P2 or R T, or a Kalibr camchain with cam0 and cam1)",
                                         path.c_str(), *keys.begin()));
    return Mat();
}

std::vector<double> readNumbers(const FileNode& n, const String& path, const String& key, size_t expected)
{
    std::vector<double> v;
    if (n.isSeq())
        for (FileNodeIterator it = n.begin(); it != n.end(); ++it)
        {
            if (!(*it).isReal() && !(*it).isInt())
                CV_Error_(Error::StsParseError, ("%s: %s must be a list of numbers", path.c_str(), key.c_str()));
            v.push_back((double)*it);
        }
    if (expected && v.size() != expected)
        CV_Error_(Error::StsParseError, ("%s: %s has %d numbers, expected %d", path.c_str(), key.c_str(), (int)v.size(),
                                         (int)expected));
    return v;
}

void rectify(StereoCalibration& c, const Mat& R, const Mat& T)
{
    Mat Q;
    if (c.fisheye)
        fisheye::stereoRectify(c.K1, c.D1, c.K2, c.D2, c.imageSize, R, T, c.R1, c.R2, c.P1, c.P2, Q,
                               CALIB_ZERO_DISPARITY, c.imageSize, 0.0, 1.0);
    else
        stereoRectify(c.K1, c.D1, c.K2, c.D2, c.imageSize, R, T, c.R1, c.R2, c.P1, c.P2, Q, CALIB_ZERO_DISPARITY, 0,
                      c.imageSize);
}

// Kalibr: cam0 / cam1 maps; cam1.T_cn_cnm1 takes cam0 coordinates to cam1's.
StereoCalibration readKalibr(const FileStorage& fs, const String& path)
{
    StereoCalibration c;
    Mat K[2], D[2];
    std::string model[2];
    for (int i = 0; i < 2; i++)
    {
        const String cam = i == 0 ? "cam0" : "cam1";
        const FileNode n = fs[cam];
        if (!n.isMap())
            CV_Error_(Error::StsParseError, ("%s: Kalibr camchain without a '%s' map", path.c_str(), cam.c_str()));
        const std::string cameraModel = n["camera_model"].empty() ? "pinhole" : (std::string)n["camera_model"];
        if (cameraModel != "pinhole")
            CV_Error_(Error::StsNotImplemented, ("%s: %s.camera_model '%s': only pinhole cameras are supported",
                                                 path.c_str(), cam.c_str(), cameraModel.c_str()));
        const std::vector<double> in = readNumbers(n["intrinsics"], path, cam + ".intrinsics", 4);
        K[i] = (Mat_<double>(3, 3) << in[0], 0, in[2], 0, in[1], in[3], 0, 0, 1);
        model[i] = n["distortion_model"].empty() ? "none" : (std::string)n["distortion_model"];
        const std::vector<double> dc = readNumbers(n["distortion_coeffs"], path, cam + ".distortion_coeffs", 0);
        if (model[i] == "radtan")
        {
            if (dc.size() != 4)
                CV_Error_(Error::StsParseError, ("%s: %s radtan needs 4 distortion_coeffs", path.c_str(), cam.c_str()));
        }
        else if (model[i] == "equidistant")
        {
            if (dc.size() != 4)
                CV_Error_(Error::StsParseError, ("%s: %s equidistant needs 4 distortion_coeffs", path.c_str(), cam.c_str()));
        }
        else if (model[i] != "none")
            CV_Error_(Error::StsNotImplemented, ("%s: %s.distortion_model '%s': supported are radtan, equidistant, none",
                                                 path.c_str(), cam.c_str(), model[i].c_str()));
        D[i] = dc.empty() ? Mat::zeros(1, 4, CV_64F) : Mat(dc, true).reshape(1, 1);
        const std::vector<double> res = readNumbers(n["resolution"], path, cam + ".resolution", 2);
        const Size size((int)res[0], (int)res[1]);
        if (i == 0)
            c.imageSize = size;
        else if (size != c.imageSize)
            CV_Error_(Error::StsNotImplemented, ("%s: cam0 is %d x %d but cam1 %d x %d: both sensors must have the same size",
                                                 path.c_str(), c.imageSize.width, c.imageSize.height, size.width, size.height));
    }
    if ((model[0] == "equidistant") != (model[1] == "equidistant"))
        CV_Error_(Error::StsNotImplemented, ("%s: one camera equidistant and one not: mixed models are not supported",
                                             path.c_str()));
    const FileNode tn = fs["cam1"]["T_cn_cnm1"];
    std::vector<double> t;
    if (tn.isSeq())
        for (FileNodeIterator it = tn.begin(); it != tn.end(); ++it)
        {
            const std::vector<double> row = readNumbers(*it, path, "cam1.T_cn_cnm1 row", 4);
            t.insert(t.end(), row.begin(), row.end());
        }
    if (t.size() != 16)
        CV_Error_(Error::StsParseError, ("%s: cam1.T_cn_cnm1 must be a 4 x 4 matrix (list of 4 rows)", path.c_str()));
    const Mat T4(4, 4, CV_64F, t.data());
    c.K1 = K[0];
    c.K2 = K[1];
    c.D1 = D[0];
    c.D2 = D[1];
    c.fisheye = model[0] == "equidistant";
    rectify(c, T4(Rect(0, 0, 3, 3)).clone(), T4(Rect(3, 0, 1, 3)).clone());
    return c;
}

StereoCalibration readOpenCV(const FileNode& root, const String& path);

// PyYAML (hence Kalibr) writes a block sequence at the indentation of its key ("key:\n- [..]");
// FileStorage's parser wants it deeper. Indents such items by two more spaces.
std::string indentBlockSequences(const std::string& text)
{
    std::istringstream in(text);
    std::ostringstream out;
    std::string line;
    size_t keyIndent = std::string::npos;  // indentation of the last "key:" line opening a block
    while (std::getline(in, line))
    {
        const size_t indent = line.find_first_not_of(' ');
        if (indent != std::string::npos && line.compare(indent, 2, "- ") == 0 && indent == keyIndent)
            line = "  " + line;
        else if (indent != std::string::npos)
        {
            const size_t end = line.find_last_not_of(" \r");
            keyIndent = line[end] == ':' ? indent : std::string::npos;
        }
        out << line << "\n";
    }
    return out.str();
}

}  // namespace

StereoCalibration StereoCalibration::fromRectified(Size imageSize, double f, double baseline)
{
    if (imageSize.width <= 0 || imageSize.height <= 0 || !(f > 0) || !(baseline != 0) || !std::isfinite(baseline))
        CV_Error_(Error::StsBadArg, ("StereoCalibration::fromRectified: size %d x %d, focal length %g, baseline %g: "
                                     "need a positive size and focal length and a non-zero baseline",
                                     imageSize.width, imageSize.height, f, baseline));
    StereoCalibration c;
    c.imageSize = imageSize;
    const double cx = 0.5 * (imageSize.width - 1), cy = 0.5 * (imageSize.height - 1);
    c.K1 = (Mat_<double>(3, 3) << f, 0, cx, 0, f, cy, 0, 0, 1);
    c.K2 = c.K1.clone();
    c.D1 = Mat::zeros(1, 5, CV_64F);
    c.D2 = Mat::zeros(1, 5, CV_64F);
    c.R1 = Mat::eye(3, 3, CV_64F);
    c.R2 = Mat::eye(3, 3, CV_64F);
    c.P1 = (Mat_<double>(3, 4) << f, 0, cx, 0, 0, f, cy, 0, 0, 0, 1, 0);
    c.P2 = (Mat_<double>(3, 4) << f, 0, cx, -f * baseline, 0, f, cy, 0, 0, 0, 1, 0);
    return c;
}

double StereoCalibration::focalLength() const
{
    return P1.empty() ? 0.0 : P1.at<double>(0, 0);
}

double StereoCalibration::baseline() const
{
    return P2.empty() || P2.at<double>(0, 0) == 0 ? 0.0 : -P2.at<double>(0, 3) / P2.at<double>(0, 0);
}

bool StereoCalibration::empty() const
{
    return P1.empty();
}

void StereoCalibration::validate() const
{
    auto check = [](const Mat& m, int rows, int cols, const char* name) {
        if (m.rows != rows || m.cols != cols || m.type() != CV_64F)
            CV_Error_(Error::StsBadArg, ("StereoCalibration: %s is %d x %d (type %d); expected %d x %d CV_64F", name,
                                         m.rows, m.cols, m.type(), rows, cols));
    };
    check(K1, 3, 3, "K1");
    check(K2, 3, 3, "K2");
    check(R1, 3, 3, "R1");
    check(R2, 3, 3, "R2");
    check(P1, 3, 4, "P1");
    check(P2, 3, 4, "P2");
    for (const Mat* d : { &D1, &D2 })
    {
        const int n = (int)d->total();
        const bool ok = d->type() == CV_64F && (d->rows == 1 || d->cols == 1) &&
                        (fisheye ? n == 4 : (n == 4 || n == 5 || n == 8 || n == 12 || n == 14));
        if (!ok)
            CV_Error_(Error::StsBadArg, ("StereoCalibration: %s has %d coefficients (type %d); expected a CV_64F vector of "
                                         "%s", d == &D1 ? "D1" : "D2", n, d->type(), fisheye ? "4 (fisheye)" : "4, 5, 8, 12 or 14"));
    }
    if (imageSize.width <= 0 || imageSize.height <= 0)
        CV_Error_(Error::StsBadArg, ("StereoCalibration: image size %d x %d", imageSize.width, imageSize.height));
    if (!(focalLength() > 0))
        CV_Error_(Error::StsBadArg, ("StereoCalibration: rectified focal length P1(0,0) = %g; must be > 0", focalLength()));
    if (!(baseline() != 0) || !std::isfinite(baseline()))
        CV_Error_(Error::StsBadArg, ("StereoCalibration: baseline -P2(0,3)/P2(0,0) = %g; the pair is not horizontal "
                                     "stereo", baseline()));
}

void StereoCalibration::rectifyPoints(InputArray points, OutputArray rectified, int camera) const
{
    validate();
    CV_CheckType(points.type(), points.type() == CV_32FC2 || points.type() == CV_64FC2,
                 "StereoCalibration::rectifyPoints: points must be 2-channel float");
    const bool left = camera == CAMERA_LEFT;
    Mat out;
    if (fisheye)
        fisheye::undistortPoints(points, out, left ? K1 : K2, left ? D1 : D2, left ? R1 : R2, left ? P1 : P2);
    else
        undistortPoints(points, out, left ? K1 : K2, left ? D1 : D2, left ? R1 : R2, left ? P1 : P2);
    out.convertTo(rectified, CV_32FC2);
}

void StereoCalibration::rectifyEvents(InputArray events, OutputArray rectified) const
{
    std::vector<Event> out = toEventVector(events);
    for (int camera = 0; camera < 2; camera++)
    {
        std::vector<Point2f> raw;
        for (const Event& e : out)
        {
            if (e.camera > 1)
                CV_Error_(Error::StsBadArg, ("StereoCalibration::rectifyEvents: event with camera id %d (expected 0 or 1)",
                                             (int)e.camera));
            if (e.camera == camera)
                raw.push_back(Point2f(e.x, e.y));
        }
        if (raw.empty())
            continue;
        Mat q;
        rectifyPoints(raw, q, camera);
        const Point2f* p = q.ptr<Point2f>();
        for (Event& e : out)
            if (e.camera == camera)
            {
                // Outside short's range only for a calibration that throws pixels far away: kept outside.
                e.x = saturate_cast<short>(cvRound(p->x));
                e.y = saturate_cast<short>(cvRound(p->y));
                p++;
            }
    }
    Mat(out).copyTo(rectified);
}

void StereoCalibration::read(const FileNode& node, const String& source)
{
    StereoCalibration c = readOpenCV(node, source);
    try
    {
        c.validate();
    }
    catch (const cv::Exception& e)
    {
        CV_Error_(Error::StsParseError, ("%s: %s", source.c_str(), e.err.c_str()));
    }
    *this = c;
}

void StereoCalibration::write(FileStorage& fs) const
{
    fs << "imageSize" << imageSize << "fisheye" << (int)fisheye << "K1" << K1 << "D1" << D1 << "R1" << R1 << "P1" << P1
       << "K2" << K2 << "D2" << D2 << "R2" << R2 << "P2" << P2;
}

StereoCalibration readStereoCalibration(const String& path)
{
    std::ifstream in(path.c_str(), std::ios::binary);
    if (!in)
        CV_Error_(Error::StsError, ("%s: cannot open the calibration file", path.c_str()));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    FileStorage fs;
    try
    {
        // Kalibr writes YAML without the "%YAML:1.0" directive FileStorage wants: add it when missing.
        const bool yaml = text.compare(0, 1, "<") != 0 && text.compare(0, 1, "{") != 0;
        if (yaml && text.compare(0, 5, "%YAML") != 0)
            text = "%YAML:1.0\n" + indentBlockSequences(text);
        fs.open(text, FileStorage::READ | FileStorage::MEMORY);
    }
    catch (const cv::Exception& e)
    {
        CV_Error_(Error::StsParseError, ("%s: cannot parse the calibration file: %s", path.c_str(), e.err.c_str()));
    }
    if (!fs.isOpened())
        CV_Error_(Error::StsError, ("%s: cannot open the calibration file", path.c_str()));
    StereoCalibration c;
    if (!fs["cam0"].isMap())
    {
        c.read(fs.root(), path);
        return c;
    }
    c = readKalibr(fs, path);
    try
    {
        c.validate();
    }
    catch (const cv::Exception& e)
    {
        CV_Error_(Error::StsParseError, ("%s: %s", path.c_str(), e.err.c_str()));
    }
    return c;
}

namespace {

StereoCalibration readOpenCV(const FileNode& root, const String& path)
{
    StereoCalibration c;
    c.K1 = readMat(root, { "K1", "M1", "cameraMatrix1" }, path, true);
    c.D1 = readMat(root, { "D1", "distCoeffs1" }, path, true);
    c.K2 = readMat(root, { "K2", "M2", "cameraMatrix2" }, path, true);
    c.D2 = readMat(root, { "D2", "distCoeffs2" }, path, true);
    c.fisheye = !root["fisheye"].empty() && (int)root["fisheye"] != 0;
    if (!root["imageSize"].empty())
        root["imageSize"] >> c.imageSize;
    else if (!root["image_width"].empty() && !root["image_height"].empty())
        c.imageSize = Size((int)root["image_width"], (int)root["image_height"]);
    else
        CV_Error_(Error::StsParseError, ("%s: no imageSize (or image_width and image_height)", path.c_str()));
    if (c.imageSize.width <= 0 || c.imageSize.height <= 0)
        CV_Error_(Error::StsParseError, ("%s: imageSize %d x %d is not valid", path.c_str(), c.imageSize.width,
                                         c.imageSize.height));
    c.R1 = readMat(root, { "R1" }, path, false);
    c.R2 = readMat(root, { "R2" }, path, false);
    c.P1 = readMat(root, { "P1" }, path, false);
    c.P2 = readMat(root, { "P2" }, path, false);
    if (c.R1.empty() || c.R2.empty() || c.P1.empty() || c.P2.empty())
    {
        const Mat R = readMat(root, { "R" }, path, true), T = readMat(root, { "T" }, path, true);
        rectify(c, R, T);
    }
    return c;
}

}  // namespace

void writeStereoCalibration(const String& path, const StereoCalibration& calibration)
{
    calibration.validate();
    FileStorage fs(path, FileStorage::WRITE);
    if (!fs.isOpened())
        CV_Error_(Error::StsError, ("%s: cannot write the calibration file", path.c_str()));
    calibration.write(fs);
}

namespace detail {

std::vector<int> buildRectificationTable(const StereoCalibration& calibration, int camera)
{
    const Size size = calibration.imageSize;
    Mat pixels(size.area(), 1, CV_32FC2), rect;
    for (int y = 0; y < size.height; y++)
        for (int x = 0; x < size.width; x++)
            pixels.at<Vec2f>(y * size.width + x) = Vec2f((float)x, (float)y);
    calibration.rectifyPoints(pixels, rect, camera);
    std::vector<int> table((size_t)size.area());
    for (int i = 0; i < size.area(); i++)
    {
        const Vec2f q = rect.at<Vec2f>(i);
        const int x = cvRound(q[0]), y = cvRound(q[1]);
        const bool inside = std::isfinite(q[0]) && std::isfinite(q[1]) && x >= 0 && y >= 0 && x < size.width &&
                            y < size.height;
        table[(size_t)i] = inside ? y * size.width + x : -1;
    }
    return table;
}

}  // namespace detail

}  // namespace event
}  // namespace cv
