// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/ProcessMemory.h"

#include <fstream>
#include <string>
#include <string_view>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vv {

namespace {

/// /proc/self/NAME or /proc/<pid>/NAME.
std::string procFile(int pid, const char* name) {
    return "/proc/" + (pid == 0 ? std::string("self") : std::to_string(pid)) + "/" + name;
}

/// The value of a "Key:   123 kB" line of /proc/<pid>/status.
std::optional<std::uint64_t> statusKiB(int pid, std::string_view key) {
    std::ifstream in(procFile(pid, "status"));
    std::string line;
    while (std::getline(in, line)) {
        if (line.size() > key.size() && line.compare(0, key.size(), key) == 0 &&
            line[key.size()] == ':') {
            try {
                return std::stoull(line.substr(key.size() + 1));
            } catch (const std::exception&) {
                return std::nullopt;
            }
        }
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::uint64_t> residentKiB(int pid) {
    return statusKiB(pid, "VmRSS");
}

std::optional<std::uint64_t> peakResidentKiB(int pid) {
    return statusKiB(pid, "VmHWM");
}

bool resetPeakResident(int pid) {
    std::ofstream out(procFile(pid, "clear_refs"));
    out << "5" << std::flush;
    return static_cast<bool>(out);
}

bool handFreedMemoryBackAtOnce() {
#if defined(__GLIBC__)
    // glibc's own defaults, fixed: setting either stops their raising.
    constexpr int kMapThresholdBytes = 128 * 1024;
    return mallopt(M_MMAP_THRESHOLD, kMapThresholdBytes) == 1 &&
           mallopt(M_TRIM_THRESHOLD, kMapThresholdBytes) == 1;
#else
    return false;
#endif
}

}  // namespace vv
