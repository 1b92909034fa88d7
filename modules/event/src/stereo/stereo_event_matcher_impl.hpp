// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_STEREO_EVENT_MATCHER_IMPL_HPP
#define OPENCV_EVENT_SRC_STEREO_STEREO_EVENT_MATCHER_IMPL_HPP

#include "opencv2/event.hpp"
#include "lifetime/row_band_lifetime_estimator.hpp"
#include "stereo/active_estimate_map.hpp"
#include "stereo/descriptor_cost.hpp"
#include "stereo/fill_surface_cache.hpp"
#include "stereo/row_band_scheduler.hpp"
#include "stereo/stereo_event_input.hpp"
#include "stereo/stereo_matcher_params.hpp"
#include "stereo/window_median.hpp"
#include "stereo/zou_descriptor_map.hpp"

#include <functional>
#include <limits>
#include <vector>

namespace cv {
namespace event {
namespace detail {

/** The outcome of matching one event along its row (StereoEventMatcherImpl::match): the best candidate,
whatever its confidence; the caller decides whether to keep it. */
struct MatchResult
{
    float disparity = -1.f;  // -1: no candidate
    int counterpartX = -1;   // the matched pixel of the other sensor (integer disparity); -1: not matched
    float confidence = 0.f;  // StereoEventEstimate::confidence
    int flags = 0;           // STEREO_NO_COUNTERPART when there was no candidate; STEREO_BEYOND_VIEW when the
                             // neighbours' estimates decided (estimateBeyondView)
};

/** The working memory of matching one event (one per thread): the candidates as disparity index (disparity -
min) in increasing order, the byte offset of each one's descriptor in the other sensor from the event's
column, and their costs (the first `count` of each, sized for the whole disparity range); the matched
window's active events (matchedLifetime); the left-right check's disparities; the lifetime
estimators' scratch, per camera.
Near the other image's border (scoreSeenColumns): the candidates' scores, the event's own mass per column of
the window and the mass of its first k unseen columns. Aligned to cache lines: each row band's thread writes
its own. */
struct alignas(64) MatchScratch
{
    int count = 0;
    std::vector<int> candidates;
    std::vector<ptrdiff_t> offsets;
    std::vector<unsigned> cost;
    int64 lifetimeTicks = 0;  // time in the lifetime estimation (setTimeLifetimes), cv::getTickCount() units
    std::vector<unsigned> seenScore;
    std::vector<float> recencyShare;   // per candidate (match())
    std::vector<uint64> columnTimeGap;  // per column of the other sensor (recencyShares())
    std::vector<unsigned> columnMass;
    std::vector<unsigned> unseenMass;
    std::vector<int> matchedValues, matchedPositions;  // the window's active lifetimes (their bits) and indices
    std::vector<uint64> matchedKeys;                    // a large window's selection (WindowMedianKernels)
    std::vector<float> disparities;
    LifetimeScratch lifetimes[2];
    std::vector<std::pair<int, StereoEventEstimate>> decided;  // a row band's estimates, stored after the run
};

/** StereoEventMatcher's implementation. Its members live in one file per concern, named in the sections
below; the neighbours' estimates are ActiveEstimateMap's, and the order of operations across row bands is
RowBandScheduler's. */
class StereoEventMatcherImpl CV_FINAL : public StereoEventMatcher
{
public:
    StereoEventMatcherImpl(Size size, int mode);

    // Smaller packets run on the calling thread: starting the others would cost more than they gain.
    enum { MIN_EVENTS_FOR_BANDS = 1000 };

    void process(InputArray events, OutputArray disparity, OutputArray lifetime, OutputArray flags, OutputArray depth,
                 OutputArray flow, OutputArray confidence) CV_OVERRIDE;

    void processEvent(const Event& e, StereoEventEstimate& est) CV_OVERRIDE;
    void renderDisparity(double t, OutputArray image, int camera, bool colourBar) const CV_OVERRIDE;
    void getActiveDisparity(double t, OutputArray disparity, int camera) const CV_OVERRIDE;
    Vec2i getDisparityDisplayRange(double t, int camera) const CV_OVERRIDE;

    void reset() CV_OVERRIDE;
    void setCalibration(const StereoCalibration& calibration) CV_OVERRIDE;

    const StereoCalibration& getCalibration() const CV_OVERRIDE { return input_.calibration(); }
    void loadCalibration(const String& path) CV_OVERRIDE { setCalibration(readStereoCalibration(path)); }

    Ptr<LifetimeEstimator> getLifetimeEstimator(int camera) const CV_OVERRIDE;

    // Parameters: StereoMatcherParams validates them; a change that alters the maps' layout or the windows
    // resets the matcher (matcher_parameters.cpp).
    int getMode() const CV_OVERRIDE { return params_.mode; }
    void setMode(int mode) CV_OVERRIDE;
    Size getSensorSize() const CV_OVERRIDE { return params_.sensorSize; }
    void setSensorSize(Size s) CV_OVERRIDE;
    int getMinDisparity() const CV_OVERRIDE { return params_.minDisparity; }
    void setMinDisparity(int d) CV_OVERRIDE { setDisparityRange(d, params_.maxDisparity); }
    int getMaxDisparity() const CV_OVERRIDE { return params_.maxDisparity; }
    void setMaxDisparity(int d) CV_OVERRIDE { setDisparityRange(params_.minDisparity, d); }
    int getDescriptorWindow() const CV_OVERRIDE { return params_.descriptorWindow; }
    void setDescriptorWindow(int n) CV_OVERRIDE { params_.setDescriptorWindow(n); reset(); }
    int getMaxVectorLength() const CV_OVERRIDE { return params_.maxVectorLength; }
    void setMaxVectorLength(int r) CV_OVERRIDE { params_.setMaxVectorLength(r); reset(); }
    int getCostWindow() const CV_OVERRIDE { return params_.costWindow; }
    void setCostWindow(int w) CV_OVERRIDE { params_.setCostWindow(w); reset(); }
    int getLifetimeWindow() const CV_OVERRIDE { return params_.lifetimeWindow; }
    void setLifetimeWindow(int w) CV_OVERRIDE { params_.setLifetimeWindow(w); reset(); }
    int getAggregationWindow() const CV_OVERRIDE { return params_.aggregationWindow; }
    void setAggregationWindow(int a) CV_OVERRIDE { params_.setAggregationWindow(a); reset(); }
    int getCostRowStep() const CV_OVERRIDE { return params_.costRowStep; }
    void setCostRowStep(int k) CV_OVERRIDE { params_.setCostRowStep(k); }
    int getUniquenessRatio() const CV_OVERRIDE { return params_.uniquenessRatio; }
    void setUniquenessRatio(int u) CV_OVERRIDE { params_.setUniquenessRatio(u); }
    double getMinConfidence() const CV_OVERRIDE { return params_.minConfidence; }
    void setMinConfidence(double c) CV_OVERRIDE { params_.setMinConfidence(c); }
    double getMatchedLifetimeConfidence() const CV_OVERRIDE { return params_.matchedLifetimeConfidence; }
    void setMatchedLifetimeConfidence(double c) CV_OVERRIDE { params_.setMatchedLifetimeConfidence(c); }
    double getLifetimeCopyConfidence() const CV_OVERRIDE { return params_.lifetimeCopyConfidence; }
    void setLifetimeCopyConfidence(double c) CV_OVERRIDE { params_.setLifetimeCopyConfidence(c); }
    int getMaxLifetimeCopies() const CV_OVERRIDE { return params_.maxLifetimeCopies; }
    void setMaxLifetimeCopies(int copies) CV_OVERRIDE { params_.setMaxLifetimeCopies(copies); }
    int getPriorTolerance() const CV_OVERRIDE { return params_.priorTolerance; }
    void setPriorTolerance(int percent) CV_OVERRIDE { params_.setPriorTolerance(percent); }
    int getRecencyWeight() const CV_OVERRIDE { return params_.recencyWeight; }
    void setRecencyWeight(int percent) CV_OVERRIDE { params_.setRecencyWeight(percent); }
    double getRecencyTime() const CV_OVERRIDE { return (double)params_.recencyTime; }
    void setRecencyTime(double us) CV_OVERRIDE { params_.setRecencyTime(us); }
    int getAveragingRadius() const CV_OVERRIDE { return params_.averagingRadius; }
    void setAveragingRadius(int px) CV_OVERRIDE { params_.setAveragingRadius(px); }
    int getFillRadius() const CV_OVERRIDE { return params_.fillRadius; }
    void setFillRadius(int px) CV_OVERRIDE { params_.setFillRadius(px); }
    double getFillReuseTime() const CV_OVERRIDE { return (double)params_.fillReuseTime; }
    void setFillReuseTime(double us) CV_OVERRIDE { params_.setFillReuseTime(us); }
    double getLookAhead() const CV_OVERRIDE { return (double)params_.lookAhead; }
    void setLookAhead(double us) CV_OVERRIDE { params_.setLookAhead(us); }
    double getFixedInterval() const CV_OVERRIDE { return (double)params_.fixedInterval; }
    void setFixedInterval(double us) CV_OVERRIDE { params_.setFixedInterval(us); }
    double getMaxLifetime() const CV_OVERRIDE { return (double)params_.maxLifetime; }
    void setMaxLifetime(double us) CV_OVERRIDE { params_.setMaxLifetime(us); }
    double getNoiseActiveTime() const CV_OVERRIDE { return (double)params_.noiseActiveTime; }
    void setNoiseActiveTime(double us) CV_OVERRIDE { params_.setNoiseActiveTime(us); }
    double getActiveDistance() const CV_OVERRIDE { return params_.activeDistance; }
    void setActiveDistance(double px) CV_OVERRIDE { params_.setActiveDistance(px); }
    int getNumThreads() const CV_OVERRIDE { return params_.numThreads; }
    void setNumThreads(int threads) CV_OVERRIDE { params_.setNumThreads(threads); }
    void setTimeLifetimes(bool on) CV_OVERRIDE { timeLifetimes_ = on; }
    bool getTimeLifetimes() const CV_OVERRIDE { return timeLifetimes_; }
    double getLifetimeSeconds() const CV_OVERRIDE;
    void write(FileStorage& fs) const CV_OVERRIDE;

    void read(const FileNode& fn) CV_OVERRIDE;
    String getDefaultName() const CV_OVERRIDE { return "StereoEventMatcher"; }

private:
    // What process() stores for event i.
    typedef std::function<void(int, const StereoEventEstimate&)> StoreFn;

    // ---- the public face (stereo_event_matcher.cpp)
    void sizeScratch(MatchScratch& s) const;

    // ---- the per-event decision (event_decision.cpp)
    // processEvent after admit() and the expiries due: the event at rectified pixel r, inside the image.
    // Reads and writes only rows within eventRowReach() of r.y, with its own scratch: see processOperations().
    // laterPending: a later event of the same pixel and polarity has arrived (look-ahead) and keeps the pixel
    // active in the map.
    void processAdmitted(const Event& e, Point r, int64 coldStartEnd, bool laterPending, MatchScratch& s,
                         StereoEventEstimate& est);

    // Checks the event (camera, sensor bounds, time order) and returns its rectified pixel, (-1, -1) when it
    // falls outside the rectified image.
    Point admit(const Event& e);

    // Makes the event of time t at rectified pixel r active in sensor c's map until its decision sets its
    // activity: it takes part in the descriptors of the events matched meanwhile, its own included.
    void activateUndecided(int c, Point r, int p, int64 t);

    // How long an event with this lifetime (us per pixel) stays active: until its edge has moved
    // the active distance in pixels, at most the max lifetime.
    int64 activeSpan(double lifetime) const;

    // ---- look-ahead and row bands (operation_schedule.cpp)
    // process() with look-ahead or on several threads (with the results of one: see RowBandScheduler): the
    // packet's admission, then its operations.
    void processOperations(const Mat_<Event>& ev, const StoreFn& store);

    // The packet's operations (into operations_: event index x 2 + 1 for a decision, + 0 for an arrival) with
    // their rows and times, for the first `valid` events of the admission.
    void scheduleOperations(int valid);

    // ---- parameters (matcher_parameters.cpp)
    void setDisparityRange(int lo, int hi);

    // How many rows above and below its own an event's processing reads or writes: the aggregation window's
    // descriptors (match), the matched window (its median lifetime), the left-right check's 3 x 3, the
    // temporal prior's neighbourhood, the vectors an activation or deactivation changes (2 x the max length
    // for the re-search) and their votes, the plane fit's window.
    int eventRowReach() const;

    // The same for an expiry (a deactivation).
    int expiryRowReach() const { return std::max(2 * params_.maxVectorLength, params_.maxVectorLength + params_.descriptorWindow / 2); }

    // How many rows above and below its own an event or an expiry writes: the votes of the vectors an
    // activation or deactivation changes (pixels within the max length, each voting into its descriptor
    // window) and the lifetime estimator's prediction for the neighbour the edge moves to (1 row). Everything
    // further out (the cost windows, the prior, the medians, the re-search) is only read.
    int rowWriteReach() const { return std::max(params_.maxVectorLength + params_.descriptorWindow / 2, 1); }

    // Row bands: two operations further apart in rows than this never touch data that one of them writes
    // (the largest write reach + the largest reach of any access; eventRowReach() includes the expiries').
    int bandConflictRows() const { return rowWriteReach() + eventRowReach(); }

    // ---- matching along the row (row_match.cpp)
    // Adds the SAD over the rectangle [x0, x1] x [y0, y1] (relative to the event; its rows sampled by
    // sampleRows()) to every candidate's cost; returns the same sum against an empty map (the event's side alone).
    unsigned addRect(const ZouDescriptorMap& self, const ZouDescriptorMap& other, Point r, int x0, int x1, int y0, int y1,
                     MatchScratch& s) const;

    // Clips the rectangle [x0, x1] x [y0, y1] relative to the event's pixel r to the image; false when nothing is
    // left. Cost windows cover only the event's own image: past its border both sensors' descriptors are zero for
    // a candidate that also runs past the other border (d near 0 at the right border of the left image), which
    // would match "nothing" against "nothing" for free and pull border events toward that candidate.
    bool clipToImage(Point r, int& x0, int& x1, int& y0, int& y1) const
    {
        x0 = std::max(x0, -r.x);
        x1 = std::min(x1, params_.sensorSize.width - 1 - r.x);
        y0 = std::max(y0, -r.y);
        y1 = std::min(y1, params_.sensorSize.height - 1 - r.y);
        return x0 <= x1 && y0 <= y1;
    }

    // Narrows the window rows [y0, y1] (offsets from the event's row) to those the cost windows read, the multiples
    // of params_.costRowStep, and returns how many they are (0: none).
    int sampleRows(int& y0, int& y1) const
    {
        const int k = params_.costRowStep;
        if (k == 1)
            return std::max(0, y1 - y0 + 1);
        y0 = y0 >= 0 ? (y0 + k - 1) / k * k : -(-y0 / k * k);
        y1 = y1 >= 0 ? y1 / k * k : -((-y1 + k - 1) / k * k);
        return y0 <= y1 ? (y1 - y0) / k + 1 : 0;
    }

    // Sum of the descriptor values over [x0, x1] x [y0, y1] relative to q, rows sampled as addRect() samples them:
    // the cost of matching against nothing.
    unsigned rectMass(const ZouDescriptorMap& map, Point q, int x0, int x1, int y0, int y1) const;

    // Matches the event at r (camera c, polarity p, time t) along its row: the best candidate and its confidence.
    MatchResult match(int c, Point r, int p, int64 t, MatchScratch& s) const;

    // How many columns of the cost window [x0, x1] (relative to the event's pixel r, clipped) disparity d maps
    // past the other image's border: the first ones for the left camera (sign -1), the last for the right.
    int unseenColumns(int sign, Point r, int x0, int x1, int d) const;

    // The candidates' scores at the window of half-width h: their costs, except for the candidates whose
    // window the other sensor sees only in part, scored on the seen columns and scaled to the whole window
    // (s.seenScore; s.cost itself when there are none). columnsAt is the half-width that s.columnMass holds
    // (-1: none yet); it grows with h, one step at a time.
    const unsigned* scoreSeenColumns(const ZouDescriptorMap& self, int sign, Point r, int h, int& columnsAt,
                                     MatchScratch& s) const;

    // The candidates' shares of the recency cost (s.recencyShare) for an event of time t matched against
    // `other` (see match()), reading its columns `columns` (recencyColumnRange).
    void recencyShares(const ZouDescriptorMap& other, const Range& columns, int sign, Point r, int p, int64 t,
                       MatchScratch& s) const;

    // The other sensor's columns within a pixel of the candidates (s.candidates), inside the image.
    Range recencyColumnRange(int sign, Point r, const MatchScratch& s) const;

    // ---- the neighbours' estimates (neighbour_estimates.cpp)
    // The temporal prior's decision for an event (polarity p) without a unique winner (best cost bestCost, the
    // candidates' scores in score): false when it has none; otherwise the chosen candidate in m.
    // Its neighbourhood: PRIOR_RADIUS rows above and below, and `columns` (priorColumnReach) to each side:
    // PRIOR_RADIUS, or PRIOR_ROW_REACH on a horizontal edge.
    enum { PRIOR_RADIUS = 5, PRIOR_ROW_REACH = 30, PRIOR_SUPPORT = 3 };
    static_assert((int)StereoMatcherParams::MAX_AVERAGING_RADIUS <= (int)PRIOR_RADIUS,
                  "the averaging must stay within the rows an event's processing reaches");
    bool decideByPrior(int c, Point r, int p, int64 t, int columns, const unsigned* score, unsigned bestCost, MatchScratch& s,
                       MatchResult& m) const;

    // How far along the row the temporal prior looks for the event at r of sensor c.
    int priorColumnReach(int c, Point r) const;

    // The estimate of an event of sensor c at r whose neighbours' estimates (PRIOR_RADIUS rows, PRIOR_ROW_REACH
    // columns) put its counterpart past the other image's border: false when they do not.
    bool estimateBeyondView(int c, Point r, int64 t, MatchScratch& s, MatchResult& m) const;

    // Left-right check against the other sensor's own estimates: the active events around the counterpart
    // were matched the other way (toward this sensor); when they have disparities, their median must agree
    // within one pixel. Without any there is nothing to contradict the match.
    bool consistent(int c, int x, int y, double d, int64 t, MatchScratch& s) const;

    // The output disparity of an event of sensor c at r with its own estimate `own`: the mean of `own` and the
    // estimates active at t within the averaging radius and AVERAGING_TOLERANCE of it, sensor c's around r
    // and, when it was matched (counterpartX >= 0), the other sensor's around its counterpart.
    float averagedDisparity(int c, Point r, int64 t, float own, int counterpartX) const;
    static constexpr float AVERAGING_TOLERANCE = 1.5f;

    // Filling (setFillRadius): the surface's disparity around an event of sensor c at r, the median of the
    // confident estimates (rememberConfident) active at t within the fill radius, in every FILL_ROW_STEP-th
    // row (or of those around an event shortly before it nearby: fillSurface), when there are FILL_SUPPORT of
    // them and FILL_AGREEING of them lie within a pixel of it, replaces the event's own estimate `own` (-1: none)
    // of confidence `confidence` when the latter is missing or less confident than FILL_BELOW_CONFIDENCE, lies
    // within FILL_REFINE_GAP of the surface's (a median of many is the finer estimate), or lies more than
    // FILL_OUTLIER_GAP from it where FILL_OUTLIER_AGREEING of the surface lie within a pixel of its median and a
    // narrow band of it (FILL_NARROW_COLUMNS either side, all the rows: a pole, a limb in front of the body) does
    // not support `own`. False: the event keeps `own`.
    bool filledDisparity(int c, Point r, int64 t, MatchScratch& s, float own, float confidence, float& disparity);
    // The surface around the event at r of sensor c at time t: one found for an event shortly before it nearby
    // (params_.fillReuseTime, fillSurfaces_), or the window's own (kept for the events after it).
    FillSurfaceCache::Surface fillSurface(int c, Point r, int64 t, MatchScratch& s);
    static_assert((int)FillSurfaceCache::ROWS <= (int)PRIOR_RADIUS,
                  "a reused surface must lie within the rows an event's processing reaches");
    // Keeps an event's own estimate for filling when it is at least FILL_SUPPORT_CONFIDENCE confident.
    void rememberConfident(int c, Point r, int64 t, float disparity, float confidence);
    static constexpr float FILL_BELOW_CONFIDENCE = 0.15f, FILL_SUPPORT_CONFIDENCE = 0.3f, FILL_AGREEING = 0.5f;
    static constexpr float FILL_REFINE_GAP = 0.5f, FILL_OUTLIER_GAP = 1.0f, FILL_OUTLIER_AGREEING = 0.8f;
    static constexpr int64 FILL_TIME = 60000;  // us: how long a confident estimate supports filling
    enum { FILL_SUPPORT = 5, FILL_ROW_STEP = 2, FILL_NARROW_COLUMNS = 3, FILL_NARROW_SUPPORT = 5 };

    // ---- the matched lifetime (matched_lifetime.cpp)
    // Median lifetime (and the flow of that event) of the active events of polarity p in the lifetime window
    // around (x, y) of sensor c. False when none has a lifetime.
    // `copies`: how many times that lifetime was copied between the sensors since a plane fit gave it.
    bool matchedLifetime(int c, int x, int y, int p, MatchScratch& s, float& lifetime, Vec2f& flow, int& copies) const;

    // COUPLED: matchedLifetime of one event's counterpart, taken on the first get() and kept; `copies` is valid
    // after a get() that found one.
    class MatchedWindow CV_FINAL : public MatchedLifetimeSource
    {
    public:
        MatchedWindow(const StereoEventMatcherImpl& matcher, int c, int x, int y, int p, MatchScratch& s)
            : matcher_(matcher), c_(c), x_(x), y_(y), p_(p), s_(s)
        {
        }
        bool get(std::pair<float, Vec2f>& matched) CV_OVERRIDE
        {
            if (state_ == UNKNOWN)
                state_ = matcher_.matchedLifetime(c_, x_, y_, p_, s_, matched_.first, matched_.second, copies) ? FOUND
                                                                                                             : NONE;
            matched = matched_;
            return state_ == FOUND;
        }
        int copies = 0;
    private:
        enum { UNKNOWN, FOUND, NONE };
        const StereoEventMatcherImpl& matcher_;
        const int c_, x_, y_, p_;
        MatchScratch& s_;
        int state_ = UNKNOWN;
        std::pair<float, Vec2f> matched_;
    };

    // COUPLED: starts loading what matchedLifetime(c, x, y, p) will read, so that the left-right check overlaps
    // its cache misses (the other sensor's lifetimes are seldom cached).
    void prefetchMatchedWindow(int c, int x, int y, int p) const;

    // The lifetimeWindow around (x, y), clipped to the image: the window matchedLifetime reads.
    Rect lifetimeWindowAround(int x, int y) const;

    StereoMatcherParams params_;
    StereoEventInput input_{ "StereoEventMatcher" };  // the checks, the rectification, the depth
    Ptr<RowBandLifetimeEstimator> estimators_[2];
    ZouDescriptorMap maps_[2];
    ActiveEstimateMap estimates_[2];  // each event's own estimate, as its neighbours read it
    ActiveEstimateMap confidentEstimates_[2];  // the confident ones among them, for filling
    FillSurfaceCache fillSurfaces_[2];  // the surfaces filling found, for the events after them (fillReuseTime)
    int64 coldStartEnd_ = 0;  // the end of the cold start: see admit()
    // The cost kernel for this CPU (candidates' costs and window masses), fetched once.
    DescriptorRectSadBatchFn rectSadBatch_ = descriptorRectSadBatchFunction();
    // The matched window's gather and median for this CPU, fetched once.
    const WindowMedianKernels& windowMedian_ = windowMedianKernelsForThisCpu();
    MatchScratch scratch_;  // processEvent's
    bool timeLifetimes_ = false;
    // processOperations: the scheduler, each band's scratch, each event's admission, the operations.
    struct Admission
    {
        Point rectified;
        int64 coldStartEnd;
    };
    RowBandScheduler bands_;
    std::vector<MatchScratch> bandScratch_;
    std::vector<Admission> admitted_;
    std::vector<int> admittedRows_;
    std::vector<int64> times_;
    std::vector<int> operations_, operationRows_;
    std::vector<int64> operationTimes_;
    // Per sensor, pixel and polarity: arrived events not decided yet (look-ahead).
    std::vector<int> pendingEvents_[2];
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_STEREO_EVENT_MATCHER_IMPL_HPP
