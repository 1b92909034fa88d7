// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_STEREO_EVENT_MATCHER_HPP
#define OPENCV_EVENT_STEREO_EVENT_MATCHER_HPP

#include "opencv2/event/lifetime_estimator.hpp"
#include "opencv2/event/stereo_calibration.hpp"

namespace cv {
namespace event {

//! @addtogroup event_stereo
//! @{

/** @brief How StereoEventMatcher couples lifetime estimation and matching. */
enum StereoMatchMode
{
    STEREO_COUPLED = 0,         //!< the paper's method: a matched event takes its lifetime from the other sensor
    STEREO_DECOUPLED = 1,       //!< plane-fit lifetime for every event of each sensor, then matching
    STEREO_FIXED_INTERVAL = 2   //!< no lifetimes: every event stays active for a fixed interval (10 ms)
};

/** @brief Bits of the per-event flags StereoEventMatcher outputs. */
enum StereoEventFlags
{
    STEREO_HAS_DISPARITY = 1,       //!< a disparity (and, with a calibration, a depth) was estimated
    STEREO_HAS_LIFETIME = 2,        //!< a lifetime was estimated
    STEREO_LIFETIME_MATCHED = 4,    //!< ... as the median lifetime of the matched window of the other sensor
    STEREO_LIFETIME_PREDICTED = 8,  //!< ... by reusing the plane predicted for this pixel (no fit)
    STEREO_NOISE = 16,              //!< no local plane and no match: classified as noise
    STEREO_AMBIGUOUS = 32,          //!< candidates existed, but the best one's confidence is below getMinConfidence()
    STEREO_NO_COUNTERPART = 64,     //!< the other sensor had no active structure along the row (yet)
    STEREO_OUTSIDE = 128,           //!< the rectified position lies outside the image: not processed
    /** the estimates around the event put its counterpart past the other sensor's border, where the other
    camera does not see it (e.g. a near object in the left image's first columns): the disparity is their
    median, not a match (doc/stereo.md, "The method") */
    STEREO_BEYOND_VIEW = 256,
    /** the disparity is the median of the confident estimates around the event, not its own estimate
    (StereoEventMatcher::setFillRadius(); doc/stereo.md, "The method") */
    STEREO_FILLED = 512
};

/** @brief Everything StereoEventMatcher estimates for one event. */
struct CV_EXPORTS StereoEventEstimate
{
    float disparity = -1.f;  //!< x_left - x_right [px], sub-pixel; StereoEventMatcher::NO_DISPARITY when none
    float depth = 0.f;       //!< f B / disparity [m] with a calibration; 0 when unknown
    float lifetime = 0.f;    //!< [us]; 0 when none
    Vec2f flow;              //!< normal optical flow [px/s] of the plane (or of the matched event); 0 when none
    /** How clearly the best candidate won, 0..1: 1 - its cost / the cost of the best alternative (a candidate
    more than 1 px away, or no counterpart at all); 0 without candidates or when the left-right check
    contradicts it. Set also when the estimate is rejected (confidence below StereoEventMatcher::getMinConfidence()),
    so that a caller can rank all events. */
    float confidence = 0.f;
    int flags = 0;           //!< StereoEventFlags
    Point rectified = Point(-1, -1);  //!< the event's rectified pixel; (-1, -1) when outside
};

/** @brief Per-event stereo disparity and lifetime for a stereo pair of event cameras (Hadviger et al.
@cite Hadviger2019), with the descriptor of Zou et al. @cite Zou2017.

Events of both sensors come in one time-ordered stream (Event::camera tells them apart, see
mergeStereoEvents / EventCapture::openStereo). Each is rectified through a per-pixel table built from the
calibration (none: the input is taken as rectified) and matched along its row against what the other sensor
shows getLookAhead() later, so either sensor's events may come first. Per pixel and polarity each sensor keeps
the vector to the nearest *active* event; a pixel's descriptor is the histogram of those vectors over its
N x N window in 12 orientation bins per polarity; a candidate disparity costs the SAD of the descriptors over a
W x W window, grown ring by ring up to A x A until the cheapest candidate beats every other one and "no
counterpart yet" by the uniqueness ratio. Every event keeps its best estimate with a confidence
(StereoEventEstimate::confidence) that ranks the estimates; getMinConfidence() rejects the less confident ones.

The modes (StereoMatchMode) differ in where lifetimes come from, and so in how long events stay active: in
COUPLED, the paper's method, a confidently matched event takes the median lifetime of the other sensor's active
events around its counterpart instead of fitting its own plane. What this implementation adds to the method as
published (the recency cost, the temporal prior, the averaging, the estimates past the other camera's view, the
look-ahead, the cold start, events the plane fit calls noise kept active, a lifetime copied once) is described
in the manual (doc/stereo.md, "The method"), with the parameter that turns each off. The frame baseline, edge
frames and cv::StereoSGBM, is FrameStereoMatcher.

Memory is O(sensor pixels): the per-pixel maps, an expiry heap over pixels (with setNumThreads(), up to three
per row band) and the two LifetimeEstimators. write() stores every parameter, the lifetime estimators' and the
calibration; read() sets those a node holds and keeps the others, and a value out of range raises
cv::Exception and changes none of them.
*/
class CV_EXPORTS_W StereoEventMatcher : public Algorithm
{
public:
    enum { NO_DISPARITY = -1 };

    /** @brief A matcher for two sensors of @p sensorSize in mode @p mode (StereoMatchMode). */
    CV_WRAP static Ptr<StereoEventMatcher> create(Size sensorSize = Size(240, 180), int mode = STEREO_COUPLED);

    /** @brief Processes a time-ordered packet of stereo events.
    @param events the packet (any form getEventMat() accepts), both cameras.
    @param disparity output N x 1 CV_32F [px]; NO_DISPARITY where none.
    @param lifetime output N x 1 CV_32F [us]; 0 where none.
    @param flags output N x 1 CV_32S StereoEventFlags.
    @param depth output N x 1 CV_32F [m] (needs a calibration); 0 where unknown.
    @param flow output N x 2 CV_32F normal flow [px/s]; 0 where none.
    @param confidence output N x 1 CV_32F, StereoEventEstimate::confidence (0..1), rejected estimates included.
    Time must not go backwards, within a packet or across calls (cv::Exception naming the event). */
    CV_WRAP virtual void process(InputArray events, OutputArray disparity, OutputArray lifetime = noArray(),
                                 OutputArray flags = noArray(), OutputArray depth = noArray(),
                                 OutputArray flow = noArray(), OutputArray confidence = noArray()) = 0;

    /** @brief The same for one event, decided at once (identical results to process() with getLookAhead() = 0). */
    virtual void processEvent(const Event& event, StereoEventEstimate& estimate) = 0;

    /** @brief Colour-coded disparity of the events of @p camera active at time @p t [us] (the paper's
    Figure 1): JET over getDisparityDisplayRange(t, camera) (blue to red), black where there is none, and a
    labelled colour bar on the right when @p colourBar is set. CV_8UC3, sensor height x (sensor width + bar). */
    CV_WRAP virtual void renderDisparity(double t, OutputArray image, int camera = CAMERA_LEFT,
                                         bool colourBar = true) const = 0;

    /** @brief The colour scale of renderDisparity() at time @p t [us] for @p camera: the disparities shown
    (getActiveDisparity()) as disparityDisplayRange() scales them, [low, high] in whole pixels. A person at
    9-20 px on a 0-40 px search spans the scale instead of showing in one colour. */
    CV_WRAP virtual Vec2i getDisparityDisplayRange(double t, int camera = CAMERA_LEFT) const = 0;

    /** @brief The disparities renderDisparity() shows, as numbers: per rectified pixel of @p camera, the own
    estimate of its last event when that estimate is active at time @p t [us], NO_DISPARITY elsewhere. CV_32F,
    the sensor's size: a sparse disparity map for code that wants one (occupancy, obstacles) without decoding
    colours. */
    CV_WRAP virtual void getActiveDisparity(double t, OutputArray disparity, int camera = CAMERA_LEFT) const = 0;

    /** @brief Forgets all events (keeps parameters and calibration). */
    CV_WRAP virtual void reset() = 0;

    /** @brief Rectification and depth: events are rectified with lookup tables built from it; an empty
    calibration (the default) takes the input as rectified and outputs no depth. */
    virtual void setCalibration(const StereoCalibration& calibration) = 0;
    virtual const StereoCalibration& getCalibration() const = 0;
    /** @brief setCalibration(readStereoCalibration(path)). */
    CV_WRAP virtual void loadCalibration(const String& path) = 0;

    /** @brief The plane fitter of a sensor (CameraId), to set its parameters; both start with the defaults. */
    CV_WRAP virtual Ptr<LifetimeEstimator> getLifetimeEstimator(int camera) const = 0;

    CV_WRAP virtual int getMode() const = 0;
    CV_WRAP virtual void setMode(int mode) = 0;
    CV_WRAP virtual Size getSensorSize() const = 0;
    CV_WRAP virtual void setSensorSize(Size size) = 0;
    /** @brief Smallest disparity searched [px] (default 0). */
    CV_WRAP virtual int getMinDisparity() const = 0;
    CV_WRAP virtual void setMinDisparity(int d) = 0;
    /** @brief Largest disparity searched [px] (default 40). */
    CV_WRAP virtual int getMaxDisparity() const = 0;
    CV_WRAP virtual void setMaxDisparity(int d) = 0;
    /** @brief N, the side of the window each descriptor histograms (odd, default 3). */
    CV_WRAP virtual int getDescriptorWindow() const = 0;
    CV_WRAP virtual void setDescriptorWindow(int n) = 0;
    /** @brief Longest nearest-active-event vector that votes [px] (default 3). */
    CV_WRAP virtual int getMaxVectorLength() const = 0;
    CV_WRAP virtual void setMaxVectorLength(int r) = 0;
    /** @brief W, the side of the first cost window (odd, default 17). */
    CV_WRAP virtual int getCostWindow() const = 0;
    CV_WRAP virtual void setCostWindow(int w) = 0;
    /** @brief COUPLED: the side of the window of the other sensor, centred on the counterpart, whose median
    lifetime a matched event takes (odd, at most 31, default 9). The paper takes the matched cost window;
    a window wider than the edge's neighbourhood mixes in other edges' speeds. */
    CV_WRAP virtual int getLifetimeWindow() const = 0;
    CV_WRAP virtual void setLifetimeWindow(int w) = 0;
    /** @brief A, the side of the largest window the iterative aggregation grows to (odd, >= W, at most 31, default 31). */
    CV_WRAP virtual int getAggregationWindow() const = 0;
    CV_WRAP virtual void setAggregationWindow(int a) = 0;
    /** @brief The cost windows read every k-th row, counting from the event's row (1..4, default 2: every
    other row; 1: every row, as published). Neighbouring rows' descriptors share most of their votes (each
    histograms an N x N window), so rows left out lose little of what tells the candidates apart, while the
    cost windows' reads, the largest part of a match's work, fall by the factor k. doc/benchmarks.md has the
    speed and the accuracy by k. */
    CV_WRAP virtual int getCostRowStep() const = 0;
    CV_WRAP virtual void setCostRowStep(int k) = 0;
    /** @brief Margin [%] by which the best cost must beat every other candidate and "no counterpart" for the
    iterative aggregation to stop growing the window (default 15). A higher margin aggregates over larger
    windows (slower, smoother); rejection is getMinConfidence()'s. */
    CV_WRAP virtual int getUniquenessRatio() const = 0;
    CV_WRAP virtual void setUniquenessRatio(int ratio) = 0;
    /** @brief Estimates with a lower confidence (StereoEventEstimate::confidence, 0..1) are rejected: no
    disparity, STEREO_AMBIGUOUS (default 0: every event keeps its best estimate). */
    CV_WRAP virtual double getMinConfidence() const = 0;
    CV_WRAP virtual void setMinConfidence(double confidence) = 0;
    /** @brief COUPLED: the confidence below which a match says nothing about whether the event is signal
    (0..1, default 0.15): every event keeps its best disparity, and noise finds some candidate. After a less
    confident match, an event whose own plane fit finds no plane is noise; from it up to
    getLifetimeCopyConfidence() it takes the match's lifetime instead. Where getLifetimeCopyConfidence() is
    lower, a match between the two passes its lifetime on once the event's own plane says it is not noise.
    0 (with getLifetimeCopyConfidence() 0): every match passes its lifetime on (more lifetimes, less noise
    found). */
    CV_WRAP virtual double getMatchedLifetimeConfidence() const = 0;
    CV_WRAP virtual void setMatchedLifetimeConfidence(double confidence) = 0;
    /** @brief COUPLED: the confidence from which a match passes its lifetime on in place of the event's own
    plane (0..1, default 0.3). Below it the event fits its own plane first (or takes its prediction), and
    takes the match's lifetime only where it finds none, from getMatchedLifetimeConfidence() up; below both
    the event is noise without a plane. The less confident matches are the wrong ones most often, and what a
    match passes on (lifetime, flow, copy count) sets how long the event stays active and what the matches
    around it copy next: with 0.3, fewer wrong matches follow on scenes where one object passes in front of
    another (doc/benchmarks.md). 0: every match passes its lifetime on, as published (with the noise check
    below getMatchedLifetimeConfidence()). */
    CV_WRAP virtual double getLifetimeCopyConfidence() const = 0;
    CV_WRAP virtual void setLifetimeCopyConfidence(double confidence) = 0;
    /** @brief COUPLED: how many times a lifetime may be passed between the sensors by matches before an event
    fits its own plane again (0..255; default 1; 255: no limit, as published; 0: every event fits first).
    Both sensors' matched events copy each other's lifetimes, so without a limit a lifetime can go round for
    as long as the matches hold while the edge changes speed (a swinging limb), and goes stale; the median
    over the other sensor's active events favours long lifetimes (their events stay active longer), so the
    copies also drift upwards. Past the limit a confidently matched event takes the match's lifetime only
    where its own fit finds no plane. 255 gives the paper's speed-up of the lifetime estimation over
    DECOUPLED, with lifetimes several times less accurate on articulated motion (doc/stereo.md,
    doc/benchmarks.md). */
    CV_WRAP virtual int getMaxLifetimeCopies() const = 0;
    CV_WRAP virtual void setMaxLifetimeCopies(int copies) = 0;
    /** @brief Temporal prior: how much more [%] than the best the cost of the candidate at the prior may be
    for it to win an otherwise ambiguous match (default 30; 0..1000; 0: no prior, the method as published). */
    CV_WRAP virtual int getPriorTolerance() const = 0;
    CV_WRAP virtual void setPriorTolerance(int percent) = 0;
    /** @brief Recency cost: the share [%] of the window's descriptor mass (its cost against nothing) that a
    candidate pays when the other sensor's events within a pixel of it are getRecencyTime() or more apart in
    time from the event, in proportion below that (default 15; 0..100; 0: the descriptors' cost alone, as
    published). See doc/stereo.md, "The method". */
    CV_WRAP virtual int getRecencyWeight() const = 0;
    CV_WRAP virtual void setRecencyWeight(int percent) = 0;
    /** @brief Recency cost: the time apart [us] from which a candidate pays the full recency cost (default
    10000; 1..1e6). */
    CV_WRAP virtual double getRecencyTime() const = 0;
    CV_WRAP virtual void setRecencyTime(double us) = 0;
    /** @brief Averaging: the radius [px] of the neighbourhood whose estimates an event's output disparity is
    averaged with (default 4; 0..5; 0: no averaging, the method as published). See doc/stereo.md, "The method". */
    CV_WRAP virtual int getAveragingRadius() const = 0;
    CV_WRAP virtual void setAveragingRadius(int px) = 0;
    /** @brief Filling: the radius [px] (rows and columns) of the surface an event's estimate is checked
    against (default 20; 0..30; 0: no filling, the method as published). The surface's disparity is the median
    of the estimates of at least 0.3 confidence that the sensor's events gave within the radius, in every other
    row, in the last 60 ms, when there are at least 5 and half of them lie within 1 px of it. The event takes it (flag
    STEREO_FILLED) when its own estimate is missing or less confident than 0.15, lies within 0.5 px of it, or
    lies more than 1 px from it where 80 % of the surface's estimates lie within 1 px of its median and those
    in the 3 columns either side of the event do not agree with the event's own; an event below
    getMinConfidence() gets no disparity, filled or not. Where one camera does not see an
    edge that the other sees (a weaker sensor, the background behind an outline that differs between the
    views), the event has no counterpart, or matches a neighbouring edge, and the surface around it says
    where it is. See doc/stereo.md, "The method". */
    CV_WRAP virtual int getFillRadius() const = 0;
    CV_WRAP virtual void setFillRadius(int px) = 0;
    /** @brief Filling: how long [us] the surface found around one event serves the events after it nearby
    (default 5000; 0..1e6; 0: every event's surface is the median of its own window). An event takes the surface
    found for an earlier event in the same stretch of 8 columns (x / 8) of its own row or of the 4 rows either side,
    less than this long before it, when that surface had enough estimates to fill; otherwise it takes the median
    of its own window, which later events may take in turn. The window's median is most of what filling costs, and
    on an edge the windows of events a few pixels and milliseconds apart hold nearly the same estimates: this
    moves the output of some events by the difference, not the matches (doc/stereo.md, "The method"). The
    results stay those of one thread whatever setNumThreads() says. */
    CV_WRAP virtual double getFillReuseTime() const = 0;
    CV_WRAP virtual void setFillReuseTime(double us) = 0;
    /** @brief Look-ahead L [us] (COUPLED, DECOUPLED, FIXED_INTERVAL; default 10000; 0..1e6). process() puts
    each event into its sensor's map when it arrives, but matches it (and gives it its lifetime) only once an
    event more than L later has arrived, or at the end of the packet: a counterpart that fires up to L later
    in the other sensor (a slower pixel, the other camera's latency, a low-contrast edge that needs longer to
    cross a threshold) is then there to match. The output of an event is thus final L after it, plus the
    processing time: that is the latency this adds. The look-ahead cannot reach past the packet, so give
    process() packets much longer than L (the 33 ms windows of EventCapture are). Lifetimes stay causal: the
    plane fit sees only the events before the event. 0 decides every event when it arrives, as the paper
    does; processEvent() always does. */
    CV_WRAP virtual double getLookAhead() const = 0;
    CV_WRAP virtual void setLookAhead(double us) = 0;
    /** @brief FIXED_INTERVAL: how long every event stays active [us] (default 10000); in the other per-event
    modes, the lifetime an event without one is taken to have for its activity during the cold start. */
    CV_WRAP virtual double getFixedInterval() const = 0;
    CV_WRAP virtual void setFixedInterval(double us) = 0;
    /** @brief Longest time an event with a lifetime stays active [us] (default 100000, the plane fit's dt),
    whatever its lifetime and getActiveDistance(): bounds how long a slow or wrong estimate pollutes the
    descriptors. */
    CV_WRAP virtual double getMaxLifetime() const = 0;
    CV_WRAP virtual void setMaxLifetime(double us) = 0;
    /** @brief COUPLED, DECOUPLED: how long [us] an event whose lifetime estimate says noise (no plane) stays
    active in the descriptors after the cold start (default 25000; 0..1e6; 0: not at all, the paper's
    method). Its disparity is output but is not one of the neighbours' estimates (temporal prior, left-right
    check). */
    CV_WRAP virtual double getNoiseActiveTime() const = 0;
    CV_WRAP virtual void setNoiseActiveTime(double us) = 0;
    /** @brief COUPLED, DECOUPLED: how far [px] an event's edge moves while the event stays active for
    matching, i.e. for how many lifetimes (the lifetime is the time the edge takes to move one pixel), up to
    getMaxLifetime() (default 2.5; 0.1..100). The paper's "active within its lifetime" is 1. A trail of a
    few pixels gives the descriptors more of each edge to match. The lifetimes output are not scaled. */
    CV_WRAP virtual double getActiveDistance() const = 0;
    CV_WRAP virtual void setActiveDistance(double px) = 0;
    /** @brief Threads for process() in the per-event modes (default 1; 1..64): the sensor's rows are split
    into this many bands, each processed on its own thread, split where the packet's events divide evenly.
    An event (or the end of an event's activity) close enough to a neighbouring band to touch data that
    band's events touch waits until that band has processed its earlier events in the rows it could touch
    and its earlier ends of activity near the boundary, so the results are identical to one thread's, bit
    for bit. Two events can touch the same data when they are at most 19 rows apart at the defaults (half the
    aggregation window read, plus the rows an activation writes); bands are taller than that, which caps the
    threads on small sensors (9 on a DAVIS240 at the defaults); packets of fewer than 1000 events run on one
    thread. More threads than the machine's cores is slower: a band whose thread is not running holds its
    neighbours back. processEvent() always runs on the calling thread. Not stored by write(). */
    CV_WRAP virtual int getNumThreads() const = 0;
    CV_WRAP virtual void setNumThreads(int threads) = 0;

    /** @brief Times the lifetime estimation inside process() and processEvent() on its own: the plane fits
    and their predictions, and in STEREO_COUPLED the matched windows' medians and the surface updates of
    matched events, without the matching. The paper's Table I times this alone ("the time needed to calculate
    the disparity is not included"); event_stereo_table prints it next to the whole matcher's time. Off by
    default: on, it reads the clock twice per event. Not stored by write(). */
    CV_WRAP virtual void setTimeLifetimes(bool on) = 0;
    CV_WRAP virtual bool getTimeLifetimes() const = 0;
    /** @brief Seconds spent in the lifetime estimation while setTimeLifetimes() was on, since the matcher was
    created or reset(); summed over the row bands' threads. */
    CV_WRAP virtual double getLifetimeSeconds() const = 0;
};

/** @brief "coupled", "decoupled" or "fixed" for a StereoMatchMode. */
CV_EXPORTS_W String getStereoModeName(int mode);
/** @brief The StereoMatchMode named (as getStereoModeName writes it, case-insensitive); -1 when unknown. */
CV_EXPORTS_W int findStereoMode(const String& name);

/** @brief The colour scale renderDisparity() gives a disparity map (@p disparity: CV_32F, negative values
none), for a map of your own (ground truth, another method's): [low, high] in whole pixels from the 2nd to the
98th percentile of its disparities, widened to at least 2 px within [@p minDisparity, @p maxDisparity], all of
that range when the map holds no disparity. */
CV_EXPORTS_W Vec2i disparityDisplayRange(InputArray disparity, int minDisparity, int maxDisparity);

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_STEREO_EVENT_MATCHER_HPP
