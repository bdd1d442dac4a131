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

/// Asks the C library to hand large blocks back to the system as soon as
/// they are freed, on every thread (glibc: blocks of 128 KiB and more are
/// mapped on their own and unmapped when freed, its default made fixed). By
/// default glibc raises that threshold to the largest mapped block freed (up
/// to 32 MiB), so later large blocks come from the heap of the thread that
/// allocates them, and a worker thread's heap keeps what it freed resident
/// beside what the next stage, on another thread, allocates. For a process
/// that runs one large computation and ends (the CLI's vessel analysis): its
/// resident peak is then what the computation holds. Not for the GUI:
/// large buffers freed and allocated again every frame would pay for their
/// pages each time. Process-wide and lasting. Returns false where it cannot
/// be set (another C library, an allocator that ignores it).
bool handFreedMemoryBackAtOnce();

}  // namespace vv
