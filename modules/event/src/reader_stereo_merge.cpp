// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stereo capture: two streams (two files, or the two cameras of one file read through two independent
// readers) merged in time order. Files often store one camera after the other (TUM's Fan recording does),
// so a merge of two sequential readers is what keeps the output time-ordered with bounded memory.

#include "event_reader.hpp"

namespace cv {
namespace event {
namespace detail {

namespace {

class StereoMergeReader CV_FINAL : public EventReader
{
public:
    StereoMergeReader(const Ptr<EventReader>& left, const Ptr<EventReader>& right, int64 offset)
        : offset_(offset)
    {
        side_[0].reader = left;
        side_[1].reader = right;
        const Size l = left->sensorSize(), r = right->sensorSize();
        size_ = l.empty() ? r : l;
        if (!l.empty() && !r.empty() && l != r)
            CV_Error_(Error::StsBadArg, ("stereo capture: the left sensor is %d x %d but the right one %d x %d",
                                         l.width, l.height, r.width, r.height));
    }

    String name() const CV_OVERRIDE { return side_[0].reader->name(); }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    bool isStereo() const CV_OVERRIDE { return true; }
    double progress() const CV_OVERRIDE
    {
        return std::min(side_[0].reader->progress(), side_[1].reader->progress());
    }
    int64 skippedEvents() const CV_OVERRIDE
    {
        return side_[0].reader->skippedEvents() + side_[1].reader->skippedEvents();
    }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        size_t produced = 0;
        while (produced < kReaderChunk)
        {
            const bool l = side_[0].ready(), r = side_[1].ready();
            if (!l && !r)
                break;
            const bool takeLeft = l && (!r || side_[0].head().t <= side_[1].head().t + offset_);
            Event e = takeLeft ? side_[0].pop() : side_[1].pop();
            e.camera = takeLeft ? CAMERA_LEFT : CAMERA_RIGHT;
            if (!takeLeft)
                e.t += offset_;
            out.push_back(e);
            produced++;
        }
        return produced > 0;
    }

private:
    struct Side
    {
        Ptr<EventReader> reader;
        std::vector<Event> buffer;
        size_t pos = 0;
        bool done = false;

        bool ready()
        {
            while (pos == buffer.size() && !done)
            {
                buffer.clear();
                pos = 0;
                done = !reader->next(buffer);
            }
            return pos < buffer.size();
        }
        const Event& head() const { return buffer[pos]; }
        Event pop() { return buffer[pos++]; }
    };

    Side side_[2];
    int64 offset_;
    Size size_;
};

}  // namespace

Ptr<EventReader> openStereoMerge(const Ptr<EventReader>& left, const Ptr<EventReader>& right, int64 rightTimeOffset)
{
    return makePtr<StereoMergeReader>(left, right, rightTimeOffset);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
