// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/core/Log.h"

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>

namespace vv::log {

namespace {

void stderrSink(Level level, std::string_view category, std::string_view message) {
    static std::mutex mutex;
    static constexpr std::array<std::string_view, 5> kNames = {"debug", "info", "warning", "error",
                                                               "off"};
    std::string line;
    line.reserve(category.size() + message.size() + 16);
    line.append("[").append(kNames.at(static_cast<std::size_t>(level))).append("] ");
    line.append(category).append(": ").append(message).append("\n");
    const std::scoped_lock lock(mutex);
    std::fwrite(line.data(), 1, line.size(), stderr);
}

// The one process-wide sink; atomic so setSink() may race with write().
std::atomic<Sink> gSink{&stderrSink};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)

// Threshold for `category` from VV_LOG: "level" or "cat=level,cat=level".
Level thresholdFor(std::string_view category) {
    const char* env = std::getenv("VV_LOG");
    if (env == nullptr) {
        return Level::Info;
    }
    const std::string_view spec(env);
    Level result = Level::Info;
    std::size_t pos = 0;
    while (pos <= spec.size()) {
        const std::size_t comma = spec.find(',', pos);
        const std::string_view item = spec.substr(
            pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos);
        const std::size_t eq = item.find('=');
        if (eq == std::string_view::npos) {
            if (!item.empty()) {
                result = parseLevel(item);
            }
        } else if (item.substr(0, eq) == category) {
            return parseLevel(item.substr(eq + 1));
        }
        if (comma == std::string_view::npos) {
            break;
        }
        pos = comma + 1;
    }
    return result;
}

}  // namespace

Level parseLevel(std::string_view name) noexcept {
    if (name == "debug") {
        return Level::Debug;
    }
    if (name == "warning") {
        return Level::Warning;
    }
    if (name == "error") {
        return Level::Error;
    }
    if (name == "off") {
        return Level::Off;
    }
    return Level::Info;
}

bool Category::enabled(Level level) const {
    return level >= thresholdFor(name_);
}

void setSink(Sink sink) noexcept {
    gSink = sink != nullptr ? sink : &stderrSink;
}

void write(const Category& category, Level level, std::string_view message) {
    if (level == Level::Off || !category.enabled(level)) {
        return;
    }
    gSink.load()(level, category.name(), message);
}

}  // namespace vv::log
