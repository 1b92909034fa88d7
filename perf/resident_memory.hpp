// Resident memory of this process from /proc/self/status, for the benchmark programs' tables (Linux).

#ifndef OPENCV_EVENT_PERF_RESIDENT_MEMORY_HPP
#define OPENCV_EVENT_PERF_RESIDENT_MEMORY_HPP

#include <cstring>
#include <fstream>
#include <string>

namespace bench {

/** A /proc/self/status field in MiB: "VmRSS:" (now) or "VmHWM:" (peak since start or the last reset);
-1 where /proc is not available. */
inline double residentMiB(const char* field)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    const size_t n = std::strlen(field);
    while (std::getline(status, line))
        if (line.compare(0, n, field) == 0)
            return std::stod(line.substr(n)) / 1024.0;
    return -1;
}

/** Resets the peak (VmHWM) to the current resident memory, so that a peak can be measured per phase. */
inline void resetPeakResident()
{
    std::ofstream("/proc/self/clear_refs") << "5";
}

}  // namespace bench

#endif
