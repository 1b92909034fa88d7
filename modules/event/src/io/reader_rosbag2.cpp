// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// ROS2 bags: a folder with metadata.yaml and its storage files, or one storage file. MCAP storage is
// reader_mcap.cpp's; here the sqlite3 storage (*.db3):
// table topics(id, name, type, ...) and messages(topic_id, timestamp, data), data = CDR-serialised
// event_camera_msgs/msg/EventPacket or its former name event_array_msgs/msg/EventArray (encodings evt3,
// libcaer). Messages are stepped through one at a time
// (ordered by timestamp): memory is one message. Two event topics make a stereo recording (sorted by name:
// the first is the left camera).

#include "precomp.hpp"
#include "io/event_reader.hpp"
#include "io/ros_event_decoder.hpp"

#include <fstream>
#include <sys/stat.h>

#ifdef OPENCV_EVENT_HAVE_SQLITE3
#include <sqlite3.h>
#endif

namespace cv {
namespace event {
namespace detail {

bool isRosBag2(const String& path)
{
    struct stat st;
    if (::stat(path.c_str(), &st) != 0)
        return false;
    if (S_ISDIR(st.st_mode))
        return ::stat((path + "/metadata.yaml").c_str(), &st) == 0;
    std::ifstream f(path.c_str(), std::ios::binary);
    char head[16] = { 0 };
    f.read(head, 16);
    return std::memcmp(head, "SQLite format 3", 16) == 0 || isMcapFile(path);
}

namespace {

// The storage files of a bag (.db3 or .mcap): those metadata.yaml lists under relative_file_paths, in order;
// the file itself when the path is one.
std::vector<std::string> bagFiles(const String& path)
{
    struct stat st;
    if (::stat(path.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        return std::vector<std::string>(1, path);
    std::ifstream meta((path + "/metadata.yaml").c_str());
    std::vector<std::string> files;
    std::string line;
    bool inList = false;
    while (std::getline(meta, line))
    {
        const size_t k = line.find_first_not_of(' ');
        if (k == std::string::npos)
            continue;
        if (line.compare(k, 19, "relative_file_paths") == 0)
        {
            inList = true;
            continue;
        }
        if (inList && line.compare(k, 2, "- ") == 0)
        {
            std::string name = line.substr(k + 2);
            while (!name.empty() && (name.back() == '\r' || name.back() == ' '))
                name.pop_back();
            files.push_back(path + "/" + name);
        }
        else if (inList)
            inList = false;
    }
    if (files.empty())
        CV_Error_(Error::StsParseError, ("%s/metadata.yaml: no relative_file_paths entry (not a ROS2 bag?)", path.c_str()));
    return files;
}

}  // namespace

#ifdef OPENCV_EVENT_HAVE_SQLITE3

namespace {

class RosBag2Reader CV_FINAL : public EventReader
{
public:
    RosBag2Reader(const String& path, const std::vector<std::string>& files, const ReaderOptions& options)
        : path_(path), files_(files)
    {
        // The destructor does not run when a constructor throws: close the database on the way out.
        try
        {
            init(options);
        }
        catch (...)
        {
            close();
            throw;
        }
    }

    ~RosBag2Reader() CV_OVERRIDE { close(); }

    String name() const CV_OVERRIDE { return "ROSBAG2"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    bool isStereo() const CV_OVERRIDE { return stereo_; }
    int64 skippedEvents() const CV_OVERRIDE { return decoder_.skipped(); }
    void takeTriggers(std::vector<EventTrigger>& out) CV_OVERRIDE { decoder_.takeTriggers(out); }
    double progress() const CV_OVERRIDE
    {
        return total_ > 0 ? (fileIndex_ + (double)rows_ / (double)total_) / (double)files_.size() : -1.0;
    }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        const size_t before = out.size();
        while (out.size() == before)
        {
            const int r = sqlite3_step(stmt_);
            if (r == SQLITE_DONE)
            {
                if (fileIndex_ + 1 >= files_.size())
                    return false;
                open(fileIndex_ + 1);
                startQuery();
                continue;
            }
            if (r != SQLITE_ROW)
                CV_Error_(Error::StsParseError, ("%s: sqlite error: %s", files_[fileIndex_].c_str(), sqlite3_errmsg(db_)));
            rows_++;
            const uchar* data = static_cast<const uchar*>(sqlite3_column_blob(stmt_, 0));
            const size_t n = (size_t)sqlite3_column_bytes(stmt_, 0);
            decodeMessage(data, n, sqlite3_column_int64(stmt_, 1), out);
        }
        return true;
    }

private:
    void init(const ReaderOptions& options)
    {
        open(0);
        // Event topics of the first file, sorted by name.
        std::vector<std::pair<std::string, int>> topics;
        sqlite3_stmt* q = prepare("SELECT name, id FROM topics WHERE type = ? OR type = ? ORDER BY name");
        sqlite3_bind_text(q, 1, kRos2EventPacket, -1, SQLITE_STATIC);
        sqlite3_bind_text(q, 2, kRos2LegacyEventArray, -1, SQLITE_STATIC);
        while (sqlite3_step(q) == SQLITE_ROW)
            topics.push_back(std::make_pair(std::string((const char*)sqlite3_column_text(q, 0)), sqlite3_column_int(q, 1)));
        sqlite3_finalize(q);
        topic_ = topics[pickRos2EventTopic(topics.size(), options.cameraFilter, files_[0], stereo_)].first;
        size_ = options.sensorSize;
        startQuery();
        if (size_.empty())
        {
            // The first message tells the sensor size; decode it, then start again.
            std::vector<Event> scratch;
            next(scratch);
            decoder_ = RosEventDecoder();
            open(0);
            startQuery();
        }
        }

    void open(size_t index)
    {
        close();
        fileIndex_ = index;
        const std::string& f = files_[index];
        if (sqlite3_open_v2(f.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
        {
            const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
            close();
            CV_Error_(Error::StsError, ("%s: cannot open the sqlite database: %s", f.c_str(), msg.c_str()));
        }
    }

    sqlite3_stmt* prepare(const char* sql)
    {
        sqlite3_stmt* s = nullptr;
        if (sqlite3_prepare_v2(db_, sql, -1, &s, nullptr) != SQLITE_OK)
            CV_Error_(Error::StsParseError, ("%s: not a ROS2 bag database (%s)", files_[fileIndex_].c_str(), sqlite3_errmsg(db_)));
        return s;
    }

    void startQuery()
    {
        sqlite3_stmt* c = prepare("SELECT count(*) FROM messages m JOIN topics t ON m.topic_id = t.id WHERE t.name = ?");
        sqlite3_bind_text(c, 1, topic_.c_str(), -1, SQLITE_TRANSIENT);
        total_ = sqlite3_step(c) == SQLITE_ROW ? sqlite3_column_int64(c, 0) : 0;
        sqlite3_finalize(c);
        rows_ = 0;
        stmt_ = prepare("SELECT m.data, m.id FROM messages m JOIN topics t ON m.topic_id = t.id "
                        "WHERE t.name = ? ORDER BY m.timestamp, m.id");
        sqlite3_bind_text(stmt_, 1, topic_.c_str(), -1, SQLITE_TRANSIENT);
    }

    void close()
    {
        if (stmt_)
            sqlite3_finalize(stmt_);
        stmt_ = nullptr;
        if (db_)
            sqlite3_close(db_);
        db_ = nullptr;
    }

    void decodeMessage(const uchar* data, size_t n, int64 messageId, std::vector<Event>& out)
    {
        decoder_.decodeCdrPacket(data, n, files_[fileIndex_] + " (message id " + std::to_string(messageId) + ")",
                                 size_, out);
    }

    String path_;
    std::vector<std::string> files_;
    size_t fileIndex_ = 0;
    sqlite3* db_ = nullptr;
    sqlite3_stmt* stmt_ = nullptr;
    std::string topic_;
    Size size_;
    bool stereo_ = false;
    int64 total_ = 0, rows_ = 0;
    RosEventDecoder decoder_;
};

}  // namespace

#endif

Ptr<EventReader> openRosBag2Reader(const String& path, const ReaderOptions& options)
{
    const std::vector<std::string> files = bagFiles(path);
    if (isMcapFile(files[0]) || fileExtension(files[0]) == "mcap")
        return openMcapReader(path, files, options);
#ifdef OPENCV_EVENT_HAVE_SQLITE3
    return makePtr<RosBag2Reader>(path, files, options);
#else
    CV_Error_(Error::StsNotImplemented, ("%s: ROS2 bags in sqlite3 storage need sqlite3, which this build was "
                                         "configured without (install libsqlite3-dev and rebuild)", path.c_str()));
#endif
}

}  // namespace detail
}  // namespace event
}  // namespace cv
