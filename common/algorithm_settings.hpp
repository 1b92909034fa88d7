// --set / --filter-set=NAME=VALUE,... on the command line: parameters of a StereoEventMatcher, a
// LifetimeEstimator or a noise filter by the names its write() stores (uniquenessRatio, costWindow,
// lifetimeEstimator.inlierDistance, correlationTime, ...), applied through read().

#ifndef OPENCV_EVENT_COMMON_ALGORITHM_SETTINGS_HPP
#define OPENCV_EVENT_COMMON_ALGORITHM_SETTINGS_HPP

#include <opencv2/event.hpp>

#include "command_line.hpp"

#include <map>
#include <set>
#include <stdexcept>
#include <string>

/** Applies "name=value,name=value" to @p algorithm through its FileStorage parameters. A parameter of a nested
    algorithm is named PARENT.NAME (lifetimeEstimator.inlierDistance for a StereoEventMatcher). Throws
    std::runtime_error naming an item that is not NAME=VALUE or a name the algorithm does not store, with the
    names it does. @p option is the command-line option for the messages ("--set"), @p what the algorithm. */
inline void applyAlgorithmSettings(const cv::Ptr<cv::Algorithm>& algorithm, const std::string& list,
                                   const std::string& option, const std::string& what)
{
    if (list.empty())
        return;
    // The names the algorithm knows: the keys of its own parameter file, and PARENT.NAME one level down.
    cv::FileStorage out(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    algorithm->write(out);
    cv::FileStorage stored(out.releaseAndGetString(), cv::FileStorage::READ | cv::FileStorage::MEMORY);
    std::set<std::string> known;
    for (const cv::FileNode& n : stored.root())
    {
        if (n.isMap())
            for (const cv::FileNode& child : n)
                known.insert(n.name() + "." + child.name());
        else
            known.insert(n.name());
    }
    std::string top;
    std::map<std::string, std::string> nested;  // parent -> its "  name: value" lines
    for (const std::pair<std::string, std::string>& item : parseNameValueList(option, list))
    {
        if (!known.count(item.first))
        {
            std::string names;
            for (const std::string& k : known)
                names += (names.empty() ? "" : ", ") + k;
            throw std::runtime_error(option + ": the " + what + " has no parameter \"" + item.first + "\" (" + names + ")");
        }
        const size_t dot = item.first.find('.');
        if (dot == std::string::npos)
            top += item.first + ": " + item.second + "\n";
        else
            nested[item.first.substr(0, dot)] += "   " + item.first.substr(dot + 1) + ": " + item.second + "\n";
    }
    std::string yaml = "%YAML:1.0\n" + top;
    for (const std::pair<const std::string, std::string>& parent : nested)
        yaml += parent.first + ":\n" + parent.second;
    algorithm->read(cv::FileStorage(yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY).root());
}

/** Applies --set's "name=value,name=value" to @p matcher (see applyAlgorithmSettings()). */
inline void applyMatcherSettings(const cv::Ptr<cv::event::StereoEventMatcher>& matcher, const std::string& list)
{
    applyAlgorithmSettings(matcher, list, "--set", "matcher");
}

/** The noise filter of --filter=NAME with --filter-set's "name=value,..." applied; empty for an empty name.
    Throws std::runtime_error for an unknown name, listing the known ones. */
inline cv::Ptr<cv::event::EventFilter> createSampleFilter(const std::string& name, const std::string& settings,
                                                          cv::Size sensorSize)
{
    if (name.empty())
    {
        if (!settings.empty())
            throw std::runtime_error("--filter-set needs --filter");
        return cv::Ptr<cv::event::EventFilter>();
    }
    std::string known;
    bool found = false;
    for (const cv::String& n : cv::event::getEventFilterNames())
    {
        known += (known.empty() ? "" : ", ") + n;
        found = found || n == name;
    }
    if (!found)
        throw std::runtime_error("--filter=" + name + ": available filters: " + known);
    cv::Ptr<cv::event::EventFilter> filter = cv::event::createEventFilter(name, sensorSize);
    applyAlgorithmSettings(filter, settings, "--filter-set", name + " filter");
    return filter;
}

#endif
