// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Between DCMTK datasets and the store: the index fields of an instance, the
// staged file, and the storage SOP classes VesselView can use.

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdatset.h>

#include <filesystem>
#include <string>
#include <vector>

#include "vv/pacs/LocalStore.h"

namespace vv::pacs::detail {

/// The index fields of `dataset` (missing attributes stay empty / -1).
InstanceFields fieldsOf(DcmDataset& dataset);

/// The index fields of the DICOM file `path` (a received instance; its large
/// values, the pixel data, are not read). Throws FormatError when it cannot
/// be parsed or its SOP instance UID / SOP class UID are not `sopInstanceUid`
/// / `sopClassUid` (what its C-STORE request announced).
InstanceFields fieldsOfFile(const std::filesystem::path& path, const std::string& sopInstanceUid,
                            const std::string& sopClassUid);

/// Writes `dataset` as a DICOM file to `path` (its own transfer syntax,
/// explicit little endian for implicit), 0600. Throws IoError.
void writeInstance(DcmDataset& dataset, const std::filesystem::path& path);

/// The storage SOP classes VesselView opens or produces: CT, enhanced CT, MR,
/// enhanced MR, X-ray angiography, Secondary Capture, Encapsulated PDF,
/// Segmentation, Enhanced SR (the measurement reports).
const std::vector<const char*>& usableStorageClasses();

/// The transfer syntaxes we receive: explicit / implicit little endian, and
/// the lossless compressions the loader decodes (JPEG lossless, JPEG-LS, RLE).
const std::vector<const char*>& receivableTransferSyntaxes();

}  // namespace vv::pacs::detail
