// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

// Events whose every field differs from every other field's value and from its neighbours', so that a
// dropped, swapped or truncated field cannot go unnoticed. Timestamps pass 2^32 us to catch 32-bit paths.
std::vector<Event> distinctEvents()
{
    std::vector<Event> ev;
    ev.push_back(Event(5000000000LL, 17, 3, POLARITY_ON, CAMERA_LEFT));
    ev.push_back(Event(5000000007LL, 239, 179, POLARITY_OFF, CAMERA_RIGHT));
    ev.push_back(Event(5000000042LL, 0, 101, POLARITY_ON, CAMERA_RIGHT));
    ev.push_back(Event(9007199254740000LL, 32767, 12, POLARITY_OFF, CAMERA_LEFT));
    return ev;
}

void expectSameEvents(const std::vector<Event>& expected, const std::vector<Event>& actual)
{
    ASSERT_EQ(expected.size(), actual.size());
    for (size_t i = 0; i < expected.size(); i++)
        EXPECT_EQ(expected[i], actual[i]) << "event " << i;
}

TEST(Event_Types, record_layout_matches_documentation)
{
    const Event e(0x0102030405060708LL, 0x1112, 0x2122, POLARITY_ON, CAMERA_RIGHT);
    uchar bytes[16];
    std::memcpy(bytes, &e, sizeof(bytes));
    int64 t;
    short x, y;
    std::memcpy(&t, bytes + 0, 8);
    std::memcpy(&x, bytes + 8, 2);
    std::memcpy(&y, bytes + 10, 2);
    EXPECT_EQ(0x0102030405060708LL, t);
    EXPECT_EQ(0x1112, x);
    EXPECT_EQ(0x2122, y);
    EXPECT_EQ(1, bytes[12]);
    EXPECT_EQ(1, bytes[13]);
    EXPECT_EQ(0, bytes[14]);
    EXPECT_EQ(0, bytes[15]);
    EXPECT_EQ(16, CV_ELEM_SIZE(EVENT_MAT_TYPE));
    EXPECT_EQ((int)EVENT_MAT_TYPE, (int)cv::traits::Type<Event>::value);
}

TEST(Event_Types, polarity_convention_from_signed_and_binary_inputs)
{
    EXPECT_EQ(POLARITY_OFF, Event(0, 0, 0, -1).p);
    EXPECT_EQ(POLARITY_OFF, Event(0, 0, 0, 0).p);
    EXPECT_EQ(POLARITY_ON, Event(0, 0, 0, 1).p);
}

TEST(Event_Types, vector_to_mat_shares_data_and_copies_back)
{
    std::vector<Event> ev = distinctEvents();
    Mat m(ev);  // a header over the vector, no copy
    EXPECT_EQ((int)EVENT_MAT_TYPE, m.type());
    EXPECT_EQ((int)ev.size(), m.rows);
    EXPECT_EQ(1, m.cols);
    EXPECT_EQ((const void*)ev.data(), (const void*)m.data);

    std::vector<Event> back;
    m.copyTo(back);  // through OutputArray into a std::vector<Event>
    expectSameEvents(ev, back);

    Mat_<Event> typed = getEventMat(ev);
    EXPECT_EQ((const void*)ev.data(), (const void*)typed.data);
    expectSameEvents(ev, std::vector<Event>(typed.begin(), typed.end()));
    expectSameEvents(ev, toEventVector(m));
    expectSameEvents(ev, toEventVector(m.t()));  // 1 x N is accepted too
    EXPECT_TRUE(toEventVector(Mat()).empty()) << "an empty packet is no events";
    EXPECT_TRUE(toEventVector(std::vector<Event>()).empty());
}

TEST(Event_Types, getEventMat_rejects_other_types)
{
    Mat wrong(10, 4, CV_64F, Scalar(0));
    try
    {
        getEventMat(wrong);
        FAIL() << "a 10x4 CV_64F Mat was accepted as an event packet";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_EQ(cv::Error::StsUnsupportedFormat, e.code);
        EXPECT_NE(std::string::npos, e.err.find("CV_64F")) << e.err;
    }
    Mat twoD(3, 3, EVENT_MAT_TYPE);
    EXPECT_THROW(getEventMat(twoD), cv::Exception);
    EXPECT_TRUE(getEventMat(noArray()).empty());
}

TEST(Event_Types, pack_unpack_round_trip)
{
    const std::vector<Event> ev = distinctEvents();
    Mat t, x, y, p, camera;
    unpackEvents(ev, t, x, y, p, camera);
    ASSERT_EQ(CV_64F, t.type());
    ASSERT_EQ(CV_32S, x.type());
    ASSERT_EQ(CV_8U, p.type());
    EXPECT_EQ(5000000007.0, t.at<double>(1));
    EXPECT_EQ(239, x.at<int>(1));
    EXPECT_EQ(179, y.at<int>(1));
    EXPECT_EQ(0, p.at<uchar>(1));
    EXPECT_EQ(1, camera.at<uchar>(1));

    std::vector<Event> packed;
    packEvents(t, x, y, p, packed, camera);
    expectSameEvents(ev, packed);

    // The -1/+1 polarity convention of many datasets, float coordinates and no camera column.
    Mat_<double> tt = (Mat_<double>(2, 1) << 10, 20);
    Mat_<float> xf = (Mat_<float>(2, 1) << 3.f, 4.f), yf = (Mat_<float>(2, 1) << 5.f, 6.f);
    Mat_<int> ps = (Mat_<int>(2, 1) << -1, 1);
    packEvents(tt, xf, yf, ps, packed);
    ASSERT_EQ(2u, packed.size());
    EXPECT_EQ(Event(10, 3, 5, POLARITY_OFF, CAMERA_LEFT), packed[0]);
    EXPECT_EQ(Event(20, 4, 6, POLARITY_ON, CAMERA_LEFT), packed[1]);

    Mat_<int> shortColumn = (Mat_<int>(1, 1) << 0);
    EXPECT_THROW(packEvents(tt, shortColumn, yf, ps, packed), cv::Exception);
    Mat_<int> badCamera = (Mat_<int>(2, 1) << 0, 2);
    EXPECT_THROW(packEvents(tt, xf, yf, ps, packed, badCamera), cv::Exception);
}

TEST(Event_Types, filestorage_round_trip_keeps_every_field)
{
    const std::vector<Event> ev = distinctEvents();
    const char* exts[] = { ".yml", ".xml", ".json" };
    for (const char* ext : exts)
    {
        FileStorage fs(std::string("events") + ext, FileStorage::WRITE | FileStorage::MEMORY);
        fs << "packet" << ev;
        fs << "single" << ev[1];
        const std::string text = fs.releaseAndGetString();

        FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
        std::vector<Event> back;
        in["packet"] >> back;
        expectSameEvents(ev, back);
        Event single;
        in["single"] >> single;
        EXPECT_EQ(ev[1], single) << ext;

        std::vector<Event> fallback(1, Event(1, 2, 3, 1)), missing;
        read(in["absent"], missing, fallback);
        expectSameEvents(fallback, missing);
    }
}

TEST(Event_Types, filestorage_rejects_malformed_event)
{
    FileStorage fs("bad.yml", FileStorage::WRITE | FileStorage::MEMORY);
    fs << "packet" << "[" << "[:" << 1 << 2 << "]" << "]";
    FileStorage in(fs.releaseAndGetString(), FileStorage::READ | FileStorage::MEMORY);
    std::vector<Event> back;
    EXPECT_THROW(in["packet"] >> back, cv::Exception);
}

TEST(Event_Types, stereo_merge_is_stable_time_ordered_and_splits_back)
{
    std::vector<Event> left, right;
    left.push_back(Event(10, 1, 1, 1));
    left.push_back(Event(20, 2, 1, 0));
    left.push_back(Event(20, 3, 1, 1));
    left.push_back(Event(35, 4, 1, 1));
    right.push_back(Event(5, 1, 2, 0, CAMERA_LEFT));  // the id is overwritten by the merge
    right.push_back(Event(20, 2, 2, 1));
    right.push_back(Event(40, 3, 2, 1));

    std::vector<Event> merged;
    mergeStereoEvents(left, right, merged);
    ASSERT_EQ(7u, merged.size());
    EXPECT_EQ(-1, findTimeOrderViolation(merged));
    const int expectedX[] = { 1, 1, 2, 3, 2, 4, 3 };       // ties: left first, order within a camera kept
    const int expectedCamera[] = { 1, 0, 0, 0, 1, 0, 1 };
    for (int i = 0; i < 7; i++)
    {
        EXPECT_EQ(expectedX[i], merged[i].x) << i;
        EXPECT_EQ(expectedCamera[i], merged[i].camera) << i;
    }

    std::vector<Event> l2, r2;
    splitStereoEvents(merged, l2, r2);
    expectSameEvents(left, l2);
    right[0].camera = CAMERA_RIGHT;
    for (Event& e : right)
        e.camera = CAMERA_RIGHT;
    expectSameEvents(right, r2);

    // A clock offset shifts the right stream before merging.
    mergeStereoEvents(left, right, merged, 100);
    EXPECT_EQ(105, merged[4].t);
    EXPECT_EQ(CAMERA_RIGHT, merged[4].camera);
    EXPECT_EQ(-1, findTimeOrderViolation(merged));
}

TEST(Event_Types, stereo_merge_rejects_unordered_input)
{
    std::vector<Event> left, right;
    left.push_back(Event(10, 0, 0, 1));
    left.push_back(Event(9, 0, 0, 1));
    EXPECT_EQ(1, findTimeOrderViolation(left));
    std::vector<Event> merged;
    EXPECT_THROW(mergeStereoEvents(left, right, merged), cv::Exception);
    EXPECT_THROW(mergeStereoEvents(right, left, merged), cv::Exception);
}

TEST(Event_Types, sensor_models)
{
    EXPECT_EQ(Size(128, 128), getSensorSize(SENSOR_DVS128));
    EXPECT_EQ(Size(240, 180), getSensorSize(SENSOR_DAVIS240));
    EXPECT_EQ(Size(346, 260), getSensorSize(SENSOR_DAVIS346));
    EXPECT_EQ(Size(1280, 720), getSensorSize(SENSOR_PROPHESEE_GEN4));
    EXPECT_EQ((int)SENSOR_DAVIS346, findSensorModel("davis346"));
    EXPECT_EQ(-1, findSensorModel("no such camera"));
    EXPECT_EQ("DAVIS240", getSensorModelName(SENSOR_DAVIS240));
    EXPECT_THROW(getSensorSize(42), cv::Exception);
    EXPECT_EQ(Size(346, 260), parseSensorSize("346x260"));
    EXPECT_EQ(Size(128, 128), parseSensorSize("dvs128"));
    EXPECT_THROW(parseSensorSize("346x"), cv::Exception);
    EXPECT_THROW(parseSensorSize("346x260x3"), cv::Exception);
}

}} // namespace
