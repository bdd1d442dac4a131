// SPDX-License-Identifier: GPL-3.0-or-later
// A German locale (decimal comma) for the tests that check machine numbers
// stay in the C locale: de_DE.UTF-8 when the system has it, else compiled
// with localedef (Debian's `locales` package, in scripts/setup-deps) into
// <test-tmp>/locales and found through LOCPATH. Header only.
#pragma once

#include <unistd.h>

#include <array>
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

namespace vv::test {

inline constexpr const char* kGerman = "de_DE.UTF-8";

/// Where the German locale comes from: "" (installed) or a LOCPATH folder
/// (set in this process's environment, so child processes find it too);
/// nullopt with `why` when it cannot be had. Checked once per process.
inline std::optional<std::string> germanLocalePath(std::string& why) {
    static std::string reason;
    static const std::optional<std::string> path = []() -> std::optional<std::string> {
        const std::string before = std::setlocale(LC_NUMERIC, nullptr);
        const auto works = [&] {
            bool ok = std::setlocale(LC_NUMERIC, kGerman) != nullptr;
            if (ok) {
                std::array<char, 16> text{};
                std::snprintf(text.data(), text.size(), "%.1f", 0.5);
                ok = std::string(text.data()) == "0,5";
            }
            std::setlocale(LC_NUMERIC, before.c_str());
            return ok;
        };
        if (works()) {
            return std::string();
        }
        const std::filesystem::path dir = std::filesystem::path(VV_TEST_TMP) / "locales";
        if (!std::filesystem::exists(dir / kGerman / "LC_NUMERIC")) {
            // Compiled beside and renamed: ctest runs test processes in parallel.
            const std::filesystem::path scratch = dir / ("tmp-" + std::to_string(::getpid()));
            std::filesystem::create_directories(scratch);
            const std::string command = "localedef -i de_DE -f UTF-8 '" +
                                        (scratch / kGerman).string() + "' >/dev/null 2>&1";
            static_cast<void>(std::system(command.c_str()));
            std::error_code ec;
            std::filesystem::rename(scratch / kGerman, dir / kGerman, ec);
            std::filesystem::remove_all(scratch, ec);
        }
        ::setenv("LOCPATH", dir.c_str(), 1);
        if (works()) {
            return dir.string();
        }
        reason =
            "no de_DE.UTF-8 locale: not installed, and `localedef -i de_DE -f UTF-8` "
            "(Debian package locales) could not compile one";
        return std::nullopt;
    }();
    why = reason;
    return path;
}

/// LC_NUMERIC German in this process while alive (germanLocalePath() first).
class GermanNumbers {
  public:
    GermanNumbers() : before_(std::setlocale(LC_NUMERIC, nullptr)) {
        std::setlocale(LC_NUMERIC, kGerman);
    }
    ~GermanNumbers() { std::setlocale(LC_NUMERIC, before_.c_str()); }
    GermanNumbers(const GermanNumbers&) = delete;
    GermanNumbers& operator=(const GermanNumbers&) = delete;
    GermanNumbers(GermanNumbers&&) = delete;
    GermanNumbers& operator=(GermanNumbers&&) = delete;

  private:
    std::string before_;
};

}  // namespace vv::test
