// SPDX-License-Identifier: GPL-3.0-or-later
// Writes small DICOM files with DCMTK for the DICOM import tests: single
// slices (any transfer syntax DCMTK can encode) and enhanced multi-frame CT.
#pragma once

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcrleerg.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmjpeg/djencode.h>
#include <dcmtk/dcmjpeg/djrplol.h>
#include <dcmtk/dcmjpeg/djrploss.h>
#include <dcmtk/dcmjpls/djencode.h>
#include <dcmtk/dcmjpls/djrparam.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "vv/demo/DemoCtSeries.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/scene/Volume.h"

namespace vv::test {

/// Fake patient data: tests check it never reaches messages.
inline constexpr const char* kPatientName = "Secretname^Jane";
inline constexpr const char* kPatientId = "PID-SECRET-4711";

inline std::string newUid() {
    char buffer[100];
    dcmGenerateUniqueIdentifier(buffer, SITE_INSTANCE_UID_ROOT);
    return buffer;
}

inline void registerEncoders() {
    static std::once_flag once;
    std::call_once(once, [] {
        DJEncoderRegistration::registerCodecs();
        DJLSEncoderRegistration::registerCodecs();
        DcmRLEEncoderRegistration::registerCodecs();
    });
}

inline std::string ds(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v);
    return b;
}

struct TestSlice {
    int rows = 16;
    int columns = 16;
    int bitsAllocated = 16;  ///< 8 or 16
    int bitsStored = 16;
    bool isSigned = true;
    std::vector<std::int32_t> stored;  ///< rows * columns stored values
    std::optional<glm::dvec3> position = glm::dvec3(0.0);
    std::optional<std::array<double, 6>> orientation = std::array<double, 6>{1, 0, 0, 0, 1, 0};
    glm::dvec2 pixelSpacing{0.5, 0.75};  ///< DICOM order: row spacing, column spacing
    double slope = 1.0;
    double intercept = 0.0;
    std::string modality = "CT";
    std::string sopClass = UID_CTImageStorage;
    std::string studyUid;
    std::string seriesUid;
    std::string description = "test series";
    int instanceNumber = 1;
    double gantryTilt = 0.0;
    double sliceThickness = 1.0;  ///< Slice Thickness (0018,0050), mm
};

inline void putCommon(DcmDataset* d, const TestSlice& s) {
    d->putAndInsertString(DCM_SOPClassUID, s.sopClass.c_str());
    d->putAndInsertString(DCM_SOPInstanceUID, newUid().c_str());
    d->putAndInsertString(DCM_StudyInstanceUID, s.studyUid.c_str());
    d->putAndInsertString(DCM_SeriesInstanceUID, s.seriesUid.c_str());
    d->putAndInsertString(DCM_FrameOfReferenceUID, (s.studyUid + ".1").c_str());
    d->putAndInsertString(DCM_PatientName, kPatientName);
    d->putAndInsertString(DCM_PatientID, kPatientId);
    d->putAndInsertString(DCM_Modality, s.modality.c_str());
    d->putAndInsertString(DCM_SeriesDescription, s.description.c_str());
    d->putAndInsertString(DCM_StudyDate, "20250101");
    d->putAndInsertString(DCM_SeriesNumber, "3");
    d->putAndInsertString(DCM_InstanceNumber, std::to_string(s.instanceNumber).c_str());
    d->putAndInsertUint16(DCM_SamplesPerPixel, 1);
    d->putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
    d->putAndInsertUint16(DCM_Rows, static_cast<Uint16>(s.rows));
    d->putAndInsertUint16(DCM_Columns, static_cast<Uint16>(s.columns));
    d->putAndInsertUint16(DCM_BitsAllocated, static_cast<Uint16>(s.bitsAllocated));
    d->putAndInsertUint16(DCM_BitsStored, static_cast<Uint16>(s.bitsStored));
    d->putAndInsertUint16(DCM_HighBit, static_cast<Uint16>(s.bitsStored - 1));
    d->putAndInsertUint16(DCM_PixelRepresentation, s.isSigned ? 1 : 0);
    if (s.gantryTilt != 0.0) {
        d->putAndInsertString(DCM_GantryDetectorTilt, ds(s.gantryTilt).c_str());
    }
}

inline void putPixels(DcmDataset* d, const TestSlice& s, const std::vector<std::int32_t>& values) {
    if (s.bitsAllocated == 8) {
        std::vector<Uint8> px(values.size());
        for (std::size_t i = 0; i < values.size(); ++i) {
            px[i] = static_cast<Uint8>(values[i]);
        }
        d->putAndInsertUint8Array(DCM_PixelData, px.data(), static_cast<unsigned long>(px.size()));
    } else {
        std::vector<Uint16> px(values.size());
        for (std::size_t i = 0; i < values.size(); ++i) {
            px[i] = static_cast<Uint16>(static_cast<std::uint32_t>(values[i]) & 0xFFFFU);
        }
        d->putAndInsertUint16Array(DCM_PixelData, px.data(), static_cast<unsigned long>(px.size()));
    }
}

/// Writes one single-frame image in `xfer` (encoded with `param` when the
/// transfer syntax is compressed). Throws std::runtime_error on failure.
inline void writeSlice(const std::filesystem::path& file, const TestSlice& s,
                       E_TransferSyntax xfer = EXS_LittleEndianExplicit,
                       const DcmRepresentationParameter* param = nullptr) {
    registerEncoders();
    DcmFileFormat ff;
    DcmDataset* d = ff.getDataset();
    putCommon(d, s);
    if (s.position) {
        const std::string p =
            ds(s.position->x) + "\\" + ds(s.position->y) + "\\" + ds(s.position->z);
        d->putAndInsertString(DCM_ImagePositionPatient, p.c_str());
    }
    if (s.orientation) {
        std::string o;
        for (int k = 0; k < 6; ++k) {
            o += (k ? "\\" : "") + ds((*s.orientation)[k]);
        }
        d->putAndInsertString(DCM_ImageOrientationPatient, o.c_str());
    }
    d->putAndInsertString(DCM_PixelSpacing,
                          (ds(s.pixelSpacing.x) + "\\" + ds(s.pixelSpacing.y)).c_str());
    d->putAndInsertString(DCM_SliceThickness, ds(s.sliceThickness).c_str());
    d->putAndInsertString(DCM_RescaleSlope, ds(s.slope).c_str());
    d->putAndInsertString(DCM_RescaleType, s.modality == "CT" ? "HU" : "US");
    d->putAndInsertString(DCM_RescaleIntercept, ds(s.intercept).c_str());
    putPixels(d, s, s.stored);
    const DcmXfer x(xfer);
    if (x.isEncapsulated()) {
        if (d->chooseRepresentation(xfer, param).bad() || !d->canWriteXfer(xfer)) {
            throw std::runtime_error("cannot encode test image as " + std::string(x.getXferName()));
        }
    }
    const OFCondition c = ff.saveFile(file.c_str(), xfer);
    if (c.bad()) {
        throw std::runtime_error("cannot write " + file.string() + ": " + c.text());
    }
}

/// Writes an enhanced CT multi-frame file: frame f at positions[f], stored
/// values frames[f], rescale slopes[f] / intercept 0.
inline void writeEnhanced(const std::filesystem::path& file, const TestSlice& s,
                          const std::vector<glm::dvec3>& positions,
                          const std::vector<std::vector<std::int32_t>>& frames,
                          const std::vector<double>& slopes) {
    DcmFileFormat ff;
    DcmDataset* d = ff.getDataset();
    TestSlice t = s;
    t.sopClass = UID_EnhancedCTImageStorage;
    putCommon(d, t);
    d->putAndInsertString(DCM_NumberOfFrames, std::to_string(frames.size()).c_str());
    DcmItem* shared = nullptr;
    d->findOrCreateSequenceItem(DCM_SharedFunctionalGroupsSequence, shared, -2);
    DcmItem* item = nullptr;
    shared->findOrCreateSequenceItem(DCM_PixelMeasuresSequence, item, -2);
    item->putAndInsertString(DCM_PixelSpacing,
                             (ds(s.pixelSpacing.x) + "\\" + ds(s.pixelSpacing.y)).c_str());
    item->putAndInsertString(DCM_SliceThickness, "1");
    shared->findOrCreateSequenceItem(DCM_PlaneOrientationSequence, item, -2);
    std::string o;
    for (int k = 0; k < 6; ++k) {
        o += (k ? "\\" : "") + ds((*s.orientation)[k]);
    }
    item->putAndInsertString(DCM_ImageOrientationPatient, o.c_str());
    std::vector<std::int32_t> all;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        DcmItem* perFrame = nullptr;
        d->findOrCreateSequenceItem(DCM_PerFrameFunctionalGroupsSequence, perFrame, -2);
        perFrame->findOrCreateSequenceItem(DCM_PlanePositionSequence, item, -2);
        const auto& p = positions[f];
        item->putAndInsertString(DCM_ImagePositionPatient,
                                 (ds(p.x) + "\\" + ds(p.y) + "\\" + ds(p.z)).c_str());
        perFrame->findOrCreateSequenceItem(DCM_PixelValueTransformationSequence, item, -2);
        item->putAndInsertString(DCM_RescaleSlope, ds(slopes[f]).c_str());
        item->putAndInsertString(DCM_RescaleIntercept, "0");
        item->putAndInsertString(DCM_RescaleType, "HU");
        all.insert(all.end(), frames[f].begin(), frames[f].end());
    }
    putPixels(d, s, all);
    const OFCondition c = ff.saveFile(file.c_str(), EXS_LittleEndianExplicit);
    if (c.bad()) {
        throw std::runtime_error("cannot write " + file.string() + ": " + c.text());
    }
}

/// Writes `volume` (values in HU) as a CT series in `folder` with the fake
/// patient above: vv::dicom::writeCtSeries() (instance numbers run backwards, so
/// that only positions give the order). Returns the Series Instance UID.
inline std::string writeCtSeries(const std::filesystem::path& folder,
                                 const vv::scene::Volume& volume,
                                 const std::string& description = "synthetic CTA") {
    vv::dicom::CtSeriesWriteOptions options;
    options.seriesDescription = description;
    options.patientName = kPatientName;
    options.patientId = kPatientId;
    return vv::dicom::writeCtSeries(folder, volume, options);
}

}  // namespace vv::test
