// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// SimulatedGroundTruthReader: the `.gt.csv` side file of writeSimulatedRecording(), read in step with its events.

#include "precomp.hpp"

#include <cstdio>
#include <fstream>
#include <string>

namespace cv {
namespace event {

static const char* const kGroundTruthHeader = "t,x,y,p,camera,depth,disparity,flow_x,flow_y,lifetime,flags";

struct SimulatedGroundTruthReader::Impl
{
    std::ifstream in;
    std::string path;
    int64 lines = 0;  // data lines read
};

SimulatedGroundTruthReader::SimulatedGroundTruthReader() : impl_(makePtr<Impl>()) {}

SimulatedGroundTruthReader::SimulatedGroundTruthReader(const String& path) : impl_(makePtr<Impl>())
{
    open(path);
}

SimulatedGroundTruthReader::~SimulatedGroundTruthReader() {}

void SimulatedGroundTruthReader::open(const String& path)
{
    impl_ = makePtr<Impl>();
    impl_->in.open(path.c_str());
    if (!impl_->in)
        CV_Error_(Error::StsError, ("%s: cannot open the ground-truth file", path.c_str()));
    std::string header;
    std::getline(impl_->in, header);
    if (!header.empty() && header.back() == '\r')
        header.pop_back();
    if (header != kGroundTruthHeader)
    {
        impl_ = makePtr<Impl>();
        CV_Error_(Error::StsParseError, ("%s: not a simulated ground-truth file (its first line is not \"%s\")",
                                         path.c_str(), kGroundTruthHeader));
    }
    impl_->path = path;
}

bool SimulatedGroundTruthReader::isOpened() const
{
    return impl_->in.is_open();
}

void SimulatedGroundTruthReader::read(InputArray _events, OutputArray groundTruth)
{
    if (!isOpened())
        CV_Error(Error::StsError, "SimulatedGroundTruthReader::read: no file is open");
    const Mat_<Event> events = getEventMat(_events);
    const int n = (int)events.total();
    Mat truth(n, GT_FLAGS + 1, CV_32F);
    std::string line;
    for (int i = 0; i < n; i++)
    {
        const Event& e = events(i);
        const int64 lineNumber = impl_->lines + 2;  // 1-based, after the header
        if (!std::getline(impl_->in, line))
            CV_Error_(Error::StsParseError, ("%s: the file ends at line %lld, before the event at t = %lld us",
                                             impl_->path.c_str(), (long long)lineNumber, (long long)e.t));
        long long t = 0;
        int x = 0, y = 0, p = 0, camera = 0, flags = 0;
        float v[5];
        if (std::sscanf(line.c_str(), "%lld,%d,%d,%d,%d,%f,%f,%f,%f,%f,%d", &t, &x, &y, &p, &camera, &v[0], &v[1],
                        &v[2], &v[3], &v[4], &flags) != 11)
            CV_Error_(Error::StsParseError, ("%s: line %lld is not t,x,y,p,camera,depth,disparity,flow_x,flow_y,"
                                             "lifetime,flags: \"%s\"", impl_->path.c_str(), (long long)lineNumber,
                                             line.c_str()));
        if (t != e.t || x != e.x || y != e.y || p != e.p || camera != e.camera)
            CV_Error_(Error::StsBadArg, ("%s: line %lld (\"%s\") does not describe its event (t %lld, x %d, y %d, p %d, "
                                         "camera %d)", impl_->path.c_str(), (long long)lineNumber, line.c_str(),
                                         (long long)e.t, e.x, e.y, e.p, e.camera));
        float* row = truth.ptr<float>(i);
        row[GT_DEPTH] = v[0];
        row[GT_DISPARITY] = v[1];
        row[GT_FLOW_X] = v[2];
        row[GT_FLOW_Y] = v[3];
        row[GT_LIFETIME] = v[4];
        row[GT_FLAGS] = (float)flags;
        impl_->lines++;
    }
    truth.copyTo(groundTruth);
}

double SimulatedGroundTruthReader::getLinesRead() const
{
    return (double)impl_->lines;
}

}  // namespace event
}  // namespace cv
