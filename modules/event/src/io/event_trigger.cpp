// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

namespace cv {
namespace event {

String getTriggerKindName(int kind)
{
    switch (kind)
    {
    case EVENT_TRIGGER_FALLING: return "falling";
    case EVENT_TRIGGER_RISING: return "rising";
    case EVENT_TRIGGER_PULSE: return "pulse";
    case EVENT_TRIGGER_GENERATOR_FALLING: return "generator falling";
    case EVENT_TRIGGER_GENERATOR_RISING: return "generator rising";
    default: CV_Error_(Error::StsOutOfRange, ("%d is not an EventTriggerKind (0..4)", kind));
    }
}

}  // namespace event
}  // namespace cv
