// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::dicom {

/// The version of DCMTK the module was built against (e.g. "3.6.7"), for the
/// About box. Never throws.
[[nodiscard]] std::string dcmtkVersion();

}  // namespace vv::dicom
