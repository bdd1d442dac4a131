// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/ResourcePaths.h"

#include <cstdlib>
#include <string>
#include <system_error>

#include "vv/core/Log.h"

#if defined(_WIN32)
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>
#elif defined(__APPLE__)
#include <mach-o/dyld.h>

#include <cstdint>
#endif

namespace vv::app {

namespace {

constexpr vv::log::Category kLog("vv.app");
constexpr std::string_view kDemoRelative = "demo/vessel-tree.vtp";
constexpr std::string_view kTranslationsRelative = "translations";

std::filesystem::path executablePath() {
#if defined(_WIN32)
    std::wstring buffer(MAX_PATH, L'\0');
    for (;;) {
        const DWORD n =
            GetModuleFileNameW(nullptr, buffer.data(), static_cast<DWORD>(buffer.size()));
        if (n == 0) {
            return {};
        }
        if (n < buffer.size()) {
            buffer.resize(n);
            return std::filesystem::path(buffer);
        }
        buffer.resize(buffer.size() * 2);
    }
#elif defined(__APPLE__)
    std::uint32_t size = 0;
    _NSGetExecutablePath(nullptr, &size);
    std::string buffer(size, '\0');
    if (_NSGetExecutablePath(buffer.data(), &size) != 0) {
        return {};
    }
    buffer.resize(std::char_traits<char>::length(buffer.c_str()));
    return std::filesystem::path(buffer);
#else
    std::error_code ec;
    auto path = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : path;
#endif
}

}  // namespace

std::filesystem::path executableDir() {
    const std::filesystem::path exe = executablePath();
    if (exe.empty()) {
        return {};
    }
    std::error_code ec;
    const auto resolved = std::filesystem::weakly_canonical(exe, ec);
    return (ec ? exe : resolved).parent_path();
}

std::vector<std::filesystem::path> dataDirCandidates(const std::filesystem::path& exeDir) {
    if (exeDir.empty()) {
        return {};
    }
    const std::filesystem::path up = exeDir / "..";
    return {
        (up / "share" / "vesselview")
            .lexically_normal(),                // installed: <prefix>/bin -> share/vesselview
        (up / "resources").lexically_normal(),  // build tree: <build>/app -> <build>/resources
        (up / "Resources").lexically_normal(),  // macOS bundle: Contents/MacOS -> Resources
    };
}

std::optional<std::filesystem::path> findData(std::string_view relative,
                                              const std::filesystem::path& exeDir) {
    for (const auto& dir : dataDirCandidates(exeDir)) {
        const std::filesystem::path candidate = dir / std::filesystem::path(relative);
        std::error_code ec;
        if (std::filesystem::exists(candidate, ec)) {
            return candidate;
        }
    }
    return std::nullopt;
}

std::optional<std::filesystem::path> findData(std::string_view relative) {
    return findData(relative, executableDir());
}

std::optional<std::filesystem::path> findDemoFile() {
    if (const char* fromEnv = std::getenv("VV_DEMO_FILE"); fromEnv != nullptr && *fromEnv != '\0') {
        log::debug(kLog, std::string("demo file from VV_DEMO_FILE: ") + fromEnv);
        return std::filesystem::path(fromEnv);
    }
    const std::filesystem::path exeDir = executableDir();
    auto found = findData(kDemoRelative, exeDir);
    std::error_code ec;
    if (!found || !std::filesystem::is_regular_file(*found, ec)) {
        log::debug(kLog, "no demo file in the data folders of " + exeDir.string());
        return std::nullopt;
    }
    log::debug(kLog, "demo file: " + found->string());
    return found;
}

bool isDemoFile(const std::filesystem::path& file) {
    const auto demo = findDemoFile();
    std::error_code ec;
    return demo && std::filesystem::equivalent(file, *demo, ec) && !ec;
}

std::optional<std::filesystem::path> findTranslationsDir() {
    auto found = findData(kTranslationsRelative);
    std::error_code ec;
    if (found && !std::filesystem::is_directory(*found, ec)) {
        return std::nullopt;
    }
    return found;
}

}  // namespace vv::app
