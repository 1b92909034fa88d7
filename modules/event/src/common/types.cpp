// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "common/ascii.hpp"

#include <cctype>
#include <cstdio>
#include <ostream>

namespace cv {
namespace event {

static_assert(EVENT_MAT_TYPE == CV_MAKETYPE(CV_8U, 16), "EVENT_MAT_TYPE is 16 x CV_8U");
static_assert(sizeof(Event) == 16, "Event must stay a 16-byte record: EVENT_MAT_TYPE depends on it");
static_assert(offsetof(Event, t) == 0 && offsetof(Event, x) == 8 && offsetof(Event, y) == 10 &&
              offsetof(Event, p) == 12 && offsetof(Event, camera) == 13,
              "Event layout is documented in types.hpp; keep them in sync");

namespace {

struct SensorEntry
{
    SensorModel model;
    const char* name;
    int width, height;
};

const SensorEntry kSensors[] = {
    { SENSOR_DVS128, "DVS128", 128, 128 },
    { SENSOR_DAVIS240, "DAVIS240", 240, 180 },
    { SENSOR_DAVIS346, "DAVIS346", 346, 260 },
    { SENSOR_DVXPLORER, "DVXplorer", 640, 480 },
    { SENSOR_DVXPLORER_LITE, "DVXplorerLite", 320, 240 },
    { SENSOR_PROPHESEE_GEN3, "Gen3", 640, 480 },
    { SENSOR_PROPHESEE_GEN4, "Gen4", 1280, 720 },
};

const SensorEntry& sensorEntry(int model)
{
    for (const SensorEntry& s : kSensors)
        if (s.model == model)
            return s;
    CV_Error_(Error::StsOutOfRange, ("unknown sensor model %d (see cv::event::SensorModel)", model));
}

// Converts one column of packEvents() input to an N x 1 Mat of the given depth.
Mat columnAs(InputArray a, int depth, size_t n, const char* what)
{
    Mat m = a.getMat();
    if (m.total() != n || m.channels() != 1)
        CV_Error_(Error::StsBadSize, ("packEvents: %s must be a single-channel column of %zu elements like t; "
                                      "got %d channel(s), %zu elements", what, n, m.channels(), m.total()));
    Mat r;
    m.reshape(1, (int)n).convertTo(r, depth);
    return r;
}

}  // namespace

Size getSensorSize(int model)
{
    const SensorEntry& s = sensorEntry(model);
    return Size(s.width, s.height);
}

String getSensorModelName(int model)
{
    return sensorEntry(model).name;
}

int findSensorModel(const String& name)
{
    const std::string key = detail::toLowerAscii(name);
    for (const SensorEntry& s : kSensors)
        if (detail::toLowerAscii(s.name) == key)
            return s.model;
    return -1;
}

Size parseSensorSize(const String& text)
{
    const int model = findSensorModel(text);
    if (model >= 0)
        return getSensorSize(model);
    int w = 0, h = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &extra) == 2 && w > 0 && h > 0 && w <= 32768 && h <= 32768)
        return Size(w, h);
    CV_Error_(Error::StsBadArg, ("sensor size \"%s\": expected WxH (e.g. 346x260) or a sensor name (DVS128, "
                                 "DAVIS240, DAVIS346, DVXplorer, DVXplorerLite, Gen3, Gen4)", text.c_str()));
}

Mat_<Event> getEventMat(InputArray events)
{
    if (events.empty())
        return Mat_<Event>();
    if (events.type() != EVENT_MAT_TYPE)
        CV_Error_(Error::StsUnsupportedFormat,
                  ("an event packet must be N x 1 of type CV_8UC(16) (cv::event::EVENT_MAT_TYPE) or a "
                   "std::vector<cv::event::Event>; got type %s, %d x %d",
                   typeToString(events.type()).c_str(), events.rows(), events.cols()));
    Mat m = events.getMat();
    if (m.dims > 2 || (m.rows != 1 && m.cols != 1) || !m.isContinuous())
        CV_Error_(Error::StsUnsupportedFormat,
                  ("an event packet must be a continuous N x 1 or 1 x N array; got %d x %d%s", m.rows, m.cols,
                   m.isContinuous() ? "" : " (not continuous)"));
    return Mat_<Event>(m.reshape(0, (int)m.total()));
}

std::vector<Event> toEventVector(InputArray events)
{
    Mat_<Event> m = getEventMat(events);
    if (m.empty())
        return std::vector<Event>();  // an empty Mat_'s iterators cannot be compared (OpenCV 4.6 crashes)
    return std::vector<Event>(m.begin(), m.end());
}

void packEvents(InputArray t, InputArray x, InputArray y, InputArray p, OutputArray events, InputArray camera)
{
    const size_t n = t.total();
    if (n == 0)
    {
        events.release();
        return;
    }
    Mat_<double> ts = columnAs(t, CV_64F, n, "t");
    Mat_<int> xs = columnAs(x, CV_32S, n, "x");
    Mat_<int> ys = columnAs(y, CV_32S, n, "y");
    Mat_<double> ps = columnAs(p, CV_64F, n, "p");
    Mat_<int> cs;
    if (!camera.empty())
        cs = columnAs(camera, CV_32S, n, "camera");

    events.create((int)n, 1, EVENT_MAT_TYPE);
    Mat_<Event> out = events.getMat();
    for (int i = 0; i < (int)n; i++)
    {
        const double ti = ts(i);
        if (!(std::abs(ti) < 9007199254740992.0))  // 2^53: beyond it a double no longer holds every integer
            CV_Error_(Error::StsOutOfRange, ("packEvents: t[%d] = %g is not a finite timestamp below 2^53 us", i, ti));
        const int xi = xs(i), yi = ys(i);
        if (xi < SHRT_MIN || xi > SHRT_MAX || yi < SHRT_MIN || yi > SHRT_MAX)
            CV_Error_(Error::StsOutOfRange, ("packEvents: (x, y)[%d] = (%d, %d) does not fit int16", i, xi, yi));
        const int ci = cs.empty() ? (int)CAMERA_LEFT : cs(i);
        if (ci != CAMERA_LEFT && ci != CAMERA_RIGHT)
            CV_Error_(Error::StsOutOfRange, ("packEvents: camera[%d] = %d; expected 0 (left) or 1 (right)", i, ci));
        out(i) = Event((int64)std::llround(ti), xi, yi, ps(i) > 0 ? POLARITY_ON : POLARITY_OFF, ci);
    }
}

void unpackEvents(InputArray events, OutputArray t, OutputArray x, OutputArray y, OutputArray p, OutputArray camera)
{
    Mat_<Event> ev = getEventMat(events);
    const int n = (int)ev.total();
    t.create(n, 1, CV_64F);
    x.create(n, 1, CV_32S);
    y.create(n, 1, CV_32S);
    p.create(n, 1, CV_8U);
    Mat_<double> tm = t.getMat();
    Mat_<int> xm = x.getMat(), ym = y.getMat();
    Mat_<uchar> pm = p.getMat(), cm;
    if (camera.needed())
    {
        camera.create(n, 1, CV_8U);
        cm = camera.getMat();
    }
    for (int i = 0; i < n; i++)
    {
        const Event& e = ev(i);
        tm(i) = (double)e.t;
        xm(i) = e.x;
        ym(i) = e.y;
        pm(i) = e.p;
        if (!cm.empty())
            cm(i) = e.camera;
    }
}

int findTimeOrderViolation(InputArray events)
{
    Mat_<Event> ev = getEventMat(events);
    for (int i = 1; i < (int)ev.total(); i++)
        if (ev(i).t < ev(i - 1).t)
            return i;
    return -1;
}

void mergeStereoEvents(InputArray left, InputArray right, OutputArray merged, double rightTimeOffsetUs)
{
    const int64 rightTimeOffset = (int64)std::llround(rightTimeOffsetUs);
    Mat_<Event> l = getEventMat(left), r = getEventMat(right);
    int bad = findTimeOrderViolation(l);
    if (bad >= 0)
        CV_Error_(Error::StsBadArg, ("mergeStereoEvents: left stream goes back in time at event %d", bad));
    bad = findTimeOrderViolation(r);
    if (bad >= 0)
        CV_Error_(Error::StsBadArg, ("mergeStereoEvents: right stream goes back in time at event %d", bad));

    const int nl = (int)l.total(), nr = (int)r.total();
    // Copy the inputs first: merged may alias left or right.
    std::vector<Event> out((size_t)nl + nr);
    int i = 0, j = 0, k = 0;
    while (i < nl || j < nr)
    {
        const bool takeLeft = j >= nr || (i < nl && l(i).t <= r(j).t + rightTimeOffset);
        Event e = takeLeft ? l(i++) : r(j++);
        if (takeLeft)
            e.camera = CAMERA_LEFT;
        else
        {
            e.t += rightTimeOffset;
            e.camera = CAMERA_RIGHT;
        }
        out[k++] = e;
    }
    Mat(out).copyTo(merged);
}

void splitStereoEvents(InputArray merged, OutputArray left, OutputArray right)
{
    Mat_<Event> m = getEventMat(merged);
    std::vector<Event> l, r;
    for (const Event& e : m)
    {
        if (e.camera == CAMERA_LEFT)
            l.push_back(e);
        else if (e.camera == CAMERA_RIGHT)
            r.push_back(e);
        else
            CV_Error_(Error::StsBadArg, ("splitStereoEvents: event with camera id %d (expected 0 or 1)", (int)e.camera));
    }
    Mat(l).copyTo(left);
    Mat(r).copyTo(right);
}

void write(FileStorage& fs, const String& name, const Event& e)
{
    fs.startWriteStruct(name, FileNode::SEQ + FileNode::FLOW);
    cv::write(fs, String(), (double)e.t);
    cv::write(fs, String(), (int)e.x);
    cv::write(fs, String(), (int)e.y);
    cv::write(fs, String(), (int)e.p);
    cv::write(fs, String(), (int)e.camera);
    fs.endWriteStruct();
}

void write(FileStorage& fs, const String& name, const std::vector<Event>& events)
{
    fs.startWriteStruct(name, FileNode::SEQ);
    for (const Event& e : events)
        write(fs, String(), e);
    fs.endWriteStruct();
}

static Event parseEvent(const FileNode& node)
{
    if (!node.isSeq() || node.size() != 5)
        CV_Error(Error::StsParseError, "an event must be stored as the sequence [ t, x, y, p, camera ]");
    const double t = (double)node[0];
    return Event((int64)t, (int)node[1], (int)node[2], (int)node[3], (int)node[4]);
}

void read(const FileNode& node, Event& event, const Event& defaultValue)
{
    event = node.empty() ? defaultValue : parseEvent(node);
}

void read(const FileNode& node, std::vector<Event>& events, const std::vector<Event>& defaultValue)
{
    if (node.empty())
    {
        events = defaultValue;
        return;
    }
    if (!node.isSeq())
        CV_Error(Error::StsParseError, "an event packet must be stored as a sequence of events");
    events.clear();
    events.reserve(node.size());
    for (FileNodeIterator it = node.begin(); it != node.end(); ++it)
        events.push_back(parseEvent(*it));
}

std::ostream& operator<<(std::ostream& out, const Event& e)
{
    return out << "Event(t=" << e.t << ", x=" << e.x << ", y=" << e.y << ", p=" << (int)e.p
               << ", camera=" << (int)e.camera << ")";
}

}  // namespace event
}  // namespace cv
