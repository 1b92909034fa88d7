// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_IO_AEDAT4_CODEC_HPP
#define OPENCV_EVENT_SRC_IO_AEDAT4_CODEC_HPP

// What the AEDAT 4.0 reader and writer share (layout: doc/formats.md, "AEDAT 4.0"): packet compression
// (LZ4 frames, ZSTD frames), a minimal bounds-checked FlatBuffers walker (no flatbuffers library: the
// schemas are tiny and fixed), and the scan of the XML info node for event streams.

#include "opencv2/event.hpp"

namespace cv {
namespace event {
namespace detail {

enum Aedat4Compression
{
    AEDAT4_NONE = 0,
    AEDAT4_LZ4 = 1,
    AEDAT4_LZ4_HIGH = 2,
    AEDAT4_ZSTD = 3,
    AEDAT4_ZSTD_HIGH = 4
};

static const char kAedat4Magic[] = "#!AER-DAT4.0\r\n";  // 14 bytes
static const size_t kAedat4MagicSize = 14;

/** Decompresses one packet. Errors name @p path and @p offset (the packet's position in the file).
The output is capped at @p maxOutput bytes: a corrupt frame cannot make the reader allocate without bound. */
std::vector<uchar> aedat4Decompress(int compression, const uchar* data, size_t size, const String& path,
                                    int64 offset, size_t maxOutput);

/** Compresses one packet as the AEDAT 4.0 writers do (one LZ4 / ZSTD frame). */
std::vector<uchar> aedat4Compress(int compression, const uchar* data, size_t size);

/** True when this build can read / write packets with that compression. */
bool aedat4CompressionSupported(int compression);

const char* aedat4CompressionName(int compression);

/** A table inside a FlatBuffer, with every access checked against the buffer's bounds. */
class FlatTable
{
public:
    /** The root table of a buffer: u32 root offset at @p buf. */
    static FlatTable root(const uchar* buf, size_t size, const String& path, int64 offset);

    bool has(int field) const { return fieldOffset(field) != 0; }
    int int8Field(int field, int defaultValue) const;
    int32_t int32Field(int field, int32_t defaultValue) const;
    int64 int64Field(int field, int64 defaultValue) const;
    std::string stringField(int field) const;
    /** A vector of structs of @p elementSize bytes: its element count and the address of element 0. */
    const uchar* vectorField(int field, size_t elementSize, size_t& count) const;
    /** A vector of tables. */
    std::vector<FlatTable> tableVectorField(int field) const;
    /** An inline struct field of @p size bytes, or nullptr when absent. */
    const uchar* structField(int field, size_t size) const;

private:
    FlatTable(const uchar* buf, size_t size, size_t pos, const String& path, int64 offset);
    uint16_t fieldOffset(int field) const;
    void check(size_t pos, size_t n, const char* what) const;
    uint32_t u32(size_t pos) const;

    const uchar* buf_;
    size_t size_, pos_, vtable_ = 0;
    uint16_t vtableSize_ = 0;
    String path_;
    int64 offset_;
};

/** A stream described in the info node. */
struct Aedat4Stream
{
    int id = -1;
    Size size;
};

/** The streams of one type ("EVTS" events, "TRIG" triggers, ...) listed in the info-node XML, in file order. */
std::vector<Aedat4Stream> aedat4Streams(const std::string& xml, const char* typeIdentifier);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_IO_AEDAT4_CODEC_HPP
