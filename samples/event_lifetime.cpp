// event_lifetime: per-event lifetime and normal flow of any recording (LifetimeEstimator), with pictures of the
// active events next to the fixed-interval accumulation people use today.
//
//   event_lifetime [FILE | --scene=NAME [--duration-ms=1000] [--sensor-set=NAME=VALUE,...]] [--camera=0|1]
//                  [--frame-ms=10] [--every-ms=50] [--csv=FILE] [--output=DIR] [--sensor=WxH|NAME] [--one-based]
//                  [--no-prediction] [--max-ms=T] [--set=NAME=VALUE,...] [--min-quality=Q]
//                  [--filter=NAME [--filter-set=NAME=VALUE,...]]
//
// Pictures DIR/active_NNNNN.png: left, the events alive at that instant (each lives from its timestamp for
// its lifetime: the sharp edge image; with --min-quality only those of at least that quality); right, all
// events of the last --frame-ms (the fixed window).
// --csv writes every event: t,x,y,p,lifetime_us,vx,vy,status,quality (status: 0 noise, 1 fitted, 2 predicted;
// quality: how far the lifetime can be trusted, LifetimeEstimator::process()). With --filter the estimator,
// the CSV, the pictures and the check see only the events the filter keeps (a flickering lamp's, noise's and
// hot pixels' removed first).
// Without FILE it simulates the "moving_line" scene. Progress bar on stderr. At the end it prints the
// LifetimeArrivalCheck: how many lifetimes the edges really took to reach the next pixel (about 1 when the
// lifetimes agree with the recording; no ground truth needed), over the lifetimes of at least --min-quality.

#include <opencv2/event.hpp>
#include <opencv2/core/utils/filesystem.hpp>  // after a core header: it needs CV_EXPORTS
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "algorithm_settings.hpp"
#include "command_line.hpp"
#include "sample_pictures.hpp"
#include "sample_progress.hpp"
#include "simulator_settings.hpp"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <iostream>

using namespace cv;
using namespace cv::event;

namespace {

const char* const keys =
    "{help h        | false           | print this message}"
    "{@input        |                 | the recording; none: simulate --scene}"
    "{scene         | moving_line     | simulated scene when no recording is given}"
    "{duration-ms   | 1000            | length of the simulated scene [ms]}"
    "{sensor-set    |                 | the simulated scene's sensor settings NAME=VALUE, comma separated (SimulatorSettings fields, e.g. blurSigmaPx=0.6)}"
    "{camera        | 0               | which camera of a stereo recording: 0 left, 1 right}"
    "{frame-ms      | 10              | the fixed window drawn beside the lifetimes [ms]}"
    "{every-ms      | 50              | one picture per this much recording time [ms]}"
    "{max-ms        | -1              | stop after this much recording time [ms]; -1: all}"
    "{csv           |                 | write every event with its lifetime and flow to this file}"
    "{output        | lifetime_output | output folder}"
    "{sensor        |                 | sensor size WxH or a name (DVS128, DAVIS240, DAVIS346) when the format has none; the model --scene is simulated on (default DAVIS240)}"
    "{one-based     | false           | text recordings count pixels from 1}"
    "{no-prediction | false           | fit a plane for every event (no prediction shortcut)}"
    "{set           |                 | estimator parameters NAME=VALUE, comma separated (FileStorage names, e.g. inlierDistance=0,windowSize=7)}"
    "{min-quality   | 0               | the lifetime check and the active events' picture only over lifetimes of at least this quality (0..1; 0: all)}"
    "{filter        |                 | a noise filter in front of the estimator: background_activity, trail, refractory, hot_pixels, anti_flicker}"
    "{filter-set    |                 | filter parameters NAME=VALUE, comma separated (e.g. minCycles=3)}";

}  // namespace

int main(int argc, char** argv)
{
    try
    {
        ProgramCommandLine cmd(argc, argv, keys,
                              "Per-event lifetime and normal flow of a recording, with pictures of the active events.");
        if (cmd.helpShown())
            return 0;
        std::string input = cmd.get<std::string>("@input");
        const std::string scene = cmd.get<std::string>("scene"), csvPath = cmd.get<std::string>("csv"),
                          output = cmd.get<std::string>("output");
        const int camera = cmd.get<int>("camera");
        const double frameMs = cmd.get<double>("frame-ms"), everyMs = cmd.get<double>("every-ms"),
                     maxMs = cmd.get<double>("max-ms");
        const bool prediction = !cmd.has("no-prediction");
        const double minQuality = cmd.get<double>("min-quality");
        if (!(minQuality >= 0 && minQuality <= 1))
            throw std::runtime_error(format("--min-quality=%g: must be 0..1", minQuality));
        Size sensor;
        if (cmd.has("sensor"))
            sensor = parseSensorSize(cmd.get<std::string>("sensor"));
        if (!utils::fs::createDirectories(output))
            throw std::runtime_error(output + ": cannot create the output folder");
        const std::string sensorSettings = cmd.get<std::string>("sensor-set");
        if (input.empty())
        {
            const int model = cmd.has("sensor") ? sceneSensorModel(cmd.get<std::string>("sensor")) : SENSOR_DAVIS240;
            input = output + "/" + scene + ".aedat4";
            const double durationMs = cmd.get<double>("duration-ms");
            if (!(durationMs > 0))
                throw std::runtime_error(format("--duration-ms=%g: must be above 0", durationMs));
            std::cerr << "no input given: simulating " << durationMs << " ms of scene \"" << scene << "\" on a "
                      << getSensorModelName(model) << (sensorSettings.empty() ? std::string() : " (" + sensorSettings + ")")
                      << " into " << input << "\n";
            writeSimulatedRecording(simulatorWithSettings(scene, model, sensorSettings), input, durationMs * 1000);
        }
        else if (!sensorSettings.empty())
            throw std::runtime_error("--sensor-set: only for a simulated scene (--scene), not a recording");
        EventCapture cap;
        cap.set(EVENT_CAP_PROP_SENSOR_WIDTH, sensor.width);
        cap.set(EVENT_CAP_PROP_SENSOR_HEIGHT, sensor.height);
        cap.set(EVENT_CAP_PROP_WINDOW_US, everyMs * 1000);
        cap.set(EVENT_CAP_PROP_TEXT_ONE_BASED, cmd.has("one-based"));
        cap.open(input);
        const Size size = cap.getSensorSize();
        if (size.empty())
            throw sensorSizeMissing(input);
        Ptr<LifetimeEstimator> est = LifetimeEstimator::create(size);
        Ptr<LifetimeArrivalCheck> check = LifetimeArrivalCheck::create(size);  // the lifetimes against the recording
        est->setUsePrediction(prediction);
        applyAlgorithmSettings(est, cmd.get<std::string>("set"), "--set", "lifetime estimator");
        const std::string filterName = cmd.get<std::string>("filter");
        Ptr<EventFilter> filter = createSampleFilter(filterName, cmd.get<std::string>("filter-set"), size);
        int64 delivered = 0;  // events of the chosen camera before the filter
        std::FILE* csv = nullptr;
        if (!csvPath.empty())
        {
            csv = std::fopen(csvPath.c_str(), "w");
            if (!csv)
                throw std::runtime_error(csvPath + ": cannot create");
            std::fprintf(csv, "t,x,y,p,lifetime_us,vx,vy,status,quality\n");
        }
        const double first = cap.get(EVENT_CAP_PROP_FIRST_TIMESTAMP_US);
        std::deque<Event> recent;  // events of the last frameMs, for the fixed-window picture
        std::vector<Event> packet;
        int64 pictures = 0, processed = 0, withLifetime = 0, trusted = 0;
        SampleProgress progress;
        const int zoom = samplePictureZoom(size);
        const int64 t0 = getTickCount();
        std::vector<Event> checked;
        std::vector<float> checkedLifetimes;
        std::vector<Vec2f> checkedFlow;
        bool touchesZero = false;  // a delivered event in column or row 0 (outsideEventsAdvice())
        while (cap.read(packet))
        {
            touchesZero = touchesZero || touchesColumnOrRowZero(packet);
            if (cap.get(EVENT_CAP_PROP_STEREO) != 0)
                packet.erase(std::remove_if(packet.begin(), packet.end(), [camera](const Event& e) { return e.camera != camera; }),
                             packet.end());
            delivered += (int64)packet.size();
            if (filter)
                filter->filter(packet, packet);
            checked.clear();
            checkedLifetimes.clear();
            checkedFlow.clear();
            for (const Event& e : packet)
            {
                Vec2f flow;
                int status;
                float quality;
                const float lifetime = est->processEvent(e, flow, status, quality);
                const bool kept = lifetime > 0 && quality >= minQuality;
                withLifetime += lifetime > 0;
                trusted += kept;
                checked.push_back(e);
                checkedLifetimes.push_back(kept ? lifetime : 0.f);  // a dropped lifetime claims nothing
                checkedFlow.push_back(flow);
                processed++;
                if (csv)
                    std::fprintf(csv, "%lld,%d,%d,%d,%.1f,%.2f,%.2f,%d,%.3f\n", (long long)e.t, e.x, e.y, e.p, lifetime,
                                 flow[0], flow[1], status, quality);
                recent.push_back(e);
            }
            check->update(checked, checkedLifetimes, checkedFlow);
            const double now = cap.get(EVENT_CAP_PROP_POS_US);
            while (!recent.empty() && recent.front().t < now - frameMs * 1000)
                recent.pop_front();
            // Picture: active events | fixed window, same colours (ON white, OFF grey).
            Mat active, fixed = Mat::zeros(size, CV_8U), pair;
            est->renderActiveEvents(now, active, minQuality);
            for (const Event& e : recent)
                fixed.at<uchar>(e.y, e.x) = e.p ? 255 : 128;
            hconcat(active, fixed, pair);
            pair = sampleEnlarge(pair, zoom);
            cvtColor(pair, pair, COLOR_GRAY2BGR);
            line(pair, Point(size.width * zoom, 0), Point(size.width * zoom, size.height * zoom), Scalar(0, 160, 255), 1);
            const String activeTitle = minQuality > 0 ? format("active events, quality >= %g", minQuality)
                                                      : String("active events (lifetime)");
            putText(pair, activeTitle, Point(6, 16), FONT_HERSHEY_SIMPLEX, 0.45, Scalar(0, 160, 255), 1);
            putText(pair, format("fixed %.0f ms window", frameMs), Point(size.width * zoom + 6, 16), FONT_HERSHEY_SIMPLEX,
                    0.45, Scalar(0, 160, 255), 1);
            char name[64];
            std::snprintf(name, sizeof(name), "/active_%05lld.png", (long long)pictures++);
            imwrite(output + name, pair);
            progress.update(cap.get(EVENT_CAP_PROP_PROGRESS), format("%.2f s, %lld events", (now - first) / 1e6, (long long)processed));
            if (maxMs > 0 && now - first >= maxMs * 1000)
                break;
        }
        if (csv)
            std::fclose(csv);
        const double secs = (getTickCount() - t0) / getTickFrequency();
        const double fitted = est->getStatusCount(LIFETIME_FITTED), predicted = est->getStatusCount(LIFETIME_PREDICTED);
        const double noise = est->getStatusCount(LIFETIME_NOISE);
        progress.finish(cap.get(EVENT_CAP_PROP_PROGRESS), format("%lld events", (long long)processed));
        std::cout << processed << " events of camera " << camera << ": " << fitted << " fitted, " << predicted
                  << " predicted (shortcut), " << noise << " noise; " << pictures << " pictures in " << output
                  << "; " << processed / std::max(1e-9, secs) / 1e6 << " Mev/s including I/O and pictures\n";
        if (filter)
            std::cout << format("filter %s: kept %lld of %lld events (%.1f %%)\n", filterName.c_str(), (long long)processed,
                                (long long)delivered, 100.0 * processed / std::max<int64>(1, delivered));
        const int64 outside = (int64)cap.get(EVENT_CAP_PROP_REJECTED_OUTSIDE);
        if (outside > 0)
            std::cerr << "event_lifetime: warning: "
                      << outsideEventsWarning(outside, size.width, size.height, cap.getBackendName() == "TEXT",
                                              cmd.has("one-based"), touchesZero) << "\n";
        // No ground truth needed: lifetimes that agree with the recording give a median near 1.
        if (minQuality > 0)
            std::cout << format("quality >= %g: %lld of %lld lifetimes (%.1f %%)\n", minQuality, (long long)trusted,
                                (long long)withLifetime, 100.0 * trusted / std::max<int64>(1, withLifetime));
        std::cout << format("lifetime check: the edge reached the next pixel after %.2f lifetimes (median; quartiles "
                            "%.2f / %.2f) over %.0f events\n", check->getRatioQuantile(0.5),
                            check->getRatioQuantile(0.25), check->getRatioQuantile(0.75), check->getSampleCount());
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "\nevent_lifetime: " << errorText(e) << "\n";
        return 1;
    }
}
