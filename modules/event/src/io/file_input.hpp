// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_IO_FILE_INPUT_HPP
#define OPENCV_EVENT_SRC_IO_FILE_INPUT_HPP

// Buffered sequential reading of a recording, with the byte offset always known so that every error
// message can say where the file is wrong.

#include "opencv2/event.hpp"
#include "common/ascii.hpp"

#include <cstdio>

namespace cv {
namespace event {
namespace detail {

/** Raises cv::Error::StsParseError: "<path>: byte <offset>: <what>". */
[[noreturn]] void formatError(const String& path, int64 offset, const String& what);

class FileInput
{
public:
    enum { kReadPadding = 16 };

    /** Opens @p path for reading; raises cv::Error::StsError naming the file when it is missing, a
    directory, unreadable, ... */
    explicit FileInput(const String& path);
    ~FileInput();
    FileInput(const FileInput&) = delete;
    FileInput& operator=(const FileInput&) = delete;

    const String& path() const { return path_; }
    /** Offset of the next byte read() or readLine() returns. */
    int64 offset() const { return fileOffset_ - (int64)(end_ - pos_); }
    int64 size() const { return size_; }
    /** offset() / size(), or -1 when the size is unknown. */
    double progress() const { return size_ > 0 ? (double)offset() / (double)size_ : -1.0; }

    /** Reads up to @p n bytes; returns how many were read (fewer only at the end of the file). */
    size_t read(void* dst, size_t n);
    /** Reads exactly @p n bytes or raises formatError("truncated: <what>"). */
    void readExact(void* dst, size_t n, const char* what);
    /** Reads one line without its "\n" / "\r\n"; false at the end of the file. */
    bool readLine(std::string& line);
    /** The same without a copy: [@p begin, @p end) is the line inside the read buffer, valid until the next
    read; a line that crosses a refill (or ends the file without a newline) is gathered in @p spill. At least
    kReadPadding bytes after @p end can be read (their values are unspecified), for word-wise parsers. */
    bool readLineView(const char*& begin, const char*& end, std::string& spill);
    /** Peeks at the next byte without consuming it; -1 at the end. */
    int peek();
    /** Moves to an absolute offset. */
    void seek(int64 offset);
    /** For formats of fixed-size records: reads up to @p n bytes of whole records of @p recordSize bytes;
    0 at the end. A file cut off inside a record (a camera unplugged, a disk full) gives the whole records
    before the cut first; the call after them raises formatError("truncated: ...") at the first byte of the
    incomplete @p what, so that a reader delivers the user's data and then says where it stops. */
    size_t readRecords(void* dst, size_t n, size_t recordSize, const char* what);

private:
    int64 truncatedAt_ = -1;  // readRecords(): where the incomplete last record starts
    size_t truncatedBytes_ = 0;
    bool refill();

    String path_;
    std::FILE* file_ = nullptr;
    std::vector<char> buffer_;
    const char* pos_ = nullptr;
    const char* end_ = nullptr;
    int64 fileOffset_ = 0;  // offset of end_
    int64 size_ = -1;
};

/** The lower-case extension of a path ("aedat4"), empty when its last component has none. */
std::string fileExtension(const String& path);

/** Reads the first @p n bytes of a file (fewer if it is shorter); empty when it cannot be opened. */
std::string readFilePrefix(const String& path, size_t n);

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_IO_FILE_INPUT_HPP
