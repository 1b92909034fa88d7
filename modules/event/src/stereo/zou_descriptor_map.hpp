// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_STEREO_ZOU_DESCRIPTOR_MAP_HPP
#define OPENCV_EVENT_SRC_STEREO_ZOU_DESCRIPTOR_MAP_HPP

#include "stereo/expiry_heap.hpp"

#include <vector>

namespace cv {
namespace event {
namespace detail {

/** The active events of one sensor and their Zou descriptors, maintained incrementally.

Per pixel and polarity: whether an event is active there (with its time, lifetime and flow), and the
vector to the nearest active event of that polarity within the maximum vector length, stored as an index
into a table of offsets sorted by length (ties by angle), so "nearest" is "smallest index".
Per pixel: the descriptor, 12 orientation bins of 30 degrees per polarity (bytes 0..11 OFF, 12..23 ON; packed,
24 bytes per pixel, so that a cost window's row is one run of bytes for the SAD kernels), counting the
vectors of the N x N window around the pixel; a pixel that is itself active votes into all 12 bins of its
polarity.

Activating an event can only shorten vectors within the maximum length of it; deactivating one
re-searches only the pixels whose nearest event it was. Each vector change moves one vote in N x N
descriptors. The descriptor map has a zero margin around the image so that cost windows can run past the
border without checks. Expiry: an ExpiryHeap over pixel x polarity, one per band of rows (setRowBands), so
that StereoEventMatcher's row bands each take their own expiries in time order (each band's zones next to its
neighbours have heaps of their own: RowBandScheduler::splitSegments). The map's state depends only
on which events are active (and their times, lifetimes and flows), not on the order in which they were activated or
deactivated: expiries due at the same moment may be taken in any order, band by band.

The per-pixel arrays (activity, nearest vector, lifetime, flow) have a border of the maximum vector length
around the image, so that the vector offsets are plain index offsets: a border pixel is never active and its
"nearest vector" is offset 0 (itself), so updates skip it without bounds checks. */
class CV_EXPORTS ZouDescriptorMap  // exported for opencv_perf_event only; not public API
{
public:
    enum { DESCRIPTOR_BYTES = 24, BINS = 12, NONE = 255 };

    void configure(Size size, int descriptorWindow, int maxVectorLength, int margin);
    void reset();

    Size size() const { return size_; }
    int margin() const { return margin_; }
    // Descriptor of (x, y); valid for x, y within the margin around the image (zero outside it).
    const uchar* descriptor(int x, int y) const { return &descriptors_[descriptorIndex(x, y)]; }
    size_t descriptorRowStep() const { return (size_t)stride_ * DESCRIPTOR_BYTES; }

    bool isActive(int x, int y, int p) const { return active_[id(x, y, p)] != 0; }
    // An active event of polarity p lies within the maximum vector length of (x, y).
    bool hasStructure(int x, int y, int p) const { return nearest_[id(x, y, p)] != NONE; }
    // Row y of hasStructure as codes: NONE where no active event of polarity p is within reach.
    const uchar* nearestRow(int y, int p) const { return &nearest_[(size_t)id(0, y, p)]; }
    float lifetime(int x, int y, int p) const { return lifetime_[id(x, y, p)]; }
    // The lifetimes of every pixel and polarity, at lifetimeIndex(x, y, p): > 0 exactly where an active event
    // has a lifetime (an inactive pixel's is 0), so that a window can be scanned on one array. A row's pixels
    // are consecutive.
    const float* lifetimes() const { return lifetime_.data(); }
    int lifetimeIndex(int x, int y, int p) const { return id(x, y, p); }
    // lifetimeIndex(x, y + 1, p) - lifetimeIndex(x, y, p).
    int lifetimeRowStep() const { return paddedWidth_; }
    Vec2f flow(int x, int y, int p) const { return flow_[id(x, y, p)]; }
    // The flow at lifetimeIndex(x, y, p).
    Vec2f flowAt(int index) const { return flow_[(size_t)index]; }
    // How many times the lifetime at lifetimeIndex(x, y, p) was copied from the other sensor since a plane fit
    // gave it (0: fitted or predicted here).
    int copiesAt(int index) const { return copies_[(size_t)index]; }
    // Starts loading the lifetimes, flows and copy counts of polarity p in the rectangle [x0, x1] x [y0, y1]
    // (inside the image) into the cache, so that a later read of them (a matched window's median) does not wait
    // for memory.
    void prefetchLifetimes(int x0, int x1, int y0, int y1, int p) const;

    // Row y of isActive for polarity p, by column (0..width - 1): nonzero where an event is active.
    const uchar* activeRow(int y, int p) const { return &active_[(size_t)id(0, y, p)]; }
    // Row y's times of the events of polarity p, by column; the time of the active event where activeRow says
    // one is (elsewhere a past event's or 0: any value is a valid time, so no value marks "none").
    const int64* eventTimeRow(int y, int p) const { return &time_[(size_t)id(0, y, p)]; }

    // Makes the event of time `time` [us] at (x, y, p) the pixel's active one until expiry (exclusive) [us].
    void activate(int x, int y, int p, int64 time, int64 expiry, float lifetime, const Vec2f& flow, int copies = 0);
    void deactivate(int x, int y, int p);
    // Deactivates every event whose expiry is <= t.
    void expireUntil(int64 t);

    // Splits the expiries into bands of rows [firstRows[b], firstRows[b + 1]) (the last up to the image's
    // height); firstRows[0] is 0. The default is one band.
    void setRowBands(const std::vector<int>& firstRows);
    const std::vector<int>& rowBands() const { return bandFirstRow_; }
    // Band b's earliest expiry: false when it has none, else its time and its pixel's row.
    bool earliestExpiry(int band, int64& time, int& row) const;
    // Deactivates band b's earliest expiry (there must be one).
    void expireEarliest(int band);
private:
    // Index of (x, y, p) in the per-pixel arrays (with their border), and the row of an index.
    int id(int x, int y, int p) const { return (p * paddedHeight_ + y + border_) * paddedWidth_ + x + border_; }
    int rowOf(int id) const { return (id / paddedWidth_) % paddedHeight_ - border_; }
    ExpiryHeap& heapOfRow(int y) { return expiry_[(size_t)rowBand_[(size_t)y]]; }
    int bandOfRow(int y) const { return rowBand_[(size_t)y]; }
    // rowBand_ from bandFirstRow_.
    void assignRowBands();
    void deactivateId(int id);
    // Empty expiry heaps, one per band of bandFirstRow_.
    void resetExpiries();
    // Empties band b's heap.
    void resetHeap(size_t b);
    // The nearest active event of pixel id from offset `from` on (NONE: none).
    int scanNearest(int id, int from) const;
    // The bins of polarity p in the descriptors that a pixel's vector votes into: the N x N window around the
    // pixel, clipped to the image; topLeft points at the first descriptor's bins, rows rowStep bytes apart.
    struct VotedWindow
    {
        uchar* topLeft;
        int width, height;
    };
    // Index of (x, y)'s descriptor in descriptors_ (x, y within the margin around the image).
    size_t descriptorIndex(int x, int y) const
    {
        return ((size_t)(y + margin_) * stride_ + (size_t)(x + margin_)) * DESCRIPTOR_BYTES;
    }
    // Polarity p's bins in the descriptor of (x, y).
    uchar* bins(int x, int y, int p) { return &descriptors_[descriptorIndex(x, y)] + p * BINS; }
    // The window of pixel (x, y), clipped.
    VotedWindow votedWindow(int x, int y, int p);
    // An event at least maximum vector length + N / 2 pixels from every border votes only inside the image.
    bool isInterior(int x, int y) const
    {
        const int reach = maxVectorLength_ + window_ / 2;
        return x >= reach && y >= reach && x < size_.width - reach && y < size_.height - reach;
    }
    // The window of the pixel that sees the event at (x, y, p) at offset k. For an interior event it is the
    // event's own bins (eventBins) plus a per-offset constant, with no clipping.
    VotedWindow windowSeeing(int x, int y, int p, int k, bool interior, uchar* eventBins)
    {
        if (interior)
            return VotedWindow{ eventBins + voteOffsets_[(size_t)k], window_, window_ };
        return votedWindow(x - offsets_[(size_t)k].x, y - offsets_[(size_t)k].y, p);
    }
    // Calls op(bins) for each descriptor of the window.
    template <typename Op>
    void forEachVoted(const VotedWindow& w, Op op);
    void vote(const VotedWindow& w, int code, int delta);
    // Moves the vote of a pixel's vector from oldCode to newCode (either may be NONE) in its window's descriptors.
    void revote(const VotedWindow& w, int oldCode, int newCode);

    Size size_;
    int window_ = 5, maxVectorLength_ = 3, margin_ = 0, stride_ = 0;
    int border_ = 0, paddedWidth_ = 0, paddedHeight_ = 0;  // of the per-pixel arrays
    std::vector<Point> offsets_;  // candidate vectors to the nearest event, by length then angle
    std::vector<int> idOffsets_;  // the same as offsets in the per-pixel arrays
    std::vector<uchar> bins_;     // orientation bin of each offset (offset 0 = the pixel itself: all bins)
    // Per offset k: from an event's own bins to the first bins of the window of the pixel that sees it at k.
    std::vector<ptrdiff_t> voteOffsets_;
    std::vector<uchar> active_, nearest_;
    std::vector<int64> time_;  // of the active event (eventTimeRow)
    std::vector<float> lifetime_;
    std::vector<Vec2f> flow_;
    std::vector<uchar> copies_;  // copiesAt()
    std::vector<uchar> descriptors_;
    std::vector<ExpiryHeap> expiry_;  // one per band of rows
    std::vector<int> bandFirstRow_;   // the bands' first rows
    std::vector<uchar> rowBand_;      // the band of each row
};

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_STEREO_ZOU_DESCRIPTOR_MAP_HPP
