// --set=NAME=VALUE,... on the command line: StereoEventMatcher parameters by the names its write() stores
// (uniquenessRatio, costWindow, ...), applied through read(), for the sample programs.

#ifndef OPENCV_EVENT_SAMPLES_SAMPLE_MATCHER_SETTINGS_HPP
#define OPENCV_EVENT_SAMPLES_SAMPLE_MATCHER_SETTINGS_HPP

#include <opencv2/event.hpp>

#include "sample_command_line.hpp"

#include <set>
#include <stdexcept>
#include <string>

/** Applies "name=value,name=value" to @p matcher. Throws std::runtime_error naming an item that is not
    NAME=VALUE or a name the matcher does not store, with the names it does. */
inline void applyMatcherSettings(const cv::Ptr<cv::event::StereoEventMatcher>& matcher, const std::string& list)
{
    if (list.empty())
        return;
    // The names the matcher knows: the keys of its own parameter file.
    cv::FileStorage out(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    matcher->write(out);
    cv::FileStorage stored(out.releaseAndGetString(), cv::FileStorage::READ | cv::FileStorage::MEMORY);
    std::set<std::string> known;
    for (const cv::FileNode& n : stored.root())
        known.insert(n.name());
    std::string yaml = "%YAML:1.0\n";
    for (const std::pair<std::string, std::string>& item : parseNameValueList("--set", list))
    {
        if (!known.count(item.first))
        {
            std::string names;
            for (const std::string& k : known)
                names += (names.empty() ? "" : ", ") + k;
            throw std::runtime_error("--set: the matcher has no parameter \"" + item.first + "\" (" + names + ")");
        }
        yaml += item.first + ": " + item.second + "\n";
    }
    matcher->read(cv::FileStorage(yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY).root());
}

#endif
