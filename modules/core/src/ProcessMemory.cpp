// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/ProcessMemory.h"

#include <fstream>
#include <string>
#include <string_view>

namespace vv {

namespace {

/// The value of a "Key:   123 kB" line of /proc/self/status.
std::optional<std::uint64_t> statusKiB(std::string_view key) {
    std::ifstream in("/proc/self/status");
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

std::optional<std::uint64_t> residentKiB() {
    return statusKiB("VmRSS");
}

std::optional<std::uint64_t> peakResidentKiB() {
    return statusKiB("VmHWM");
}

bool resetPeakResident() {
    std::ofstream out("/proc/self/clear_refs");
    out << "5" << std::flush;
    return static_cast<bool>(out);
}

}  // namespace vv
