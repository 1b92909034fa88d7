// How far row bands can speed the stereo matcher up while they give the results of one thread: prints one
// Markdown table.
//
//   row_band_ceiling [--scenes=boxes,walking_near] [--sensor=DAVIS240] [--duration-ms=2000] [--bands=2,4,8,16]
//                    [--conflict-rows=24] [--recordings=a.aedat4,b.aedat4]
//
// With setNumThreads(N) the matcher splits the image rows into bands, each taking its own events in order, and an
// event waits for every earlier event of another band within the conflict rows of its own (the rows two events
// can both touch: 24 at the defaults, the filling's 20 rows above and below plus the 4 an activation's votes
// write). This replays a recording's events through that rule, in 33 ms windows as process() gets them, with
// every event taking one unit of time and one core per band, the bands split as the matcher splits them (equal
// shares of the window's events, each band more than the conflict rows tall). The events over the units the
// windows take is the speed-up no schedule under the rule can beat on any machine: it leaves out the arrivals and
// expiries between the events, what the bands cost to keep in step and their cache misses, and lets no event
// cost more than another.

#include "command_line.hpp"

#include <opencv2/event.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace cv;
using namespace cv::event;

namespace {

const int64 WINDOW_US = 33000;

struct Recording
{
    std::string name;
    Size size;
    int64 events = 0;
    std::vector<std::vector<int>> windowRows;  // each window's event rows, in time order

    void addWindow(const std::vector<Event>& window)
    {
        std::vector<int> rows;
        for (const Event& e : window)
            rows.push_back(e.y);
        events += (int64)rows.size();
        windowRows.push_back(std::move(rows));
    }
};

Recording simulated(const std::string& scene, double durationMs, int sensorModel)
{
    Recording r;
    Ptr<StereoEventSimulator> sim = StereoEventSimulator::create(scene, sensorModel);
    r.name = scene + " (sim, " + getSensorModelName(sensorModel) + ")";
    r.size = sim->getSensorSize();
    for (double t = (double)WINDOW_US; t < durationMs * 1000 + (double)WINDOW_US; t += (double)WINDOW_US)
    {
        std::vector<Event> ev;
        Mat truth;
        sim->generate(std::min(t, durationMs * 1000), ev, truth);
        r.addWindow(ev);
    }
    return r;
}

Recording recorded(const std::string& path)
{
    Recording r;
    EventCapture cap;
    cap.set(EVENT_CAP_PROP_WINDOW_US, (double)WINDOW_US);
    if (!cap.open(path))
        throw std::runtime_error("cannot open " + path);
    r.name = path;
    r.size = cap.getSensorSize();
    std::vector<Event> ev;
    while (cap.read(ev))
        r.addWindow(ev);
    return r;
}

// The first row of each of `bands` bands that hold about equal shares of the events, each at least `minHeight`
// rows tall (the matcher's split).
std::vector<int> bandTops(const std::vector<int>& rows, int height, int bands, int minHeight)
{
    std::vector<int64> below((size_t)height + 1, 0);  // below[y]: events in the rows above row y
    for (int y : rows)
        below[(size_t)y + 1]++;
    for (int y = 0; y < height; y++)
        below[(size_t)y + 1] += below[(size_t)y];
    std::vector<int> tops(1, 0);
    for (int b = 1; b < bands; b++)
    {
        const int64 share = below.back() * b / bands;
        const int even = (int)(std::lower_bound(below.begin(), below.end(), share) - below.begin());
        tops.push_back(std::min(std::max(even, tops.back() + minHeight), height - (bands - b) * minHeight));
    }
    return tops;
}

// The units of time one window takes on `bands` bands: each event starts when its band is free and every earlier
// event within conflictRows rows of it is done (an event's own band's earlier ones are done by then too).
int64 windowUnits(const std::vector<int>& rows, int height, int bands, int conflictRows)
{
    const std::vector<int> tops = bandTops(rows, height, bands, conflictRows + 1);
    std::vector<int> bandOfRow((size_t)height, 0);
    for (int b = 1; b < bands; b++)
        std::fill(bandOfRow.begin() + tops[(size_t)b], bandOfRow.end(), b);
    std::vector<int64> bandFree((size_t)bands, 0), rowDone((size_t)height, 0);
    for (int y : rows)
    {
        int64 start = bandFree[(size_t)bandOfRow[(size_t)y]];
        for (int yy = std::max(0, y - conflictRows); yy <= std::min(height - 1, y + conflictRows); yy++)
            start = std::max(start, rowDone[(size_t)yy]);
        bandFree[(size_t)bandOfRow[(size_t)y]] = rowDone[(size_t)y] = start + 1;
    }
    return *std::max_element(bandFree.begin(), bandFree.end());
}

}  // namespace

const char* const keys =
    "{help h        | false             | print this message}"
    "{scenes        | boxes,walking_near | simulated scenes, comma separated (none: \"\")}"
    "{sensor        | DAVIS240          | the simulated scenes' sensor: DAVIS240 or DAVIS346}"
    "{duration-ms   | 2000              | length of each simulated scene [ms]}"
    "{recordings    |                   | recordings EventCapture reads as they are (AEDAT4: its sizes), comma separated}"
    "{bands         | 2,4,8,16          | band counts, comma separated}"
    "{conflict-rows | 24                | rows within which two events may touch the same data (the matcher's at its defaults)}";

int main(int argc, char** argv)
{
    std::string scenes, recordings, bandList;
    double durationMs = 0;
    int conflictRows = 0, sensorModel = SENSOR_DAVIS240;
    try
    {
        ProgramCommandLine cmd(argc, argv, keys,
                               "The speed-up row bands cannot beat while they give the results of one thread.");
        if (cmd.helpShown())
            return 0;
        scenes = cmd.get<std::string>("scenes");
        recordings = cmd.get<std::string>("recordings");
        bandList = cmd.get<std::string>("bands");
        durationMs = cmd.get<double>("duration-ms");
        conflictRows = cmd.get<int>("conflict-rows");
        const std::string sensor = cmd.get<std::string>("sensor");
        sensorModel = findSensorModel(sensor);
        if (sensorModel != SENSOR_DAVIS240 && sensorModel != SENSOR_DAVIS346)
            throw std::invalid_argument("--sensor must be DAVIS240 or DAVIS346 (the simulator's presets), got " + sensor);
        if (conflictRows < 0)
            throw std::invalid_argument("--conflict-rows must be at least 0, got " + std::to_string(conflictRows));
    }
    catch (const std::exception& e)
    {
        std::cerr << "row_band_ceiling: " << errorText(e) << "\n";
        return 2;
    }
    try
    {
        std::vector<int> bandCounts;
        for (const std::string& b : commaList(bandList))
        {
            const int n = std::stoi(b);
            if (n < 1)
                throw std::invalid_argument("--bands must list counts of at least 1, got " + b);
            bandCounts.push_back(n);
        }
        std::vector<Recording> all;
        for (const std::string& scene : commaList(scenes))
        {
            std::cerr << "simulating " << scene << " (" << durationMs << " ms)...\n";
            all.push_back(simulated(scene, durationMs, sensorModel));
        }
        for (const std::string& path : commaList(recordings))
            all.push_back(recorded(path));

        std::ostringstream table;
        table << "| recording | events | most bands (rows / " << conflictRows + 1 << ") |";
        for (int n : bandCounts)
            table << " " << n << " bands |";
        table << "\n|---|---|---|";
        for (size_t i = 0; i < bandCounts.size(); i++)
            table << "---|";
        table << "\n";
        for (const Recording& r : all)
        {
            const int most = std::max(1, r.size.height / (conflictRows + 1));
            table << "| " << r.name << " | " << r.events << " | " << most << " |";
            for (int n : bandCounts)
            {
                if (n > most)
                {
                    table << " - |";
                    continue;
                }
                int64 units = 0;
                for (const std::vector<int>& rows : r.windowRows)
                    units += rows.empty() ? 0 : windowUnits(rows, r.size.height, n, conflictRows);
                char cell[32];
                std::snprintf(cell, sizeof(cell), " %.2f |", units > 0 ? (double)r.events / (double)units : 1.0);
                table << cell;
            }
            table << "\n";
        }
        std::cout << table.str();
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "row_band_ceiling: " << errorText(e) << "\n";
        return 1;
    }
}
