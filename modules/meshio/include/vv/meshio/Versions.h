// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::meshio {

/// The version of VTK as the linked library reports it (e.g. "9.1.0"), for
/// the About box. Never throws.
[[nodiscard]] std::string vtkVersion();

}  // namespace vv::meshio
