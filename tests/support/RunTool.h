// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a command-line tool the tests check their output with (dcmdump,
// dciodvfy, dsrdump, pdftotext), capturing what it prints.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace vv::test {

/// Runs `command` through the shell with stderr joined to stdout into
/// `output`; returns its exit status (-1 when it could not run or did not
/// exit).
inline int runTool(const std::string& command, std::string& output) {
    output.clear();
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) {
        return -1;
    }
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
        output += buffer.data();
    }
    const int status = ::pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace vv::test
