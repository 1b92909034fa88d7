// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "precomp.hpp"
#include "io/file_input.hpp"

#include <cerrno>
#include <sys/stat.h>

namespace cv {
namespace event {
namespace detail {

void formatError(const String& path, int64 offset, const String& what)
{
    CV_Error_(Error::StsParseError, ("%s: byte %lld: %s", path.c_str(), (long long)offset, what.c_str()));
}

FileInput::FileInput(const String& path) : path_(path), buffer_((1 << 20) + kReadPadding)
{
    struct stat st;
    if (::stat(path.c_str(), &st) != 0)
        CV_Error_(Error::StsError, ("%s: cannot open: %s", path.c_str(), std::strerror(errno)));
    if (S_ISDIR(st.st_mode))
        CV_Error_(Error::StsError, ("%s: is a directory, not a recording", path.c_str()));
    file_ = std::fopen(path.c_str(), "rb");
    if (!file_)
        CV_Error_(Error::StsError, ("%s: cannot open: %s", path.c_str(), std::strerror(errno)));
    size_ = S_ISREG(st.st_mode) ? (int64)st.st_size : -1;
    pos_ = end_ = buffer_.data();
}

FileInput::~FileInput()
{
    if (file_)
        std::fclose(file_);
}

bool FileInput::refill()
{
    const size_t got = std::fread(buffer_.data(), 1, buffer_.size() - kReadPadding, file_);
    if (got == 0 && std::ferror(file_))
        CV_Error_(Error::StsError, ("%s: byte %lld: read error: %s", path_.c_str(), (long long)fileOffset_,
                                    std::strerror(errno)));
    pos_ = buffer_.data();
    end_ = pos_ + got;
    fileOffset_ += (int64)got;
    return got > 0;
}

size_t FileInput::read(void* dst, size_t n)
{
    char* out = static_cast<char*>(dst);
    size_t done = 0;
    while (done < n)
    {
        if (pos_ == end_ && !refill())
            break;
        const size_t k = std::min(n - done, (size_t)(end_ - pos_));
        std::memcpy(out + done, pos_, k);
        pos_ += k;
        done += k;
    }
    return done;
}

void FileInput::readExact(void* dst, size_t n, const char* what)
{
    const int64 at = offset();
    const size_t got = read(dst, n);
    if (got != n)
        formatError(path_, at, format("truncated: %s needs %zu bytes, only %zu left", what, n, got));
}

bool FileInput::readLine(std::string& line)
{
    line.clear();
    bool any = false;
    for (;;)
    {
        if (pos_ == end_ && !refill())
            break;
        any = true;
        const char* nl = static_cast<const char*>(std::memchr(pos_, '\n', (size_t)(end_ - pos_)));
        if (nl)
        {
            line.append(pos_, nl);
            pos_ = nl + 1;
            break;
        }
        line.append(pos_, end_);
        pos_ = end_;
    }
    if (!line.empty() && line.back() == '\r')
        line.pop_back();
    return any;
}

bool FileInput::readLineView(const char*& begin, const char*& end, std::string& spill)
{
    if (pos_ == end_ && !refill())
        return false;
    const char* nl = static_cast<const char*>(std::memchr(pos_, '\n', (size_t)(end_ - pos_)));
    if (nl)
    {
        begin = pos_;
        end = nl;
        pos_ = nl + 1;
    }
    else
    {
        readLine(spill);  // the rest of this buffer, the next refill up to its newline
        const size_t n = spill.size();
        spill.append(kReadPadding, '\0');  // the same readable padding as the buffer's
        begin = spill.data();
        end = begin + n;
        return true;
    }
    if (end > begin && end[-1] == '\r')
        end--;
    return true;
}

int FileInput::peek()
{
    if (pos_ == end_ && !refill())
        return -1;
    return (unsigned char)*pos_;
}

void FileInput::seek(int64 offset)
{
    if (std::fseek(file_, (long)offset, SEEK_SET) != 0)
        CV_Error_(Error::StsError, ("%s: cannot seek to byte %lld", path_.c_str(), (long long)offset));
    fileOffset_ = offset;
    pos_ = end_ = buffer_.data();
}

size_t FileInput::readRecords(void* dst, size_t n, size_t recordSize, const char* what)
{
    CV_Assert(recordSize > 0 && n >= recordSize);
    if (truncatedAt_ >= 0)
        formatError(path_, truncatedAt_, format("truncated: the file ends %zu bytes into a %zu-byte %s",
                                                truncatedBytes_, recordSize, what));
    const int64 at = offset();
    const size_t got = read(dst, n - n % recordSize);
    const size_t rest = got % recordSize;
    if (rest != 0)
    {
        truncatedAt_ = at + (int64)(got - rest);
        truncatedBytes_ = rest;
        if (got == rest)
            return readRecords(dst, n, recordSize, what);  // nothing whole before the cut: raises now
    }
    return got - rest;
}

std::string fileExtension(const String& path)
{
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == String::npos || (slash != String::npos && dot < slash))
        return std::string();
    return toLowerAscii(path.substr(dot + 1));
}

std::string readFilePrefix(const String& path, size_t n)
{
    struct stat st;
    if (::stat(path.c_str(), &st) != 0 || S_ISDIR(st.st_mode))
        return std::string();
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f)
        return std::string();
    std::string s(n, '\0');
    s.resize(std::fread(&s[0], 1, n, f));
    std::fclose(f);
    return s;
}

}  // namespace detail
}  // namespace event
}  // namespace cv
