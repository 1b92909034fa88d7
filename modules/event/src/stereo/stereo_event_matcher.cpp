// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// StereoEventMatcher's public face: construction, process() over a packet (event by event, or by look-ahead and
// row bands in operation_schedule.cpp), processEvent(), reset(), calibration and the active estimates' maps.
// The method is described in the public header.

#include "precomp.hpp"
#include "common/ascii.hpp"
#include "common/optional_output.hpp"
#include "stereo/disparity_rendering.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

StereoEventMatcherImpl::StereoEventMatcherImpl(Size size, int mode)
{
    estimators_[0] = createRowBandLifetimeEstimator(size);
    estimators_[1] = createRowBandLifetimeEstimator(size);
    // The crossings as the matching's own settings were chosen on (activeDistance, the lifetime copies and their
    // confidences): refitted crossings lengthen the lifetimes, and with them every event's time in the
    // descriptors. getLifetimeEstimator() turns them on.
    for (const Ptr<RowBandLifetimeEstimator>& estimator : estimators_)
        estimator->setRefitCrossingLifetimes(0);
    params_.setMode(mode);
    setSensorSize(size);
}

void StereoEventMatcherImpl::process(InputArray events, OutputArray disparity, OutputArray lifetime, OutputArray flags, OutputArray depth,
             OutputArray flow, OutputArray confidence)
{
    Mat_<Event> ev = getEventMat(events);
    const int n = (int)ev.total();
    disparity.create(n, 1, CV_32F);
    Mat_<float> disp = disparity.getMat();
    Mat_<float> lt = optionalOutput<float>(lifetime, n), dep = optionalOutput<float>(depth, n);
    Mat_<float> fl = optionalOutput<float>(flow, n, 2), conf = optionalOutput<float>(confidence, n);
    Mat_<int> fla = optionalOutput<int>(flags, n);
    auto store = [&](int i, const StereoEventEstimate& s) {
        disp(i) = s.disparity;
        if (!conf.empty())
            conf(i) = s.confidence;
        if (!lt.empty())
            lt(i) = s.lifetime;
        if (!fla.empty())
            fla(i) = s.flags;
        if (!dep.empty())
            dep(i) = s.depth;
        if (!fl.empty())
        {
            fl(i, 0) = s.flow[0];
            fl(i, 1) = s.flow[1];
        }
    };
    if (params_.lookAhead > 0 || (params_.numThreads > 1 && n >= MIN_EVENTS_FOR_BANDS))
    {
        processOperations(ev, store);
        return;
    }
    StereoEventEstimate s;
    for (int i = 0; i < n; i++)
    {
        processEvent(ev(i), s);
        store(i, s);
    }
}

void StereoEventMatcherImpl::processEvent(const Event& e, StereoEventEstimate& est)
{
    est = StereoEventEstimate();
    const Point r = admit(e);
    est.rectified = r;
    if (r.x < 0)
    {
        est.flags = STEREO_OUTSIDE;
        return;
    }
    maps_[0].expireUntil(e.t);
    maps_[1].expireUntil(e.t);
    processAdmitted(e, r, coldStartEnd_, false, scratch_, est);
    estimators_[e.camera]->addStatusCounts(scratch_.lifetimes[e.camera]);
}

void StereoEventMatcherImpl::reset()
{
    const int margin = std::max(params_.aggregationWindow / 2, params_.descriptorWindow / 2);
    for (int c = 0; c < 2; c++)
    {
        maps_[c].configure(params_.sensorSize, params_.descriptorWindow, params_.maxVectorLength, margin);
        estimators_[c]->reset();
        estimates_[c].reset(params_.sensorSize);
        confidentEstimates_[c].reset(params_.sensorSize);
        fillSurfaces_[c].reset(params_.sensorSize);
        pendingEvents_[c].assign((size_t)params_.sensorSize.area() * 2, 0);
    }
    input_.restart();
    sizeScratch(scratch_);
    scratch_.lifetimeTicks = 0;
    for (MatchScratch& s : bandScratch_)
    {
        sizeScratch(s);
        s.lifetimeTicks = 0;
    }
}

double StereoEventMatcherImpl::getLifetimeSeconds() const
{
    int64 ticks = scratch_.lifetimeTicks;
    for (const MatchScratch& s : bandScratch_)
        ticks += s.lifetimeTicks;
    return (double)ticks / getTickFrequency();
}

void StereoEventMatcherImpl::sizeScratch(MatchScratch& s) const
{
    s.matchedValues.resize((size_t)params_.lifetimeWindow * params_.lifetimeWindow + WINDOW_MEDIAN_PAD);
    s.matchedPositions.resize((size_t)params_.lifetimeWindow * params_.lifetimeWindow + WINDOW_MEDIAN_PAD);
    s.matchedKeys.resize((size_t)params_.lifetimeWindow * params_.lifetimeWindow);
    const size_t range = (size_t)(params_.maxDisparity - params_.minDisparity + 1);
    s.candidates.resize(range);
    s.offsets.resize(range);
    s.cost.resize(range);
    s.seenScore.resize(range);
    s.recencyShare.resize(range);
    s.columnTimeGap.resize((size_t)params_.sensorSize.width);
    s.columnMass.resize((size_t)params_.aggregationWindow);
    s.unseenMass.resize((size_t)params_.aggregationWindow + 1);
}

void StereoEventMatcherImpl::setCalibration(const StereoCalibration& calibration)
{
    input_.setCalibration(calibration);
    reset();
}

Ptr<LifetimeEstimator> StereoEventMatcherImpl::getLifetimeEstimator(int camera) const
{
    CV_CheckGE(camera, 0, "StereoEventMatcher::getLifetimeEstimator: camera is CAMERA_LEFT or CAMERA_RIGHT");
    CV_CheckLE(camera, 1, "StereoEventMatcher::getLifetimeEstimator: camera is CAMERA_LEFT or CAMERA_RIGHT");
    return estimators_[camera];
}

void StereoEventMatcherImpl::getActiveDisparity(double t, OutputArray disparity, int camera) const
{
    activeDisparityMap(estimates_, params_.sensorSize, t, camera,
                       "StereoEventMatcher::getActiveDisparity", disparity);
}

void StereoEventMatcherImpl::renderDisparity(double t, OutputArray image, int camera, bool colourBar) const
{
    Mat_<float> disparity;
    activeDisparityMap(estimates_, params_.sensorSize, t, camera,
                       "StereoEventMatcher::renderDisparity", disparity);
    renderDisparityMap(disparity, params_.minDisparity, params_.maxDisparity, colourBar, image);
}

Vec2i StereoEventMatcherImpl::getDisparityDisplayRange(double t, int camera) const
{
    return activeDisparityDisplayRange(estimates_, params_.sensorSize, t, camera, params_.minDisparity,
                                       params_.maxDisparity, "StereoEventMatcher::getDisparityDisplayRange");
}

}  // namespace detail

Ptr<StereoEventMatcher> StereoEventMatcher::create(Size sensorSize, int mode)
{
    return makePtr<detail::StereoEventMatcherImpl>(sensorSize, mode);
}

String getStereoModeName(int mode)
{
    switch (mode)
    {
    case STEREO_COUPLED: return "coupled";
    case STEREO_DECOUPLED: return "decoupled";
    case STEREO_FIXED_INTERVAL: return "fixed";
    default: CV_Error_(Error::StsBadArg, ("getStereoModeName: mode %d is not a StereoMatchMode", mode));
    }
}

int findStereoMode(const String& name)
{
    const std::string n = detail::toLowerAscii(name);
    for (int m = STEREO_COUPLED; m <= STEREO_FIXED_INTERVAL; m++)
        if (n == getStereoModeName(m))
            return m;
    return -1;
}

}  // namespace event
}  // namespace cv
