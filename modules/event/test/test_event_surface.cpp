// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

namespace opencv_test { namespace {

TEST(Event_Surface, stores_last_timestamp_per_pixel_and_polarity)
{
    Ptr<EventSurface> s = EventSurface::create(Size(6, 4));
    EXPECT_EQ(EventSurface::NO_EVENT, s->at(2, 1, POLARITY_ON));
    std::vector<Event> ev;
    ev.push_back(Event(100, 2, 1, POLARITY_ON));
    ev.push_back(Event(150, 2, 1, POLARITY_OFF));
    ev.push_back(Event(200, 2, 1, POLARITY_ON));
    ev.push_back(Event(210, 5, 3, POLARITY_OFF));
    s->update(ev);
    EXPECT_EQ(200, s->at(2, 1, POLARITY_ON));
    EXPECT_EQ(150, s->at(2, 1, POLARITY_OFF));
    EXPECT_EQ(200, s->latest(2, 1));
    EXPECT_EQ(210, s->at(5, 3, POLARITY_OFF));
    EXPECT_EQ(EventSurface::NO_EVENT, s->at(5, 3, POLARITY_ON));
    EXPECT_EQ(4.0, s->getEventCount());

    // ptr(): contiguous rows, width stride.
    EXPECT_EQ(200, s->ptr(POLARITY_ON, 1)[2]);
    EXPECT_EQ(210, s->ptr(POLARITY_OFF, 0)[3 * 6 + 5]);

    s->update(Event(300, 0, 0, POLARITY_ON));
    EXPECT_EQ(300, s->at(0, 0, POLARITY_ON));
    EXPECT_EQ(5.0, s->getEventCount());

    s->reset();
    EXPECT_EQ(EventSurface::NO_EVENT, s->at(2, 1, POLARITY_ON));
    EXPECT_EQ(0.0, s->getEventCount());
}

TEST(Event_Surface, time_surface_matches_exponential_decay)
{
    Ptr<EventSurface> s = EventSurface::create(Size(5, 3));
    s->update(Event(1000, 0, 0, POLARITY_ON));
    s->update(Event(4000, 1, 0, POLARITY_OFF));
    s->update(Event(9000, 2, 0, POLARITY_ON));  // after the render time: must not show
    const double tau = 2000;
    Mat f, u;
    s->renderTimeSurface(5000, tau, f, CV_32F);
    s->renderTimeSurface(5000, tau, u, CV_8U);
    ASSERT_EQ(CV_32F, f.type());
    ASSERT_EQ(Size(5, 3), f.size());
    EXPECT_NEAR(std::exp(-4000 / tau), f.at<float>(0, 0), 1e-6);
    EXPECT_NEAR(std::exp(-1000 / tau), f.at<float>(0, 1), 1e-6);
    EXPECT_EQ(0.f, f.at<float>(0, 2));
    EXPECT_EQ(0.f, f.at<float>(2, 4));
    EXPECT_EQ(cvRound(255 * std::exp(-1000 / tau)), (int)u.at<uchar>(0, 1));

    s->renderTimeSurface(5000, tau, f, CV_32F, POLARITY_ON);
    EXPECT_EQ(0.f, f.at<float>(0, 1));  // that pixel only had an OFF event
    EXPECT_THROW(s->renderTimeSurface(5000, 0, f, CV_32F), cv::Exception);
    EXPECT_THROW(s->renderTimeSurface(5000, tau, f, CV_16U), cv::Exception);
}

TEST(Event_Surface, event_count_frames_per_polarity)
{
    Ptr<EventSurface> s = EventSurface::create(Size(4, 4));
    for (int k = 0; k < 3; k++)
        s->update(Event(10 * k, 1, 2, POLARITY_ON));
    s->update(Event(40, 1, 2, POLARITY_OFF));
    s->update(Event(50, 3, 3, POLARITY_OFF));
    Mat c;
    s->renderEventCount(c);
    ASSERT_EQ(CV_32S, c.type());
    EXPECT_EQ(4, c.at<int>(2, 1));
    EXPECT_EQ(1, c.at<int>(3, 3));
    EXPECT_EQ(5, (int)sum(c)[0]);
    s->renderEventCount(c, POLARITY_ON);
    EXPECT_EQ(3, c.at<int>(2, 1));
    s->renderEventCount(c, -2);
    EXPECT_EQ(2, c.at<int>(2, 1));
    EXPECT_EQ(-1, c.at<int>(3, 3));

    s->clearCounts();
    s->renderEventCount(c);
    EXPECT_EQ(0, countNonZero(c));
    EXPECT_EQ(50, s->at(3, 3, POLARITY_OFF));  // timestamps survive clearCounts()
}

TEST(Event_Surface, out_of_sensor_packet_is_rejected_whole_with_clear_message)
{
    Ptr<EventSurface> s = EventSurface::create(Size(240, 180));
    std::vector<Event> ev;
    ev.push_back(Event(1, 10, 10, POLARITY_ON));
    ev.push_back(Event(2, 240, 5, POLARITY_ON));
    try
    {
        s->update(ev);
        FAIL() << "an event at x = 240 was accepted by a 240 x 180 surface";
    }
    catch (const cv::Exception& e)
    {
        EXPECT_EQ(cv::Error::StsOutOfRange, e.code);
        EXPECT_NE(std::string::npos, e.err.find("#1")) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("x=240")) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("240 x 180")) << e.err;
    }
    EXPECT_EQ(EventSurface::NO_EVENT, s->at(10, 10, POLARITY_ON));  // nothing of the packet was written
    EXPECT_EQ(0.0, s->getEventCount());
    EXPECT_THROW(s->update(Event(3, -1, 0, POLARITY_ON)), cv::Exception);
    EXPECT_THROW(s->at(0, 180, POLARITY_ON), cv::Exception);
}

TEST(Event_Surface, raw_surface_export)
{
    Ptr<EventSurface> s = EventSurface::create(Size(3, 2));
    s->update(Event(5000000000LL, 1, 1, POLARITY_OFF));
    s->update(Event(5000000100LL, 1, 1, POLARITY_ON));
    Mat d, i;
    s->getSurface(-1, d);
    ASSERT_EQ(CV_64F, d.type());
    EXPECT_EQ(5000000100.0, d.at<double>(1, 1));
    EXPECT_TRUE(cvIsInf(d.at<double>(0, 0)) && d.at<double>(0, 0) < 0);
    s->getSurface(POLARITY_OFF, i, CV_32S, 5000000000LL);
    EXPECT_EQ(0, i.at<int>(1, 1));
    EXPECT_EQ(INT_MIN, i.at<int>(0, 2));
}

TEST(Event_Surface, parameters_round_trip_through_filestorage)
{
    Ptr<EventSurface> a = EventSurface::create(Size(346, 260));
    FileStorage fs("surface.yml", FileStorage::WRITE | FileStorage::MEMORY);
    a->write(fs);
    const std::string text = fs.releaseAndGetString();
    EXPECT_NE(std::string::npos, text.find("sensorWidth: 346")) << text;

    Ptr<EventSurface> b = EventSurface::create(Size(10, 10));
    FileStorage in(text, FileStorage::READ | FileStorage::MEMORY);
    b->read(in.root());
    EXPECT_EQ(Size(346, 260), b->getSensorSize());
    EXPECT_NO_THROW(b->update(Event(1, 345, 259, POLARITY_ON)));

    // Algorithm::save() nests the parameters under the algorithm's name.
    const std::string path = cv::tempfile(".yml");
    a->save(path);
    Ptr<EventSurface> c = EventSurface::create(Size(10, 10));
    FileStorage saved(path, FileStorage::READ);
    c->read(saved[c->getDefaultName()]);
    EXPECT_EQ(Size(346, 260), c->getSensorSize());
    saved.release();
    std::remove(path.c_str());
}

}} // namespace
