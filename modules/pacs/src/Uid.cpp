// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/pacs/Uid.h"

#include <algorithm>

#include "vv/core/Error.h"

namespace vv::pacs {

void validateUid(const std::string& uid) {
    const bool chars = std::all_of(uid.begin(), uid.end(),
                                   [](char c) { return (c >= '0' && c <= '9') || c == '.'; });
    if (uid.empty() || uid.size() > 64 || !chars || uid.front() == '.' || uid.back() == '.' ||
        uid.find("..") != std::string::npos) {
        throw InvalidArgumentError("\"" + uid + "\" is not a DICOM UID");
    }
}

}  // namespace vv::pacs
