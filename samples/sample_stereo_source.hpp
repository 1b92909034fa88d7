// Where the stereo samples' events come from: a capture (one file of both cameras, a file per camera, a live
// DAVIS pair) or the simulator's scene with its ground truth.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_SOURCE_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_SOURCE_HPP

#include <opencv2/event.hpp>

#include "command_line.hpp"
#include "simulator_settings.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

/** What picks the source and how it is read. No input, no --left/--right and not live: the simulated scene. */
struct StereoSourceOptions
{
    std::string input, left, right, scene;
    std::string sensorSettings;  // --sensor-set: the simulated scene's SimulatorSettings changed by name
    bool live = false, oneBased = false;
    double liveMs = 0, durationMs = 0, frameMs = 0, rightTimeOffsetMs = 0;
    cv::Size sensor;
    int sceneModel = cv::event::SENSOR_DAVIS240;  // the sensor model the scene is simulated on
    int leftCameraValue = 0;

    /** No recording and no live pair: the events come from the simulator. */
    bool simulated() const { return input.empty() && left.empty() && !live; }
};

// Why a recording of this back-end holds one camera, in its own terms.
inline std::string oneCameraReason(const std::string& backend)
{
    if (backend == "TEXT")
        return "no camera column";
    if (backend == "ROSBAG1" || backend == "ROSBAG2")
        return "one event topic";
    if (backend == "AEDAT4")
        return "one event stream";
    if (backend == "HDF5_MVSEC")
        return "one camera's events";
    return "a " + backend + " file holds one camera";
}

// Where events come from: a capture (file, file pair, live pair) or the simulator with ground truth.
class SampleStereoSource
{
public:
    explicit SampleStereoSource(const StereoSourceOptions& o)
    {
        if (o.simulated())
        {
            sim_ = cv::event::StereoEventSimulator::create(o.scene, o.sceneModel);
            if (o.rightTimeOffsetMs != 0 || !o.sensorSettings.empty())
            {
                cv::event::SimulatorSettings s = sim_->getSettings();
                applySimulatorSettings(s, o.sensorSettings);
                // The simulated right camera restamped as a capture would do it.
                s.rightClockOffsetUs += o.rightTimeOffsetMs * 1000;
                sim_ = cv::event::StereoEventSimulator::create(sim_->getPlanes(), s);
            }
            durationUs_ = o.durationMs * 1000;
            windowUs_ = o.frameMs * 1000;
            name_ = "simulated scene \"" + o.scene + "\" (" + std::to_string((int)o.durationMs) + " ms" +
                    (o.sensorSettings.empty() ? std::string() : ", " + o.sensorSettings) + ")";
            return;
        }
        if (!o.sensorSettings.empty())
            throw std::runtime_error("--sensor-set: only for a simulated scene (--scene), not a recording or a live pair");
        cap_.set(cv::event::EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, o.leftCameraValue);
        cap_.set(cv::event::EVENT_CAP_PROP_TEXT_ONE_BASED, o.oneBased);
        cap_.set(cv::event::EVENT_CAP_PROP_RIGHT_TIME_OFFSET_US, o.rightTimeOffsetMs * 1000);
        cap_.set(cv::event::EVENT_CAP_PROP_SENSOR_WIDTH, o.sensor.width);
        cap_.set(cv::event::EVENT_CAP_PROP_SENSOR_HEIGHT, o.sensor.height);
        cap_.set(cv::event::EVENT_CAP_PROP_WINDOW_US, o.frameMs * 1000);
        if (o.live)
        {
            cap_.openStereo("davis:0", "davis:1");
            liveEndUs_ = o.liveMs * 1000;
        }
        else if (!o.left.empty())
            cap_.openStereo(o.left, o.right);
        else
            cap_.open(o.input);
        if (cap_.get(cv::event::EVENT_CAP_PROP_STEREO) == 0)
            throw std::runtime_error(cap_.getSource() + ": not a stereo source (" + oneCameraReason(cap_.getBackendName()) +
                                     "); give each camera's recording with --left and --right");
        name_ = cap_.getSource() + " (" + cap_.getBackendName() + ")";
    }

    /** Also writes the events as read to @p path: a simulated scene at once, whole, with its ground truth
    beside (path.gt.csv; the same scene simulated again from the start gives the same events), a capture's
    events as next() reads them (.aedat4, else text with a camera column). */
    void record(const std::string& path)
    {
        if (sim_)
        {
            cv::event::writeSimulatedRecording(
                cv::event::StereoEventSimulator::create(sim_->getPlanes(), sim_->getSettings()), path, durationUs_);
            return;
        }
        recorder_.set(cv::event::EVENT_WRITER_PROP_STEREO, 1);
        recorder_.open(path, cap_.getSensorSize());
    }

    cv::Size sensorSize() const { return sim_ ? sim_->getSensorSize() : cap_.getSensorSize(); }
    const std::string& name() const { return name_; }
    bool isText() const { return !sim_ && cap_.getBackendName() == "TEXT"; }
    bool hasTruth() const { return !sim_.empty(); }
    const cv::Ptr<cv::event::StereoEventSimulator>& simulator() const { return sim_; }

    bool next(std::vector<cv::event::Event>& events, cv::Mat& truth, double& windowEnd)
    {
        if (sim_)
        {
            if (sim_->getTime() >= durationUs_)
                return false;
            windowEnd = std::min(durationUs_, sim_->getTime() + windowUs_);
            sim_->generate(windowEnd, events, truth);
            return true;
        }
        if (liveEndUs_ > 0 && lastWindowEnd_ >= liveEndUs_)
            return false;
        if (!cap_.read(events))
            return false;
        if (recorder_.isOpened())
            recorder_.write(events);
        windowEnd = lastWindowEnd_ = cap_.get(cv::event::EVENT_CAP_PROP_POS_US);
        touchesZero_ = touchesZero_ || touchesColumnOrRowZero(events);
        return true;
    }

    // Input events the capture did not deliver (outside the sensor) and events that went back in time
    // (delivered with the previous timestamp): both are counted, never silent.
    double rejectedOutside() const { return sim_ ? 0 : cap_.get(cv::event::EVENT_CAP_PROP_REJECTED_OUTSIDE); }
    double timeBackwards() const { return sim_ ? 0 : cap_.get(cv::event::EVENT_CAP_PROP_TIME_BACKWARDS); }
    // Whether a delivered event lay in column or row 0 (a file counted from 1 never has one).
    bool eventsTouchZero() const { return touchesZero_; }

    // 0..1, or -1 when unknown (live).
    double progress() const
    {
        if (sim_)
            return sim_->getTime() / durationUs_;
        return cap_.get(cv::event::EVENT_CAP_PROP_PROGRESS);
    }

private:
    cv::Ptr<cv::event::StereoEventSimulator> sim_;
    cv::event::EventCapture cap_;
    cv::event::EventWriter recorder_;
    double durationUs_ = 0, windowUs_ = 0;
    double liveEndUs_ = 0, lastWindowEnd_ = 0;
    std::string name_;
    bool touchesZero_ = false;
};

#endif  // OPENCV_EVENT_SAMPLES_SAMPLE_STEREO_SOURCE_HPP
