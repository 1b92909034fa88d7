// event_player: plays any supported recording as video, as time surfaces or as event-count frames.
//
//   event_player FILE [--mode=surface|frames] [--window-ms=33] [--tau-ms=30] [--output=DIR] [--video=FILE.avi]
//                     [--show] [--start-ms=T] [--max-frames=N] [--zoom=N] [--sensor=WxH|NAME] [--one-based]
//                     [--filter=NAME [--filter-set=NAME=VALUE,...]]
//
// Frames go to DIR/frame_NNNNN.png (default), to an MJPG video with --video, and/or to a window with --show.
// Stereo recordings are shown left | right. Small sensors are enlarged (a DVS128 four times) so that single
// pixels stay visible. With --filter, only the events a noise filter keeps are shown.
// A progress bar runs on stderr.

#include <opencv2/event.hpp>
#include <opencv2/core/utils/filesystem.hpp>  // after a core header: it needs CV_EXPORTS
#include <opencv2/highgui.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "algorithm_settings.hpp"
#include "command_line.hpp"
#include "sample_pictures.hpp"
#include "sample_progress.hpp"

#include <cstdio>
#include <iostream>

using namespace cv;
using namespace cv::event;

namespace {

struct Options
{
    std::string input, output, video, mode, filter, filterSettings;
    double windowMs = 0, tauMs = 0, startMs = -1;
    int maxFrames = -1, zoom = 0;
    bool show = false, oneBased = false;
    Size sensor;
};

// ON red, OFF blue: recent events bright (time surface) or one level per event (count frame).
Mat render(const EventSurface& s, int64 t, const Options& o)
{
    Mat on, off;
    if (o.mode == "frames")
    {
        Mat c;
        s.renderEventCount(c, POLARITY_ON);
        c.convertTo(on, CV_8U, 64);
        s.renderEventCount(c, POLARITY_OFF);
        c.convertTo(off, CV_8U, 64);
    }
    else
    {
        s.renderTimeSurface(t, o.tauMs * 1000, on, CV_8U, POLARITY_ON);
        s.renderTimeSurface(t, o.tauMs * 1000, off, CV_8U, POLARITY_OFF);
    }
    Mat bgr;
    merge(std::vector<Mat>{ off, Mat::zeros(on.size(), CV_8U), on }, bgr);
    return bgr;
}

const char* const keys =
    "{help h     | false         | print this message}"
    "{@input     |               | the recording}"
    "{mode       | surface       | surface (time surfaces) or frames (event counts)}"
    "{window-ms  | 33            | time per frame [ms]}"
    "{tau-ms     | 30            | decay of the time surface [ms]}"
    "{start-ms   | -1            | first frame at this time of the recording [ms]; -1: from the start}"
    "{max-frames | -1            | stop after this many frames; -1: all}"
    "{zoom       | 0             | enlarge the pictures this many times (nearest pixel); 0: to at least 512 px across}"
    "{output     | player_output | folder for frame_NNNNN.png (not written when --video or --show is given)}"
    "{video      |               | write an MJPG video instead of PNG files}"
    "{show       | false         | show the frames in a window}"
    "{sensor     |               | sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none}"
    "{one-based  | false         | text recordings count pixels from 1}"
    "{filter     |               | show only the events a noise filter keeps: background_activity, trail, refractory, hot_pixels, anti_flicker}"
    "{filter-set |               | filter parameters NAME=VALUE, comma separated (e.g. correlationTime=10000)}";

bool parse(int argc, char** argv, Options& o)
{
    ProgramCommandLine cmd(argc, argv, keys,
                          "Plays an event recording as time surfaces or event-count frames.");
    if (cmd.helpShown())
        return false;
    o.input = cmd.get<std::string>("@input");
    o.mode = cmd.get<std::string>("mode");
    o.windowMs = cmd.get<double>("window-ms");
    o.tauMs = cmd.get<double>("tau-ms");
    o.startMs = cmd.get<double>("start-ms");
    o.maxFrames = cmd.get<int>("max-frames");
    o.zoom = cmd.get<int>("zoom");
    if (o.zoom < 0)
        throw std::runtime_error("--zoom=" + std::to_string(o.zoom) + ": give 1 or more, or 0 for automatic");
    o.output = cmd.get<std::string>("output");
    o.video = cmd.get<std::string>("video");
    o.show = cmd.has("show");
    if (cmd.has("sensor"))
        o.sensor = parseSensorSize(cmd.get<std::string>("sensor"));
    o.oneBased = cmd.has("one-based");
    o.filter = cmd.get<std::string>("filter");
    o.filterSettings = cmd.get<std::string>("filter-set");
    if (o.input.empty())
        throw std::runtime_error("no recording given: event_player FILE [options] (--help lists them)");
    if (o.mode != "surface" && o.mode != "frames")
        throw std::runtime_error("--mode is surface or frames");
    return true;
}

}  // namespace

int main(int argc, char** argv)
{
    Options o;
    try
    {
        if (!parse(argc, argv, o))
            return 0;
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, o.sensor.width);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, o.sensor.height);
        cap.set(EVENT_CAP_PROP_TEXT_ONE_BASED, o.oneBased);
        cap.set(EVENT_CAP_PROP_WINDOW_US, o.windowMs * 1000);
        cap.open(o.input);
        const Size size = cap.getSensorSize();
        if (size.empty())
            throw sensorSizeMissing(o.input);
        if (o.startMs >= 0)
            cap.set(EVENT_CAP_PROP_POS_US, cap.get(EVENT_CAP_PROP_FIRST_TIMESTAMP_US) + o.startMs * 1000);
        const bool stereo = cap.get(EVENT_CAP_PROP_STEREO) != 0;
        const int zoom = o.zoom > 0 ? o.zoom : samplePictureZoom(size);
        const bool writePngs = o.video.empty() && !o.show;
        if (writePngs && !utils::fs::createDirectories(o.output))
            throw std::runtime_error(o.output + ": cannot create the output folder");

        Ptr<EventFilter> filter = createSampleFilter(o.filter, o.filterSettings, size);
        Ptr<EventSurface> surface[2] = { EventSurface::create(size), EventSurface::create(size) };
        VideoWriter video;
        std::vector<Event> packet;
        int64 frames = 0;
        SampleProgress progress;
        bool touchesZero = false;  // for the advice on events outside the sensor
        while ((o.maxFrames < 0 || frames < o.maxFrames) && cap.read(packet))
        {
            touchesZero = touchesZero || touchesColumnOrRowZero(packet);
            surface[0]->clearCounts();
            surface[1]->clearCounts();
            if (filter)
                filter->filter(packet, packet);
            for (const Event& e : packet)
                surface[stereo ? e.camera : 0]->update(e);
            const int64 now = (int64)cap.get(EVENT_CAP_PROP_POS_US);
            Mat frame = render(*surface[0], now, o);
            if (stereo)
                hconcat(frame, render(*surface[1], now, o), frame);
            frame = sampleEnlarge(frame, zoom);
            if (!o.video.empty())
            {
                if (!video.isOpened() &&
                    !video.open(o.video, VideoWriter::fourcc('M', 'J', 'P', 'G'), 1000.0 / o.windowMs, frame.size()))
                    throw std::runtime_error(o.video + ": cannot open a video writer (MJPG)");
                video.write(frame);
            }
            if (o.show)
            {
                imshow("event_player", frame);
                if (waitKey(std::max(1, (int)o.windowMs)) == 27)
                    break;
            }
            if (writePngs)
            {
                char name[64];
                std::snprintf(name, sizeof(name), "/frame_%05lld.png", (long long)frames);
                imwrite(o.output + name, frame);
            }
            frames++;
            progress.update(cap.get(EVENT_CAP_PROP_PROGRESS), std::to_string(frames) + " frames");
        }
        progress.finish(cap.get(EVENT_CAP_PROP_PROGRESS), std::to_string(frames) + " frames");
        std::cerr << cap.get(EVENT_CAP_PROP_EVENTS_DELIVERED) << " events, " << frames << " frames of " << o.windowMs
                  << " ms" << (writePngs ? " in " + o.output : std::string()) << "\n";
        if (filter)
            std::cerr << o.filter << " kept " << filter->getKeptCount() << " of " << filter->getProcessedCount() << " events\n";
        const long long outside = (long long)cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE);
        if (outside > 0)
            std::cerr << "event_player: warning: "
                      << outsideEventsWarning(outside, cap.getSensorSize().width, cap.getSensorSize().height,
                                              cap.getBackendName() == "TEXT", o.oneBased, touchesZero) << "\n";
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "\nevent_player: " << errorText(e) << "\n";
        return 1;
    }
}
