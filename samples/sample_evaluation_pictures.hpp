// The pictures of event_evaluate's report: the density-precision curve, histograms, the disparity maps and a
// filter's before / after.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_PICTURES_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_PICTURES_HPP

#include <opencv2/event.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace sample_evaluation {

using namespace cv;
using namespace cv::event;

// The density-precision curve of the estimates ranked by confidence (from the most confident bin down), with
// the method's own operating point (its rejection threshold) marked.
inline void drawDensityPrecision(const StereoEventScores& ranking, double density, double precision,
                                 const std::string& path, const std::string& title)
{
    const int w = 500, h = 300, left = 50, top = 40;
    Mat img(h + top + 50, w + left + 20, CV_8UC3, Scalar::all(255));
    const double lowest = 50;  // precision axis from 50 to 100 %
    auto at = [&](double d, double p) {
        return Point(left + (int)std::lround(d / 100 * w), top + (int)std::lround((100 - std::max(lowest, p)) / (100 - lowest) * h));
    };
    rectangle(img, at(0, 100), at(100, lowest), Scalar(200, 200, 200));
    for (int p = 60; p < 100; p += 10)
        line(img, at(0, p), at(100, p), Scalar(235, 235, 235));
    double taken = 0, good = 0;
    Point previous(-1, -1);
    for (int b = (int)ranking.confidenceEstimated.size() - 1; b >= 0; b--)
    {
        taken += ranking.confidenceEstimated[(size_t)b];
        good += ranking.confidenceWithin1[(size_t)b];
        if (ranking.confidenceEstimated[(size_t)b] == 0)
            continue;
        const Point q = at(100.0 * taken / ranking.visibleSignal, 100.0 * good / taken);
        if (previous.x >= 0)
            line(img, previous, q, Scalar(180, 90, 30), 2, LINE_AA);
        previous = q;
    }
    circle(img, at(density, precision), 5, Scalar(0, 0, 220), FILLED, LINE_AA);
    putText(img, title, Point(10, 22), FONT_HERSHEY_SIMPLEX, 0.5, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "100 %", Point(5, top + 5), FONT_HERSHEY_SIMPLEX, 0.35, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "50 %", Point(10, top + h), FONT_HERSHEY_SIMPLEX, 0.35, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "density (estimates / non-occluded signal events), 0 .. 100 %", Point(left, top + h + 20),
            FONT_HERSHEY_SIMPLEX, 0.38, Scalar(0, 0, 0), 1, LINE_AA);
    putText(img, "up: precision (within 1 px); red dot: the rejection threshold", Point(left, top + h + 38),
            FONT_HERSHEY_SIMPLEX, 0.38, Scalar(0, 0, 0), 1, LINE_AA);
    imwrite(path, img);
}

// Left camera's events of a window as a picture: signal ON white, signal OFF grey, noise red, flicker blue; and
// the same for the events a filter kept, side by side.
inline Mat drawFilterBeforeAfter(const std::vector<Event>& window, const std::vector<std::array<float, 6>>& truth,
                          const std::vector<uchar>& keepMask, Size size)
{
    Mat before(size, CV_8UC3, Scalar::all(0)), after(size, CV_8UC3, Scalar::all(0));
    for (size_t i = 0; i < window.size(); i++)
    {
        const Event& e = window[i];
        if (e.camera != CAMERA_LEFT)
            continue;
        const int flags = (int)truth[i][GT_FLAGS];
        const Vec3b colour = (flags & GT_FLAG_NOISE) ? Vec3b(40, 40, 255)
                           : (flags & GT_FLAG_FLICKER) ? Vec3b(255, 120, 0)
                           : e.p ? Vec3b(255, 255, 255) : Vec3b(150, 150, 150);
        before.at<Vec3b>(e.y, e.x) = colour;
        if (keepMask[i])
            after.at<Vec3b>(e.y, e.x) = colour;
    }
    Mat pair;
    hconcat(std::vector<Mat>{ before, Mat(size.height, 4, CV_8UC3, Scalar(80, 80, 80)), after }, pair);
    resize(pair, pair, Size(), 2, 2, INTER_NEAREST);
    return pair;
}

// Bars with the first and last bin labelled "0" and the range end.
inline void drawHistogram(const std::vector<int>& h, const std::string& path, const std::string& title,
                   const std::string& endLabel = "10 px")
{
    const int w = 20 * (int)h.size(), height = 300;
    Mat img(height + 70, w + 20, CV_8UC3, Scalar::all(255));  // title above the bars, labels below
    const int peak = std::max(1, *std::max_element(h.begin(), h.end()));
    for (size_t k = 0; k < h.size(); k++)
    {
        const int bar = (int)std::lround((double)h[k] / peak * height);
        rectangle(img, Point(10 + 20 * (int)k, height + 40 - bar), Point(10 + 20 * (int)k + 17, height + 40), Scalar(180, 90, 30), FILLED);
    }
    putText(img, title, Point(10, 25), FONT_HERSHEY_SIMPLEX, 0.5, Scalar(0, 0, 0), 1);
    putText(img, "0", Point(10, height + 60), FONT_HERSHEY_SIMPLEX, 0.4, Scalar(0, 0, 0), 1);
    putText(img, endLabel, Point(w - 30, height + 60), FONT_HERSHEY_SIMPLEX, 0.4, Scalar(0, 0, 0), 1);
    imwrite(path, img);
}

}  // namespace sample_evaluation

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_PICTURES_HPP
