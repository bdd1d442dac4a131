// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/meshio/Versions.h"

#include <vtkVersion.h>

namespace vv::meshio {

std::string vtkVersion() {
    const char* version = vtkVersion::GetVTKVersion();
    return version != nullptr ? version : "unknown";
}

}  // namespace vv::meshio
