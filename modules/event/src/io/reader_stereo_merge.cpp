// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Stereo capture: two streams (two files, or the two cameras of one file read through two independent
// readers) merged in time order. Files often store one camera after the other (TUM's Fan recording does),
// so a merge of two sequential readers is what keeps the output time-ordered with bounded memory.

#include "precomp.hpp"
#include "io/event_reader.hpp"

#include <exception>

namespace cv {
namespace event {
namespace detail {

namespace {

class StereoMergeReader CV_FINAL : public EventReader
{
public:
    StereoMergeReader(const Ptr<EventReader>& left, const Ptr<EventReader>& right, int64 offset, bool oneFile)
        : offset_(offset), oneFile_(oneFile)
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
        // One file read twice: the bytes each camera's reader has used add up; two files go as the slower one.
        if (oneFile_ && side_[0].share() >= 0 && side_[1].share() >= 0)
            return (side_[0].done && side_[1].done) ? 1.0 : std::min(1.0, side_[0].share() + side_[1].share());
        return std::min(side_[0].progress(), side_[1].progress());
    }
    int64 skippedEvents() const CV_OVERRIDE
    {
        return side_[0].reader->skippedEvents() + side_[1].reader->skippedEvents();
    }

    bool isLive() const CV_OVERRIDE { return side_[0].reader->isLive(); }
    int64 timeHorizon() const CV_OVERRIDE
    {
        const int64 l = side_[0].reader->timeHorizon(), r = side_[1].reader->timeHorizon();
        return std::min(l, r == INT64_MIN ? r : r + offset_);
    }
    String endMessage() const CV_OVERRIDE
    {
        const String l = side_[0].reader->endMessage(), r = side_[1].reader->endMessage();
        return l.empty() ? r : (r.empty() ? l : l + "; " + r);
    }
    bool setProperty(int propId, double value) CV_OVERRIDE
    {
        // Both cameras get the setting (ROI, filters, ...); it holds when both took it.
        const bool l = side_[0].reader->setProperty(propId, value);
        const bool r = side_[1].reader->setProperty(propId, value);
        return l && r;
    }
    bool getProperty(int propId, double& value) const CV_OVERRIDE
    {
        double l = 0, r = 0;
        if (!side_[0].reader->getProperty(propId, l))
            return false;
        const bool counter = propId == EVENT_CAP_PROP_DROPPED_EVENTS || propId == EVENT_CAP_PROP_DROPPED_TRANSFERS ||
                             propId == EVENT_CAP_PROP_INVALID_ADDRESSES;
        value = counter && side_[1].reader->getProperty(propId, r) ? l + r : l;  // counters: both cameras
        return true;
    }

    // Both cameras' triggers, stamped with their camera, the right ones on the merged clock, in time order.
    void takeTriggers(std::vector<EventTrigger>& out) CV_OVERRIDE
    {
        const size_t from = out.size();
        for (int camera = CAMERA_LEFT; camera <= CAMERA_RIGHT; camera++)
        {
            const size_t first = out.size();
            side_[camera].reader->takeTriggers(out);
            for (size_t i = first; i < out.size(); i++)
            {
                out[i].camera = (uchar)camera;
                if (camera == CAMERA_RIGHT)
                    out[i].t += offset_;
            }
        }
        std::stable_sort(out.begin() + from, out.end(),
                         [](const EventTrigger& a, const EventTrigger& b) { return a.t < b.t; });
    }

    // Takes the older head of the two streams. A stream with nothing buffered is asked for more only when the
    // choice needs it: a live stream answers within a poll period, possibly with nothing, and its clock
    // (timeHorizon) may already rule out an event older than the other stream's head, so that a silent camera
    // does not stall the other one.
    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        Side& l = side_[0];
        Side& r = side_[1];
        // Two live cameras are one instrument: when one stops (unplugged, its sync cable gone), the pair's
        // stream ends with its message instead of going on as a single camera. Files go on to the longer one.
        const bool live = isLive();
        size_t produced = 0;
        while (produced < kReaderChunk && !(live && (l.done || r.done)))
        {
            const bool lr = l.ready(), rr = r.ready();
            bool takeLeft;
            if (lr && rr)
                takeLeft = l.head().t <= r.head().t + offset_;
            else if (lr || rr)
            {
                Side& empty = lr ? r : l;
                const int64 head = lr ? l.head().t - offset_ : r.head().t + offset_;  // in the empty side's clock
                const int64 horizon = empty.reader->timeHorizon();
                const bool ruledOut = empty.done || empty.error ||
                                      (horizon != INT64_MIN && (lr ? horizon >= head : horizon > head));
                if (!ruledOut)
                {
                    if (produced > 0)
                        break;  // hand out what is merged before waiting on a reader
                    empty.poll();
                    if (!empty.ready() && !empty.done && isLive())
                        break;  // a live camera had nothing within its poll period: the caller may look at the clock
                    continue;
                }
                takeLeft = lr;
            }
            else
            {
                if ((l.done && r.done) || produced > 0)
                    break;
                if (l.error || r.error)
                    std::rethrow_exception(l.error ? l.error : r.error);
                l.poll();
                r.poll();
                if (!l.ready() && !r.ready() && isLive())
                    break;
                continue;
            }
            Event e = takeLeft ? l.pop() : r.pop();
            e.camera = takeLeft ? CAMERA_LEFT : CAMERA_RIGHT;
            if (!takeLeft)
                e.t += offset_;
            out.push_back(e);
            produced++;
        }
        return produced > 0 || !(live ? l.done || r.done : l.done && r.done);
    }

private:
    struct Side
    {
        Ptr<EventReader> reader;
        std::vector<Event> buffer;
        size_t pos = 0;
        bool done = false;
        std::exception_ptr error;                  // raised by the reader after the events in `buffer`
        double before = -1, after = -1;            // the reader's progress around the chunk in `buffer`
        double shareBefore = -1, shareAfter = -1;  // and its ownShare()

        // One call of next() when the buffer is empty (a live reader may return nothing).
        void poll()
        {
            if (pos < buffer.size() || done || error)
                return;
            buffer.clear();
            pos = 0;
            before = reader->progress();
            shareBefore = reader->ownShare();
            try
            {
                done = !reader->next(buffer);
            }
            catch (const cv::Exception&)
            {
                // The events decoded before the error (a file cut off mid-line) and those the other camera
                // has buffered are merged first; the error comes when nothing else is left to merge.
                error = std::current_exception();
            }
            after = reader->progress();
            shareAfter = reader->ownShare();
        }
        /** The reader's progress told by how far the merge has taken from its chunk: one camera's chunk of a
        one-file recording may reach far into the file (the other camera's events are skipped over). */
        double progress() const
        {
            return progressThroughChunk(before, after, pos, buffer.size(), done ? 1.0 : reader->progress());
        }
        double share() const
        {
            return progressThroughChunk(shareBefore, shareAfter, pos, buffer.size(), reader->ownShare());
        }
        bool ready() const { return pos < buffer.size(); }
        const Event& head() const { return buffer[pos]; }
        Event pop() { return buffer[pos++]; }
    };

    Side side_[2];
    int64 offset_;
    bool oneFile_;
    Size size_;
};

}  // namespace

Ptr<EventReader> openStereoMerge(const Ptr<EventReader>& left, const Ptr<EventReader>& right, int64 rightTimeOffset,
                                 bool oneFile)
{
    return makePtr<StereoMergeReader>(left, right, rightTimeOffset, oneFile);
}

}  // namespace detail
}  // namespace event
}  // namespace cv
