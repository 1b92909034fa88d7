// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_STEREO_CALIBRATION_HPP
#define OPENCV_EVENT_STEREO_CALIBRATION_HPP

#include "opencv2/event/types.hpp"

namespace cv {
namespace event {

//! @addtogroup event_stereo
//! @{

/** @brief Calibration of a stereo event-camera pair, in the form cv::stereoRectify produces.

Camera i maps a raw pixel through its intrinsics Ki and distortion Di (pinhole with OpenCV's radial-
tangential model, or the equidistant fisheye model when @ref fisheye is set), rotates it by Ri into the common
rectified frame and projects it with the 3x4 Pi. In the rectified images corresponding points share a row,
and a left point at x_l matches the right point at x_r = x_l - d; depth = f B / d with f = P1(0,0) and the
baseline B = -P2(0,3) / P2(0,0).

Sources: readStereoCalibration() (an OpenCV FileStorage file as cv::stereoCalibrate + cv::stereoRectify write
it, or a Kalibr camchain YAML), fromRectified() (a pair that is rectified already, e.g. the simulator), or
the fields set directly. */
struct CV_EXPORTS_W_SIMPLE StereoCalibration
{
    CV_PROP_RW Size imageSize;  //!< sensor size of both cameras (raw and rectified images share it)
    CV_PROP_RW Mat K1;  //!< left camera: 3x3 intrinsics
    CV_PROP_RW Mat D1;  //!< left camera: distortion coefficients
    CV_PROP_RW Mat R1;  //!< left camera: 3x3 rectifying rotation
    CV_PROP_RW Mat P1;  //!< left camera: 3x4 projection in the rectified frame
    CV_PROP_RW Mat K2;  //!< right camera: 3x3 intrinsics
    CV_PROP_RW Mat D2;  //!< right camera: distortion coefficients
    CV_PROP_RW Mat R2;  //!< right camera: 3x3 rectifying rotation
    CV_PROP_RW Mat P2;  //!< right camera: 3x4 projection in the rectified frame (P2(0,3) = -f B)
    CV_PROP_RW bool fisheye;  //!< D1 / D2 are equidistant (cv::fisheye) coefficients k1..k4

    CV_WRAP StereoCalibration() : fisheye(false) {}

    /** @brief A pair that needs no rectification (identity rotation, no distortion): both cameras have focal
    length @p focalLength [px] and the principal point at the image centre, the right camera @p baseline [m]
    to the right of the left one. */
    CV_WRAP static StereoCalibration fromRectified(Size imageSize, double focalLength, double baseline);

    /** @brief Rectified focal length f = P1(0,0) [px]; 0 when the calibration is empty. */
    CV_WRAP double focalLength() const;
    /** @brief Baseline B = -P2(0,3) / P2(0,0) [m, or the unit of the calibration's translation]. */
    CV_WRAP double baseline() const;
    /** @brief True when no calibration is set (P1 is empty). */
    CV_WRAP bool empty() const;
    /** @brief Throws cv::Exception (StsBadArg) naming the first wrong field: sizes and types of the
    matrices, a positive image size and focal length, a non-zero baseline. */
    CV_WRAP void validate() const;

    /** @brief Maps raw pixels to rectified coordinates (CV_32FC2, N x 1) for camera @p camera (CameraId). */
    CV_WRAP void rectifyPoints(InputArray points, OutputArray rectified, int camera) const;

    /** @brief Moves each event of a stereo packet to its rectified pixel (rounded), by its camera column, for
    the checks that look at rows and columns as StereoEventMatcher will (estimateRowAlignment(),
    checkStereoPair(), estimateClockOffset()). Times, polarities and the order are kept; a pixel that
    rectifies outside the image keeps its coordinates there (the estimates ignore it). @p rectified may be
    @p events. Events of a camera other than 0 and 1 raise cv::Error::StsBadArg. */
    CV_WRAP void rectifyEvents(InputArray events, OutputArray rectified) const;

    /** @brief Writes K1 D1 R1 P1 K2 D2 R2 P2, imageSize and fisheye under the current node. */
    void write(FileStorage& fs) const;
    /** @brief Reads what write() writes (or any OpenCV form readStereoCalibration() accepts) from @p node,
    and validates it; errors name @p source. */
    void read(const FileNode& node, const String& source = "calibration node");
};

/** @brief Reads a stereo calibration file; the kind is recognised from the keys.
- OpenCV FileStorage (YAML, XML or JSON) with the intrinsics under K1/M1/cameraMatrix1, D1/distCoeffs1,
  K2/M2/cameraMatrix2, D2/distCoeffs2, the image size under imageSize or image_width + image_height, and
  either R1, R2, P1, P2 (as cv::stereoRectify returns them; used as given) or the extrinsics R, T (rectified
  here with cv::stereoRectify, CALIB_ZERO_DISPARITY, alpha = 0). An optional `fisheye` flag (0/1) selects the
  equidistant model.
- Kalibr camchain YAML: cam0 / cam1 with camera_model pinhole, intrinsics [fu, fv, pu, pv], distortion_model
  radtan, equidistant or none, distortion_coeffs, resolution [w, h], and cam1's T_cn_cnm1 (4x4, cam0 -> cam1);
  rectified as above.
Errors (missing file, missing or malformed key, a camchain that is not pinhole) raise cv::Exception with the
path and the key. */
CV_EXPORTS_W StereoCalibration readStereoCalibration(const String& path);

/** @brief Writes @p calibration to an OpenCV FileStorage file that readStereoCalibration() reads back. */
CV_EXPORTS_W void writeStereoCalibration(const String& path, const StereoCalibration& calibration);

/** @brief How far a stereo pair's rows are off, measured from its events: (row offset [px] at the image
centre, roll [rad]). Zero for a well rectified pair.

The events of each camera are counted per pixel; three vertical strips of the left image (left, middle and
right third) are each matched against the right image over disparities [minDisparity, maxDisparity] and row
shifts of up to 4 px by normalised correlation, the row shift refined to sub-pixel by a parabola; a line through
the three shifts over the strips' centres gives the offset at the centre and the roll. Positive: the right
camera sees a point lower (larger y) than the left one does, and more so to the right for a positive roll.
Give it the events of a stretch with motion in more than one direction (horizontal edges carry the row
information), already rectified when a calibration exists; a second or two of a typical recording is enough.
@param events stereo events (camera column), any form getEventMat() accepts; events outside the sensor are
ignored.
@param sensorSize the sensor size.
@param minDisparity, maxDisparity the disparity range searched.
@param score optional output: the smallest of the three strips' best correlations (0..1); below about 0.4 the
events do not say much, and the estimate should not be trusted.
*/
CV_EXPORTS_W Vec2d estimateRowAlignment(InputArray events, Size sensorSize, int minDisparity = 0, int maxDisparity = 40,
                                        CV_OUT double* score = 0);

/** @brief How far the right camera's clock is off the left one's, measured from a stereo pair's events: the
offset [us] to add to the right camera's timestamps (EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US, mergeStereoEvents())
so that both cameras stamp an edge at the same moment. Zero for a pair that ticks together.

Two cameras whose clocks disagree by tau (a software synchronisation, different readout latencies) see an edge
that moves along the rows at u px/s where it was tau earlier or later: matched at the same timestamp, its
disparity comes out u tau too large. An edge's speed along the row is u = |f|^2 / f_x for its normal flow f,
so an offset shows as disparities that grow with u on one surface. The events are matched (StereoEventMatcher,
STEREO_COUPLED, defaults, each event's own estimate: no averaging); for each camera, 8 x 8 px block and ten
seconds, the confident estimates are cut into surfaces where their disparities are more than a pixel apart,
and the disparity is regressed on u within them, each camera's events on their own: a clock moves both
cameras' matches the same way, while the matching itself (which looks a little ahead in the other camera)
moves them opposite ways, so the mean of the two slopes is the clock's. The flows come from each camera's
own events (LifetimeEstimator, defaults), so that they are the same whatever the restamping; u is taken as
the median of the block's estimates over 50 ms, as one plane fit's flow is too noisy. A second regressor,
f_y / f_x, takes up a residual row offset, which moves oblique edges along the row; a third, |u|, what the
matching does with faster edges whichever way they move, where a clock moves edges that travel left and
right in opposite directions. The right camera is restamped by the offset that makes the slope zero (secant
steps, within +-20 ms), and the events are matched again, up to five matchings in all, and once more 2 ms
away when the offsets tried lie closer together, so that how the slope follows the restamping (the gain) is
measured. The estimate is where the line through every slope measured crosses zero.

An offset can only be told from a disparity where the speed along the rows varies on one surface: objects
that speed up, slow down or turn, edges of several directions on an object moving with a vertical component,
rotation. Where one object moves at one speed along the rows, an offset shifts every disparity by one amount,
exactly as a different depth would, and nothing in the events tells them apart: @p uncertaintyUs is then large
and the offset should not be applied. The estimate is refused (0, infinite uncertainty) where the slope hardly
follows the restamping or not measurably (a gain below 0.1, or within three of its standard errors of none),
where it would lie at the +-20 ms end, and where it follows only weakly (less than half as much as a clock
would) and the matches at the estimate are less clear-cut (mean confidence) than with the clocks as given.
@param events stereo events (camera column), time-ordered and rectified, any form getEventMat() accepts; a few
seconds of a recording with motion is enough (the events are matched up to six times). Events outside the
sensor are ignored.
@param sensorSize the sensor size.
@param minDisparity, maxDisparity the disparity range searched.
@param uncertaintyUs optional output: the standard error of the offset [us] (clustered by block and ten
seconds). Above a few hundred us the events hardly tell an offset from a disparity.
@return the offset [us]; 0 when nothing could be compared or the estimate is refused.
*/
CV_EXPORTS_W double estimateClockOffset(InputArray events, Size sensorSize, int minDisparity = 0, int maxDisparity = 40,
                                        CV_OUT double* uncertaintyUs = 0);

/** @brief The disparity at which a stereo pair's events line up best, measured from its events: the shift of
most of the scene, and a check that the cameras are the right way round.

The events are cut into slices of @p sliceUs; in each, a camera's image marks the pixels that fired (a hot
pixel counts once per slice, as any other), spread over three rows so that a pair a pixel off rectification
still lines up. The left slices are compared with the right ones moved by every disparity d in
[-maxDisparity, maxDisparity] (left pixel x against right pixel x - d, over the columns both cover) by
normalised correlation over all slices at once. A normal pair peaks at a positive d (a point appears further
left in the right camera); a peak at a negative d means the right camera sees the scene to the right of the
left one: the cameras are exchanged (or the pair is not left-right). The work grows with the events and the
disparity range, not with the sensor's area.
@param events stereo events (camera column), time-ordered, any form getEventMat() accepts; events outside the
sensor or of other cameras are ignored.
@param sensorSize the sensor size.
@param maxDisparity largest |d| tried, 1 .. sensorSize.width / 2.
@param correlation optional output: 1 x (2 maxDisparity + 1) CV_64F, the correlation at d = -maxDisparity ..
maxDisparity (0 where a camera fired nowhere in the compared columns).
@param score optional output: the correlation at the returned disparity (-1..1; 0 when the events do not
overlap in time or space). Below about 0.1 the events do not say much.
@param sliceUs the slice length [us]: short enough that a moving edge is still thin in it.
@return the disparity of the highest correlation (0 when there is nothing to compare).
*/
CV_EXPORTS_W int estimateDominantDisparity(InputArray events, Size sensorSize, int maxDisparity = 40,
                                           OutputArray correlation = noArray(), CV_OUT double* score = 0,
                                           double sliceUs = 20000);

//! @}

}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_STEREO_CALIBRATION_HPP
