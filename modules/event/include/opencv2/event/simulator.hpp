// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SIMULATOR_HPP
#define OPENCV_EVENT_SIMULATOR_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_simulator
//! @{

/** @brief Columns of the ground-truth matrix the simulator returns next to its events (N x 6, CV_32F). */
enum SimulatorGroundTruthColumn
{
    GT_DEPTH = 0,      //!< depth of the scene point that caused the event [m] (0 for noise)
    GT_DISPARITY = 1,  //!< its disparity x_left - x_right = f * B / depth [px] (0 for noise)
    GT_FLOW_X = 2,     //!< normal optical flow, x [px/s]: the image motion along the brightness gradient
    GT_FLOW_Y = 3,     //!< normal optical flow, y [px/s]
    GT_LIFETIME = 4,   //!< time for the edge to move one pixel, 1 / |normal flow| [us] (0 when it does not move)
    GT_FLAGS = 5       //!< SimulatorEventFlags, as a number
};

/** @brief Flags in the GT_FLAGS column. */
enum SimulatorEventFlags
{
    GT_FLAG_NOISE = 1,    //!< background-activity noise: no scene point caused it
    GT_FLAG_OCCLUDED = 2, //!< the scene point is hidden from the other camera: it has no stereo counterpart
    /** a plane's flicker made the pixel fire, not motion: since the pixel's previous threshold crossing, the
    scene's steady (flicker-free) log intensity there has moved by less than half the threshold in the
    event's direction. The scene point is real: depth and disparity are filled in. */
    GT_FLAG_FLICKER = 4
};

/** @brief Procedural textures of simulated planes. */
enum SimulatorTexture
{
    TEXTURE_BLOCKS = 0,   //!< random-intensity square cells with sharp (about 1/8 cell) edges, rotated
    TEXTURE_UNIFORM = 1   //!< one intensity (a thin line or a plain background)
};

/** @brief A textured planar rectangle moving rigidly in the scene.

World frame = left camera frame: +X right, +Y down, +Z forward (depth), metres. The right camera sits at
(baseline, 0, 0), both looking along +Z with the same intrinsics: the pair is rectified. */
struct CV_EXPORTS SimulatedPlane
{
    Vec3d center = Vec3d(0, 0, 1);   //!< centre at t = 0 [m]
    Vec3d rotation = Vec3d(0, 0, 0); //!< orientation at t = 0, Rodrigues vector; zero = facing the cameras
    Vec2d halfSize = Vec2d(1, 1);    //!< half width and height in the plane [m]
    Vec3d velocity = Vec3d(0, 0, 0); //!< linear velocity [m/s]
    Vec3d angularVelocity = Vec3d(0, 0, 0); //!< angular velocity about the centre, world frame [rad/s]
    int texture = TEXTURE_BLOCKS;    //!< SimulatorTexture
    double cellSize = 0.05;          //!< texture cell size [m]
    double intensity = 1.0;          //!< brightest value (linear units)
    double contrast = 0.8;           //!< blocks: intensities spread over [intensity * (1 - contrast), intensity]
    int textureSeed = 1;             //!< blocks: pattern seed
    /** Swing (limbs): after its rigid motion the plane turns about @p swingPivot (a point in the plane, in
    its in-plane coordinates [m], e.g. (0, -halfSize[1]) for the top end) by swingAmplitude * sin(2 pi
    swingFrequency t + swingPhase) [rad] about the world axis @p swingAxis (unit). Zero amplitude: no swing. */
    Vec3d swingAxis = Vec3d(0, 0, 1);
    Vec2d swingPivot = Vec2d(0, 0);  //!< @copydoc swingAxis
    double swingAmplitude = 0;       //!< @copydoc swingAxis
    double swingFrequency = 0;       //!< @copydoc swingAxis
    double swingPhase = 0;           //!< @copydoc swingAxis
    /** Flicker: the plane's intensity is multiplied by 1 + flickerDepth * sin(2 pi f t), f =
    SimulatorSettings::flickerFrequencyHz, in [0, 1). A lamp in view, or a surface lit by one (mains lighting
    flickers at twice the mains frequency: 100 or 120 Hz). 0: steady. */
    double flickerDepth = 0;
};

/** @brief Sensors, pair geometry and event generation of the simulator. */
struct CV_EXPORTS SimulatorSettings
{
    Size resolution = Size(240, 180);  //!< pixels per camera
    double focalLength = 200;          //!< [px]; principal point at the image centre
    double baseline = 0.1;             //!< [m]
    double thresholdOn = 0.2;          //!< log-intensity contrast threshold of ON events
    double thresholdOff = 0.2;         //!< ... of OFF events
    double thresholdSigma = 0.03;      //!< per-pixel threshold mismatch (standard deviation, absolute)
    double rightThresholdScale = 1.0;  //!< > 1 makes the right camera less sensitive
    double refractoryUs = 100;         //!< a pixel fires at most once per this period [us]
    double noiseRateHz = 0;            //!< background activity per pixel [events/s]
    double maxPixelStep = 0.25;        //!< adaptive stepping: no point moves more than this between renders [px]
    double maxStepUs = 1000;           //!< longest render step [us]
    double backgroundIntensity = 0.05; //!< where no plane is hit
    int seed = 0;                      //!< everything random (thresholds, noise) derives from it

    // Sensor non-idealities (all off by default). Each draws from its own random sequence, so turning one on
    // leaves the events the others make unchanged.
    /** Temporal threshold noise: each crossing's threshold is the pixel's plus a normal draw of this standard
    deviation (absolute, log intensity), so a pixel does not fire the same way on every edge. */
    double thresholdNoise = 0;
    /** Lens blur: a Gaussian of this standard deviation [px] on the image before the sensor, out to 4 standard
    deviations (0: sharp). An event's ground truth is that of the nearest surface within the blur's reach: an
    edge between two surfaces is the nearer one's contour. */
    double blurSigmaPx = 0;
    /** Readout latency: every event is stamped this long after its threshold crossing, plus a per-pixel
    offset drawn once from a normal distribution of standard deviation latencySigmaUs (clipped at 0) [us]. */
    double latencyUs = 0;
    double latencySigmaUs = 0;         //!< @copydoc latencyUs
    /** Extra readout latency per camera and polarity, (left ON, left OFF, right ON, right OFF) [us], on top of
    latencyUs: two sensors of a pair, or a sensor's ON and OFF circuits, biased differently react at different
    speeds. Each must be >= 0. */
    Vec4d extraLatencyUs = Vec4d(0, 0, 0, 0);
    /** The right camera's clock against the left one: every right-camera event (noise included) is stamped
    t + rightClockOffsetUs + rightClockDriftPpm * 1e-6 * t, where t is the stamp a shared clock would give.
    Two cameras synchronised in software, or not at all, disagree by a few milliseconds and drift apart by
    tens of parts per million. */
    double rightClockOffsetUs = 0;
    double rightClockDriftPpm = 0;     //!< @copydoc rightClockOffsetUs
    /** Timestamp jitter: a further delay per event, exponential with this mean [us]. A pixel's events keep
    their order (a stamp earlier than the pixel's previous one is moved up to it). */
    double jitterUs = 0;
    /** Hot pixels: this share of each camera's pixels fires on its own, at hotPixelRateHz, each with one
    polarity (flagged GT_FLAG_NOISE). */
    double hotPixelShare = 0;
    double hotPixelRateHz = 0;         //!< @copydoc hotPixelShare
    /** Leak events: ON events every pixel fires on its own, Poisson at this rate [events/s] (flagged
    GT_FLAG_NOISE). */
    double leakRateHz = 0;
    /** Imperfect rectification of the right camera: its pixel grid is rotated by rightRollRad about the image
    centre, scaled about it by 1 + rightScale (its focal length calibrated that much off) and shifted by
    rightColumnOffset and rightRowOffset [px] (its principal point off) against the ideal rectified camera, so a
    point at ideal pixel (u, v) is seen at (1 + rightScale) R(roll) (u - cx, v - cy) + (cx + rightColumnOffset,
    cy + rightRowOffset). Its events' true flow and lifetime are the motion on that grid (turned and stretched
    alike). The ground-truth disparity stays the ideal f B / Z: the column offset and the scale move what the
    right camera sees along the rows, so a match against it is off the truth by -rightColumnOffset - rightScale
    (u - d - cx) px, which no matcher can tell from the scene's own depth. */
    double rightRowOffset = 0;
    double rightRollRad = 0;           //!< @copydoc rightRowOffset
    double rightScale = 0;             //!< @copydoc rightRowOffset
    double rightColumnOffset = 0;      //!< @copydoc rightRowOffset
    /** Frequency of the planes' flicker (SimulatedPlane::flickerDepth) [Hz]. While a plane flickers, render
    steps are at most 1/40 of its period long. */
    double flickerFrequencyHz = 100;

    /** @brief Presets: SENSOR_DAVIS240 (240 x 180, f = 200 px) and SENSOR_DAVIS346 (346 x 260, f = 250 px),
    ideal sensors. */
    static SimulatorSettings preset(int sensorModel);
};

/** @brief A stereo event-camera simulator with per-event ground truth (ESIM-style).

Renders the log intensity of a scene of textured planes for both cameras at adaptively spaced instants,
so that no image point moves more than SimulatorSettings::maxPixelStep pixels between two renders; a pixel
emits an event each time its log intensity moves by its contrast threshold from the level of its last
event, with the time interpolated linearly between the renders. Every event comes with its ground truth
(see SimulatorGroundTruthColumn). Output is deterministic for a given seed, and streams: generate() hands
out events up to a time, the memory holds only per-pixel state.

Named scenes (create()):
- "plane": a textured plane 1 m away translating parallel to the sensor (disparity 20 px at f = 200 px,
  B = 0.1 m);
- "two_planes": a textured foreground plane sliding over a textured background twice as far (occlusion);
- "moving_line": a single thin bright line moving over a dark background; the right camera is 1.6x less
  sensitive (the paper's asymmetric-sensitivity case);
- "faint_line": the same with a faint line (log contrast at the weak sensor's threshold), so the right camera
  fires at only part of its pixels (the paper's Figure 4 case);
- "cluttered": several textured planes at different depths, translating and rotating, with background
  activity noise;
- "boxes", "boxes_fast", "walking", "walking_near", "low_contrast": the realistic scenes (sparse edges on a
  plain wall, a walking figure 3 m and 1.5 m away, faint texture) with a real DAVIS's noise, latency and
  imperfect rectification; on SENSOR_DVS128, with a real DVS128's instead (thresholds of 0.3 that vary from
  one crossing to the next, a 10 us refractory period, 0.5 px of lens blur, a slower readout);
- "fan": a small four-bladed fan 1 m away turning at 25 revolutions per second, its blades under two thresholds
  brighter than the wall behind, with the same real sensor's departures (the fan of the TUM DVS128 pairs, on a
  DVS128);
- "pendulum": a dark ball 5 cm across on a string swinging towards and away from the left camera, 0.24-0.60 m
  away, every 1.75 s, over a plain wall, with the same real sensor's departures (the pendulum of the TUM DVS128
  pairs, on a DVS128: disparity 17-42 px);
- "pendulum_patterned": the same ball printed with blocks of 5 mm, so that it fires inside its outline as the
  real pendulum's ball does;
- "boxes_pair", "boxes_fast_pair", "walking_pair": boxes slid to and fro (their faces turned a little, so that
  their disparities fall between whole pixels) and the walking figure 1.8 m away in front of a patterned wall,
  as a real DAVIS240 pair records them: thicker, dotted edges, more OFF than ON events, sensors of different
  sensitivity and latency, and the right camera's clock a few milliseconds off;
- "boxes_flicker": "boxes" lit by a lamp flickering at 100 Hz, the lamp itself in view (events flagged
  GT_FLAG_FLICKER).
*/
class CV_EXPORTS_W StereoEventSimulator : public Algorithm
{
public:
    /** @brief A simulator of a named scene (see the class description) on a sensor preset. */
    CV_WRAP static Ptr<StereoEventSimulator> create(const String& scene = "plane", int sensorModel = SENSOR_DAVIS240,
                                                    int seed = 0);
    /** @brief A simulator of a custom scene. */
    static Ptr<StereoEventSimulator> create(const std::vector<SimulatedPlane>& planes, const SimulatorSettings& settings);

    /** @brief Names accepted by create(). */
    static std::vector<String> sceneNames();

    /** @brief Simulates from the current time up to @p untilUs (exclusive) and returns the events, both
    cameras merged in time (left first on equal times), with their ground truth (N x 6 CV_32F, rows as
    the events). Returns false when there was nothing to simulate (untilUs not after the current time). */
    CV_WRAP virtual bool generate(double untilUs, OutputArray events, OutputArray groundTruth) = 0;

    /** @brief Simulated time reached so far [us]. */
    CV_WRAP virtual double getTime() const = 0;

    /** @brief Renders the ground-truth disparity map of one camera at the current time (CV_32F, 0 where
    no plane is hit), e.g. for pictures next to estimated disparities. */
    CV_WRAP virtual void renderDisparity(int camera, OutputArray disparity) const = 0;

    /** @brief Renders the scene's intensity (CV_32F, linear units) seen by one camera at the current time. */
    CV_WRAP virtual void renderIntensity(int camera, OutputArray intensity) const = 0;

    virtual const SimulatorSettings& getSettings() const = 0;
    virtual const std::vector<SimulatedPlane>& getPlanes() const = 0;
    CV_WRAP virtual Size getSensorSize() const = 0;
};

/** @brief Simulates @p durationUs of a scene and writes it: the events through EventWriter (stereo; text or
AEDAT 4.0 by the extension of @p path) and their ground truth to `<path>.gt.csv`, one line per event in the
same order: `t,x,y,p,camera,depth,disparity,flow_x,flow_y,lifetime,flags` (units as in
SimulatorGroundTruthColumn). Memory does not grow with the duration.
@return the number of events written. */
CV_EXPORTS_W double writeSimulatedRecording(const Ptr<StereoEventSimulator>& simulator, const String& path,
                                            double durationUs);

/** @brief Reads the ground truth that writeSimulatedRecording() writes beside a recording (`<path>.gt.csv`),
in step with the recording's events as EventCapture delivers them.

Memory does not grow with the file: each read() takes the next lines. */
class CV_EXPORTS_W SimulatedGroundTruthReader
{
public:
    CV_WRAP SimulatedGroundTruthReader();
    /** @brief Opens @p path at once; see open(). */
    CV_WRAP explicit SimulatedGroundTruthReader(const String& path);
    ~SimulatedGroundTruthReader();

    /** @brief Opens a ground-truth file (`t,x,y,p,camera,depth,disparity,flow_x,flow_y,lifetime,flags` per
    line, after that header). A file that cannot be opened, or whose first line is not that header, raises
    cv::Exception naming it. */
    CV_WRAP void open(const String& path);
    CV_WRAP bool isOpened() const;

    /** @brief The ground truth of the next events: N x 6 CV_32F, rows as @p events, columns as
    StereoEventSimulator::generate() gives them (SimulatorGroundTruthColumn). Each line must describe its event
    (same t, x, y, polarity and camera): a line that does not, a malformed line, or a file that ends first raise
    cv::Exception naming the file and the line. */
    CV_WRAP void read(InputArray events, OutputArray groundTruth);

    /** @brief Lines of ground truth read so far (the events they described). */
    CV_WRAP double getLinesRead() const;

private:
    struct Impl;
    Ptr<Impl> impl_;
};

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SIMULATOR_HPP
