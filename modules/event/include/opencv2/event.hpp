// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_HPP
#define OPENCV_EVENT_HPP

#include "opencv2/event/types.hpp"
#include "opencv2/event/event_surface.hpp"
#include "opencv2/event/event_statistics.hpp"
#include "opencv2/event/event_filter.hpp"
#include "opencv2/event/event_trigger.hpp"
#include "opencv2/event/event_capture.hpp"
#include "opencv2/event/event_writer.hpp"
#include "opencv2/event/simulator.hpp"
#include "opencv2/event/lifetime_estimator.hpp"
#include "opencv2/event/lifetime_arrival_check.hpp"
#include "opencv2/event/stereo_calibration.hpp"
#include "opencv2/event/stereo_pair_check.hpp"
#include "opencv2/event/stereo_event_matcher.hpp"
#include "opencv2/event/frame_stereo_matcher.hpp"
#include "opencv2/event/stereo_evaluation.hpp"

/** @defgroup event Event cameras: lifetime and stereo disparity

Processing for dynamic vision sensors (DVS / DAVIS / Prophesee), which report per-pixel brightness changes
as a stream of events (t, x, y, polarity) instead of frames. The module estimates, per event, its
**lifetime** (how long the edge that caused it stays at that pixel, Mueggler et al. @cite Mueggler2015) and,
for a stereo pair, its **disparity / depth** by the coupled lifetime-and-matching method of Hadviger et al.
@cite Hadviger2019 with the descriptor of Zou et al. @cite Zou2017.

Events travel as packets: an N x 1 Mat of type event::EVENT_MAT_TYPE or a `std::vector<event::Event>`,
through the usual InputArray / OutputArray (see event::Event for the layout and why).

Where to start: event::EventCapture reads a recording or a camera, event::StereoEventMatcher gives each event
its disparity, depth and lifetime, event::LifetimeEstimator does the lifetimes of one camera. The manual
(doc/ in the repository: stereo.md, lifetime.md, reading_recordings.md, live_davis.md, filters.md,
simulator.md) says what to do and how; doc/benchmarks.md holds the figures with their commands.

@{
    @defgroup event_types Event records, packets and sensor geometry
    @defgroup event_surface Surface of active events, time surfaces and event frames
    @defgroup event_statistics Statistics of an event stream
    @defgroup event_filter Noise filters: background activity, trails, refractory period, hot pixels, flicker
    @defgroup event_io Reading recordings and cameras
    @defgroup event_simulator Stereo event simulator with ground truth
    @defgroup event_lifetime Event lifetime and normal flow
    @defgroup event_stereo Stereo calibration, per-event disparity and depth
@}
*/

#endif  // OPENCV_EVENT_HPP
