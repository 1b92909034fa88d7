// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// MVSEC-style HDF5 (doc/formats.md, "MVSEC-style HDF5"): /davis/left/events and /davis/right/events, float64 N x 4
// rows [x, y, t (s), p (-1/+1; > 0 is ON)], DAVIS346 346 x 260. Rows are read in hyperslabs of one chunk:
// memory does not grow with the file. A file with both cameras is a stereo recording.
// Optional: only built when CMake finds libhdf5.

#include "precomp.hpp"
#include "io/event_reader.hpp"

#ifdef OPENCV_EVENT_HAVE_HDF5
#include <hdf5.h>
#endif

namespace cv {
namespace event {
namespace detail {

#ifdef OPENCV_EVENT_HAVE_HDF5

namespace {

const char* kDatasets[2] = { "/davis/left/events", "/davis/right/events" };

class Hdf5Reader CV_FINAL : public EventReader
{
public:
    Hdf5Reader(const String& path, const ReaderOptions& options) : path_(path)
    {
        // The destructor does not run when a constructor throws: release the HDF5 handles on the way out.
        try
        {
            init(options);
        }
        catch (...)
        {
            closeHandles();
            throw;
        }
    }

    ~Hdf5Reader() CV_OVERRIDE { closeHandles(); }

    String name() const CV_OVERRIDE { return "HDF5_MVSEC"; }
    Size sensorSize() const CV_OVERRIDE { return size_; }
    bool isStereo() const CV_OVERRIDE { return stereo_; }
    double progress() const CV_OVERRIDE { return rows_ > 0 ? (double)row_ / (double)rows_ : 1.0; }

    bool next(std::vector<Event>& out) CV_OVERRIDE
    {
        if (row_ >= rows_)
            return false;
        const hsize_t n = (hsize_t)std::min<int64>((int64)kReaderChunk, rows_ - row_);
        const hsize_t start[2] = { (hsize_t)row_, 0 }, count[2] = { n, 4 };
        buffer_.resize((size_t)n * 4);
        hid_t mem = H5Screate_simple(2, count, nullptr);
        H5Sselect_hyperslab(space_, H5S_SELECT_SET, start, nullptr, count, nullptr);
        const herr_t r = H5Dread(dataset_, H5T_NATIVE_DOUBLE, mem, space_, H5P_DEFAULT, buffer_.data());
        H5Sclose(mem);
        if (r < 0)
            fail(format("cannot read rows %lld..%lld", (long long)row_, (long long)(row_ + (int64)n)));
        for (hsize_t i = 0; i < n; i++)
        {
            const double* e = &buffer_[4 * i];
            if (!(std::abs(e[0]) < 32768 && std::abs(e[1]) < 32768 && std::abs(e[2]) < 9e9))
                fail(format("row %lld holds no event (%g, %g, %g, %g)", (long long)(row_ + (int64)i), e[0], e[1], e[2], e[3]));
            out.push_back(Event((int64)std::llround(e[2] * 1e6), (int)std::lround(e[0]), (int)std::lround(e[1]),
                                e[3] > 0 ? POLARITY_ON : POLARITY_OFF));
        }
        row_ += (int64)n;
        return true;
    }

private:
    void init(const ReaderOptions& options)
    {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported as cv::Exception, not printed
        file_ = H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        if (file_ < 0)
            CV_Error_(Error::StsError, ("%s: cannot open as HDF5", path_.c_str()));
        const bool have[2] = { exists(kDatasets[0]), exists(kDatasets[1]) };
        if (!have[0] && !have[1])
            fail("no /davis/left/events or /davis/right/events dataset (MVSEC layout)");
        stereo_ = options.cameraFilter < 0 && have[0] && have[1];
        const int pick = options.cameraFilter >= 0 ? options.cameraFilter : (have[0] ? 0 : 1);
        if (!have[pick])
            fail(std::string("no ") + kDatasets[pick] + " dataset");
        dataset_ = H5Dopen2(file_, kDatasets[pick], H5P_DEFAULT);
        space_ = H5Dget_space(dataset_);
        hsize_t dims[2] = { 0, 0 };
        if (dataset_ < 0 || space_ < 0 || H5Sget_simple_extent_ndims(space_) != 2)
            fail(std::string(kDatasets[pick]) + " is not a 2-D dataset");
        H5Sget_simple_extent_dims(space_, dims, nullptr);
        if (dims[1] != 4)
            fail(format("%s has %llu columns; MVSEC events have 4 (x, y, t, p)", kDatasets[pick], (unsigned long long)dims[1]));
        rows_ = (int64)dims[0];
        size_ = options.sensorSize.empty() ? Size(346, 260) : options.sensorSize;  // MVSEC: DAVIS346
        }

    void closeHandles()
    {
        if (space_ >= 0) H5Sclose(space_);
        if (dataset_ >= 0) H5Dclose(dataset_);
        if (file_ >= 0) H5Fclose(file_);
        space_ = dataset_ = file_ = -1;
    }

    bool exists(const char* name) const
    {
        // Walk the path: H5Lexists needs every parent to exist.
        std::string prefix;
        std::string p(name);
        size_t from = 1;
        for (;;)
        {
            const size_t slash = p.find('/', from);
            prefix = p.substr(0, slash);
            if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0)
                return false;
            if (slash == std::string::npos)
                return true;
            from = slash + 1;
        }
    }

    [[noreturn]] void fail(const std::string& what) const
    {
        CV_Error_(Error::StsParseError, ("%s: %s", path_.c_str(), what.c_str()));
    }

    String path_;
    hid_t file_ = -1, dataset_ = -1, space_ = -1;
    int64 rows_ = 0, row_ = 0;
    Size size_;
    bool stereo_ = false;
    std::vector<double> buffer_;
};

}  // namespace

Ptr<EventReader> openHdf5Reader(const String& path, const ReaderOptions& options)
{
    return makePtr<Hdf5Reader>(path, options);
}

#else

Ptr<EventReader> openHdf5Reader(const String& path, const ReaderOptions&)
{
    CV_Error_(Error::StsNotImplemented, ("%s: HDF5 recordings need libhdf5, which this build was configured "
                                         "without (install libhdf5-dev and rebuild)", path.c_str()));
}

#endif

}  // namespace detail
}  // namespace event
}  // namespace cv
