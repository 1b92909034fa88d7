// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_LIFETIME_ESTIMATOR_HPP
#define OPENCV_EVENT_LIFETIME_ESTIMATOR_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_lifetime
//! @{

/** @brief How an event's lifetime was obtained (LifetimeEstimator status output). */
enum LifetimeStatus
{
    LIFETIME_NOISE = 0,      //!< no local plane: the event is classified as noise, lifetime 0
    LIFETIME_FITTED = 1,     //!< RANSAC plane fit + regularised least-squares refit
    LIFETIME_PREDICTED = 2,  //!< a plane reused without a fit: the one predicted for the pixel (the event arrived when
                             //!< it said), or its crossing's when the event continues a crossing and fits none
    LIFETIME_MATCHED = 3     //!< given by a stereo match (StereoEventMatcher, coupled mode)
};

/** @brief Per-event lifetime and normal flow by local plane fitting on the Surface of Active Events
(Mueggler et al. @cite Mueggler2015, with the prediction shortcut of Hadviger et al. @cite Hadviger2019).

For each event, the past events of its polarity in an N x N window no older than dt are taken in local coordinates
(x, y relative to the event, t relative to the event in ms). The surface holds, per pixel, when an edge arrived: a
blurred or strong edge fires a pixel several times as it passes, and the later events of such a crossing (see
getCrossingLifetimes() and getRefitCrossingLifetimes()) keep the first one's time there and are fitted at it.
Where the pixel's previous crossing says an earlier edge had left the window before this one came, its timestamps
are left out (see getSkipEarlierEdges()). RANSAC hypotheses are planes t = a x + b y through the current event and
two random past events (degenerate pairs are skipped); inliers lie within the inlier distance of the edge position
the plane gives them (in pixels, so in time the threshold is that distance times the plane's time per pixel), and
within the inlier threshold [ms]; the best hypothesis is accepted with at least minInliers inliers, and refitted
by least squares on its inliers (t = a x + b y + c), regularised toward the plane predicted for this pixel when
there is one. No accepted plane within the iteration cap: noise.

From the plane, g = (a, b) ms/px is the time-surface gradient: lifetime = |g| (the time the edge needs to
move one pixel, sqrt(n1^2 + n2^2) / n3 for the plane normal n) and normal flow v = g / |g|^2 px/ms.
The estimator then predicts when the edge reaches the neighbour pixel it moves to (8-neighbourhood, by the
flow direction) and stores the plane there; an event arriving there within the prediction tolerance reuses
that plane without any fit (the shortcut), unless prediction is disabled.

Fitting in local coordinates makes the thresholds independent of how long the recording has run (the public
MATLAB reference fits in absolute microseconds; its threshold drifts with time).
Memory: per pixel and polarity, the crossing's first timestamp, its plane and a predicted plane: O(sensor pixels).
*/
class CV_EXPORTS_W LifetimeEstimator : public Algorithm
{
public:
    CV_WRAP static Ptr<LifetimeEstimator> create(Size sensorSize = Size(240, 180));

    /** @brief Estimates the lifetime of each event of a time-ordered packet.
    @param events the packet (any form getEventMat() accepts); all events go into one surface per polarity
    (use one estimator per camera).
    @param lifetimes output N x 1 CV_32F, microseconds; 0 for noise.
    @param flow output N x 2 CV_32F normal optical flow (vx, vy) [px/s]; 0 for noise.
    @param status output N x 1 CV_8U LifetimeStatus.
    @param quality output N x 1 CV_32F, how far each lifetime can be trusted, 0..1: 1 / (1 + e + 1 / (n - 2))
    for a plane refitted on n inliers (the event included) whose least squares put the lifetime's relative
    standard error at e (from the residuals). A predicted event takes the quality of the plane that predicted
    it. 0: noise, a plane passed on by a stereo match, or one with no residual to judge it by (three inliers,
    or all on one line). Higher is better; it ranks the lifetimes, it is not a probability. */
    CV_WRAP virtual void process(InputArray events, OutputArray lifetimes, OutputArray flow = noArray(),
                                 OutputArray status = noArray(), OutputArray quality = noArray()) = 0;

    /** @brief The same for one event (the incremental API; identical results to process()).
    @return the lifetime [us], 0 for noise. */
    virtual float processEvent(const Event& event, Vec2f& flow, int& status) = 0;

    /** @brief The same, with the lifetime's quality (as process() gives it). */
    virtual float processEvent(const Event& event, Vec2f& flow, int& status, float& quality) = 0;

    /** @brief Records an event whose lifetime was obtained elsewhere (a stereo match; counted as
    LIFETIME_MATCHED): it enters the surface and the active-event image, and a non-zero @p flow [px/s]
    predicts the neighbour's plane as a fitted one would. Nothing is fitted. */
    virtual void insertEvent(const Event& event, float lifetime, const Vec2f& flow) = 0;

    /** @brief Image of the events alive at time @p t: an event lives from its timestamp to timestamp +
    lifetime; one per pixel (the latest). CV_8U, 255 = alive ON, 128 = alive OFF, 0 = nothing.
    @param t the instant [us].
    @param image output.
    @param minQuality only the events whose lifetime has at least this quality (0..1, as process() gives it;
    0: all) are drawn; a pixel whose latest event has less is drawn as nothing. Lifetimes passed on by
    insertEvent() have quality 0. */
    CV_WRAP virtual void renderActiveEvents(double t, OutputArray image, double minQuality = 0) const = 0;

    /** @brief Forgets every event and prediction. */
    CV_WRAP virtual void reset() = 0;

    /** @brief Counts since the last reset, per LifetimeStatus (0..3). */
    CV_WRAP virtual double getStatusCount(int status) const = 0;

    CV_WRAP virtual Size getSensorSize() const = 0;
    CV_WRAP virtual void setSensorSize(Size size) = 0;
    /** @brief Neighbourhood size N (odd, >= 3; default 5). */
    CV_WRAP virtual int getWindowSize() const = 0;
    CV_WRAP virtual void setWindowSize(int n) = 0;
    /** @brief Oldest past event used [us] (default 100000, the paper's 100 ms). */
    CV_WRAP virtual double getTimeWindow() const = 0;
    CV_WRAP virtual void setTimeWindow(double us) = 0;
    /** @brief RANSAC inlier threshold: distance to the plane in time [ms] (default 2). It caps the
    threshold that inlierDistance gives a hypothesis. */
    CV_WRAP virtual double getInlierThreshold() const = 0;
    CV_WRAP virtual void setInlierThreshold(double ms) = 0;
    /** @brief RANSAC inlier distance in pixels (default 0.5): a past event is an inlier of a hypothesis
    when it lies within this distance of the edge position that hypothesis gives it, that is within
    inlierDistance x |g| ms of the plane in time, |g| being the hypothesis' time per pixel, and at most
    inlierThreshold. Fast edges then get a threshold to their scale. 0: the fixed inlierThreshold alone. */
    CV_WRAP virtual double getInlierDistance() const = 0;
    CV_WRAP virtual void setInlierDistance(double px) = 0;
    /** @brief Inliers (the current event included) needed to accept a plane (default 5). */
    CV_WRAP virtual int getMinInliers() const = 0;
    CV_WRAP virtual void setMinInliers(int n) = 0;
    /** @brief RANSAC iteration cap (default 19, the MATLAB reference's count for 40 % outliers at 99 %). */
    CV_WRAP virtual int getMaxIterations() const = 0;
    CV_WRAP virtual void setMaxIterations(int n) = 0;
    /** @brief Weight of the pull of the refit toward the predicted plane [ms^2 per (ms/px)^2] (default 1). */
    CV_WRAP virtual double getRegularization() const = 0;
    CV_WRAP virtual void setRegularization(double lambda) = 0;
    /** @brief An event within this of its predicted time reuses the predicted plane [us] (default 1000). */
    CV_WRAP virtual double getPredictionTolerance() const = 0;
    CV_WRAP virtual void setPredictionTolerance(double us) = 0;
    /** @brief Enables the prediction shortcut (default true). */
    CV_WRAP virtual bool getUsePrediction() const = 0;
    CV_WRAP virtual void setUsePrediction(bool use) = 0;
    /** @brief How long an edge's crossing of a pixel lasts, in lifetimes of the pixel's last event (default 2).
    An event of the polarity of its pixel's last event, which had a lifetime, continues that pixel's crossing
    while the crossing began less than this many of that lifetime before: the surface keeps the crossing's first
    time (when the edge arrived), the event's plane is fitted with its origin there (over the past events up
    to the event itself), and an event that fits no plane takes the crossing's (LIFETIME_PREDICTED). 0: every
    event starts a crossing and the surface holds each pixel's last time, as in Mueggler et al. */
    CV_WRAP virtual double getCrossingLifetimes() const = 0;
    CV_WRAP virtual void setCrossingLifetimes(double lifetimes) = 0;
    /** @brief Leaves an earlier edge's timestamps out of the fit (default true). When the pixel's previous
    crossing of this polarity had a plane and began more than twice the window's half-diagonal, in that
    plane's lifetimes, before the event, that edge had left the window before this one entered it: the
    window's timestamps from before it left (its crossing's time plus the half-diagonal in lifetimes) are the
    earlier edge's and are not fitted. An edge that comes back at a steady rate and fires sparsely (a fan's
    blades) otherwise gets planes through both edges, lifetimes a whole number of periods too long. false:
    every timestamp within the time window is fitted, as in Mueggler et al. */
    CV_WRAP virtual bool getSkipEarlierEdges() const = 0;
    CV_WRAP virtual void setSkipEarlierEdges(bool skip) = 0;
    /** @brief How long a crossing may last, in lifetimes of a plane fitted at its first time, where
    getCrossingLifetimes() alone would start a new one (default 4; 0: off). When the pixel's last event had the
    event's polarity but no lifetime, or one too short for the time since the crossing began, and the crossing began
    within the time window (and within this many lifetimes of its first events' plane, where they had one), the
    event is first fitted with its origin at the crossing's first time; it continues the crossing with that plane
    when the crossing began less than this many of the plane's lifetimes before, else it starts a new crossing and
    is fitted at its own time. An edge whose contrast spans several thresholds, blurred over a pixel or more, fires
    each pixel a train of events over a few lifetimes, and the train's first events often get no plane, or one too
    flat, as its neighbours have not all fired yet; starting a crossing at a later event puts the edge late at that
    pixel, and the planes of the pixels ahead, fitted through it, come out too flat. A second fit on the events that
    still start a crossing. Off where getCrossingLifetimes() is 0. */
    CV_WRAP virtual double getRefitCrossingLifetimes() const = 0;
    CV_WRAP virtual void setRefitCrossingLifetimes(double lifetimes) = 0;
    /** @brief Seed of the RANSAC sampling (default 0): results are deterministic. An event's samples are drawn
    from the seed and the event itself (pixel, polarity, time), not from a sequence shared by all events, so
    they do not depend on how many fits ran before it. */
    CV_WRAP virtual int getSeed() const = 0;
    CV_WRAP virtual void setSeed(int seed) = 0;
};

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_LIFETIME_ESTIMATOR_HPP
