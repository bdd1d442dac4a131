// SPDX-License-Identifier: GPL-3.0-or-later
// Running a check as an unprivileged user when the suite runs as root (as CI
// does): root reads and writes regardless of permissions, so the tests of
// unreadable inputs and read-only outputs would otherwise never run there.
#pragma once

#include <grp.h>
#include <unistd.h>

#include <string>

namespace vv::test {

/// The user and group "nobody" (65534 on Debian).
inline constexpr unsigned kNobody = 65534;

/// True when this process runs as root.
inline bool runningAsRoot() {
    return ::geteuid() == 0;
}

/// Drops this process (a forked child: it cannot be undone) to nobody:
/// no supplementary groups, then group, then user. False when it failed.
inline bool becomeNobody() {
    return ::setgroups(0, nullptr) == 0 && ::setresgid(kNobody, kNobody, kNobody) == 0 &&
           ::setresuid(kNobody, kNobody, kNobody) == 0 && ::geteuid() == kNobody;
}

/// `command` prefixed so that it runs as nobody (setpriv, of util-linux,
/// which every Debian system has).
inline std::string asNobody(const std::string& command) {
    return "setpriv --reuid=" + std::to_string(kNobody) + " --regid=" + std::to_string(kNobody) +
           " --clear-groups " + command;
}

}  // namespace vv::test
