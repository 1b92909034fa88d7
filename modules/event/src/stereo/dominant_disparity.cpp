// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// estimateDominantDisparity(): the disparity at which a pair's events line up best, from short event images.

#include "precomp.hpp"
#include "opencv2/imgproc.hpp"
#include "common/sensor_bounds.hpp"

#include <cmath>
#include <limits>

namespace cv {
namespace event {
namespace {

// Sums over all slices, per disparity, that the normalised correlation needs. The images are 0 / 1, so a
// camera's sum of squares is its sum.
struct ShiftSums
{
    std::vector<double> pixels, both;  // compared pixel-slices; pixels marked in both images
};

class SliceCorrelation
{
public:
    SliceCorrelation(Size size, int maxDisparity)
        : size_(size), maxDisparity_(maxDisparity), columns_{ std::vector<double>((size_t)size.width, 0.0),
                                                              std::vector<double>((size_t)size.width, 0.0) }
    {
        for (Mat& m : marks_)
            m = Mat::zeros(size, CV_8U);
        sums_.pixels.assign((size_t)(2 * maxDisparity + 1), 0.0);
        sums_.both.assign((size_t)(2 * maxDisparity + 1), 0.0);
    }

    void mark(const Event& e)
    {
        marks_[e.camera].at<uchar>(e.y, e.x) = 1;
        count_[e.camera]++;
    }

    // Adds the slice marked so far to the sums and clears it. A slice one camera saw nothing in says nothing
    // about where the other's events belong: skipped.
    void endSlice()
    {
        if (count_[0] > 0 && count_[1] > 0)
        {
            // A pixel marks its row and the rows above and below: a pair off rectification by up to a pixel
            // still lines up.
            Mat spread[2];
            const Mat column = Mat::ones(3, 1, CV_8U);
            for (int c = 0; c < 2; c++)
            {
                dilate(marks_[c], spread[c], column);
                Mat sums;
                reduce(spread[c], sums, 0, REDUCE_SUM, CV_64F);
                for (int x = 0; x < size_.width; x++)
                    columns_[c][(size_t)x] += sums.at<double>(0, x);
            }
            // Pixels marked in both images, per disparity, visited from the left image's marked pixels: the
            // work grows with the events, not with the sensor's area.
            const int width = size_.width, reach = maxDisparity_;
            findNonZero(spread[0], marked_);
            both_.assign((size_t)(2 * reach + 1), 0);
            for (const Point& q : marked_)
            {
                const uchar* right = spread[1].ptr<uchar>(q.y);
                // Left x against right x - d, where both lie on the sensor.
                const int dLow = std::max(-reach, q.x - width + 1), dHigh = std::min(reach, q.x);
                for (int d = dLow; d <= dHigh; d++)
                    both_[(size_t)(d + reach)] += right[q.x - d];
            }
            for (int d = -reach; d <= reach; d++)
            {
                const size_t k = (size_t)(d + reach);
                sums_.both[k] += (double)both_[k];
                sums_.pixels[k] += (double)(width - std::abs(d)) * size_.height;
            }
        }
        for (int c = 0; c < 2; c++)
        {
            if (count_[c] > 0)
                marks_[c].setTo(0);
            count_[c] = 0;
        }
    }

    // Pearson's correlation per disparity, from the sums.
    void correlation(std::vector<double>& r) const
    {
        r.assign(sums_.pixels.size(), 0.0);
        std::vector<double> prefix[2];
        for (int c = 0; c < 2; c++)
        {
            prefix[c].assign((size_t)size_.width + 1, 0.0);
            for (int x = 0; x < size_.width; x++)
                prefix[c][(size_t)x + 1] = prefix[c][(size_t)x] + columns_[c][(size_t)x];
        }
        for (int d = -maxDisparity_; d <= maxDisparity_; d++)
        {
            const size_t k = (size_t)(d + maxDisparity_);
            const double n = sums_.pixels[k];
            if (n <= 0)
                continue;
            const int x0 = std::max(0, d), x1 = size_.width + std::min(0, d);  // left columns [x0, x1)
            const double left = prefix[0][(size_t)x1] - prefix[0][(size_t)x0];
            const double right = prefix[1][(size_t)(x1 - d)] - prefix[1][(size_t)(x0 - d)];
            const double varLeft = n * left - left * left, varRight = n * right - right * right;
            if (varLeft > 0 && varRight > 0)
                r[k] = (n * sums_.both[k] - left * right) / std::sqrt(varLeft * varRight);
        }
    }

private:
    Size size_;
    int maxDisparity_;
    Mat marks_[2];
    int64 count_[2] = { 0, 0 };
    std::vector<double> columns_[2];  // per column, the marked pixels of all compared slices
    ShiftSums sums_;
    std::vector<Point> marked_;       // working memory of endSlice()
    std::vector<int64> both_;
};

}  // namespace

int estimateDominantDisparity(InputArray events, Size sensorSize, int maxDisparity, OutputArray correlation,
                              double* score, double sliceUs)
{
    if (sensorSize.width < 2 || sensorSize.height < 1)
        CV_Error_(Error::StsBadArg, ("estimateDominantDisparity: sensor %d x %d is not a valid pixel array",
                                     sensorSize.width, sensorSize.height));
    if (maxDisparity < 1 || maxDisparity > sensorSize.width / 2)
        CV_Error_(Error::StsBadArg, ("estimateDominantDisparity: max disparity %d; expected 1..%d (half the "
                                     "sensor width)", maxDisparity, sensorSize.width / 2));
    if (!(sliceUs >= 1 && sliceUs < 1e12))
        CV_Error_(Error::StsBadArg, ("estimateDominantDisparity: slice length %g us; expected 1 us .. 1e12 us",
                                     sliceUs));
    Mat_<Event> ev = getEventMat(events);
    SliceCorrelation slices(sensorSize, maxDisparity);
    const int64 slice = (int64)sliceUs;
    int64 sliceEnd = std::numeric_limits<int64>::min();
    for (int i = 0; i < (int)ev.total(); i++)
    {
        const Event& e = ev(i);
        if (i > 0 && e.t < ev(i - 1).t)
            CV_Error_(Error::StsBadArg, ("estimateDominantDisparity: event #%d at (x=%d, y=%d), t=%lld us, goes "
                                         "back in time (previous event at %lld us)", i, e.x, e.y, (long long)e.t,
                                         (long long)ev(i - 1).t));
        if (!detail::onSensor(e.x, e.y, sensorSize) || e.camera > 1)
            continue;
        if (sliceEnd == std::numeric_limits<int64>::min() || e.t >= sliceEnd)
        {
            slices.endSlice();
            // The slice that holds the event (empty slices in between skipped), without overflow.
            sliceEnd = e.t <= std::numeric_limits<int64>::max() - slice ? e.t + slice : std::numeric_limits<int64>::max();
        }
        slices.mark(e);
    }
    slices.endSlice();
    std::vector<double> r;
    slices.correlation(r);
    int best = 0;
    double bestScore = 0;
    for (int d = -maxDisparity; d <= maxDisparity; d++)
    {
        const double c = r[(size_t)(d + maxDisparity)];
        if (c > bestScore)
        {
            bestScore = c;
            best = d;
        }
    }
    if (score)
        *score = bestScore;
    if (correlation.needed())
        Mat(1, (int)r.size(), CV_64F, r.data()).copyTo(correlation);
    return best;
}

}  // namespace event
}  // namespace cv
