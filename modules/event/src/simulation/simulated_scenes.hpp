// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_SIMULATION_SIMULATED_SCENES_HPP
#define OPENCV_EVENT_SRC_SIMULATION_SIMULATED_SCENES_HPP

#include "opencv2/event/simulator.hpp"

#include <vector>

namespace cv {
namespace event {
namespace detail {

/** The planes of a named scene; sets the settings the scene brings (a real sensor's noise, a weaker right
    camera, ...) in @p settings. Raises cv::Error::StsBadArg naming the scenes for an unknown name. */
std::vector<SimulatedPlane> simulatedScene(const String& name, int sensorModel, SimulatorSettings& settings);

/** The names simulatedScene() takes. */
std::vector<String> simulatedSceneNames();

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif
