// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace vv::pacs {

/// What a study browser shows of a study (a C-FIND match, a stored study).
/// Patient data: never logged.
struct StudyFields {
    std::string studyInstanceUid;
    std::string patientName;
    std::string patientId;
    std::string studyDate;  ///< YYYYMMDD as sent
    std::string studyDescription;
    std::string accessionNumber;
};

}  // namespace vv::pacs
