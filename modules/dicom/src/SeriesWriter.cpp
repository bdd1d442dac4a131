// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/dicom/SeriesWriter.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <system_error>
#include <vector>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/dicom/Uid.h"

namespace vv::dicom {

namespace {

/// A DICOM DS value: at most 16 characters, always the C locale.
std::string ds(double v) {
    return significantText(v, 10);
}

std::string ds3(const glm::dvec3& v) {
    return ds(v.x) + "\\" + ds(v.y) + "\\" + ds(v.z);
}

}  // namespace

std::string writeCtSeries(const std::filesystem::path& folder, const scene::Volume& volume,
                          const CtSeriesWriteOptions& options, const Progress& progress) {
    if (volume.empty()) {
        throw InvalidArgumentError(folder, "cannot write an empty volume as a CT series");
    }
    if (options.modality != "CT" && options.modality != "MR") {
        throw InvalidArgumentError(folder, "cannot write a series of modality '" +
                                               options.modality + "' (only CT and MR)");
    }
    const bool mr = options.modality == "MR";
    const double intercept = mr ? 0.0 : -1024.0;
    const glm::dmat4& m = volume.indexToWorld();
    const glm::dvec3 c0(m[0]);
    const glm::dvec3 c1(m[1]);
    const glm::dvec3 c2(m[2]);
    const glm::dvec3 origin(m[3]);
    const double spacingX = glm::length(c0);
    const double spacingY = glm::length(c1);
    if (!(spacingX > 0.0) || !(spacingY > 0.0) ||
        !(glm::length(glm::cross(c0, c1)) > 1e-9 * spacingX * spacingY)) {
        throw InvalidArgumentError(folder, "the volume's geometry is degenerate");
    }
    const glm::dvec3 row = c0 / spacingX;
    const glm::dvec3 column = c1 / spacingY;
    const glm::dvec3 normal = glm::normalize(glm::cross(row, column));
    const double thickness = std::abs(glm::dot(c2, normal));
    if (!(thickness > 0.0)) {
        throw InvalidArgumentError(folder, "the volume's slice step is degenerate");
    }
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec || !std::filesystem::is_directory(folder)) {
        throw IoError(folder, "cannot create the folder" + (ec ? ": " + ec.message() : ""));
    }

    const std::string studyUid = newUid();
    const std::string seriesUid = newUid();
    const std::string frameUid = newUid();
    const std::string orientation = ds3(row) + "\\" + ds3(column);
    // DICOM order: row spacing (between rows = along the column direction), column spacing.
    const std::string pixelSpacing = ds(spacingY) + "\\" + ds(spacingX);
    const int columns = volume.dims().x;
    const int rows = volume.dims().y;
    const int slices = volume.dims().z;
    std::vector<Uint16> pixels(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
    const char* stage = "Writing the CT series";
    for (int k = 0; k < slices; ++k) {
        progress.report(static_cast<double>(k) / slices, stage);
        for (int j = 0; j < rows; ++j) {
            for (int i = 0; i < columns; ++i) {
                const double value = std::round(static_cast<double>(volume.value(i, j, k)));
                pixels[static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) +
                       static_cast<std::size_t>(i)] =
                    static_cast<Uint16>(std::clamp(value - intercept, 0.0, 65535.0));
            }
        }
        DcmFileFormat ff;
        DcmDataset* d = ff.getDataset();
        const int instance = options.reverseInstanceNumbers ? slices - k : k + 1;
        const auto put = [d](const DcmTagKey& tag, const std::string& value) {
            d->putAndInsertString(tag, value.c_str());
        };
        put(DCM_SOPClassUID, mr ? UID_MRImageStorage : UID_CTImageStorage);
        put(DCM_SOPInstanceUID, newUid());
        put(DCM_StudyInstanceUID, studyUid);
        put(DCM_SeriesInstanceUID, seriesUid);
        put(DCM_FrameOfReferenceUID, frameUid);
        put(DCM_SpecificCharacterSet, "ISO_IR 192");
        put(DCM_ImageType, "DERIVED\\SECONDARY\\AXIAL");
        put(DCM_PatientName, options.patientName);
        put(DCM_PatientID, options.patientId);
        put(DCM_PatientBirthDate, "");
        put(DCM_PatientSex, "O");
        put(DCM_StudyDate, "20250101");
        put(DCM_StudyTime, "120000");
        put(DCM_StudyID, "1");
        put(DCM_AccessionNumber, "");
        put(DCM_ReferringPhysicianName, "");
        put(DCM_StudyDescription, options.studyDescription);
        put(DCM_Modality, options.modality);
        put(DCM_Manufacturer, "VesselView");
        put(DCM_SeriesDescription, options.seriesDescription);
        put(DCM_SeriesNumber, "1");
        put(DCM_InstanceNumber, std::to_string(instance));
        put(DCM_PositionReferenceIndicator, "");
        put(DCM_ImagePositionPatient, ds3(origin + static_cast<double>(k) * c2));
        put(DCM_ImageOrientationPatient, orientation);
        put(DCM_PixelSpacing, pixelSpacing);
        put(DCM_SliceThickness, ds(thickness));
        put(DCM_SpacingBetweenSlices, ds(thickness));
        put(DCM_PatientPosition, options.patientPosition);
        if (mr) {
            put(DCM_ScanningSequence, "GR");
            put(DCM_SequenceVariant, "SP");
            put(DCM_MRAcquisitionType, "3D");
            put(DCM_RescaleIntercept, "0");
            put(DCM_RescaleSlope, "1");
        } else {
            put(DCM_KVP, "120");
            put(DCM_RescaleIntercept, "-1024");
            put(DCM_RescaleSlope, "1");
            put(DCM_RescaleType, "HU");
            put(DCM_WindowCenter, "200");
            put(DCM_WindowWidth, "800");
        }
        put(DCM_PhotometricInterpretation, "MONOCHROME2");
        d->putAndInsertUint16(DCM_SamplesPerPixel, 1);
        d->putAndInsertUint16(DCM_Rows, static_cast<Uint16>(rows));
        d->putAndInsertUint16(DCM_Columns, static_cast<Uint16>(columns));
        d->putAndInsertUint16(DCM_BitsAllocated, 16);
        d->putAndInsertUint16(DCM_BitsStored, 16);
        d->putAndInsertUint16(DCM_HighBit, 15);
        d->putAndInsertUint16(DCM_PixelRepresentation, 0);
        d->putAndInsertUint16Array(DCM_PixelData, pixels.data(),
                                   static_cast<unsigned long>(pixels.size()));
        const std::filesystem::path file = folder / ("slice" + std::to_string(k) + ".dcm");
        writeAtomically(file, [&](const std::filesystem::path& temporary) {
            const OFCondition c = ff.saveFile(temporary.c_str(), EXS_LittleEndianExplicit);
            if (c.bad()) {
                throw IoError(file, std::string("cannot write the DICOM file: ") + c.text());
            }
        });
    }
    progress.report(1.0, stage);
    return seriesUid;
}

}  // namespace vv::dicom
