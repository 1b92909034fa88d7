// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// estimateClockOffset(): the right camera's clock against the left one's, from how matched disparities grow
// with the speed of the edge along the row on one surface.

#include "precomp.hpp"
#include "common/sensor_bounds.hpp"

#include <limits>
#include <map>

namespace cv {
namespace event {
namespace {

const int kBlock = 8;              // px: a surface's disparity is taken as one within a block ...
const int64 kSlotUs = 10000000;    // ... over ten seconds
const int64 kCellUs = 50000;       // speeds are taken as one within a block over this time
const float kSurfaceGap = 1.0f;    // px: disparities further apart than this in a block are other surfaces
const size_t kMinSurfaceEvents = 4;
const float kMinConfidence = 0.3f;
const double kMaxRowSpeed = 3000;  // px/s: faster along the row is an edge nearly along the row
const int kMaxMatcherRuns = 5;
const double kMaxOffsetUs = 20000;         // the offsets tried: software-synchronised clocks are closer
const double kConfidenceTolerance = 0.002; // mean confidence an offset may cost before it counts as worse
const double kMaxConfidenceLoss = 0.05;    // share of the mean confidence no clock offset costs
const double kMinGain = 0.1;               // below, the slope hardly follows the offset: nothing to go by
const double kClearGain = 0.5;             // from here on the slope follows the offset as a clock would
const double kMinGainSignificance = 3;     // standard errors of the gain
const double kGainProbeUs = 2000;          // the least span of offsets the gain is measured over

double clampOffset(double offsetUs)
{
    return std::max(-kMaxOffsetUs, std::min(kMaxOffsetUs, offsetUs));
}

// One matched event: its block and ten seconds (its group), its disparity, its edge's speed along the row u and the
// row-offset regressor w (how far a row shift moves the edge along the row).
struct Sample
{
    int64 group, cell;  // cell: the group's 50 ms in which the event fired
    float d, u, w;
    float side;         // +1 for the left camera's events, -1 for the right one's
};

// A plane fit's flow on a dotted edge is noisy, and noise in the regressor flattens the slope: each event takes
// the median speed of its camera's events in its block and 50 ms instead.
void smoothSpeeds(std::vector<Sample>& samples)
{
    std::sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.cell < b.cell; });
    std::vector<float> u, w;
    size_t out = 0;
    for (size_t begin = 0; begin < samples.size();)
    {
        size_t end = begin;
        u.clear();
        w.clear();
        for (; end < samples.size() && samples[end].cell == samples[begin].cell; end++)
        {
            u.push_back(samples[end].u);
            w.push_back(samples[end].w);
        }
        if (u.size() >= 3)
        {
            std::nth_element(u.begin(), u.begin() + u.size() / 2, u.end());
            std::nth_element(w.begin(), w.begin() + w.size() / 2, w.end());
            for (size_t i = begin; i < end; i++)
            {
                samples[out] = samples[i];
                samples[out].u = u[u.size() / 2];
                samples[out].w = w[w.size() / 2];
                out++;
            }
        }
        begin = end;
    }
    samples.resize(out);
}

struct SlopeFit
{
    bool ok = false;
    double slopeUs = 0;  // d(disparity) / d(u), as a time [us]
    double standardErrorUs = std::numeric_limits<double>::infinity();
    double offsetUs = 0;        // the right camera's restamping it was measured at
    double meanConfidence = 0;  // of the events with a disparity: how clear-cut the matches were
};

// Within-surface least squares of d on (u, w, |u|) per camera: every surface has its own intercept (its
// disparity), so only how d changes with them on one surface counts.
class SurfaceRegression
{
    // The regressors (see row()); a side one is the same regressor times +1 for the left camera's events and -1
    // for the right one's.
    enum { U, W, ABS_U, SIDE_U, SIDE_W, SIDE_ABS_U, kRegressors };
    typedef Vec<double, kRegressors> Coefficients;
    typedef Matx<double, kRegressors, kRegressors> Square;
    typedef Vec<double, kRegressors + 1> Row;  // the regressors, then d

public:
    explicit SurfaceRegression(std::vector<Sample> samples) : samples_(std::move(samples))
    {
        std::sort(samples_.begin(), samples_.end(), [](const Sample& a, const Sample& b) {
            return a.group != b.group ? a.group < b.group : a.d < b.d;
        });
    }

    SlopeFit fit()
    {
        SlopeFit result;
        std::vector<char> kept(samples_.size(), 1);
        Coefficients beta;
        for (int pass = 0; pass < 3; pass++)
        {
            if (!solve(kept, beta))
                return result;
            if (pass == 2)
                break;
            // Trim what no surface explains (a wrong match, a surface cut wrongly): beyond 3 robust sigmas of the
            // samples on a surface (the others, of infinite residual, go as well).
            std::vector<float> absResidual;
            for (size_t i = 0; i < samples_.size(); i++)
                if (kept[i] && std::isfinite(residuals_[i]))
                    absResidual.push_back(std::abs(residuals_[i]));
            if (absResidual.empty())
                return result;
            std::nth_element(absResidual.begin(), absResidual.begin() + absResidual.size() / 2, absResidual.end());
            const double limit = std::max(0.05, 3 * 1.4826 * absResidual[absResidual.size() / 2]);
            for (size_t i = 0; i < samples_.size(); i++)
                if (kept[i] && std::abs(residuals_[i]) > limit)
                    kept[i] = 0;
        }
        result.ok = true;
        result.slopeUs = beta[U] * 1e6;
        result.standardErrorUs = standardError_ * 1e6;
        return result;
    }

private:
    // Fits the kept samples; sets residuals_ and standardError_ (of the u slope, clustered by group, as
    // neighbouring events share their matches).
    bool solve(const std::vector<char>& kept, Coefficients& beta)
    {
        const size_t n = samples_.size();
        centred_.assign(n, Row::all(0));
        std::vector<char> used(n, 0);
        Square A = Square::zeros();
        Coefficients b = Coefficients::all(0);
        for (size_t begin = 0; begin < n;)
        {
            // One surface: the kept samples of a group whose disparities follow each other within the gap.
            size_t end = begin;
            std::vector<size_t> surface;
            float last = 0;
            while (end < n && samples_[end].group == samples_[begin].group &&
                   (surface.empty() || samples_[end].d - last <= kSurfaceGap || !kept[end]))
            {
                if (kept[end])
                {
                    surface.push_back(end);
                    last = samples_[end].d;
                }
                end++;
            }
            if (surface.size() >= kMinSurfaceEvents)
            {
                Row mean = Row::all(0);
                for (size_t i : surface)
                    mean += row(samples_[i]);
                mean *= 1.0 / (double)surface.size();
                for (size_t i : surface)
                {
                    const Row c = row(samples_[i]) - mean;
                    centred_[i] = c;
                    used[i] = 1;
                    for (int j = 0; j < kRegressors; j++)
                    {
                        for (int k = j; k < kRegressors; k++)
                            A(j, k) += c[j] * c[k];
                        b[j] += c[j] * c[kRegressors];
                    }
                }
            }
            begin = end;
        }
        for (int j = 0; j < kRegressors; j++)
            for (int k = 0; k < j; k++)
                A(j, k) = A(k, j);
        // Vertical edges only: w does not vary and takes nothing up (a tiny ridge keeps the system solvable).
        for (int j : { W, SIDE_W })
            A(j, j) += 1e-9 + 1e-9 * A(j, j);
        // Edges that all move one way make |u| a copy of u, and one camera's events alone make side u one: the
        // slope is then not measurable.
        double diagonal = 1;
        for (int j = 0; j < kRegressors; j++)
            diagonal *= A(j, j);
        if (!(A(U, U) > 0) || !(determinant(A) > 1e-6 * diagonal))
            return false;
        const Square inv = A.inv(DECOMP_SVD);
        beta = inv * b;
        residuals_.assign(n, 0.f);
        std::map<int64, Coefficients> score;  // per group: sum of x e
        for (size_t i = 0; i < n; i++)
        {
            if (!used[i])
            {
                residuals_[i] = std::numeric_limits<float>::infinity();  // not on a surface: trimmed with the outliers
                continue;
            }
            const Coefficients x(centred_[i].val);  // the regressors of the row
            double e = centred_[i][kRegressors];
            for (int j = 0; j < kRegressors; j++)
                e -= beta[j] * x[j];
            residuals_[i] = (float)e;
            score[samples_[i].group] += x * e;
        }
        if (score.size() < 5)
            return false;
        Square meat = Square::zeros();
        for (const auto& kv : score)
            meat += kv.second * kv.second.t();
        const double groups = (double)score.size();
        const Square V = inv * meat * inv * (groups / (groups - 1));
        standardError_ = std::sqrt(std::max(0.0, V(U, U)));
        return true;
    }

    // (u, w, |u|, side u, side w, side |u|, d), side +1 for the left camera's events and -1 for the right one's:
    // each camera has its own slopes, and the u slope is their mean. A clock offset moves an edge by u tau, one
    // way for edges moving right and the other way for edges moving left, and the same way for both cameras'
    // events (either way the right camera sees the edge tau late). What the matching itself does with faster
    // edges is the same both ways (|u|: a walking figure's fast limbs come out a little nearer than its slow
    // body), and what it does with the other camera's events after the event (the look-ahead's: the
    // counterpart is found a little along the motion) is opposite for the two cameras (side u): on a figure that
    // moves one way it would read as a clock in either camera's events alone.
    static Row row(const Sample& s)
    {
        Row r;
        r[U] = s.u;
        r[W] = s.w;
        r[ABS_U] = std::abs(s.u);
        r[SIDE_U] = s.side * s.u;
        r[SIDE_W] = s.side * s.w;
        r[SIDE_ABS_U] = s.side * std::abs(s.u);
        r[kRegressors] = s.d;
        return r;
    }

    std::vector<Sample> samples_;
    std::vector<Row> centred_;  // row() less the surface's means
    std::vector<float> residuals_;
    double standardError_ = 0;
};

// Each camera's normal flows from its own events (LifetimeEstimator): the same at every restamping, so that the
// slope changes with the offset through the disparities alone. The matcher's flows would not be: a
// matched event takes its flow from the other camera's window, which the restamping moves, and that makes a
// slope of its own.
std::vector<Vec2f> ownFlows(const std::vector<Event>& events, Size size)
{
    Mat lifetimes, flow;
    Ptr<LifetimeEstimator> estimator = LifetimeEstimator::create(size);
    // Over every timestamp in the window and with the matcher's crossings (its lifetimes in slopeAt() too): the
    // rules below were set on these; with the earlier edges left out walking_near (clocks alike) reads +1.65 +-
    // 0.47 ms, applied.
    estimator->setSkipEarlierEdges(false);
    estimator->setRefitCrossingLifetimes(0);
    estimator->process(events, lifetimes, flow);
    std::vector<Vec2f> flows(events.size());
    for (size_t i = 0; i < events.size(); i++)
        flows[i] = flow.at<Vec2f>((int)i);
    return flows;
}

// Matches the pair with the right camera restamped by @p offsetUs and fits the slope of disparity on speed
// (@p flows: each camera's, in its events' order).
SlopeFit slopeAt(const std::vector<Event>& left, const std::vector<Event>& right, const std::vector<Vec2f> flows[2],
                 Size size, int minD, int maxD, double offsetUs)
{
    Mat merged;
    mergeStereoEvents(left, right, merged, offsetUs);
    Ptr<StereoEventMatcher> matcher = StereoEventMatcher::create(size, STEREO_COUPLED);
    matcher->setMinDisparity(minD);
    matcher->setMaxDisparity(maxD);
    // Each event's own disparity against its own speed: a neighbourhood's mean or median mixes the speeds of
    // its events.
    matcher->setAveragingRadius(0);
    matcher->setFillRadius(0);
    // Lifetimes over every timestamp in the window, as the flows (ownFlows()).
    for (int camera : { CAMERA_LEFT, CAMERA_RIGHT })
        matcher->getLifetimeEstimator(camera)->setSkipEarlierEdges(false);
    Mat disparity, flags, confidence;
    matcher->process(merged, disparity, noArray(), flags, noArray(), noArray(), confidence);
    const Mat_<Event> ev = getEventMat(merged);
    const int blocksX = (size.width + kBlock - 1) / kBlock, blocksY = (size.height + kBlock - 1) / kBlock;
    const int64 t0 = ev.rows > 0 ? ev(0).t : 0;
    std::vector<Sample> samples;
    double confidenceSum = 0, matched = 0;
    size_t taken[2] = { 0, 0 };  // each camera's events keep their order in the merged stream
    for (int i = 0; i < ev.rows; i++)
    {
        const Vec2f v = flows[ev(i).camera][taken[ev(i).camera]++];
        const int f = flags.at<int>(i);
        if (f & STEREO_HAS_DISPARITY)
        {
            confidenceSum += confidence.at<float>(i);
            matched++;
        }
        if (!(f & STEREO_HAS_DISPARITY) || (f & STEREO_BEYOND_VIEW) || confidence.at<float>(i) < kMinConfidence)
            continue;
        const double speed2 = (double)v[0] * v[0] + (double)v[1] * v[1];
        // An edge within 60 degrees of vertical: along the row it moves |f|^2 / f_x.
        if (!(speed2 > 0) || 4.0 * v[0] * v[0] < speed2)
            continue;
        const double u = speed2 / v[0];
        if (std::abs(u) > kMaxRowSpeed)
            continue;
        const Event& e = ev(i);
        // A row offset moves an edge along the row by f_y / f_x rows, in opposite directions for the two cameras.
        const double w = (e.camera == CAMERA_LEFT ? 1.0 : -1.0) * v[1] / v[0];
        const int64 slot = (e.t - t0) / kSlotUs;
        const int64 group = ((slot * 2 + e.camera) * blocksY + e.y / kBlock) * blocksX + e.x / kBlock;
        const int64 cell = group * (kSlotUs / kCellUs) + ((e.t - t0) % kSlotUs) / kCellUs;
        samples.push_back(Sample{ group, cell, disparity.at<float>(i), (float)u, (float)w,
                                  e.camera == CAMERA_LEFT ? 1.f : -1.f });
    }
    smoothSpeeds(samples);
    SlopeFit fit = SurfaceRegression(std::move(samples)).fit();
    fit.offsetUs = offsetUs;
    fit.meanConfidence = confidenceSum / std::max(1.0, matched);
    return fit;
}

}  // namespace

double estimateClockOffset(InputArray events, Size sensorSize, int minDisparity, int maxDisparity, double* uncertaintyUs)
{
    if (sensorSize.width <= 0 || sensorSize.height <= 0)
        CV_Error_(Error::StsBadArg, ("estimateClockOffset: sensor %d x %d", sensorSize.width, sensorSize.height));
    if (minDisparity < 0 || maxDisparity < minDisparity || maxDisparity >= sensorSize.width)
        CV_Error_(Error::StsBadArg, ("estimateClockOffset: disparities %d..%d; expected 0 <= min <= max < the sensor width %d",
                                     minDisparity, maxDisparity, sensorSize.width));
    Mat left, right;
    splitStereoEvents(events, left, right);
    // Events outside the sensor (a calibration rectifies some past the border) are ignored, as the other
    // estimates from a pair's events do: the matcher would refuse them.
    auto inside = [&](const Mat& events) {
        std::vector<Event> kept;
        for (const Event& e : toEventVector(events))
            if (detail::onSensor(e.x, e.y, sensorSize))
                kept.push_back(e);
        return kept;
    };
    const std::vector<Event> l = inside(left), r = inside(right);
    if (uncertaintyUs)
        *uncertaintyUs = std::numeric_limits<double>::infinity();
    if (l.empty() || r.empty())
        return 0;
    // The slope g(offset) is the residual offset, damped by how noisy the measured speeds are (a regression
    // on a noisy regressor is flattened): secant steps find its root.
    const std::vector<Vec2f> flows[2] = { ownFlows(l, sensorSize), ownFlows(r, sensorSize) };
    const auto slope = [&](double offsetUs) { return slopeAt(l, r, flows, sensorSize, minDisparity, maxDisparity, offsetUs); };
    std::vector<SlopeFit> fits(1, slope(0));
    if (!fits[0].ok)
        return 0;
    // The first step assumes the damping typical of smoothed plane-fit flows; the secant then measures it.
    double gain = 0.25;
    double offset = clampOffset(-fits[0].slopeUs / gain);
    for (int run = 1; run < kMaxMatcherRuns; run++)
    {
        const SlopeFit fit = slope(offset);
        if (!fit.ok)
            break;
        fits.push_back(fit);
        if (std::abs(fit.slopeUs) < std::max(20.0, 0.1 * fit.standardErrorUs))
            break;
        const SlopeFit& before = fits[fits.size() - 2];
        if (std::abs(fit.offsetUs - before.offsetUs) >= 1)
        {
            const double measuredGain = (fit.slopeUs - before.slopeUs) / (fit.offsetUs - before.offsetUs);
            if (measuredGain > 0.05 && measuredGain < 2)
                gain = measuredGain;
        }
        offset = clampOffset(fit.offsetUs - fit.slopeUs / gain);
        if (offset == fit.offsetUs)
            break;
    }
    const SlopeFit* best = &fits[0];
    for (const SlopeFit& f : fits)
        if (std::abs(f.slopeUs) <= std::abs(best->slopeUs))
            best = &f;
    // The gain is measured over the offsets tried; where they lie close together (the first slope was already
    // near zero) one more run a little way off gives it a span.
    double lowest = best->offsetUs, highest = best->offsetUs;
    for (const SlopeFit& f : fits)
    {
        lowest = std::min(lowest, f.offsetUs);
        highest = std::max(highest, f.offsetUs);
    }
    if (highest - lowest < kGainProbeUs)
    {
        const double probe = best->offsetUs + kGainProbeUs <= kMaxOffsetUs ? best->offsetUs + kGainProbeUs
                                                                            : best->offsetUs - kGainProbeUs;
        const ptrdiff_t bestIndex = best - fits.data();
        const SlopeFit fit = slope(probe);
        if (fit.ok)
        {
            fits.push_back(fit);
            lowest = std::min(lowest, probe);
            highest = std::max(highest, probe);
        }
        best = &fits[(size_t)bestIndex];
    }
    // How sure: the slope's standard error through the gain of g over every offset tried (a line through them
    // all, each slope weighted by its precision). Where a surface's disparity follows its speed for another
    // reason (parts of a figure at slightly different depths swinging in turn, surfaces a block cannot tell
    // apart) or its speeds hardly vary (one object at one speed: what varies is the speed estimates' noise), g
    // hardly follows the offset, or not measurably beyond the slopes' own errors: a low gain, or one within
    // kMinGainSignificance standard errors of none, says so. Where it follows only weakly, an offset that makes
    // the matches less clear-cut than none is no correction; where it follows as a clock would, the events
    // have spoken (a more sensitive camera's earlier events match a little less clear-cut once aligned, and
    // better), unless they are more than kMaxConfidenceLoss less clear-cut than at any offset tried: then the
    // slope vanished by chance far from the clock (objects that each move at one speed: it passes through
    // zero again 17-18 ms past the clock, where the matches are clearly worse than further on).
    const auto weight = [](const SlopeFit& f) { return 1.0 / std::max(1.0, f.standardErrorUs * f.standardErrorUs); };
    double sumW = 0, sumO = 0, sumG = 0;
    for (const SlopeFit& f : fits)
    {
        const double w = weight(f);
        sumW += w;
        sumO += w * f.offsetUs;
        sumG += w * f.slopeUs;
    }
    double spread = 0, covariance = 0;
    for (const SlopeFit& f : fits)
    {
        const double w = weight(f);
        spread += w * (f.offsetUs - sumO / sumW) * (f.offsetUs - sumO / sumW);
        covariance += w * (f.offsetUs - sumO / sumW) * (f.slopeUs - sumG / sumW);
    }
    if (!(spread > 0))
        return 0;
    const double overallGain = covariance / spread, gainError = std::sqrt(1.0 / spread);
    double clearest = 0;
    for (const SlopeFit& f : fits)
        clearest = std::max(clearest, f.meanConfidence);
    if (!(overallGain >= kMinGain) || overallGain < kMinGainSignificance * gainError ||
        std::abs(best->offsetUs) >= kMaxOffsetUs ||
        (overallGain < kClearGain && best->meanConfidence < fits[0].meanConfidence - kConfidenceTolerance) ||
        best->meanConfidence < clearest * (1 - kMaxConfidenceLoss))
        return 0;
    // Near the root the slopes of offsets a few hundred us apart differ by about their standard error (a few
    // matches flip), so the fit of least |slope| is only as good as one fit; the line through every slope
    // measured, whose far ends are large against that noise, crosses zero closer to the clock.
    const double lineRoot = sumO / sumW - (sumG / sumW) / overallGain;
    if (uncertaintyUs)
        *uncertaintyUs = best->standardErrorUs / std::min(overallGain, 1.0);
    return lowest <= lineRoot && lineRoot <= highest ? lineRoot : best->offsetUs;
}

}  // namespace event
}  // namespace cv
