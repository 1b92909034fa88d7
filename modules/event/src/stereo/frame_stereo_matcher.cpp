// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// FrameStereoMatcher: the frame baseline's public face over FrameSgbmMatcher, with StereoEventMatcher's input
// checks, rectification, outputs and maps of shown estimates.

#include "precomp.hpp"
#include "common/optional_output.hpp"
#include "stereo/active_estimate_map.hpp"
#include "stereo/disparity_rendering.hpp"
#include "stereo/frame_sgbm_matcher.hpp"
#include "stereo/stereo_event_input.hpp"
#include "stereo/stereo_matcher_params.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

struct FrameStereoParams
{
    Size sensorSize;
    int minDisparity = 0, maxDisparity = 40;
    int64 frameWindow = 33000;

    void setSensorSize(Size s)
    {
        checkSensorSize(s, "FrameStereoMatcher");
        sensorSize = s;
    }
    void setDisparityRange(int lo, int hi)
    {
        checkDisparityRange(lo, hi, "FrameStereoMatcher");
        minDisparity = lo;
        maxDisparity = hi;
    }
    void setFrameWindow(double us) { frameWindow = checkedDuration(us, "frame window", "FrameStereoMatcher"); }
};

}  // namespace

class FrameStereoMatcherImpl CV_FINAL : public FrameStereoMatcher
{
public:
    explicit FrameStereoMatcherImpl(Size size)
    {
        setSensorSize(size);
    }

    void process(InputArray events, OutputArray disparity, OutputArray flags, OutputArray depth) CV_OVERRIDE;
    void renderDisparity(double t, OutputArray image, int camera, bool colourBar) const CV_OVERRIDE
    {
        Mat_<float> disparity;
        activeDisparityMap(estimates_, params_.sensorSize, t, camera, "FrameStereoMatcher::renderDisparity", disparity);
        renderDisparityMap(disparity, params_.minDisparity, params_.maxDisparity, colourBar, image);
    }
    Vec2i getDisparityDisplayRange(double t, int camera) const CV_OVERRIDE
    {
        return activeDisparityDisplayRange(estimates_, params_.sensorSize, t, camera, params_.minDisparity,
                                           params_.maxDisparity, "FrameStereoMatcher::getDisparityDisplayRange");
    }
    void getActiveDisparity(double t, OutputArray disparity, int camera) const CV_OVERRIDE
    {
        activeDisparityMap(estimates_, params_.sensorSize, t, camera, "FrameStereoMatcher::getActiveDisparity",
                           disparity);
    }
    void reset() CV_OVERRIDE
    {
        frames_.configure(params_.sensorSize, params_.minDisparity, params_.maxDisparity, params_.frameWindow);
        for (ActiveEstimateMap& e : estimates_)
            e.reset(params_.sensorSize);
        input_.restart();
    }

    void setCalibration(const StereoCalibration& calibration) CV_OVERRIDE
    {
        input_.setCalibration(calibration);
        reset();
    }
    const StereoCalibration& getCalibration() const CV_OVERRIDE { return input_.calibration(); }
    void loadCalibration(const String& path) CV_OVERRIDE { setCalibration(readStereoCalibration(path)); }

    Size getSensorSize() const CV_OVERRIDE { return params_.sensorSize; }
    void setSensorSize(Size size) CV_OVERRIDE
    {
        params_.setSensorSize(size);
        input_.setSensorSize(size);
        reset();
    }
    int getMinDisparity() const CV_OVERRIDE { return params_.minDisparity; }
    void setMinDisparity(int d) CV_OVERRIDE
    {
        params_.setDisparityRange(d, params_.maxDisparity);
        reset();
    }
    int getMaxDisparity() const CV_OVERRIDE { return params_.maxDisparity; }
    void setMaxDisparity(int d) CV_OVERRIDE
    {
        params_.setDisparityRange(params_.minDisparity, d);
        reset();
    }
    double getFrameWindow() const CV_OVERRIDE { return (double)params_.frameWindow; }
    void setFrameWindow(double us) CV_OVERRIDE
    {
        params_.setFrameWindow(us);
        reset();
    }

    void write(FileStorage& fs) const CV_OVERRIDE;
    void read(const FileNode& fn) CV_OVERRIDE;
    String getDefaultName() const CV_OVERRIDE { return "FrameStereoMatcher"; }

private:
    FrameStereoParams params_;
    StereoEventInput input_{ "FrameStereoMatcher" };
    FrameSgbmMatcher frames_;
    ActiveEstimateMap estimates_[2];  // each event's disparity, shown for one frame window
    std::vector<Point> pixels_;
    std::vector<int64> times_;
    std::vector<uchar> cameras_;
    std::vector<float> disparity_;
};

void FrameStereoMatcherImpl::process(InputArray events, OutputArray disparity, OutputArray flags, OutputArray depth)
{
    const Mat_<Event> ev = getEventMat(events);
    const int n = (int)ev.total();
    pixels_.resize((size_t)n);
    times_.resize((size_t)n);
    cameras_.resize((size_t)n);
    for (int i = 0; i < n; i++)
    {
        const Point r = input_.admit(ev(i));
        pixels_[(size_t)i] = r;
        times_[(size_t)i] = ev(i).t;
        cameras_[(size_t)i] = (uchar)(r.x < 0 ? (int)FrameSgbmMatcher::NOT_IN_IMAGE : ev(i).camera);
    }
    frames_.process(pixels_, times_, cameras_, disparity_);
    disparity.create(n, 1, CV_32F);
    Mat_<float> disp = disparity.getMat(), dep = optionalOutput<float>(depth, n);
    Mat_<int> fla = optionalOutput<int>(flags, n);
    for (int i = 0; i < n; i++)
    {
        const size_t k = (size_t)i;
        const bool inside = cameras_[k] != FrameSgbmMatcher::NOT_IN_IMAGE;
        const float d = inside ? disparity_[k] : (float)StereoEventMatcher::NO_DISPARITY;
        if (inside)
            estimates_[cameras_[k]].remember(pixels_[k], times_[k], params_.frameWindow, d);
        disp(i) = d;
        if (!fla.empty())
            fla(i) = !inside ? STEREO_OUTSIDE : d >= 0 ? STEREO_HAS_DISPARITY : 0;
        if (!dep.empty())
            dep(i) = input_.depthOf(d);
    }
}

void FrameStereoMatcherImpl::write(FileStorage& fs) const
{
    writeFormat(fs);
    fs << "sensorWidth" << params_.sensorSize.width << "sensorHeight" << params_.sensorSize.height << "minDisparity"
       << params_.minDisparity << "maxDisparity" << params_.maxDisparity << "frameWindow" << (double)params_.frameWindow;
    if (!input_.calibration().empty())
    {
        fs << "calibration" << "{";
        input_.calibration().write(fs);
        fs << "}";
    }
}

void FrameStereoMatcherImpl::read(const FileNode& fn)
{
    auto num = [&](const char* key, double def) { return fn[key].empty() ? def : (double)fn[key]; };
    FrameStereoParams p = params_;
    p.setSensorSize(Size((int)num("sensorWidth", p.sensorSize.width), (int)num("sensorHeight", p.sensorSize.height)));
    p.setDisparityRange((int)num("minDisparity", p.minDisparity), (int)num("maxDisparity", p.maxDisparity));
    p.setFrameWindow(num("frameWindow", (double)p.frameWindow));
    StereoCalibration c;
    const bool hasCalibration = !fn["calibration"].empty();
    if (hasCalibration)
    {
        c.read(fn["calibration"], "FrameStereoMatcher calibration");
        input_.checkCalibration(c, p.sensorSize);
    }
    if (p.sensorSize != params_.sensorSize)
        setSensorSize(p.sensorSize);
    params_ = p;
    if (hasCalibration)
        setCalibration(c);
    reset();
}

}  // namespace detail

Ptr<FrameStereoMatcher> FrameStereoMatcher::create(Size sensorSize)
{
    return makePtr<detail::FrameStereoMatcherImpl>(sensorSize);
}

}  // namespace event
}  // namespace cv
