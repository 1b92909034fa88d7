// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

#include "perf_precomp.hpp"
#include "opencv2/core/utils/logger.hpp"

// CV_PERF_TEST_MAIN(event), except that the regression data is looked for quietly: this module ships no
// sanity file (event.xml), and FileStorage would print "Can't open file: 'event.xml'" on every run.
int main(int argc, char** argv)
{
    CV_TRACE_FUNCTION();
    {
        CV_TRACE_REGION("INIT");
        const cv::utils::logging::LogLevel level = cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
        ::perf::Regression::Init("event");
        cv::utils::logging::setLogLevel(level);
        const char* plainOnly[] = { "plain" };
        ::perf::TestBase::Init(std::vector<std::string>(plainOnly, plainOnly + 1), argc, argv);
        ::testing::InitGoogleTest(&argc, argv);
        ::testing::UnitTest::GetInstance()->listeners().Append(new cvtest::SystemInfoCollector);
        ::testing::Test::RecordProperty("cv_module_name", "event");
        ::perf::TestBase::RecordRunParameters();
    }
    return RUN_ALL_TESTS();
}
