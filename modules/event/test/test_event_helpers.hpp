// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// Helpers of opencv_test_event: reading a capture whole, writing fixture files.

#ifndef OPENCV_EVENT_TEST_EVENT_HELPERS_HPP
#define OPENCV_EVENT_TEST_EVENT_HELPERS_HPP

#include "opencv2/ts.hpp"
#include "opencv2/event.hpp"

#include <fstream>
#include <string>
#include <vector>

namespace opencv_test {

/** Every event @p cap delivers, read in batches of @p batch events (batches that need not line up with the
file's own packets). */
inline std::vector<cv::event::Event> readAllEvents(cv::event::EventCapture& cap, int batch = 1 << 20)
{
    cap.set(cv::event::EVENT_CAP_PROP_BATCH_EVENTS, batch);
    std::vector<cv::event::Event> all, packet;
    while (cap.read(packet))
        all.insert(all.end(), packet.begin(), packet.end());
    return all;
}

/** Writes @p content to a fresh temporary file with the given suffix and returns its path. */
inline std::string writeTempFile(const std::string& content, const std::string& suffix)
{
    const std::string path = cv::tempfile(suffix.c_str());
    std::ofstream out(path.c_str(), std::ios::binary);
    out.write(content.data(), (std::streamsize)content.size());
    return path;
}
}  // namespace opencv_test

#endif  // OPENCV_EVENT_TEST_EVENT_HELPERS_HPP
