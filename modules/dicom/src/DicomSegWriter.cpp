// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/dicom/DicomSegWriter.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmfg/fgfracon.h>
#include <dcmtk/dcmfg/fgpixmsr.h>
#include <dcmtk/dcmfg/fgplanor.h>
#include <dcmtk/dcmfg/fgplanpo.h>
#include <dcmtk/dcmiod/iodmacro.h>
#include <dcmtk/dcmiod/modequipment.h>
#include <dcmtk/dcmseg/segdoc.h>
#include <dcmtk/dcmseg/segment.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <set>
#include <vector>

#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/dicom/Uid.h"

namespace vv::dicom {
namespace {

constexpr int kMaxSide = 65535;

/// A DICOM DS value: at most 16 characters, always the C locale.
std::string ds(double v) {
    return significantText(v, 10);
}

/// Throws IoError naming `path` when `status` is bad.
void check(const OFCondition& status, const std::filesystem::path& path, const char* what) {
    if (status.bad()) {
        throw IoError(path, std::string("DICOM SEG: cannot set ") + what + ": " + status.text());
    }
}

void checkMap(const scene::LabelMap& map, const std::filesystem::path& path) {
    const glm::ivec3 d = map.dims;
    if (d.x < 1 || d.y < 1 || d.z < 1 || d.x > kMaxSide || d.y > kMaxSide) {
        throw InvalidArgumentError(path, "DICOM SEG: the label map must be 1..65535 voxels a side");
    }
    const std::size_t voxels = static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) *
                               static_cast<std::size_t>(d.z);
    if (map.labels.size() != voxels) {
        throw InvalidArgumentError(path, "DICOM SEG: the label map has " +
                                             std::to_string(map.labels.size()) + " labels for " +
                                             std::to_string(voxels) + " voxels");
    }
}

std::string segmentLabel(const scene::LabelMap& map, std::uint8_t label, bool several) {
    const std::size_t i = label - 1U;
    if (i < map.segmentNames.size() && !map.segmentNames[i].empty()) {
        return map.segmentNames[i];
    }
    return several ? "Vessels " + std::to_string(label) : std::string("Vessels");
}

/// Patient, study, series and frame of reference of the SEG.
void putModules(DcmSegmentation& seg, const ExportStudy& study, const std::string& frameOfReference,
                const ExportSeries& series, const std::filesystem::path& path) {
    const bool known = study.patient && !study.patient->anonymise;
    IODPatientModule& patient = seg.getPatient();
    if (known) {
        check(patient.setPatientName(study.patient->name.c_str()), path, "the patient's name");
        check(patient.setPatientID(study.patient->id.c_str()), path, "the patient ID");
        check(patient.setPatientBirthDate(study.patient->birthDate.c_str()), path, "birth date");
        check(patient.setPatientSex(study.patient->sex.c_str()), path, "the patient's sex");
    }
    check(seg.getStudy().setStudyInstanceUID(study.studyInstanceUid.c_str()), path, "the study");
    if (!(study.patient && study.patient->anonymise)) {
        check(seg.getStudy().setStudyDate(study.studyDate.c_str()), path, "the study date");
        check(seg.getStudy().setStudyTime(study.studyTime.c_str()), path, "the study time");
        check(seg.getStudy().setStudyID(study.studyId.c_str()), path, "the study ID");
    }
    check(seg.getFrameOfReference().setFrameOfReferenceUID(
              (frameOfReference.empty() ? newUid() : frameOfReference).c_str()),
          path, "the frame of reference");
    check(seg.getSeries().setSeriesInstanceUID(newUid().c_str()), path, "the series");
    check(seg.getSeries().setSeriesNumber(std::to_string(series.seriesNumber).c_str()), path,
          "the series number");
    check(seg.getSeries().setSeriesDescription(series.description.c_str()), path,
          "the series description");
}

/// Pixel measures and orientation, the same for all frames; the dimensions.
void putGeometry(DcmSegmentation& seg, const glm::dmat4& m, const std::filesystem::path& path) {
    const glm::dvec3 c0(m[0]);
    const glm::dvec3 c1(m[1]);
    const glm::dvec3 c2(m[2]);
    FGPixelMeasures measures;
    // Pixel Spacing: between rows (along a column), then between columns.
    check(measures.setPixelSpacing((ds(glm::length(c1)) + "\\" + ds(glm::length(c0))).c_str()),
          path, "the pixel spacing");
    check(measures.setSliceThickness(ds(glm::length(c2)).c_str()), path, "the slice thickness");
    check(seg.addForAllFrames(measures), path, "the pixel measures");
    const glm::dvec3 row = glm::normalize(c0);
    const glm::dvec3 col = glm::normalize(c1);
    const std::unique_ptr<FGPlaneOrientationPatient> orientation(
        FGPlaneOrientationPatient::createMinimal(ds(row.x).c_str(), ds(row.y).c_str(),
                                                 ds(row.z).c_str(), ds(col.x).c_str(),
                                                 ds(col.y).c_str(), ds(col.z).c_str()));
    if (!orientation) {
        throw IoError(path, "DICOM SEG: cannot set the orientation");
    }
    check(seg.addForAllFrames(*orientation), path, "the orientation");
    const std::string dimensions = newUid();
    check(seg.getDimensions().addDimensionIndex(DCM_ReferencedSegmentNumber, dimensions.c_str(),
                                                DCM_SegmentIdentificationSequence, "Segment"),
          path, "the segment dimension");
    check(seg.getDimensions().addDimensionIndex(DCM_ImagePositionPatient, dimensions.c_str(),
                                                DCM_PlanePositionSequence, "Position"),
          path, "the position dimension");
}

/// The frames of `label`: one per slice holding a voxel of it.
void addFrames(DcmSegmentation& seg, const scene::LabelMap& map, std::uint8_t label, Uint16 segment,
               const std::filesystem::path& path) {
    const std::size_t pixels =
        static_cast<std::size_t>(map.dims.x) * static_cast<std::size_t>(map.dims.y);
    const glm::dvec3 origin(map.indexToWorld[3]);
    const glm::dvec3 step(map.indexToWorld[2]);
    std::vector<Uint8> frame(pixels);
    for (int k = 0; k < map.dims.z; ++k) {
        bool any = false;
        const std::size_t first = static_cast<std::size_t>(k) * pixels;
        for (std::size_t p = 0; p < pixels; ++p) {
            frame[p] = map.labels[first + p] == label ? 1 : 0;
            any = any || frame[p] != 0;
        }
        if (!any) {
            continue;
        }
        const glm::dvec3 at = origin + static_cast<double>(k) * step;
        const std::unique_ptr<FGPlanePosPatient> position(
            FGPlanePosPatient::createMinimal(ds(at.x).c_str(), ds(at.y).c_str(), ds(at.z).c_str()));
        if (!position) {
            throw IoError(path, "DICOM SEG: cannot set a frame's position");
        }
        FGFrameContent content;
        check(content.setDimensionIndexValues(segment, 0), path, "a frame's segment index");
        check(content.setDimensionIndexValues(static_cast<Uint32>(k + 1), 1), path,
              "a frame's position index");
        OFVector<FGBase*> perFrame;
        perFrame.push_back(position.get());
        perFrame.push_back(&content);
        check(seg.addFrame(frame.data(), segment, perFrame), path, "a frame");
    }
}

}  // namespace

std::string writeDicomSeg(const std::filesystem::path& path, const scene::LabelMap& labelMap,
                          const ExportStudy& study, const std::string& frameOfReferenceUid,
                          const ExportSeries& series) {
    checkMap(labelMap, path);
    const std::set<std::uint8_t> labels = [&] {
        std::set<std::uint8_t> found;
        for (const std::uint8_t l : labelMap.labels) {
            if (l != 0) {
                found.insert(l);
            }
        }
        return found;
    }();
    if (labels.empty()) {
        throw InvalidArgumentError(path, "DICOM SEG: no voxel is labelled");
    }
    DcmSegmentation* created = nullptr;
    check(DcmSegmentation::createBinarySegmentation(
              created, static_cast<Uint16>(labelMap.dims.y), static_cast<Uint16>(labelMap.dims.x),
              // Enhanced General Equipment: all type 1 (a workstation has no serial number).
              IODGeneralEquipmentModule::EquipmentInfo(
                  "VesselView", "VesselView", "1",
                  series.softwareVersion.empty() ? "unknown" : series.softwareVersion.c_str()),
              ContentIdentificationMacro("1", "VESSELS", series.description.c_str(), "VesselView")),
          path, "the segmentation");
    const std::unique_ptr<DcmSegmentation> seg(created);
    putModules(*seg, study, frameOfReferenceUid, series, path);
    putGeometry(*seg, labelMap.indexToWorld, path);
    for (const std::uint8_t label : labels) {
        DcmSegment* segment = nullptr;
        check(DcmSegment::create(segment, segmentLabel(labelMap, label, labels.size() > 1).c_str(),
                                 CodeSequenceMacro("85756007", "SCT", "Tissue"),
                                 CodeSequenceMacro("59820001", "SCT", "Blood vessel"),
                                 DcmSegTypes::SAT_AUTOMATIC, "VesselView threshold segmentation"),
              path, "a segment");
        Uint16 number = 0;
        check(seg->addSegment(segment, number), path, "a segment");
        addFrames(*seg, labelMap, label, number, path);
    }
    const std::string sopInstance = newUid();
    check(seg->getSOPCommon().setSOPInstanceUID(sopInstance.c_str()), path, "the SOP instance");
    writeAtomically(path, [&](const std::filesystem::path& temporary) {
        const OFCondition status = seg->saveFile(temporary.c_str(), EXS_LittleEndianExplicit);
        if (status.bad()) {
            throw IoError(path, std::string("cannot write the DICOM SEG: ") + status.text());
        }
    });
    return sopInstance;
}

}  // namespace vv::dicom
