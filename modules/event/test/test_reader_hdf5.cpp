// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "test_precomp.hpp"

#ifdef OPENCV_EVENT_HAVE_HDF5
#include <hdf5.h>
#endif

namespace opencv_test { namespace {

#ifdef OPENCV_EVENT_HAVE_HDF5
// Writes an MVSEC-style file: float64 N x 4 rows [x, y, t (s), p (-1/+1)] per camera (doc/formats.md, "MVSEC-style HDF5").
void writeMvsec(const std::string& path, const std::vector<std::vector<double>>& left,
                const std::vector<std::vector<double>>& right)
{
    hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    hid_t g = H5Gcreate2(f, "/davis", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const char* groups[2] = { "/davis/left", "/davis/right" };
    const std::vector<std::vector<double>>* rows[2] = { &left, &right };
    for (int c = 0; c < 2; c++)
    {
        if (rows[c]->empty())
            continue;
        hid_t gc = H5Gcreate2(f, groups[c], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        std::vector<double> flat;
        for (const auto& r : *rows[c])
            flat.insert(flat.end(), r.begin(), r.end());
        const hsize_t dims[2] = { rows[c]->size(), 4 };
        hid_t space = H5Screate_simple(2, dims, nullptr);
        hid_t d = H5Dcreate2(f, (std::string(groups[c]) + "/events").c_str(), H5T_IEEE_F64LE, space,
                             H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, flat.data());
        H5Dclose(d);
        H5Sclose(space);
        H5Gclose(gc);
    }
    H5Gclose(g);
    H5Fclose(f);
}
#endif

TEST(Event_Capture_Hdf5, mvsec_left_right_datasets_are_a_stereo_pair)
{
#ifndef OPENCV_EVENT_HAVE_HDF5
    throw SkipTestException("built without libhdf5");
#else
    const std::string path = cv::tempfile(".hdf5");
    writeMvsec(path, { { 10, 20, 1504645177.000001, 1 }, { 345, 259, 1504645177.000250, -1 } },
               { { 5, 6, 1504645177.000100, -1 } });
    EXPECT_EQ("HDF5", detectEventFileFormat(path));
    EventCapture cap(path);
    EXPECT_EQ("HDF5_MVSEC", cap.getBackendName());
    EXPECT_EQ(Size(346, 260), cap.getSensorSize());
    EXPECT_EQ(1.0, cap.get(EVENT_CAP_PROP_STEREO));
    cap.set(EVENT_CAP_PROP_BATCH_EVENTS, 10);
    std::vector<Event> ev;
    ASSERT_TRUE(cap.read(ev));
    ASSERT_EQ(3u, ev.size());
    EXPECT_EQ(Event(1504645177000001LL, 10, 20, POLARITY_ON, CAMERA_LEFT), ev[0]);
    EXPECT_EQ(Event(1504645177000100LL, 5, 6, POLARITY_OFF, CAMERA_RIGHT), ev[1]);
    EXPECT_EQ(Event(1504645177000250LL, 345, 259, POLARITY_OFF, CAMERA_LEFT), ev[2]);
    EXPECT_FALSE(cap.read(ev));
    std::remove(path.c_str());

    // A file without the MVSEC datasets: an error naming the file.
    const std::string other = cv::tempfile(".h5");
    writeMvsec(other, {}, {});
    try { EventCapture c(other); FAIL() << "an HDF5 file without events was accepted"; }
    catch (const cv::Exception& e)
    {
        EXPECT_NE(std::string::npos, e.err.find(other)) << e.err;
        EXPECT_NE(std::string::npos, e.err.find("/davis/left/events")) << e.err;
    }
    std::remove(other.c_str());
#endif
}

}} // namespace
