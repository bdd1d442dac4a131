// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::meshio: small helpers shared by the preflight checks
// (MeshPreflight.h): text and count parsing, saturating arithmetic, quoting
// file content in messages, and progress while the checks run.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vv/core/Progress.h"

namespace vv::meshio::detail {

/// `s` with ASCII letters in lower case (std::tolower, byte by byte).
[[nodiscard]] std::string lower(std::string_view s);

/// a * b, saturating at the largest value instead of overflowing.
[[nodiscard]] std::uint64_t mulSat(std::uint64_t a, std::uint64_t b);

/// The count spelled by `token` (decimal digits only, at most 20 of them),
/// saturating at the largest value; nullopt when `token` is not one.
[[nodiscard]] std::optional<std::uint64_t> parseCount(std::string_view token);

/// The whitespace-separated words of `line`, as views into it.
[[nodiscard]] std::vector<std::string_view> splitWords(std::string_view line);

/// `text` cut to `max` characters with bytes outside printable ASCII shown
/// as '?', for quoting file content in messages.
[[nodiscard]] std::string printable(std::string_view text, std::size_t max = 40);

/// Reports preflight progress every few MB, as the first tenth of the load.
class PreflightTicker {
  public:
    /// Reports to `progress` (kept by reference: it must outlive the ticker)
    /// for a file of `size` bytes, under the stage name `stage`.
    PreflightTicker(const Progress& progress, std::uintmax_t size, std::string stage);
    /// Reports when `position` (bytes checked) is 4 MiB past the last report;
    /// throws what Progress::report throws (CancelledError when cancelled).
    void operator()(std::uint64_t position);

  private:
    const Progress& progress_;
    std::uintmax_t size_;
    std::string stage_;
    std::uint64_t next_ = 0;
};

}  // namespace vv::meshio::detail
