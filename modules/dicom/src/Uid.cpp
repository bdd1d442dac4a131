// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/dicom/Uid.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcuid.h>

namespace vv::dicom {

std::string newUid() {
    char uid[100] = {};
    dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT);
    return uid;
}

}  // namespace vv::dicom
