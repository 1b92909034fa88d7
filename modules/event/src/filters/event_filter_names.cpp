// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"

namespace cv {
namespace event {

std::vector<String> getEventFilterNames()
{
    return std::vector<String>{ "background_activity", "trail", "refractory", "hot_pixels", "anti_flicker" };
}

Ptr<EventFilter> createEventFilter(const String& name, Size sensorSize)
{
    if (name == "background_activity")
        return BackgroundActivityFilter::create(sensorSize);
    if (name == "trail")
        return TrailFilter::create(sensorSize);
    if (name == "refractory")
        return RefractoryFilter::create(sensorSize);
    if (name == "hot_pixels")
    {
        Ptr<HotPixelFilter> f = HotPixelFilter::create(sensorSize);
        f->setLearningTime(1e6);
        return f;
    }
    if (name == "anti_flicker")
        return AntiFlickerFilter::create(sensorSize);
    String known;
    for (const String& n : getEventFilterNames())
        known += (known.empty() ? "" : ", ") + n;
    CV_Error_(Error::StsBadArg, ("createEventFilter: unknown filter \"%s\" (%s)", name.c_str(), known.c_str()));
}

}  // namespace event
}  // namespace cv
