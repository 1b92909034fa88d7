// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_EXPIRY_HEAP_HPP
#define OPENCV_EVENT_SRC_STEREO_EXPIRY_HEAP_HPP

#include "opencv2/core.hpp"

#include <vector>

namespace cv {
namespace event {
namespace detail {

/** A min-heap of expiry times keyed by a fixed id range (pixel x polarity), with update and removal in
O(log n). One entry per id: a pixel that fires again moves its entry instead of adding one, so the heap
never holds more than the number of ids, however many events arrive (memory O(sensor pixels)). */
class alignas(64) ExpiryHeap  // a cache line each: the heaps of neighbouring row bands change on two threads
{
public:
    // Empty, for ids 0..ids-1, with room for `capacity` entries before the heap grows.
    void reset(int ids, size_t capacity)
    {
        heap_.clear();
        heap_.reserve(capacity);
        slot_.assign((size_t)ids, -1);
    }

    bool empty() const { return heap_.empty(); }
    size_t size() const { return heap_.size(); }
    // The i-th entry in heap order (not time order), for moving entries between heaps.
    int64 timeAt(size_t i) const { return heap_[i].time; }
    int idAt(size_t i) const { return heap_[i].id; }
    int64 topTime() const { return heap_[0].time; }
    int topId() const { return heap_[0].id; }
    bool contains(int id) const { return slot_[(size_t)id] >= 0; }

    // Inserts id with expiry time, or moves it there when present.
    void set(int id, int64 time)
    {
        int i = slot_[(size_t)id];
        if (i < 0)
        {
            i = (int)heap_.size();
            heap_.push_back(Entry{ time, id });
            slot_[(size_t)id] = i;
            up(i);
            return;
        }
        const int64 old = heap_[(size_t)i].time;
        heap_[(size_t)i].time = time;
        if (time < old)
            up(i);
        else
            down(i);
    }

    void remove(int id)
    {
        const int i = slot_[(size_t)id];
        if (i < 0)
            return;
        const int last = (int)heap_.size() - 1;
        if (i != last)
        {
            place(i, heap_[(size_t)last]);
            heap_.pop_back();
            up(i);
            down(i);
        }
        else
            heap_.pop_back();
        slot_[(size_t)id] = -1;
    }

private:
    struct Entry
    {
        int64 time;
        int id;
    };

    void place(int i, const Entry& e)
    {
        heap_[(size_t)i] = e;
        slot_[(size_t)e.id] = i;
    }

    void up(int i)
    {
        const Entry e = heap_[(size_t)i];
        while (i > 0)
        {
            const int parent = (i - 1) / 2;
            if (heap_[(size_t)parent].time <= e.time)
                break;
            place(i, heap_[(size_t)parent]);
            i = parent;
        }
        place(i, e);
    }

    void down(int i)
    {
        const Entry e = heap_[(size_t)i];
        const int n = (int)heap_.size();
        for (;;)
        {
            int child = 2 * i + 1;
            if (child >= n)
                break;
            if (child + 1 < n && heap_[(size_t)child + 1].time < heap_[(size_t)child].time)
                child++;
            if (e.time <= heap_[(size_t)child].time)
                break;
            place(i, heap_[(size_t)child]);
            i = child;
        }
        place(i, e);
    }

    std::vector<Entry> heap_;
    std::vector<int> slot_;  // position of each id in heap_, -1 when absent
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_EXPIRY_HEAP_HPP
