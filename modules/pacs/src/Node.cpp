// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/Node.h"

#include <algorithm>

#include "vv/core/Error.h"

namespace vv::pacs {

void validateAeTitle(const std::string& aeTitle) {
    if (aeTitle.empty() || aeTitle.size() > 16) {
        throw InvalidArgumentError("AE title \"" + aeTitle + "\" must have 1 to 16 characters");
    }
    const bool printable = std::all_of(aeTitle.begin(), aeTitle.end(),
                                       [](char c) { return c >= 0x20 && c < 0x7f && c != '\\'; });
    if (!printable) {
        throw InvalidArgumentError("AE title \"" + aeTitle +
                                   "\" may hold printable ASCII only, no backslash");
    }
    if (aeTitle.find_first_not_of(' ') == std::string::npos) {
        throw InvalidArgumentError("AE title must not be only spaces");
    }
}

void validateNode(const Node& node) {
    validateAeTitle(node.aeTitle);
    if (node.host.empty()) {
        throw InvalidArgumentError("node " + node.aeTitle + " has no host");
    }
    if (node.port == 0) {
        throw InvalidArgumentError("node " + node.aeTitle + " has no port");
    }
}

std::string describe(const Node& node) {
    return node.aeTitle + "@" + node.host + ":" + std::to_string(node.port);
}

}  // namespace vv::pacs
