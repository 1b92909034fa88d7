// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#ifndef OPENCV_EVENT_TEST_ROS_MESSAGES_HPP
#define OPENCV_EVENT_TEST_ROS_MESSAGES_HPP

// ROS2 event messages as the bag tests write them (sqlite3 and MCAP storage).

#include <cstdint>
#include <string>
#include <vector>

namespace opencv_test {

// CDR (little-endian) serialisation of event_camera_msgs/msg/EventPacket, aligned relative to byte 4.
struct Cdr
{
    std::string b = std::string("\x00\x01\x00\x00", 4);
    void align(size_t a) { while ((b.size() - 4) % a) b.push_back('\0'); }
    template<typename T> void put(T v) { align(sizeof(T)); b.append(reinterpret_cast<const char*>(&v), sizeof(T)); }
    void str(const std::string& s) { put<uint32_t>((uint32_t)s.size() + 1); b += s; b.push_back('\0'); }
};

inline std::string eventPacket(uint32_t width, uint32_t height, const std::string& encoding, uint64_t timeBase,
                               const std::vector<uint16_t>& words)
{
    Cdr c;
    c.put<int32_t>(1700000000);
    c.put<uint32_t>(5);
    c.str("camera");  // 7 bytes with the NUL: the next field needs padding
    c.put<uint32_t>(height);
    c.put<uint32_t>(width);
    c.put<uint64_t>(42);  // seq: 8-byte alignment
    c.put<uint64_t>(timeBase);
    c.str(encoding);
    c.put<uint8_t>(0);  // is_bigendian
    c.put<uint32_t>((uint32_t)(words.size() * 2));
    c.b.append(reinterpret_cast<const char*>(words.data()), words.size() * 2);
    return c.b;
}

}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_ROS_MESSAGES_HPP
