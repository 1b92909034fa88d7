// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The simulator's named scenes: the planes, their motion and the sensor settings each scene brings.

#include "precomp.hpp"
#include "simulation/simulated_scenes.hpp"
#include "opencv2/calib3d.hpp"

namespace cv {
namespace event {
namespace detail {
namespace {

SimulatedPlane movingPlane(Vec3d center, Vec2d halfSize, Vec3d velocity)
{
    SimulatedPlane p;
    p.center = center;
    p.halfSize = halfSize;
    p.velocity = velocity;
    return p;
}

SimulatedPlane texturedPlane(Vec3d center, Vec2d halfSize, Vec3d velocity, double cellSize, int seed)
{
    SimulatedPlane p = movingPlane(center, halfSize, velocity);
    p.cellSize = cellSize;
    p.textureSeed = seed;
    return p;
}

SimulatedPlane uniformPlane(Vec3d center, Vec2d halfSize, double intensity, Vec3d velocity = Vec3d(0, 0, 0))
{
    SimulatedPlane p = movingPlane(center, halfSize, velocity);
    p.texture = TEXTURE_UNIFORM;
    p.intensity = intensity;
    return p;
}

// A real DAVIS's departures from the ideal sensor, as the realistic scenes use them: thresholds of 0.25 with
// a 0.05 spread, 0.5 ms refractory period, background activity, a few hot pixels, leak, readout latency and
// jitter, and a pair rectified to within about a pixel.
void davisSensor(SimulatorSettings& s)
{
    s.thresholdOn = s.thresholdOff = 0.25;
    s.thresholdSigma = 0.05;
    s.refractoryUs = 500;
    s.noiseRateHz = 0.1;
    s.hotPixelShare = 0.0005;
    s.hotPixelRateHz = 20;
    s.leakRateHz = 0.02;
    s.latencyUs = 50;
    s.latencySigmaUs = 30;
    s.jitterUs = 30;
    s.rightRowOffset = 0.5;
    s.rightRollRad = 0.004;  // with the offset: 0.5 px at one side of a DAVIS240, 1 px at the other
}

// A DVS128's departures instead, so that the realistic scenes record as real DVS128 pairs do (1.2-1.3 events
// per pixel per edge crossing, as many ON as OFF events): pixels twice a DAVIS240's pitch, so half its blur in
// pixels; thresholds of 0.3 that also vary from one crossing to the next; a refractory period short enough
// for a burst; a slower, more varied readout; and a pair rectified by hand to within about a pixel.
void dvs128Sensor(SimulatorSettings& s)
{
    s.thresholdOn = s.thresholdOff = 0.3;
    s.thresholdSigma = 0.03;
    s.thresholdNoise = 0.03;
    s.refractoryUs = 10;
    s.noiseRateHz = 0.1;
    s.hotPixelShare = 0.0005;
    s.hotPixelRateHz = 20;
    s.latencyUs = 100;
    s.latencySigmaUs = 50;
    s.jitterUs = 50;
    s.blurSigmaPx = 0.5;
    s.rightRowOffset = 0.5;
    s.rightRollRad = 0.008;  // with the offset: 0.5 px at one side, 1 px at the other
}

// The realistic scenes' sensor: a DVS128's departures on that model, a DAVIS's on any other.
void realSensor(SimulatorSettings& s, int sensorModel)
{
    if (sensorModel == SENSOR_DVS128)
        dvs128Sensor(s);
    else
        davisSensor(s);
}

// Two DAVIS240s of a real stereo rig (measured against recordings of such pairs): on top of davisSensor(), OFF
// events fire more readily than ON ones, thresholds vary more from pixel to pixel and from one crossing to
// the next (dotted edges with holes), the optics blur edges to 2-4 px, the right sensor's thresholds are
// rightScale times the left's (below 1: it fires more events), and it stamps them rightClockUs later (its
// clock, and its OFF circuit, which is slower than its ON one).
void davis240Pair(SimulatorSettings& s, double rightScale, double rightClockUs)
{
    davisSensor(s);
    s.thresholdOn = 0.5;
    s.thresholdOff = 0.25;
    s.thresholdSigma = 0.08;
    s.thresholdNoise = 0.05;
    s.noiseRateHz = 0.03;
    s.blurSigmaPx = 0.8;
    s.rightThresholdScale = rightScale;
    s.rightClockOffsetUs = rightClockUs;
    s.extraLatencyUs = Vec4d(0, 200, 0, 500);
}

// A box that a hand slides to and fro along the baseline: a swing of @p amplitude [m] at @p frequency [Hz]
// about a pivot far above, so that it moves nearly straight, fastest in the middle and turning at the ends.
SimulatedPlane slidingBox(Vec3d center, Vec2d halfSize, double intensity, double amplitude, double frequency, double phase)
{
    SimulatedPlane p = uniformPlane(center, halfSize, intensity);
    const double pivotHeight = 6.0;  // [m] above the box's centre
    p.swingPivot = Vec2d(0, -pivotHeight);
    p.swingAmplitude = amplitude / pivotHeight;
    p.swingFrequency = frequency;
    p.swingPhase = phase;
    return p;
}

// How a walking figure's limbs look: the far-side leg's and arm's intensities (the near side's are 1.2 and
// 1.12 times brighter), and the contrast of a block texture on them (0: plain).
struct WalkerLook
{
    double legIntensity, armIntensity, limbTexture;
};

// A person walking across the view at @p depth: torso and head, arms and legs swinging about shoulders and
// hips in opposite phases, the far-side limbs 0.12 m behind the body and the near-side ones 0.12 m before it.
void addWalker(std::vector<SimulatedPlane>& planes, double depth, double speed, double startX, const WalkerLook& look)
{
    const Vec3d v(speed, 0, 0);
    const double stride = 0.9;  // steps per second per leg
    // Far-side limbs first: planes do not need an order, but this reads as the figure is built.
    for (int side = 0; side < 2; side++)
    {
        const double z = depth + (side == 0 ? 0.12 : -0.12);  // side 0 is the far side
        const double phase = side == 0 ? 0 : CV_PI;
        SimulatedPlane leg = uniformPlane(Vec3d(startX, 0.45, z), Vec2d(0.07, 0.45),
                                          look.legIntensity * (side == 0 ? 1.0 : 1.2), v);
        leg.swingPivot = Vec2d(0, -0.45);  // the hip
        leg.swingAmplitude = 0.4;
        leg.swingFrequency = stride;
        leg.swingPhase = phase;
        SimulatedPlane arm = uniformPlane(Vec3d(startX, -0.3, z), Vec2d(0.05, 0.32),
                                          look.armIntensity * (side == 0 ? 1.0 : 1.12), v);
        arm.swingPivot = Vec2d(0, -0.32);  // the shoulder
        arm.swingAmplitude = 0.35;
        arm.swingFrequency = stride;
        arm.swingPhase = phase + CV_PI;    // each arm against its leg
        if (look.limbTexture > 0)
        {
            // Cloth: folds and seams, blocks of 8 cm.
            for (SimulatedPlane* limb : { &leg, &arm })
            {
                limb->texture = TEXTURE_BLOCKS;
                limb->contrast = look.limbTexture;
                limb->cellSize = 0.08;
            }
            leg.textureSeed = 70 + side;
            arm.textureSeed = 80 + side;
        }
        planes.push_back(leg);
        planes.push_back(arm);
    }
    SimulatedPlane torso = texturedPlane(Vec3d(startX, -0.27, depth), Vec2d(0.18, 0.3), v, 0.12, 41);
    torso.intensity = 0.38;
    torso.contrast = 0.3;
    planes.push_back(torso);
    planes.push_back(uniformPlane(Vec3d(startX, -0.72, depth), Vec2d(0.1, 0.12), 0.4, v));  // the head
}

}  // namespace

std::vector<SimulatedPlane> simulatedScene(const String& name, int sensorModel, SimulatorSettings& s)
{
    std::vector<SimulatedPlane> planes;
    if (name == "plane")
    {
        // Fills the view at 1 m and slides right at 0.5 m/s: 100 px/s at f = 200 px, disparity 20 px.
        planes.push_back(texturedPlane(Vec3d(0, 0, 1.0), Vec2d(3, 3), Vec3d(0.5, 0, 0), 0.06, 11));
    }
    else if (name == "two_planes")
    {
        planes.push_back(texturedPlane(Vec3d(0, 0, 2.0), Vec2d(5, 5), Vec3d(-0.2, 0, 0), 0.12, 21));
        planes.push_back(texturedPlane(Vec3d(-0.6, 0, 1.0), Vec2d(0.25, 0.3), Vec3d(0.6, 0, 0), 0.05, 22));
    }
    else if (name == "moving_line" || name == "faint_line")
    {
        // A thin line over a dark background; the right sensor is 1.6 x less sensitive. moving_line's line is
        // bright (log contrast ln 9 = 2.2), so both sensors fire full edges. faint_line's has log contrast
        // ln(0.1375 / 0.1) = 0.32, the right sensor's mean threshold (1.6 x 0.2): with the per-pixel mismatch
        // the weak sensor fires at only part of the line's pixels (the paper's Figure 4 case).
        planes.push_back(uniformPlane(Vec3d(0, 0, 1.5), Vec2d(5, 5), 0.1));
        planes.push_back(uniformPlane(Vec3d(-0.5, 0, 1.2), Vec2d(0.012, 0.35), name == "moving_line" ? 0.9 : 0.1375,
                                      Vec3d(0.45, 0, 0)));
        s.rightThresholdScale = 1.6;
    }
    else if (name == "cluttered")
    {
        planes.push_back(texturedPlane(Vec3d(0, 0, 3.0), Vec2d(6, 6), Vec3d(0.1, 0.05, 0), 0.15, 31));
        SimulatedPlane a = texturedPlane(Vec3d(-0.4, -0.2, 1.2), Vec2d(0.2, 0.15), Vec3d(0.3, 0.05, 0), 0.04, 32);
        a.angularVelocity = Vec3d(0, 0, 0.8);
        SimulatedPlane b = texturedPlane(Vec3d(0.3, 0.25, 1.8), Vec2d(0.3, 0.2), Vec3d(-0.25, 0, 0), 0.06, 33);
        b.rotation = Vec3d(0, 0.3, 0);
        b.angularVelocity = Vec3d(0, 0.3, 0);
        SimulatedPlane c = texturedPlane(Vec3d(0.1, -0.4, 2.4), Vec2d(0.25, 0.1), Vec3d(0.15, 0.1, 0), 0.05, 34);
        c.angularVelocity = Vec3d(0.2, 0, -0.5);
        planes.push_back(a);
        planes.push_back(b);
        planes.push_back(c);
        s.noiseRateHz = 0.5;
    }
    else if (name == "boxes" || name == "boxes_fast" || name == "boxes_flicker")
    {
        // Two boxes and a pole at three depths (disparity 20, 10 and 8 px) over a plain wall at 5 m (4 px):
        // few edges, of moderate contrast, with a faint pattern on the near box. The boxes move diagonally, so
        // that their horizontal edges fire too (the ones a row search finds hardest). boxes_fast moves 2.5 x
        // faster.
        const double k = name == "boxes" ? 1.0 : 2.5;
        planes.push_back(uniformPlane(Vec3d(0, 0, 5.0), Vec2d(8, 6), 0.22));
        SimulatedPlane nearBox = texturedPlane(Vec3d(-0.55, 0.05, 1.0), Vec2d(0.15, 0.13), Vec3d(0.25 * k, 0.1 * k, 0), 0.1, 51);
        nearBox.intensity = 0.55;
        nearBox.contrast = 0.25;
        planes.push_back(nearBox);
        planes.push_back(uniformPlane(Vec3d(0.9, 0.1, 2.0), Vec2d(0.25, 0.2), 0.45, Vec3d(-0.35 * k, -0.15 * k, 0)));
        planes.push_back(uniformPlane(Vec3d(-0.2, 0, 2.5), Vec2d(0.025, 1.5), 0.12, Vec3d(0.15 * k, 0, 0)));
        if (name == "boxes_flicker")
        {
            // Lit by a lamp on mains power, 100 Hz: the room's surfaces flicker by 6 %, a log swing of 0.12,
            // about half a threshold, so only the most sensitive pixels follow it; the lamp itself, high on the
            // wall (about 40 x 6 px), swings by 60 %, several thresholds per half period.
            for (SimulatedPlane& p : planes)
                p.flickerDepth = 0.06;
            SimulatedPlane lamp = uniformPlane(Vec3d(0.6, -1.7, 4.9), Vec2d(0.45, 0.07), 1.5);
            lamp.flickerDepth = 0.6;
            planes.push_back(lamp);
            s.flickerFrequencyHz = 100;
        }
        realSensor(s, sensorModel);
    }
    else if (name == "walking")
    {
        // A person walking right at 1.1 m/s, 3 m away (disparity 6.7 px), in front of a plain wall at 6 m (3.3 px).
        planes.push_back(uniformPlane(Vec3d(0, 0, 6.0), Vec2d(10, 8), 0.5));
        addWalker(planes, 3.0, 1.1, -1.6, WalkerLook{ 0.2, 0.32, 0 });
        realSensor(s, sensorModel);
    }
    else if (name == "walking_near")
    {
        // The same walk 1.5 m away (disparity 13.3 px; the near limbs 14.5 px, the far ones 12.3 px) in
        // clothes of little contrast against the wall (the near leg's mean is less than one threshold from
        // it), textured: ragged, partly missing edges. The right camera is 10 % less sensitive, as in real
        // pairs (they differ by 9-13 % in event count, one by 85 %).
        planes.push_back(uniformPlane(Vec3d(0, 0, 6.0), Vec2d(10, 8), 0.5));
        addWalker(planes, 1.5, 1.1, -0.8, WalkerLook{ 0.33, 0.38, 0.3 });
        realSensor(s, sensorModel);
        s.rightThresholdScale = 1.1;
    }
    else if (name == "boxes_pair" || name == "boxes_fast_pair")
    {
        // Two plain boxes about 1 m and 2 m away (19.3-20.7 and 9.8-10.2 px) slid to and fro in front of a plain
        // wall at 5 m, as recorded by a real DAVIS240 pair (davis240Pair): boxes_pair's right camera fires 1.4 x
        // the events and stamps them 2 ms late; boxes_fast_pair's boxes move a third faster and its right
        // camera fires 1.6 x the events 2.5 ms early. The boxes' faces turn a little away from the cameras, as a
        // box held by hand does, so that their disparities fall between whole pixels.
        const bool fast = name == "boxes_fast_pair";
        const double k = fast ? 4.0 : 3.0;
        planes.push_back(uniformPlane(Vec3d(0, 0, 5.0), Vec2d(8, 6), 0.22));
        SimulatedPlane nearBox = slidingBox(Vec3d(-0.25, 0.05, 1.0), Vec2d(0.1, 0.12), 0.4, 0.2, 0.35 * k, 0);
        nearBox.rotation = Vec3d(0, 0.35, 0);
        nearBox.texture = TEXTURE_BLOCKS;  // a print on it
        nearBox.cellSize = 0.03;
        nearBox.contrast = 0.3;
        nearBox.textureSeed = 53;
        planes.push_back(nearBox);
        SimulatedPlane farBox = slidingBox(Vec3d(0.45, -0.1, 2.0), Vec2d(0.15, 0.2), 0.345, 0.3, 0.25 * k, 2.0);
        farBox.rotation = Vec3d(0, -0.3, 0);
        planes.push_back(farBox);
        davis240Pair(s, fast ? 0.82 : 0.86, fast ? -2500 : 2000);
    }
    else if (name == "walking_pair")
    {
        // A person walking 1.8 m away (11.1 px; the near limbs 11.9 px, the far ones 10.4 px) past a room's
        // far wall at 6 m (3.3 px) hung with posters and shelves (blocks of 0.3 m, intensities 0.3-0.5), as a
        // real DAVIS240 pair records it (davis240Pair): the right camera fires 0.6 x the left's events and
        // stamps them 1.7 ms early. The clothes are about as bright as the wall, so where the figure passes
        // a darker block its edges fire one polarity, a brighter one the other, a similar one not at all; the
        // two cameras see each point of the figure's outline against wall blocks 7.8 px apart, so an outline
        // fires differently in each.
        SimulatedPlane wall = texturedPlane(Vec3d(0, 0, 6.0), Vec2d(10, 8), Vec3d(0, 0, 0), 0.3, 91);
        wall.intensity = 0.5;
        wall.contrast = 0.4;
        planes.push_back(wall);
        addWalker(planes, 1.8, 1.1, -1.0, WalkerLook{ 0.36, 0.4, 0 });
        davis240Pair(s, 1.3, -1700);
    }
    else if (name == "fan")
    {
        // A small four-bladed fan 1 m away (14 cm across: 14 px on a DVS128, 28 px on a DAVIS240) turning at
        // 25 revolutions per second in front of a plain wall at 3 m, its blades a little brighter than the wall
        // (log contrast 0.45, under two thresholds): a pixel fires once or not at all as a blade passes, and a
        // blade's edge moves at 2 pi 25 r px/s at r px from the hub.
        planes.push_back(uniformPlane(Vec3d(0, 0, 3.0), Vec2d(5, 5), 0.3));
        for (int k = 0; k < 2; k++)  // two crossed bars, each two blades
        {
            SimulatedPlane bar = uniformPlane(Vec3d(0, 0, 1.0), Vec2d(0.07, 0.012), 0.47);
            bar.rotation = Vec3d(0, 0, 0.5 * CV_PI * k);
            bar.angularVelocity = Vec3d(0, 0, 2 * CV_PI * 25);
            planes.push_back(bar);
        }
        realSensor(s, sensorModel);
    }
    else if (name == "pendulum" || name == "pendulum_patterned")
    {
        // A dark ball (an octagon 5 cm across) on a string swinging towards and away from the left camera in
        // front of a plain wall 1.5 m away, as in the TUM pendulum recording: 0.24-0.60 m away (disparity 42-17
        // px on a DVS128), +-50 degrees every 1.75 s on a 0.24 m string, in the vertical plane through the left
        // camera's centre along its line of sight x = 0.254 z (column 90 of 128), the camera tilted 8 degrees
        // up. The left camera sees the ball grow and shrink and move up and down, lowest mid-swing; the right
        // one sees it move along the rows as well.
        const double k = 0.254, zMid = 0.42, yMid = 0.12, amplitude = 50 * CV_PI / 180, pitch = -8 * CV_PI / 180;
        const double length = 0.18 * std::sqrt(1 + k * k) / std::sin(amplitude);
        planes.push_back(uniformPlane(Vec3d(0, 0, 1.5), Vec2d(2, 2), 0.5));
        // Gravity in the camera's frame, and the swing's axis: level, across the line of sight, so that a
        // positive angle takes the ball away from the camera.
        const Vec3d down(0, std::cos(pitch), std::sin(pitch));
        const Vec3d axis = normalize(down.cross(Vec3d(k, 0, 1)));
        const Vec3d ball(k * zMid, yMid, zMid);
        std::vector<SimulatedPlane> parts;
        for (int side = 0; side < 2; side++)  // two squares, the second turned by 45 degrees: an octagon
        {
            SimulatedPlane half = uniformPlane(ball, Vec2d(0.025, 0.025), 0.2);
            if (name == "pendulum_patterned")
            {
                // A print of 5 mm blocks (1-3 px), half as bright at the darkest, so that the ball fires inside
                // its outline as the recording's printed ball does.
                half.texture = TEXTURE_BLOCKS;
                half.cellSize = 0.005;
                half.contrast = 0.5;
                half.textureSeed = 71 + side;
            }
            const double turn = side * CV_PI / 4;
            Vec3d rotation;
            Rodrigues(Matx33d(1, 0, 0, 0, std::cos(pitch), -std::sin(pitch), 0, std::sin(pitch), std::cos(pitch)) *
                          Matx33d(std::cos(turn), -std::sin(turn), 0, std::sin(turn), std::cos(turn), 0, 0, 0, 1),
                      rotation);
            half.rotation = rotation;
            // The pivot, straight above the ball, in the turned square's own coordinates.
            half.swingPivot = Vec2d(-length * std::sin(turn), -length * std::cos(turn));
            parts.push_back(half);
        }
        SimulatedPlane cord = uniformPlane(ball - 0.5 * length * down, Vec2d(0.0015, 0.5 * length), 0.2);
        cord.rotation = Vec3d(pitch, 0, 0);
        cord.swingPivot = Vec2d(0, -0.5 * length);
        parts.push_back(cord);
        for (SimulatedPlane& part : parts)
        {
            part.swingAxis = axis;
            part.swingAmplitude = amplitude;
            part.swingFrequency = 1 / 1.75;
            planes.push_back(part);
        }
        realSensor(s, sensorModel);
    }
    else if (name == "low_contrast")
    {
        // A faintly textured plane (log contrast up to 0.36, about one threshold) sliding over a plain wall.
        planes.push_back(uniformPlane(Vec3d(0, 0, 4.0), Vec2d(8, 6), 0.3));
        SimulatedPlane p = texturedPlane(Vec3d(-0.2, 0, 1.5), Vec2d(0.5, 0.35), Vec3d(0.3, 0, 0), 0.08, 61);
        p.intensity = 0.5;
        p.contrast = 0.3;
        planes.push_back(p);
        realSensor(s, sensorModel);
    }
    else
    {
        String known;
        for (const String& n : simulatedSceneNames())
            known += (known.empty() ? "" : ", ") + n;
        CV_Error_(Error::StsBadArg, ("StereoEventSimulator: unknown scene \"%s\" (%s)", name.c_str(), known.c_str()));
    }
    return planes;
}

std::vector<String> simulatedSceneNames()
{
    return std::vector<String>{ "plane", "two_planes", "moving_line", "faint_line", "cluttered",
                                "boxes", "boxes_fast", "walking", "walking_near", "low_contrast", "fan", "pendulum",
                                "pendulum_patterned", "boxes_flicker", "boxes_pair", "boxes_fast_pair", "walking_pair" };
}

}  // namespace detail
}  // namespace event
}  // namespace cv
