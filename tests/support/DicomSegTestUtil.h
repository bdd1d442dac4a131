// SPDX-License-Identifier: GPL-3.0-or-later
// Writes DICOM Segmentation objects (binary SEG) with DCMTK's dcmseg for the
// label map tests.
#pragma once

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmfg/fgfracon.h>
#include <dcmtk/dcmfg/fgpixmsr.h>
#include <dcmtk/dcmfg/fgplanor.h>
#include <dcmtk/dcmfg/fgplanpo.h>
#include <dcmtk/dcmiod/iodmacro.h>
#include <dcmtk/dcmiod/modequipment.h>
#include <dcmtk/dcmseg/segdoc.h>
#include <dcmtk/dcmseg/segment.h>

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "DicomTestUtil.h"

namespace vv::test {

/// One segment: its label and a dims.x * dims.y * dims.z mask (x fastest).
struct TestSegment {
    std::string label;
    std::vector<std::uint8_t> mask;
};

/// Writes a binary SEG: one frame per (segment, slice holding a voxel of
/// it), frames in reverse slice order so that only positions give the
/// order. The grid is `indexToWorld` (columns 0 and 1 orthogonal, column 2
/// along their normal). Throws std::runtime_error.
inline void writeBinarySeg(const std::filesystem::path& file, glm::ivec3 dims,
                           const glm::dmat4& indexToWorld,
                           const std::vector<TestSegment>& segments) {
    const glm::dvec3 c0(indexToWorld[0]);
    const glm::dvec3 c1(indexToWorld[1]);
    const glm::dvec3 c2(indexToWorld[2]);
    const glm::dvec3 origin(indexToWorld[3]);
    const glm::dvec3 row = glm::normalize(c0);
    const glm::dvec3 col = glm::normalize(c1);
    const auto check = [&](const OFCondition& c, const char* what) {
        if (c.bad()) {
            throw std::runtime_error(std::string("writing SEG: ") + what + ": " + c.text());
        }
    };
    DcmSegmentation* raw = nullptr;
    check(DcmSegmentation::createBinarySegmentation(
              raw, static_cast<Uint16>(dims.y), static_cast<Uint16>(dims.x),
              IODGeneralEquipmentModule::EquipmentInfo("VesselView", "tests", "0", "0.1"),
              ContentIdentificationMacro("1", "VESSELS", "test segmentation", "VesselView")),
          "create");
    std::unique_ptr<DcmSegmentation> seg(raw);
    seg->getPatient().setPatientName(kPatientName);
    seg->getPatient().setPatientID(kPatientId);
    seg->getStudy().setStudyInstanceUID(newUid().c_str());
    seg->getFrameOfReference().setFrameOfReferenceUID(newUid().c_str());
    seg->getSeries().setSeriesInstanceUID(newUid().c_str());
    seg->getSeries().setSeriesNumber("7");

    FGPixelMeasures measures;
    check(measures.setPixelSpacing((ds(glm::length(c1)) + "\\" + ds(glm::length(c0))).c_str()),
          "pixel spacing");
    check(measures.setSliceThickness(ds(glm::length(c2)).c_str()), "slice thickness");
    check(seg->addForAllFrames(measures), "pixel measures");
    std::unique_ptr<FGPlaneOrientationPatient> orientation(FGPlaneOrientationPatient::createMinimal(
        ds(row.x).c_str(), ds(row.y).c_str(), ds(row.z).c_str(), ds(col.x).c_str(),
        ds(col.y).c_str(), ds(col.z).c_str()));
    check(seg->addForAllFrames(*orientation), "orientation");
    const std::string dimensionUid = newUid();
    check(seg->getDimensions().addDimensionIndex(DCM_ReferencedSegmentNumber, dimensionUid.c_str(),
                                                 DCM_SegmentIdentificationSequence, "segment"),
          "dimension");
    check(seg->getDimensions().addDimensionIndex(DCM_ImagePositionPatient, dimensionUid.c_str(),
                                                 DCM_PlanePositionSequence, "position"),
          "dimension");

    const std::size_t pixels = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y);
    for (const TestSegment& s : segments) {
        DcmSegment* segment = nullptr;
        check(DcmSegment::create(segment, s.label.c_str(),
                                 CodeSequenceMacro("85756007", "SCT", "Tissue"),
                                 CodeSequenceMacro("59820001", "SCT", "Blood vessel"),
                                 DcmSegTypes::SAT_AUTOMATIC, "threshold"),
              "segment");
        Uint16 number = 0;
        check(seg->addSegment(segment, number), "add segment");
        for (int k = dims.z - 1; k >= 0; --k) {
            std::vector<Uint8> frame(
                s.mask.begin() + static_cast<std::ptrdiff_t>(k * pixels),
                s.mask.begin() + static_cast<std::ptrdiff_t>((k + 1) * pixels));
            if (std::find(frame.begin(), frame.end(), Uint8{1}) == frame.end()) {
                continue;
            }
            const glm::dvec3 p = origin + static_cast<double>(k) * c2;
            std::unique_ptr<FGPlanePosPatient> position(FGPlanePosPatient::createMinimal(
                ds(p.x).c_str(), ds(p.y).c_str(), ds(p.z).c_str()));
            FGFrameContent content;
            check(content.setDimensionIndexValues(number, 0), "index");
            check(content.setDimensionIndexValues(static_cast<Uint32>(k + 1), 1), "index");
            OFVector<FGBase*> perFrame;
            perFrame.push_back(position.get());
            perFrame.push_back(&content);
            check(seg->addFrame(frame.data(), number, perFrame), "frame");
        }
    }
    check(seg->saveFile(file.c_str()), "save");
}

}  // namespace vv::test
