// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_SRC_COMMON_ASCII_HPP
#define OPENCV_EVENT_SRC_COMMON_ASCII_HPP

// Case-insensitive matching of names (sensor models, file extensions, chip classes in headers).

#include <cctype>
#include <string>

namespace cv {
namespace event {
namespace detail {

inline std::string toLowerAscii(std::string s)
{
    for (char& c : s)
        c = (char)std::tolower((unsigned char)c);
    return s;
}

}  // namespace detail
}  // namespace event
}  // namespace cv

#endif  // OPENCV_EVENT_SRC_COMMON_ASCII_HPP
