// What event_evaluate runs and sums: the methods it evaluates (the stereo methods, LifetimeEstimator, none)
// and the totals of their estimates against per-event ground truth.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_HPP

#include <opencv2/event.hpp>

#include "algorithm_settings.hpp"
#include "sample_signed_errors.hpp"
#include "stereo_method.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sample_evaluation {

using namespace cv;
using namespace cv::event;

// What a method says about each event of a window: disparity (-1: none), lifetime [us] (0: noise), and
// which of the two it estimates at all.
struct MethodOutput
{
    std::vector<float> disparity, lifetime, confidence;
    std::vector<int> flags;
    // The same method with no rejection (minimum confidence 0): every event's best estimate and its confidence,
    // for the density-precision curve; empty for methods without a confidence.
    std::vector<float> bestDisparity, bestConfidence;
    bool hasDisparity = false, hasLifetime = false;
};

class Method
{
public:
    virtual ~Method() {}
    virtual void process(const std::vector<Event>& window, MethodOutput& out) = 0;
    // Fills out.bestDisparity / bestConfidence (not timed); nothing for methods without a confidence.
    virtual void processUnfiltered(const std::vector<Event>& window, MethodOutput& out)
    {
        (void)window;
        out.bestDisparity.clear();
        out.bestConfidence.clear();
    }
};

// A stereo method (StereoMethod: a StereoEventMatcher mode per event, or frames + SGBM per window; the windows
// here are the frame baseline's, so each frame gets exactly one window of events).
class Matcher CV_FINAL : public Method
{
public:
    Matcher(Size size, const std::string& name, double windowUs, const std::string& settings) : method_(name, size)
    {
        if (method_.frames)
            method_.frames->setFrameWindow(windowUs);
        method_.applySettings(settings);
        // Without rejection (the default) the run itself gives every event's best estimate.
        if (method_.matcher && method_.matcher->getMinConfidence() > 0)
        {
            unfiltered_.reset(new StereoMethod(name, size));
            unfiltered_->applySettings(settings);
            unfiltered_->matcher->setMinConfidence(0);
        }
    }

    void process(const std::vector<Event>& window, MethodOutput& out) CV_OVERRIDE
    {
        Mat disparity, lifetime, flags, confidence;
        method_.process(window, disparity, lifetime, flags, noArray(), confidence);
        out.hasDisparity = true;
        out.hasLifetime = method_.hasLifetime();
        out.disparity.assign(disparity.begin<float>(), disparity.end<float>());
        out.lifetime.assign(lifetime.begin<float>(), lifetime.end<float>());
        out.flags.assign(flags.begin<int>(), flags.end<int>());
        out.confidence.assign(confidence.begin<float>(), confidence.end<float>());
    }

    void processUnfiltered(const std::vector<Event>& window, MethodOutput& out) CV_OVERRIDE
    {
        if (!method_.hasConfidence())
            return Method::processUnfiltered(window, out);
        if (!unfiltered_)
        {
            out.bestDisparity = out.disparity;
            out.bestConfidence = out.confidence;
            return;
        }
        Mat disparity, confidence;
        unfiltered_->process(window, disparity, noArray(), noArray(), noArray(), confidence);
        out.bestDisparity.assign(disparity.begin<float>(), disparity.end<float>());
        out.bestConfidence.assign(confidence.begin<float>(), confidence.end<float>());
    }

private:
    StereoMethod method_;
    std::unique_ptr<StereoMethod> unfiltered_;
};

// Lifetime per camera (LifetimeEstimator, plane fitting); no disparity. Lifetimes of a quality below minQuality
// are dropped (0: the event counts as one without a lifetime).
class Lifetime CV_FINAL : public Method
{
public:
    Lifetime(Size size, const std::string& settings, double minQuality = 0)
        : est_{ LifetimeEstimator::create(size), LifetimeEstimator::create(size) }, minQuality_(minQuality)
    {
        for (const Ptr<LifetimeEstimator>& est : est_)
            applyAlgorithmSettings(est, settings, "--set", "lifetime estimator");
    }

    void process(const std::vector<Event>& window, MethodOutput& out) CV_OVERRIDE
    {
        out.hasLifetime = true;
        out.lifetime.resize(window.size());
        for (size_t i = 0; i < window.size(); i++)
        {
            Vec2f flow;
            int status;
            float quality;
            const float lifetime = est_[window[i].camera]->processEvent(window[i], flow, status, quality);
            out.lifetime[i] = quality >= minQuality_ ? lifetime : 0.f;
        }
    }

private:
    Ptr<LifetimeEstimator> est_[2];
    double minQuality_;
};

// No estimate at all: --method=none evaluates a --filter alone.
class NoEstimate CV_FINAL : public Method
{
public:
    void process(const std::vector<Event>&, MethodOutput& out) CV_OVERRIDE { out = MethodOutput(); }
};

// The method's output for the kept events of a window, spread back over the whole window: a removed event has
// no disparity, no lifetime (the filter calls it noise) and no best estimate.
inline void spreadOverWindow(const MethodOutput& kept, const std::vector<uchar>& keepMask, MethodOutput& out)
{
    const size_t n = keepMask.size();
    MethodOutput all;
    all.hasDisparity = kept.hasDisparity;
    all.hasLifetime = kept.hasLifetime;
    auto spread = [&](const std::vector<float>& from, std::vector<float>& to, float none) {
        if (from.empty())
            return;
        to.assign(n, none);
        for (size_t i = 0, k = 0; i < n; i++)
            if (keepMask[i])
                to[i] = from[k++];
    };
    spread(kept.disparity, all.disparity, -1.f);
    spread(kept.lifetime, all.lifetime, 0.f);
    spread(kept.confidence, all.confidence, 0.f);
    spread(kept.bestDisparity, all.bestDisparity, -1.f);
    spread(kept.bestConfidence, all.bestConfidence, 0.f);
    if (!kept.flags.empty())
    {
        all.flags.assign(n, 0);
        for (size_t i = 0, k = 0; i < n; i++)
            if (keepMask[i])
                all.flags[i] = kept.flags[k++];
    }
    out = all;
}

// What event_evaluate sums over the windows of a run: the disparities scored against the ground truth, the
// lifetimes' errors, the noise classification, what a filter kept, and the last window's maps for the pictures.
// The median of non-negative values without keeping them, so that memory does not grow with the recording:
// a count per value of the top 20 bits of their float representation (the exponent and 11 bits of mantissa,
// bins 0.05 % of the value wide); the median is the middle of the bin that holds it.
class StreamingMedian
{
public:
    void add(double value)
    {
        const float v = (float)value;
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        counts_[bits >> SHIFT]++;
        total_++;
    }
    bool empty() const { return total_ == 0; }
    // The value at rank total / 2 in sorted order (within its bin).
    double median() const
    {
        int64 seen = 0;
        for (size_t b = 0; b < counts_.size(); b++)
            if ((seen += (int64)counts_[b]) > total_ / 2)
                return 0.5 * (binStart((uint32_t)b) + binStart((uint32_t)b + 1));
        return 0;
    }

private:
    enum { SHIFT = 12 };
    static double binStart(uint32_t bin)
    {
        const uint32_t bits = bin << SHIFT;
        float v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    std::vector<uint32_t> counts_ = std::vector<uint32_t>((size_t)1 << (32 - SHIFT), 0);
    int64 total_ = 0;
};

struct EvaluationTotals
{
    int64 events = 0, signal = 0, withLifetime = 0;
    // The disparities scored (scoreStereoEvents): over every event; over the left signal events the right camera
    // sees (not flagged occluded: what a matcher can reach); over the events motion caused (flicker left out:
    // with a flickering lamp in view, what a user's moving scene gets).
    StereoEventScores scores, visible, motion;
    // Left signal events without a disparity: rejected (STEREO_AMBIGUOUS), no candidate (STEREO_NO_COUNTERPART);
    // the rest had neither (outside the rectified image).
    int64 leftAmbiguous = 0, leftNoCounterpart = 0;
    int64 withLifetimeCamera[2] = { 0, 0 };
    int64 noiseTrue = 0, noiseFlagged = 0, noiseCorrect = 0;
    std::vector<int> errorHistogram = std::vector<int>(41, 0);  // |error| in 0.25 px bins up to 10 px
    // |lifetime - truth| / truth of the signal events with both: median, and 2.5 % bins up to 100 %.
    StreamingMedian lifetimeError;
    std::vector<int> lifetimeErrorHistogram = std::vector<int>(41, 0);
    // Signal events a flickering plane caused (GT_FLAG_FLICKER); signal - flicker are the motion's.
    int64 flicker = 0;
    // --filter: what it kept of the motion's events, of the noise and of the flicker, and its own time.
    int64 filterSignalKept = 0, filterNoiseKept = 0, filterFlickerKept = 0;
    double filterSeconds = 0;
    // Every event's best estimate (no rejection) with its confidence, for the precision at a density; empty bins
    // for a method without a confidence.
    StereoEventScores ranking;
    // The left estimates' mean signed error by third of the columns (a rectification a little off).
    SampleSignedErrors signedErrors;
    // The left events' estimated and true disparities of the last window (0: none), for the pictures.
    Mat lastEstimate, lastTruth;

    /** One window's estimates against its ground truth (rows as the events). A method without disparities
    scores as one that estimates none. */
    void add(const std::vector<Event>& window, std::vector<std::array<float, 6>>& truth, MethodOutput& estimate, Size size)
    {
        std::vector<uchar> visibleMask(window.size(), 0), motionMask(window.size(), 0);
        std::vector<float> depth(window.size(), 0.f);
        lastEstimate = Mat::zeros(size, CV_32F);
        lastTruth = Mat::zeros(size, CV_32F);
        for (size_t i = 0; i < window.size(); i++)
        {
            const std::array<float, 6>& g = truth[i];
            const int flags = (int)g[GT_FLAGS];
            events++;
            if (estimate.hasDisparity)
                signedErrors.add(window[i], size.width, estimate.disparity[i], g[GT_DISPARITY], flags);
            const bool isNoise = (flags & GT_FLAG_NOISE) != 0;
            noiseTrue += isNoise;
            if (estimate.hasLifetime)
            {
                const bool flagged = estimate.lifetime[i] <= 0;  // no lifetime = classified as noise
                noiseFlagged += flagged;
                noiseCorrect += flagged && isNoise;
                if (!isNoise && !flagged)
                {
                    withLifetime++;
                    withLifetimeCamera[window[i].camera]++;
                    if (g[GT_LIFETIME] > 0)
                    {
                        const double r = std::abs(estimate.lifetime[i] - g[GT_LIFETIME]) / g[GT_LIFETIME];
                        lifetimeError.add(r);
                        lifetimeErrorHistogram[std::min<size_t>(lifetimeErrorHistogram.size() - 1, (size_t)(r / 0.025))]++;
                    }
                }
            }
            if (isNoise)
                continue;
            signal++;
            flicker += (flags & GT_FLAG_FLICKER) != 0;
            motionMask[i] = !(flags & GT_FLAG_FLICKER);
            const bool estimated = estimate.hasDisparity && estimate.disparity[i] >= 0;
            if (window[i].camera == CAMERA_LEFT && !estimated && !estimate.flags.empty())
            {
                leftAmbiguous += (estimate.flags[i] & STEREO_AMBIGUOUS) != 0;
                leftNoCounterpart += (estimate.flags[i] & STEREO_NO_COUNTERPART) != 0;
            }
            if (flags & GT_FLAG_OCCLUDED)
                continue;
            visibleMask[i] = 1;
            if (window[i].camera == CAMERA_LEFT)
                lastTruth.at<float>(window[i].y, window[i].x) = g[GT_DISPARITY];
            if (!estimated)
                continue;
            const float d = estimate.disparity[i];
            const double err = std::abs(d - g[GT_DISPARITY]);
            errorHistogram[std::min<size_t>(errorHistogram.size() - 1, (size_t)(err / 0.25))]++;
            // The depth the pair's own f B gives (true depth x true disparity), whatever f and B are.
            if (d > 0)
                depth[i] = g[GT_DEPTH] * g[GT_DISPARITY] / d;
            if (window[i].camera == CAMERA_LEFT)
                lastEstimate.at<float>(window[i].y, window[i].x) = d;
        }
        if (!window.empty())
        {
            // A method without disparities scores as one that estimates none (the counts of events stay).
            if (!estimate.hasDisparity)
                estimate.disparity.assign(window.size(), -1.f);
            const Mat truthRows((int)truth.size(), 6, CV_32F, truth.data());
            const Mat disparity((int)window.size(), 1, CV_32F, estimate.disparity.data());
            scoreStereoEvents(window, disparity, truthRows, scores, depth);
            scoreStereoEvents(window, disparity, truthRows, visible, noArray(), visibleMask);
            scoreStereoEvents(window, disparity, truthRows, motion, noArray(), motionMask);
            if (!estimate.bestDisparity.empty())
                scoreStereoEvents(window, Mat((int)window.size(), 1, CV_32F, estimate.bestDisparity.data()), truthRows,
                                  ranking, noArray(), noArray(),
                                  Mat((int)window.size(), 1, CV_32F, estimate.bestConfidence.data()));
        }
    }

    /** What a filter kept of one window (@p keepMask: non-zero for a kept event). */
    void addFiltered(const std::vector<std::array<float, 6>>& truth, const std::vector<uchar>& keepMask)
    {
        for (size_t i = 0; i < truth.size(); i++)
        {
            const int flags = (int)truth[i][GT_FLAGS];
            const bool isNoise = (flags & GT_FLAG_NOISE) != 0, isFlicker = (flags & GT_FLAG_FLICKER) != 0;
            filterSignalKept += keepMask[i] && !isNoise && !isFlicker;
            filterNoiseKept += keepMask[i] && isNoise;
            filterFlickerKept += keepMask[i] && isFlicker;
        }
    }
};

}  // namespace sample_evaluation

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_EVALUATION_HPP
