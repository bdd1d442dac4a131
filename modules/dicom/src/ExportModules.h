// SPDX-License-Identifier: GPL-3.0-or-later
// Private to vv::dicom: the modules every exported instance shares (the
// patient and the study, de-identification) and the atomic save.
#pragma once

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include <filesystem>
#include <string>

#include "vv/dicom/ExportObjects.h"

namespace vv::dicom::detail {

/// Puts `value` as `tag`'s value (replacing one there). Throws IoError
/// naming `path` when DCMTK refuses it.
void put(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
         const std::filesystem::path& path);

/// Whether the study's patient is to be anonymised.
[[nodiscard]] bool anonymised(const ExportStudy& study);

/// Puts `value`, or nothing when anonymising: for type 3 attributes that the
/// basic confidentiality profile removes (dates and times of the instance).
void putUnlessAnonymised(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
                         const std::filesystem::path& path, const ExportStudy& study);

/// Puts `value`, or an empty value when anonymising (type 2 attributes).
void putOrEmpty(DcmDataset& data, const DcmTagKey& tag, const std::string& value,
                const std::filesystem::path& path, const ExportStudy& study);

/// The Patient module (with the de-identification attributes when
/// anonymising) and the General Study module. Throws IoError naming `path`.
void putPatientAndStudy(DcmDataset& data, const std::filesystem::path& path,
                        const ExportStudy& study);

/// Saves `file` to `path` atomically (explicit VR little endian). Throws
/// IoError naming `path`.
void save(DcmFileFormat& file, const std::filesystem::path& path);

}  // namespace vv::dicom::detail
