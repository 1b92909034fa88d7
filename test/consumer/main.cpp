// A downstream program linked through find_package(opencv_event): merges two tiny streams and checks the
// result, so that a broken install (missing header, library or dependency) fails here.
#include <opencv2/event.hpp>
#include <iostream>

int main()
{
    using namespace cv::event;
    std::vector<Event> left = { Event(1, 10, 5, POLARITY_ON), Event(4, 11, 5, POLARITY_OFF) };
    std::vector<Event> right = { Event(2, 3, 5, POLARITY_ON) };
    std::vector<Event> merged;
    mergeStereoEvents(left, right, merged);
    const bool ok = merged.size() == 3 && merged[1].camera == CAMERA_RIGHT && merged[1].x == 3 &&
                    getSensorSize(SENSOR_DAVIS240) == cv::Size(240, 180);
    std::cout << "event_consumer: " << (ok ? "ok" : "WRONG") << ", " << merged.size() << " events, middle "
              << merged[1] << std::endl;
    return ok ? 0 : 1;
}
