// Command lines of the sample and benchmark programs: cv::CommandLineParser, as OpenCV's own samples use it,
// plus the checks it leaves to the caller.
//
// The syntax is CommandLineParser's: --key=value for options, --flag for switches, plain words for positional
// arguments, --help for the generated usage. CommandLineParser itself ignores a key it does not know and reads
// "--left FILE" as the switch --left=true followed by a positional FILE; ProgramCommandLine refuses both, with
// a message saying what to write instead, so that a typo never runs with a default silently.
//
// Conventions of the keys string: a switch has the default "false"; every other key takes a value.

#ifndef OPENCV_EVENT_COMMON_COMMAND_LINE_HPP
#define OPENCV_EVENT_COMMON_COMMAND_LINE_HPP

#include <opencv2/core/utility.hpp>
#include <opencv2/event/types.hpp>

#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

/** What a program prints of an error that stopped it: a cv::Exception's own message (naming the file or the
    camera and the problem), without OpenCV's source location and function name; any other exception's text. */
inline std::string errorText(const std::exception& e)
{
    const cv::Exception* cvError = dynamic_cast<const cv::Exception*>(&e);
    return cvError ? cvError->err : std::string(e.what());
}

/** The error for a recording whose format does not record the sensor size (text without a size line, DAT
    without a geometry line): what to give, and where to find it. */
inline std::runtime_error sensorSizeMissing(const std::string& source)
{
    return std::runtime_error(source + ": the file does not record the sensor size; pass --sensor=WxH (event_info "
                              "lists the pixels its events lie on)");
}

/** The sensor model --sensor names for a simulated scene (cv::event::findSensorModel(): DVS128, DAVIS240,
    DAVIS346, any case); a size or an unknown name is an error saying what to give instead. */
inline int sceneSensorModel(const std::string& name)
{
    const int model = cv::event::findSensorModel(name);
    if (model < 0)
        throw std::runtime_error("--sensor=" + name
                                 + ": a simulated scene needs a sensor model by name (DVS128, DAVIS240, DAVIS346)");
    return model;
}

/** What to do about input events outside the sensor. A text recording that counts pixels from 1 (TUM's DVS128
    pairs, x and y in 1..128) puts its last column and row one past a sensor counted from 0 and never uses
    column or row 0: --one-based reads it. */
inline std::string outsideEventsAdvice(bool textFile, bool oneBased, bool eventsTouchZero)
{
    if (textFile && !oneBased && !eventsTouchZero)
        return "no event lies in column or row 0: if the file counts pixels from 1, give --one-based";
    return "--sensor=WxH sets the size";
}

/** The warning for @p outside input events that lay outside the @p sensor and were not processed, with
    outsideEventsAdvice(). */
inline std::string outsideEventsWarning(long long outside, int width, int height, bool textFile, bool oneBased,
                                        bool eventsTouchZero)
{
    return std::to_string(outside) + " input events lie outside the " + std::to_string(width) + " x " +
           std::to_string(height) + " sensor and were not processed (" +
           outsideEventsAdvice(textFile, oneBased, eventsTouchZero) + ")";
}

/** True when an event of @p events lies in column 0 or row 0 (see outsideEventsAdvice()). */
template <typename EventT>
inline bool touchesColumnOrRowZero(const std::vector<EventT>& events)
{
    for (const EventT& e : events)
        if (e.x == 0 || e.y == 0)
            return true;
    return false;
}

/** The items of a comma-separated option value ("boxes,walking"), empty ones left out. */
inline std::vector<std::string> commaList(const std::string& text)
{
    std::vector<std::string> items;
    std::stringstream list(text);
    for (std::string item; std::getline(list, item, ',');)
        if (!item.empty())
            items.push_back(item);
    return items;
}

/** "a=1,b=2" -> {(a, 1), (b, 2)}: the value of list options such as --set. Empty items are skipped; an item
    that is not NAME=VALUE throws std::runtime_error naming @p option. */
inline std::vector<std::pair<std::string, std::string>> parseNameValueList(const std::string& option,
                                                                           const std::string& list)
{
    std::vector<std::pair<std::string, std::string>> out;
    for (const std::string& item : commaList(list))
    {
        const size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw std::runtime_error(option + ": \"" + item + "\" is not NAME=VALUE");
        out.push_back(std::make_pair(item.substr(0, eq), item.substr(eq + 1)));
    }
    return out;
}

class ProgramCommandLine
{
public:
    /** Parses @p argv against @p keys (CommandLineParser syntax). @p extraPositionals: plain words beyond the
        declared @-keys are kept (positionals()) instead of refused. Throws std::runtime_error on an unknown
        key, a value key without "=value", a switch given a value other than true/false, or a surplus word. */
    ProgramCommandLine(int argc, const char* const argv[], const std::string& keys, const std::string& about,
                      bool extraPositionals = false)
        : parser_(argc, argv, keys)
    {
        parser_.about(about);
        readKeys(keys);
        for (int i = 1; i < argc; i++)
            checkArgument(argv[i], extraPositionals);
    }

    /** When --help (or -h) was given: prints the generated usage and returns true. */
    bool helpShown()
    {
        if (!has("help"))
            return false;
        parser_.printMessage();
        return true;
    }

    template <typename T>
    T get(const std::string& name)
    {
        const T value = parser_.get<T>(name);
        throwOnError(name);
        return value;
    }

    /** Whether the key was given on the command line (switches: and not as =false). */
    bool has(const std::string& name) const
    {
        if (switches_.count(name))
            return parser_.get<bool>(name);
        return given_.count(name) != 0;
    }

    /** The plain words, in order (all of them, the declared @-keys included). */
    const std::vector<std::string>& positionals() const { return positionals_; }

private:
    void readKeys(const std::string& keys)
    {
        // Each key: {names | default | help}; names are separated by spaces, positionals start with '@'.
        size_t pos = 0;
        while ((pos = keys.find('{', pos)) != std::string::npos)
        {
            const size_t end = keys.find('}', pos);
            if (end == std::string::npos)
                break;
            const std::string entry = keys.substr(pos + 1, end - pos - 1);
            pos = end + 1;
            const size_t bar1 = entry.find('|'), bar2 = entry.find('|', bar1 + 1);
            if (bar1 == std::string::npos || bar2 == std::string::npos)
                continue;
            const std::string names = entry.substr(0, bar1), defaultValue = trim(entry.substr(bar1 + 1, bar2 - bar1 - 1));
            std::string primary;
            size_t s = 0;
            while (s < names.size())
            {
                const size_t e = names.find(' ', s);
                const std::string name = names.substr(s, e == std::string::npos ? std::string::npos : e - s);
                s = e == std::string::npos ? names.size() : e + 1;
                if (name.empty())
                    continue;
                if (name[0] == '@')
                {
                    declaredPositionals_++;
                    break;
                }
                if (primary.empty())
                    primary = name;
                primaryOf_[name] = primary;
                if (defaultValue == "false" || name == "help" || name == "h")
                    switches_.insert(name);
            }
        }
    }

    void checkArgument(const std::string& a, bool extraPositionals)
    {
        if (a.size() < 2 || a[0] != '-')
        {
            positionals_.push_back(a);
            if (!extraPositionals && (int)positionals_.size() > declaredPositionals_)
                throw std::runtime_error("unexpected argument \"" + a + "\" (options are written --key=value; "
                                         "--help lists them)");
            return;
        }
        const std::string body = a.substr(a[1] == '-' ? 2 : 1);
        const size_t eq = body.find('=');
        const std::string name = body.substr(0, eq);
        const auto known = primaryOf_.find(name);
        if (known == primaryOf_.end())
            throw std::runtime_error("unknown option " + a + " (--help lists them)");
        given_.insert(known->second);
        if (switches_.count(name))
        {
            if (eq != std::string::npos && body.substr(eq + 1) != "true" && body.substr(eq + 1) != "false")
                throw std::runtime_error("--" + name + " is a switch: write --" + name + " alone");
        }
        else if (eq == std::string::npos)
            throw std::runtime_error("--" + name + " needs a value: write --" + name + "=VALUE");
    }

    void throwOnError(const std::string& name)
    {
        if (parser_.check())
            return;
        throw std::runtime_error("--" + name + ": not a valid value (--help lists the options)");
    }

    static std::string trim(const std::string& s)
    {
        const size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
        return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
    }

    cv::CommandLineParser parser_;
    std::map<std::string, std::string> primaryOf_;
    std::set<std::string> switches_, given_;  // switch names (aliases too); primary names given
    std::vector<std::string> positionals_;
    int declaredPositionals_ = 0;
};

#endif
