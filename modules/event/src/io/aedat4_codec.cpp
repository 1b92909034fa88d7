// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "io/aedat4_codec.hpp"
#include "io/file_input.hpp"

#include <cstdlib>

#ifdef OPENCV_EVENT_HAVE_LZ4
#include <lz4frame.h>
#include <lz4hc.h>
#endif
#ifdef OPENCV_EVENT_HAVE_ZSTD
#include <zstd.h>
#endif

namespace cv {
namespace event {
namespace detail {

const char* aedat4CompressionName(int c)
{
    switch (c)
    {
    case AEDAT4_NONE: return "NONE";
    case AEDAT4_LZ4: return "LZ4";
    case AEDAT4_LZ4_HIGH: return "LZ4_HIGH";
    case AEDAT4_ZSTD: return "ZSTD";
    case AEDAT4_ZSTD_HIGH: return "ZSTD_HIGH";
    default: return "unknown";
    }
}

bool aedat4CompressionSupported(int c)
{
    switch (c)
    {
    case AEDAT4_NONE: return true;
#ifdef OPENCV_EVENT_HAVE_LZ4
    case AEDAT4_LZ4:
    case AEDAT4_LZ4_HIGH: return true;
#endif
#ifdef OPENCV_EVENT_HAVE_ZSTD
    case AEDAT4_ZSTD:
    case AEDAT4_ZSTD_HIGH: return true;
#endif
    default: return false;
    }
}

std::vector<uchar> aedat4Decompress(int compression, const uchar* data, size_t size, const String& path,
                                    int64 offset, size_t maxOutput)
{
    if (compression == AEDAT4_NONE)
        return std::vector<uchar>(data, data + size);
    if (!aedat4CompressionSupported(compression))
        formatError(path, offset, format("%s compression is not available in this build (compression code %d)",
                                         aedat4CompressionName(compression), compression));
    std::vector<uchar> out;
#ifdef OPENCV_EVENT_HAVE_LZ4
    if (compression == AEDAT4_LZ4 || compression == AEDAT4_LZ4_HIGH)
    {
        LZ4F_dctx* ctx = nullptr;
        if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION)))
            CV_Error(Error::StsNoMem, "LZ4F_createDecompressionContext failed");
        out.resize(std::min(maxOutput, std::max<size_t>(size * 4, 1 << 16)));
        size_t produced = 0, consumed = 0;
        for (;;)
        {
            size_t dstSize = out.size() - produced, srcSize = size - consumed;
            const size_t r = LZ4F_decompress(ctx, out.data() + produced, &dstSize, data + consumed, &srcSize, nullptr);
            if (LZ4F_isError(r))
            {
                const std::string msg = LZ4F_getErrorName(r);
                LZ4F_freeDecompressionContext(ctx);
                formatError(path, offset, "corrupt LZ4 packet: " + msg);
            }
            produced += dstSize;
            consumed += srcSize;
            if (r == 0)
                break;  // frame complete
            if (consumed == size && dstSize == 0)
            {
                LZ4F_freeDecompressionContext(ctx);
                formatError(path, offset, "truncated LZ4 packet: the frame does not end inside the packet");
            }
            if (produced == out.size())
            {
                if (out.size() >= maxOutput)
                {
                    LZ4F_freeDecompressionContext(ctx);
                    formatError(path, offset, format("LZ4 packet decompresses to more than %zu bytes", maxOutput));
                }
                out.resize(std::min(maxOutput, out.size() * 2));
            }
        }
        LZ4F_freeDecompressionContext(ctx);
        out.resize(produced);
        return out;
    }
#endif
#ifdef OPENCV_EVENT_HAVE_ZSTD
    if (compression == AEDAT4_ZSTD || compression == AEDAT4_ZSTD_HIGH)
    {
        ZSTD_DStream* ds = ZSTD_createDStream();
        ZSTD_initDStream(ds);
        out.resize(std::min(maxOutput, std::max<size_t>(size * 4, 1 << 16)));
        ZSTD_inBuffer in = { data, size, 0 };
        ZSTD_outBuffer o = { out.data(), out.size(), 0 };
        for (;;)
        {
            const size_t r = ZSTD_decompressStream(ds, &o, &in);
            if (ZSTD_isError(r))
            {
                const std::string msg = ZSTD_getErrorName(r);
                ZSTD_freeDStream(ds);
                formatError(path, offset, "corrupt ZSTD packet: " + msg);
            }
            if (r == 0)
                break;
            if (o.pos == o.size)
            {
                if (out.size() >= maxOutput)
                {
                    ZSTD_freeDStream(ds);
                    formatError(path, offset, format("ZSTD packet decompresses to more than %zu bytes", maxOutput));
                }
                out.resize(std::min(maxOutput, out.size() * 2));
                o.dst = out.data();
                o.size = out.size();
            }
            else if (in.pos == in.size)
            {
                ZSTD_freeDStream(ds);
                formatError(path, offset, "truncated ZSTD packet: the frame does not end inside the packet");
            }
        }
        ZSTD_freeDStream(ds);
        out.resize(o.pos);
        return out;
    }
#endif
    formatError(path, offset, format("unknown compression code %d", compression));
}

std::vector<uchar> aedat4Compress(int compression, const uchar* data, size_t size)
{
    CV_Assert(aedat4CompressionSupported(compression));
    if (compression == AEDAT4_NONE)
        return std::vector<uchar>(data, data + size);
    std::vector<uchar> out;
#ifdef OPENCV_EVENT_HAVE_LZ4
    if (compression == AEDAT4_LZ4 || compression == AEDAT4_LZ4_HIGH)
    {
        LZ4F_preferences_t prefs;
        std::memset(&prefs, 0, sizeof(prefs));
        prefs.frameInfo.blockSizeID = LZ4F_max64KB;
        prefs.frameInfo.blockMode = LZ4F_blockLinked;
        prefs.compressionLevel = compression == AEDAT4_LZ4_HIGH ? LZ4HC_CLEVEL_DEFAULT : 0;
        out.resize(LZ4F_compressFrameBound(size, &prefs));
        const size_t n = LZ4F_compressFrame(out.data(), out.size(), data, size, &prefs);
        if (LZ4F_isError(n))
            CV_Error_(Error::StsError, ("LZ4 compression failed: %s", LZ4F_getErrorName(n)));
        out.resize(n);
        return out;
    }
#endif
#ifdef OPENCV_EVENT_HAVE_ZSTD
    if (compression == AEDAT4_ZSTD || compression == AEDAT4_ZSTD_HIGH)
    {
        out.resize(ZSTD_compressBound(size));
        const size_t n = ZSTD_compress(out.data(), out.size(), data, size, compression == AEDAT4_ZSTD_HIGH ? 19 : 3);
        if (ZSTD_isError(n))
            CV_Error_(Error::StsError, ("ZSTD compression failed: %s", ZSTD_getErrorName(n)));
        out.resize(n);
        return out;
    }
#endif
    CV_Error_(Error::StsBadArg, ("AEDAT 4.0: compression %d not available", compression));
}

// ---- FlatBuffers --------------------------------------------------------------------------------------

FlatTable::FlatTable(const uchar* buf, size_t size, size_t pos, const String& path, int64 offset)
    : buf_(buf), size_(size), pos_(pos), path_(path), offset_(offset)
{
    check(pos_, 4, "table");
    int32_t soffset;
    std::memcpy(&soffset, buf_ + pos_, 4);
    const int64 vt = (int64)pos_ - soffset;
    if (vt < 0 || vt + 4 > (int64)size_)
        formatError(path_, offset_, "corrupt FlatBuffer: vtable outside the buffer");
    vtable_ = (size_t)vt;
    std::memcpy(&vtableSize_, buf_ + vtable_, 2);
    if (vtableSize_ < 4 || vtable_ + vtableSize_ > size_)
        formatError(path_, offset_, "corrupt FlatBuffer: vtable size");
}

FlatTable FlatTable::root(const uchar* buf, size_t size, const String& path, int64 offset)
{
    if (size < 4)
        formatError(path, offset, "corrupt FlatBuffer: shorter than its root offset");
    uint32_t root;
    std::memcpy(&root, buf, 4);
    return FlatTable(buf, size, root, path, offset);
}

void FlatTable::check(size_t pos, size_t n, const char* what) const
{
    if (pos > size_ || n > size_ - pos)
        formatError(path_, offset_, format("corrupt FlatBuffer: %s outside the buffer", what));
}

uint32_t FlatTable::u32(size_t pos) const
{
    check(pos, 4, "offset");
    uint32_t v;
    std::memcpy(&v, buf_ + pos, 4);
    return v;
}

uint16_t FlatTable::fieldOffset(int field) const
{
    const size_t slot = 4 + 2 * (size_t)field;
    if (slot + 2 > vtableSize_)
        return 0;
    uint16_t off;
    std::memcpy(&off, buf_ + vtable_ + slot, 2);
    return off;
}

// Scalars are inline fields: read them through structField(), which checks the bounds.
int32_t FlatTable::int32Field(int field, int32_t defaultValue) const
{
    const uchar* p = structField(field, 4);
    int32_t v = defaultValue;
    if (p)
        std::memcpy(&v, p, 4);
    return v;
}

int FlatTable::int8Field(int field, int defaultValue) const
{
    const uchar* p = structField(field, 1);
    return p ? (int)(signed char)p[0] : defaultValue;
}

int64 FlatTable::int64Field(int field, int64 defaultValue) const
{
    const uchar* p = structField(field, 8);
    int64 v = defaultValue;
    if (p)
        std::memcpy(&v, p, 8);
    return v;
}

std::string FlatTable::stringField(int field) const
{
    const uint16_t off = fieldOffset(field);
    if (!off)
        return std::string();
    const size_t at = pos_ + off;
    const size_t s = at + u32(at);
    const uint32_t len = u32(s);
    check(s + 4, len, "string");
    return std::string(reinterpret_cast<const char*>(buf_ + s + 4), len);
}

const uchar* FlatTable::vectorField(int field, size_t elementSize, size_t& count) const
{
    count = 0;
    const uint16_t off = fieldOffset(field);
    if (!off)
        return nullptr;
    const size_t at = pos_ + off;
    const size_t v = at + u32(at);
    count = u32(v);
    if (count > (size_ - std::min(size_, v + 4)) / elementSize)
        formatError(path_, offset_, format("corrupt FlatBuffer: a vector of %zu elements does not fit the packet", count));
    return buf_ + v + 4;
}

std::vector<FlatTable> FlatTable::tableVectorField(int field) const
{
    size_t count = 0;
    const uchar* first = vectorField(field, 4, count);
    std::vector<FlatTable> tables;
    tables.reserve(count);
    for (size_t i = 0; i < count; i++)
    {
        const size_t at = (size_t)(first - buf_) + 4 * i;
        tables.push_back(FlatTable(buf_, size_, at + u32(at), path_, offset_));
    }
    return tables;
}

const uchar* FlatTable::structField(int field, size_t size) const
{
    const uint16_t off = fieldOffset(field);
    if (!off)
        return nullptr;
    check(pos_ + off, size, "struct field");
    return buf_ + pos_ + off;
}

// ---- info node ----------------------------------------------------------------------------------------

namespace {

int attrInt(const std::string& xml, size_t from, size_t to, const char* key)
{
    const std::string k = std::string("key=\"") + key + "\"";
    const size_t p = xml.find(k, from);
    if (p == std::string::npos || p >= to)
        return 0;
    const size_t gt = xml.find('>', p);
    return gt == std::string::npos ? 0 : std::atoi(xml.c_str() + gt + 1);
}

}  // namespace

std::vector<Aedat4Stream> aedat4Streams(const std::string& xml, const char* typeIdentifier)
{
    // Each output stream is a <node name="ID"> (numeric name) whose attributes include its typeIdentifier;
    // its child node "info" holds sizeX / sizeY. Scan stream by stream: enough for the DV info node.
    std::vector<size_t> starts;
    std::vector<int> ids;
    for (size_t p = xml.find("<node name=\""); p != std::string::npos; p = xml.find("<node name=\"", p + 1))
    {
        const char* name = xml.c_str() + p + 12;
        char* end = nullptr;
        const long id = std::strtol(name, &end, 10);
        if (end != name && *end == '"')
        {
            starts.push_back(p);
            ids.push_back((int)id);
        }
    }
    std::vector<Aedat4Stream> streams;
    for (size_t i = 0; i < starts.size(); i++)
    {
        const size_t from = starts[i], to = i + 1 < starts.size() ? starts[i + 1] : xml.size();
        const size_t type = xml.find(std::string(">") + typeIdentifier + "<", from);
        if (type == std::string::npos || type >= to)
            continue;
        Aedat4Stream s;
        s.id = ids[i];
        s.size = Size(attrInt(xml, from, to, "sizeX"), attrInt(xml, from, to, "sizeY"));
        streams.push_back(s);
    }
    return streams;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
