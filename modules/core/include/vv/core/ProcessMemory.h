// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <optional>

// This process's memory as Linux reports it (/proc/self/status), for the
// soak, benchmarks and memory tests. Elsewhere the readings are absent.

namespace vv {

/// Resident memory now (VmRSS), KiB; nullopt when it cannot be read.
[[nodiscard]] std::optional<std::uint64_t> residentKiB();

/// Peak resident memory since the start or the last resetPeakResident()
/// (VmHWM), KiB; nullopt when it cannot be read.
[[nodiscard]] std::optional<std::uint64_t> peakResidentKiB();

/// Resets the peak to the current resident memory (/proc/self/clear_refs).
/// Returns false when the kernel does not allow it (then peakResidentKiB()
/// keeps the older peak).
bool resetPeakResident();

}  // namespace vv
