// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::dicom {

/// A fresh, globally unique DICOM UID under DCMTK's root (at most 64
/// characters, digits and dots). Never throws but std::bad_alloc.
[[nodiscard]] std::string newUid();

}  // namespace vv::dicom
