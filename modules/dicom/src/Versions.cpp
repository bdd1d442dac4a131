// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/dicom/Versions.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcuid.h>

namespace vv::dicom {

std::string dcmtkVersion() {
    return OFFIS_DCMTK_VERSION_STRING;
}

}  // namespace vv::dicom
