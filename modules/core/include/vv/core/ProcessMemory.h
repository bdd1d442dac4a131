// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <optional>

// A process's memory as Linux reports it (/proc/<pid>/status), for the
// soak, benchmarks and memory tests: this process's (pid 0) or a child's
// (the benchmarks' listener process). Elsewhere the readings are absent.

namespace vv {

/// Resident memory now (VmRSS) of process `pid` (0: this process), KiB;
/// nullopt when it cannot be read (no such process, not Linux).
[[nodiscard]] std::optional<std::uint64_t> residentKiB(int pid = 0);

/// Peak resident memory of process `pid` (0: this process) since its start
/// or the last resetPeakResident() (VmHWM), KiB; nullopt when it cannot be
/// read.
[[nodiscard]] std::optional<std::uint64_t> peakResidentKiB(int pid = 0);

/// Resets the peak of process `pid` (0: this process) to its current
/// resident memory (/proc/<pid>/clear_refs). Returns false when the kernel
/// does not allow it (then peakResidentKiB() keeps the older peak).
bool resetPeakResident(int pid = 0);

}  // namespace vv
