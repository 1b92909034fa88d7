// Stereo recording overview: reads a stereo event recording, renders left | right time surfaces every few
// windows, and writes a summary (events per camera, rates, and the dominant disparity: the disparity at which
// most windows' events line up, estimateDominantDisparity(), with a warning when the cameras look exchanged).
//
//   event_stereo_overview [--input=FILE | --left=FILE --right=FILE] [--sensor=128x128]
//                         [--left-camera-value=1] [--one-based] [--window-ms=33] [--max-disparity=40] [--output=DIR]
//
// Without input it simulates the built-in default recording (StereoEventSimulator scene --scene, default
// "two_planes": a textured plane sliding over a textured background, disparities 20 and 10 px), writes it
// with its ground truth into the output folder (<scene>.aedat4 + .gt.csv) and reads that.

#include <opencv2/event.hpp>
#include <opencv2/core/utils/filesystem.hpp>  // after a core header: it needs CV_EXPORTS
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "command_line.hpp"
#include "sample_pictures.hpp"
#include "sample_progress.hpp"
#include "sample_stereo_pair.hpp"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

using namespace cv;
using namespace cv::event;

namespace {

struct Options
{
    std::string input, left, right, output, scene;
    double simulateMs = 0, windowMs = 0;
    Size sensor;
    int leftCameraValue = 0, maxDisparity = 0;
    bool oneBased = false;
};

const char* const keys =
    "{help h            | false      | print this message}"
    "{input             |            | a stereo recording (one file holding both cameras)}"
    "{left              |            | the left camera's recording (with --right)}"
    "{right             |            | the right camera's recording (with --left)}"
    "{sensor            |            | sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none}"
    "{left-camera-value | 0          | the camera column's value that means left, in text recordings}"
    "{one-based         | false      | text recordings count pixels from 1}"
    "{window-ms         | 33         | window of one picture [ms]}"
    "{max-disparity     | 40         | largest disparity searched by the correlation, either way [px]}"
    "{output            | output     | output folder}"
    "{scene             | two_planes | simulated scene when no input is given: plane, two_planes, moving_line, cluttered}"
    "{simulate-ms       | 1000       | length of the simulated scene [ms]}";

bool parse(int argc, char** argv, Options& o)
{
    ProgramCommandLine cmd(argc, argv, keys,
                          "Overview of a stereo recording: time surfaces, event counts and the dominant disparity.");
    if (cmd.helpShown())
        return false;
    o.input = cmd.get<std::string>("input");
    o.left = cmd.get<std::string>("left");
    o.right = cmd.get<std::string>("right");
    if (cmd.has("sensor"))
        o.sensor = parseSensorSize(cmd.get<std::string>("sensor"));
    o.leftCameraValue = cmd.get<int>("left-camera-value");
    o.oneBased = cmd.has("one-based");
    o.windowMs = cmd.get<double>("window-ms");
    o.maxDisparity = cmd.get<int>("max-disparity");
    o.output = cmd.get<std::string>("output");
    o.scene = cmd.get<std::string>("scene");
    o.simulateMs = cmd.get<double>("simulate-ms");
    if ((o.left.empty()) != (o.right.empty()))
        throw std::runtime_error("--left and --right go together");
    return true;
}

// Colour picture of a time surface: recent events bright, ON red, OFF blue.
Mat renderSurface(const EventSurface& s, int64 t, double tau)
{
    Mat on, off;
    s.renderTimeSurface(t, tau, on, CV_8U, POLARITY_ON);
    s.renderTimeSurface(t, tau, off, CV_8U, POLARITY_OFF);
    Mat zero = Mat::zeros(on.size(), CV_8U), bgr;
    merge(std::vector<Mat>{ off, zero, on }, bgr);
    return bgr;
}

}  // namespace

int main(int argc, char** argv)
{
    Options opt;
    try
    {
        if (!parse(argc, argv, opt))
            return 0;
        if (!utils::fs::createDirectories(opt.output))
            throw std::runtime_error(opt.output + ": cannot create the output folder");
        if (opt.input.empty() && opt.left.empty())
        {
            opt.input = opt.output + "/" + opt.scene + ".aedat4";
            std::cerr << "no input given: simulating " << opt.simulateMs << " ms of scene \"" << opt.scene << "\" into "
                      << opt.input << " (+ .gt.csv)\n";
            writeSimulatedRecording(StereoEventSimulator::create(opt.scene), opt.input, opt.simulateMs * 1000);
        }

        EventCapture cap;
        cap.set(EVENT_CAP_PROP_TEXT_LEFT_CAMERA_VALUE, opt.leftCameraValue);
        cap.set(EVENT_CAP_PROP_TEXT_ONE_BASED, opt.oneBased);
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, opt.sensor.width);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, opt.sensor.height);
        cap.set(EVENT_CAP_PROP_WINDOW_US, opt.windowMs * 1000);
        if (!opt.left.empty())
            cap.openStereo(opt.left, opt.right);
        else
            cap.open(opt.input);
        if (cap.get(EVENT_CAP_PROP_STEREO) == 0)
            throw std::runtime_error(cap.getSource() + ": not a stereo recording (no camera column)");
        Size size = cap.getSensorSize();
        if (size.empty())
            throw sensorSizeMissing(cap.getSource());

        const int reach = std::max(1, std::min(opt.maxDisparity, size.width / 2));
        Ptr<EventSurface> surface[2] = { EventSurface::create(size), EventSurface::create(size) };
        std::map<int, int> disparityVotes;
        int64 counts[2][2] = { { 0, 0 }, { 0, 0 } };
        int64 windows = 0, picturesWritten = 0;
        bool touchesZero = false;  // a delivered event in column or row 0 (outsideEventsAdvice())
        SampleProgress progress;
        const int pictureEvery = std::max(1, (int)std::lround(500 / opt.windowMs));  // about 2 per second
        const int zoom = samplePictureZoom(size);
        const double first = cap.get(EVENT_CAP_PROP_FIRST_TIMESTAMP_US);
        std::vector<Event> packet, side[2];
        const int64 t0 = getTickCount();

        while (cap.read(packet))
        {
            side[0].clear();
            side[1].clear();
            touchesZero = touchesZero || touchesColumnOrRowZero(packet);
            for (const Event& e : packet)
            {
                side[e.camera].push_back(e);
                counts[e.camera][e.p]++;
            }
            for (int c = 0; c < 2; c++)
                surface[c]->update(side[c]);
            if (side[0].size() > 50 && side[1].size() > 50)
            {
                // Both ways: a pair given the wrong way round lines up at a negative disparity.
                double score = 0;
                const int d = estimateDominantDisparity(packet, size, reach, noArray(), &score);
                if (score >= kSampleMinLineUpScore)
                    disparityVotes[d]++;
            }
            const int64 now = (int64)cap.get(EVENT_CAP_PROP_POS_US);
            if (windows % pictureEvery == 0 && !packet.empty())
            {
                Mat row;
                hconcat(renderSurface(*surface[0], now, opt.windowMs * 1000), renderSurface(*surface[1], now, opt.windowMs * 1000), row);
                char name[64];
                std::snprintf(name, sizeof(name), "/surfaces_%05lld.png", (long long)picturesWritten++);
                imwrite(opt.output + name, sampleEnlarge(row, zoom));
            }
            windows++;
            progress.update(cap.get(EVENT_CAP_PROP_PROGRESS), format("%s: %.2f s, %.0f events", cap.getSource().c_str(),
                                                                     (now - first) / 1e6, cap.get(EVENT_CAP_PROP_EVENTS_DELIVERED)));
        }
        const double seconds = (getTickCount() - t0) / getTickFrequency();
        const double delivered = cap.get(EVENT_CAP_PROP_EVENTS_DELIVERED);
        const double span = cap.get(EVENT_CAP_PROP_POS_US) - first;
        progress.finish(cap.get(EVENT_CAP_PROP_PROGRESS), format("%s: %.0f events", cap.getSource().c_str(), delivered));

        // The disparity most windows' events line up at and the runner-up: a scene at two depths shows both.
        int dominant = 0, votes = 0, next = 0, nextVotes = 0, totalVotes = 0;
        for (const auto& kv : disparityVotes)
        {
            totalVotes += kv.second;
            if (kv.second > votes)
            {
                next = dominant;
                nextVotes = votes;
                votes = kv.second;
                dominant = kv.first;
            }
            else if (kv.second > nextVotes)
            {
                next = kv.first;
                nextVotes = kv.second;
            }
        }
        std::string lineUp = totalVotes ? cv::format("%d px (%d of %d windows", dominant, votes, totalVotes)
                                        : std::string("not estimated (no window whose events line up)");
        if (totalVotes)
            lineUp += nextVotes ? cv::format("; next %d px, %d)", next, nextVotes) : std::string(")");
        if (totalVotes && dominant < 0)
        {
            const std::string advice = sampleCameraSwapAdvice(!opt.left.empty(), cap.getBackendName() == "TEXT",
                                                              opt.leftCameraValue);
            lineUp += "; the right camera sees the scene to the right of the left one: the cameras look exchanged; "
                      + advice;
            std::cerr << "event_stereo_overview: warning: the events line up at " << dominant
                      << " px: the cameras look exchanged; " << advice << "\n";
        }
        const int64 outside = (int64)cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE);
        if (outside > 0)
            std::cerr << "event_stereo_overview: warning: "
                      << outsideEventsWarning(outside, size.width, size.height, cap.getBackendName() == "TEXT",
                                              opt.oneBased, touchesZero) << "\n";
        std::ofstream summary(opt.output + "/summary.md");
        std::ostringstream text;
        text << "# Stereo recording overview\n\n"
             << "| | |\n|---|---|\n"
             << "| source | " << cap.getSource() << " (" << cap.getBackendName() << ") |\n"
             << "| sensor | " << size.width << " x " << size.height << " |\n"
             << "| events | " << (int64)delivered << " (left " << counts[0][0] + counts[0][1] << ": "
             << counts[0][1] << " ON / " << counts[0][0] << " OFF; right " << counts[1][0] + counts[1][1] << ": "
             << counts[1][1] << " ON / " << counts[1][0] << " OFF) |\n"
             << "| duration | " << span / 1e6 << " s (" << windows << " windows of " << opt.windowMs << " ms) |\n"
             << "| event rate | " << delivered / std::max(1e-9, span / 1e6) / 1e3 << " kev/s |\n"
             << "| rejected outside sensor / time steps back | " << outside << " / "
             << cap.get(EVENT_CAP_PROP_TIME_BACKWARDS) << " |\n"
             << "| dominant disparity (estimateDominantDisparity per window) | " << lineUp << " |\n"
             << "| processing | " << seconds << " s, " << delivered / std::max(1e-9, seconds) / 1e6 << " Mev/s |\n"
             << "| pictures | " << picturesWritten << " x surfaces_NNNNN.png (left | right time surfaces, ON red, OFF blue) |\n";
        summary << text.str();
        std::cout << text.str();
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "event_stereo_overview: " << errorText(e) << "\n";
        return 1;
    }
}
