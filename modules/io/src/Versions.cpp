// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/io/Versions.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <vtkVersion.h>

namespace vv::io {

std::vector<LibraryVersion> libraryVersions() {
    std::vector<LibraryVersion> versions;
    const char* vtk = vtkVersion::GetVTKVersion();
    versions.push_back({"VTK", vtk != nullptr ? vtk : "unknown"});
    versions.push_back({"DCMTK", OFFIS_DCMTK_VERSION_STRING});
    return versions;
}

}  // namespace vv::io
