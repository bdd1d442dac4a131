// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Writes a volume as a CT (or MR) image series (DCMTK, one file per slice):
// the demo series (`vesselview-cli demo --dicom`) and the tests' synthetic
// series.

#include <filesystem>
#include <string>

#include "vv/core/Progress.h"
#include "vv/scene/Volume.h"

namespace vv::dicom {

struct CtSeriesWriteOptions {
    std::string seriesDescription = "synthetic CTA";
    std::string studyDescription = "VesselView demo";
    std::string patientName = "VesselView^Demo";  ///< synthetic; never logged
    std::string patientId = "VV-DEMO";
    /// Patient Position (0018,5100): how the patient lay, "HFS" (head first,
    /// supine), "FFS" (feet first), "HFP", …. Only recorded: the geometry is
    /// indexToWorld()'s, in the patient frame whatever the position.
    std::string patientPosition = "HFS";
    /// Instance numbers run backwards (slice 0 = highest number), so that
    /// readers that sort by instance number instead of position go wrong.
    bool reverseInstanceNumbers = true;
    /// "CT" (CT Image Storage, HU) or "MR" (MR Image Storage: stored value =
    /// the value, 0..65535, no rescale type; for synthetic MR volumes).
    std::string modality = "CT";
};

/// Writes `volume` (values in HU) as a CT series into `folder` (created when
/// missing), one file "slice<k>.dcm" per slice, each written atomically:
/// CT Image Storage, explicit VR little endian, unsigned 16-bit stored values
/// with Rescale Slope 1 / Intercept -1024 (values clamped to -1024..64511),
/// new Study / Series / Frame of Reference / SOP Instance UIDs, Image
/// Orientation (Patient) from indexToWorld() columns 0 and 1, Image Position
/// (Patient) of slice k = origin + k × column 2, Pixel Spacing from the column
/// lengths, Slice Thickness and Spacing Between Slices = the step along the
/// normal, Patient Position. With options.modality "MR": MR Image Storage, stored values =
/// the values (clamped to 0..65535), Rescale Slope 1 / Intercept 0.
/// Returns the Series Instance UID. Reports progress ("Writing the CT
/// series"); throws IoError (naming the file), InvalidArgumentError for an
/// empty volume, a degenerate geometry or another modality, CancelledError
/// (files already written stay).
std::string writeCtSeries(const std::filesystem::path& folder, const scene::Volume& volume,
                          const CtSeriesWriteOptions& options = {}, const Progress& progress = {});

}  // namespace vv::dicom
