// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// StereoEventMatcher's side of its parameters (StereoMatcherParams validates them): what a change resets, the
// FileStorage form with the nested lifetime estimator and calibration, and the row reach they imply.

#include "precomp.hpp"
#include "stereo/stereo_event_matcher_impl.hpp"

namespace cv {
namespace event {
namespace detail {

void StereoEventMatcherImpl::setMode(int mode)
{
    params_.setMode(mode);
    reset();
}

void StereoEventMatcherImpl::setSensorSize(Size s)
{
    params_.setSensorSize(s);
    for (const Ptr<RowBandLifetimeEstimator>& est : estimators_)
        est->setSensorSize(s);
    input_.setSensorSize(s);
    reset();
}

void StereoEventMatcherImpl::setDisparityRange(int lo, int hi)
{
    params_.setDisparityRange(lo, hi);
    reset();
}

void StereoEventMatcherImpl::write(FileStorage& fs) const
{
    writeFormat(fs);
    params_.write(fs);
    fs << "lifetimeEstimator" << "{";
    estimators_[0]->write(fs);
    fs << "}";
    if (!input_.calibration().empty())
    {
        fs << "calibration" << "{";
        input_.calibration().write(fs);
        fs << "}";
    }
}

void StereoEventMatcherImpl::read(const FileNode& fn)
{
    StereoMatcherParams p = params_;
    p.read(fn);
    if (p.sensorSize != params_.sensorSize)
        setSensorSize(p.sensorSize);
    params_ = p;
    if (!fn["lifetimeEstimator"].empty())
        for (const Ptr<RowBandLifetimeEstimator>& est : estimators_)
            est->read(fn["lifetimeEstimator"]);
    if (!fn["calibration"].empty())
    {
        StereoCalibration c;
        c.read(fn["calibration"], "StereoEventMatcher calibration");
        setCalibration(c);
    }
    reset();
}

int StereoEventMatcherImpl::eventRowReach() const
{
    return std::max({ params_.aggregationWindow / 2, params_.costWindow / 2, params_.lifetimeWindow / 2, 1,
                      (int)PRIOR_RADIUS, params_.fillRadius, expiryRowReach(), estimators_[0]->rowReach(), estimators_[1]->rowReach() });
}

}  // namespace detail
}  // namespace event
}  // namespace cv
