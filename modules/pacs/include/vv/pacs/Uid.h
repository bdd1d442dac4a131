// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::pacs {

/// Throws InvalidArgumentError unless `uid` is a DICOM UID (digits and dots,
/// at most 64 characters, no empty component). UIDs name the store's folders
/// and files, so nothing else may pass.
void validateUid(const std::string& uid);

}  // namespace vv::pacs
