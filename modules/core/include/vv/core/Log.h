// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string_view>

namespace vv::log {

enum class Level { Debug = 0, Info = 1, Warning = 2, Error = 3, Off = 4 };

/// A named logging category ("vv.dicom", "vv.vss", ...). Categories are cheap
/// constants; their threshold comes from the environment variable VV_LOG,
/// e.g. `VV_LOG=debug` or `VV_LOG=vv.dicom=debug,vv.vss=warning` (default: info).
class Category {
  public:
    explicit constexpr Category(std::string_view name) : name_(name) {}
    [[nodiscard]] constexpr std::string_view name() const noexcept { return name_; }
    [[nodiscard]] bool enabled(Level level) const;

  private:
    std::string_view name_;
};

/// Where messages go. The default sink writes "[level] category: message" to
/// stderr; the GUI installs one that forwards to Qt's logging.
using Sink = void (*)(Level, std::string_view category, std::string_view message);
void setSink(Sink sink) noexcept;

/// Writes `message` under `category` if its threshold lets `level` through.
void write(const Category& category, Level level, std::string_view message);

inline void debug(const Category& c, std::string_view m) {
    write(c, Level::Debug, m);
}
inline void info(const Category& c, std::string_view m) {
    write(c, Level::Info, m);
}
inline void warning(const Category& c, std::string_view m) {
    write(c, Level::Warning, m);
}
inline void error(const Category& c, std::string_view m) {
    write(c, Level::Error, m);
}

/// Parses a level name ("debug", "info", "warning", "error", "off"); Info if unknown.
[[nodiscard]] Level parseLevel(std::string_view name) noexcept;

}  // namespace vv::log
