// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <stop_token>
#include <string_view>

namespace vv {

/// What long work is handed: where to report progress and how to learn that it
/// should stop. Both parts are optional; a default Progress reports nowhere and
/// never stops.
class Progress {
  public:
    using Callback = std::function<void(double fraction, std::string_view stage)>;

    Progress() = default;
    Progress(Callback callback, std::stop_token stop)
        : callback_(std::move(callback)), stop_(std::move(stop)) {}

    /// Reports `fraction` in [0, 1] of `stage` done. Throws CancelledError when a
    /// stop was requested, so long loops stop at their next report.
    void report(double fraction, std::string_view stage) const;

    /// Throws CancelledError when a stop was requested.
    void throwIfCancelled() const;

    [[nodiscard]] bool cancelled() const noexcept { return stop_.stop_requested(); }
    [[nodiscard]] const std::stop_token& stopToken() const noexcept { return stop_; }

    /// A Progress for the sub-range [begin, end) of this one's fraction.
    [[nodiscard]] Progress sub(double begin, double end) const;

  private:
    Callback callback_;
    std::stop_token stop_;
};

}  // namespace vv
