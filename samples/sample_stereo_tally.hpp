// What event_stereo counts over a run for its summary: events per camera, those with a disparity and with a
// lifetime, the disparities' histogram, the left estimates' confidence and, when simulated, the scores against
// the ground truth.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_TALLY_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_TALLY_HPP

#include <opencv2/event.hpp>
#include <opencv2/imgproc.hpp>

#include "sample_signed_errors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

class SampleStereoTally
{
public:
    SampleStereoTally(int minDisparity, int maxDisparity, int sensorWidth)
        : minDisparity_(minDisparity), sensorWidth_(sensorWidth), histogram_((size_t)(maxDisparity - minDisparity + 1), 0),
          confidences_(101, 0)
    {
    }

    /** One packet's outputs (StereoEventMatcher::process()); @p truth empty unless simulated. */
    void add(const std::vector<cv::event::Event>& packet, const cv::Mat& disparity, const cv::Mat& flags,
             const cv::Mat& confidence, const cv::Mat& truth)
    {
        if (!truth.empty())
            cv::event::scoreStereoEvents(packet, disparity, truth, scores);
        for (size_t i = 0; i < packet.size(); i++)
        {
            const int camera = packet[i].camera;
            const float d = disparity.at<float>((int)i);
            if (!truth.empty())
                signedErrors_.add(packet[i], sensorWidth_, d, truth.at<float>((int)i, cv::event::GT_DISPARITY),
                                  (int)truth.at<float>((int)i, cv::event::GT_FLAGS));
            perCamera_[camera]++;
            withDisparity_[camera] += d >= 0;
            withLifetime_[camera] += (flags.at<int>((int)i) & cv::event::STEREO_HAS_LIFETIME) != 0;
            if (d >= 0 && camera == cv::event::CAMERA_LEFT)
                confidences_[(size_t)std::min(100, std::max(0, (int)(confidence.at<float>((int)i) * 100.f)))]++;
            if (d >= 0)
                histogram_[(size_t)std::min<int>((int)histogram_.size() - 1, std::max(0, (int)std::lround(d) - minDisparity_))]++;
        }
    }

    int64_t events() const { return perCamera_[0] + perCamera_[1]; }

    /** The summary's rows on the events per camera and their estimates. */
    std::string eventRows() const
    {
        std::ostringstream text;
        text << "| events | " << events() << " (left " << perCamera_[0] << ", right " << perCamera_[1] << ") |\n";
        return text.str();
    }
    std::string estimateRows() const
    {
        std::ostringstream text;
        text << "| events with a disparity | " << pct(withDisparity_[0] + withDisparity_[1], events()) << " % (left "
             << pct(withDisparity_[0], perCamera_[0]) << " %, right " << pct(withDisparity_[1], perCamera_[1]) << " %) |\n"
             << "| events with a lifetime | " << pct(withLifetime_[0] + withLifetime_[1], events()) << " % (left "
             << withLifetime_[0] << ", right " << withLifetime_[1] << ") |\n";
        return text.str();
    }
    /** The dominant disparity and the confidence's quartiles (frames + SGBM give no confidence). */
    std::string disparityRows(bool withConfidence) const
    {
        int dominant = -1;
        int64_t votes = 0;
        for (size_t k = 0; k < histogram_.size(); k++)
            if (histogram_[k] > votes)
            {
                votes = histogram_[k];
                dominant = minDisparity_ + (int)k;
            }
        std::ostringstream text;
        text << "| dominant disparity | " << dominant << " px (" << pct(votes, withDisparity_[0] + withDisparity_[1])
             << " % of estimates) |\n"
             << "| confidence of the left estimates (quartiles) | "
             << (withConfidence ? confidenceQuartiles() : std::string("none (frames + SGBM give no confidence)")) << " |\n";
        return text.str();
    }
    std::string truthRows() const
    {
        std::ostringstream text;
        text << "| ground truth: density (estimated / non-occluded signal) | " << scores.density() << " % |\n"
             << "| ground truth: estimates within 1 px | " << scores.precision() << " % |\n"
             << "| ground truth: matching rate (left signal events within 1 px, over all of them) | "
             << scores.matchingRate() << " % |\n"
             << "| ground truth: left signal events 1-2 px off / over 2 px off / without a disparity | "
             << cv::format("%.1f / %.1f / %.1f", pct(scores.leftWithin2 - scores.leftWithin1, scores.leftSignal),
                           pct(scores.leftEstimated - scores.leftWithin2, scores.leftSignal),
                           pct(scores.leftSignal - scores.leftEstimated, scores.leftSignal))
             << " % |\n"
             << "| ground truth: mean absolute disparity error | " << scores.meanAbsError() << " px |\n"
             << "| ground truth: mean signed error of the left estimates within 3 px, by third of the columns (left / "
                "middle / right) | "
             << signedErrors_.text() << " |\n";
        return text.str();
    }

    /** Bars of events per disparity. */
    cv::Mat histogramPicture() const
    {
        const std::vector<int64_t>& h = histogram_;
        const int bar = 8, height = 200;
        cv::Mat img(height + 50, bar * (int)h.size() + 20, CV_8UC3, cv::Scalar::all(255));
        const int64_t peak = std::max<int64_t>(1, *std::max_element(h.begin(), h.end()));
        for (size_t k = 0; k < h.size(); k++)
        {
            const int len = (int)std::lround((double)h[k] / (double)peak * height);
            cv::rectangle(img, cv::Point(10 + bar * (int)k, height + 20 - len),
                          cv::Point(10 + bar * (int)k + bar - 2, height + 20), cv::Scalar(180, 90, 30), cv::FILLED);
        }
        const cv::Scalar black = cv::Scalar::all(0);
        cv::putText(img, "events per disparity [px]", cv::Point(10, 14), cv::FONT_HERSHEY_SIMPLEX, 0.45, black, 1);
        cv::putText(img, std::to_string(minDisparity_), cv::Point(10, height + 40), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                    black, 1);
        cv::putText(img, std::to_string(minDisparity_ + (int)h.size() - 1), cv::Point(img.cols - 30, height + 40),
                    cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1);
        return img;
    }

    cv::event::StereoEventScores scores;

private:
    static double pct(double a, double b) { return b != 0 ? 100.0 * a / b : 0.0; }

    // The quartiles of the left estimates' confidence (bins of 0.01) and the share below 0.15 (the threshold
    // the benchmarks' rejection examples use): how clear-cut the matches of this recording are (a scene with
    // few, alike edges along the rows gives low values, whatever the matcher).
    std::string confidenceQuartiles() const
    {
        const std::vector<int64_t>& h = confidences_;
        const double lowConfidence = 0.15;
        const double binsPerUnit = (double)(h.size() - 1);
        int64_t n = 0;
        for (int64_t c : h)
            n += c;
        if (n == 0)
            return "none (no left estimate)";
        auto quantile = [&](double q) {
            int64_t seen = 0;
            for (size_t k = 0; k < h.size(); k++)
                if ((seen += h[k]) > (int64_t)(q * (double)(n - 1)))
                    return (double)k / binsPerUnit;
            return 1.0;
        };
        int64_t low = 0;
        for (size_t k = 0; k < (size_t)std::lround(lowConfidence * binsPerUnit); k++)
            low += h[k];
        return cv::format("%.2f / %.2f / %.2f (%.1f %% below %.2f)", quantile(0.25), quantile(0.5), quantile(0.75),
                          100.0 * (double)low / (double)n, lowConfidence);
    }

    int minDisparity_, sensorWidth_;
    std::vector<int64_t> histogram_, confidences_;
    SampleSignedErrors signedErrors_;
    int64_t perCamera_[2] = { 0, 0 }, withDisparity_[2] = { 0, 0 }, withLifetime_[2] = { 0, 0 };
};

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_TALLY_HPP
