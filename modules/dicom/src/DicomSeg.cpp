// SPDX-License-Identifier: GPL-3.0-or-later
// DICOM SEG -> label maps with DCMTK's dcmseg / dcmfg.
#include "vv/dicom/DicomSeg.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <dcmtk/dcmfg/fginterface.h>
#include <dcmtk/dcmfg/fgpixmsr.h>
#include <dcmtk/dcmfg/fgplanor.h>
#include <dcmtk/dcmfg/fgplanpo.h>
#include <dcmtk/dcmfg/fgseg.h>
#include <dcmtk/dcmseg/segdoc.h>
#include <dcmtk/dcmseg/segment.h>
#include <dcmtk/dcmseg/segutils.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "DicomHeader.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::dicom {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStage = "Reading DICOM SEG";

struct SegFrame {
    std::size_t frame = 0;
    Uint16 segment = 0;
    glm::dvec3 position{0.0};
    double along = 0.0;  ///< position projected on the slice normal
};

std::string describe(double v) {
    return significantText(v, 4);
}

}  // namespace

bool isDicomSegFile(const fs::path& path) {
    try {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) {
            return false;
        }
        detail::ensureCodecs();  // also switches DCMTK's logger off
        DcmFileFormat ff;
        // Elements longer than 4 KiB (pixel data) are not read.
        if (ff.loadFile(path.c_str(), EXS_Unknown, EGL_noChange, 4096).bad()) {
            return false;
        }
        OFString sopClass;
        if (ff.getDataset()->findAndGetOFString(DCM_SOPClassUID, sopClass).bad()) {
            ff.getMetaInfo()->findAndGetOFString(DCM_MediaStorageSOPClassUID, sopClass);
        }
        return sopClass == UID_SegmentationStorage;
    } catch (...) {
        return false;
    }
}

std::vector<scene::LabelMap> loadDicomSegLabelMaps(const fs::path& file, const Progress& progress) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        throw IoError(file, "no such file");
    }
    if (!isDicomSegFile(file)) {
        throw FormatError(file, "not a DICOM Segmentation object");
    }
    progress.report(0.0, kStage);
    DcmFileFormat ff;
    const OFCondition read = ff.loadFile(file.c_str());
    if (read.bad()) {
        throw FormatError(file, std::string("cannot read the file: ") + read.text());
    }
    // Compressed (e.g. RLE) pixel data is decoded before dcmseg reads frames.
    DcmDataset* dataset = ff.getDataset();
    if (DcmXfer(dataset->getOriginalXfer()).isEncapsulated() &&
        (dataset->chooseRepresentation(EXS_LittleEndianExplicit, nullptr).bad() ||
         !dataset->canWriteXfer(EXS_LittleEndianExplicit))) {
        throw FormatError(file, std::string("cannot decode the pixel data (") +
                                    DcmXfer(dataset->getOriginalXfer()).getXferName() + ")");
    }
    Uint16 maxFraction = 255;
    ff.getDataset()->findAndGetUint16(DCM_MaximumFractionalValue, maxFraction);
    DcmSegmentation* raw = nullptr;
    const OFCondition loaded = DcmSegmentation::loadDataset(*ff.getDataset(), raw);
    std::unique_ptr<DcmSegmentation> seg(raw);
    if (loaded.bad() || !seg) {
        throw FormatError(file, std::string("cannot read the segmentation: ") + loaded.text());
    }
    progress.report(0.3, kStage);
    const std::size_t frames = seg->getNumberOfFrames();
    const std::size_t segments = seg->getNumberOfSegments();
    if (frames == 0 || segments == 0) {
        throw FormatError(file, "the segmentation has no frames or no segments");
    }
    const bool binary = seg->getSegmentationType() == DcmSegTypes::ST_BINARY;
    const bool fractional = seg->getSegmentationType() == DcmSegTypes::ST_FRACTIONAL;
    if (!binary && !fractional) {
        throw FormatError(file, "unsupported segmentation type (neither BINARY nor FRACTIONAL)");
    }
    Uint16 rows = 0;
    Uint16 columns = 0;
    ff.getDataset()->findAndGetUint16(DCM_Rows, rows);
    ff.getDataset()->findAndGetUint16(DCM_Columns, columns);
    if (rows == 0 || columns == 0) {
        throw FormatError(file, "the segmentation has no rows or columns");
    }
    if (fractional && maxFraction == 0) {
        throw FormatError(file, "Maximum Fractional Value is 0");
    }

    // Geometry: orientation and spacing (shared or per frame, must agree),
    // positions per frame.
    FGInterface& groups = seg->getFunctionalGroups();
    std::vector<SegFrame> list(frames);
    glm::dvec3 row(0.0);
    glm::dvec3 col(0.0);
    glm::dvec2 spacing(0.0);  // DICOM order: between rows, between columns
    for (std::size_t f = 0; f < frames; ++f) {
        const auto n = static_cast<Uint32>(f);
        auto* orient = dynamic_cast<FGPlaneOrientationPatient*>(
            groups.get(n, DcmFGTypes::EFG_PLANEORIENTPATIENT));
        auto* measures =
            dynamic_cast<FGPixelMeasures*>(groups.get(n, DcmFGTypes::EFG_PIXELMEASURES));
        auto* position =
            dynamic_cast<FGPlanePosPatient*>(groups.get(n, DcmFGTypes::EFG_PLANEPOSPATIENT));
        auto* segment = dynamic_cast<FGSegmentation*>(groups.get(n, DcmFGTypes::EFG_SEGMENTATION));
        if (orient == nullptr || measures == nullptr || position == nullptr || segment == nullptr) {
            throw FormatError(file, "frame " + std::to_string(f + 1) +
                                        " lacks its orientation, pixel spacing, position or "
                                        "segment number");
        }
        Float64 o[6] = {};
        if (orient->getImageOrientationPatient(o[0], o[1], o[2], o[3], o[4], o[5]).bad()) {
            throw FormatError(file, "frame " + std::to_string(f + 1) +
                                        ": unreadable Image Orientation (Patient)");
        }
        const glm::dvec3 r(o[0], o[1], o[2]);
        const glm::dvec3 c(o[3], o[4], o[5]);
        Float64 sy = 0.0;
        Float64 sx = 0.0;
        if (measures->getPixelSpacing(sy, 0).bad() || measures->getPixelSpacing(sx, 1).bad() ||
            !(sy > 0.0) || !(sx > 0.0)) {
            throw FormatError(file, "frame " + std::to_string(f + 1) + ": no valid Pixel Spacing");
        }
        if (f == 0) {
            row = r;
            col = c;
            spacing = {sy, sx};
        } else if (glm::length(r - row) > 1e-4 || glm::length(c - col) > 1e-4 ||
                   std::abs(sy - spacing.x) > 1e-6 || std::abs(sx - spacing.y) > 1e-6) {
            throw FormatError(file, "frames of different orientations or pixel spacings");
        }
        Float64 px = 0.0;
        Float64 py = 0.0;
        Float64 pz = 0.0;
        if (position->getImagePositionPatient(px, py, pz).bad()) {
            throw FormatError(
                file, "frame " + std::to_string(f + 1) + ": unreadable Image Position (Patient)");
        }
        Uint16 number = 0;
        if (segment->getReferencedSegmentNumber(number).bad() || number < 1 || number > segments) {
            throw FormatError(file, "frame " + std::to_string(f + 1) +
                                        " refers to a segment that does not exist");
        }
        list[f] = SegFrame{f, number, glm::dvec3(px, py, pz), 0.0};
    }
    if (!(glm::length(row) > 0.5) || !(glm::length(col) > 0.5)) {
        throw FormatError(file, "invalid Image Orientation (Patient)");
    }
    row = glm::normalize(row);
    col = glm::normalize(col);
    const glm::dvec3 normal = glm::normalize(glm::cross(row, col));
    for (SegFrame& f : list) {
        f.along = glm::dot(f.position, normal);
    }
    std::vector<double> positions;
    for (const SegFrame& f : list) {
        positions.push_back(f.along);
    }
    std::sort(positions.begin(), positions.end());
    const double tolerance = 1e-3 * std::min(spacing.x, spacing.y);
    positions.erase(std::unique(positions.begin(), positions.end(),
                                [&](double a, double b) { return std::abs(a - b) <= tolerance; }),
                    positions.end());
    double step = 0.0;
    for (std::size_t k = 1; k < positions.size(); ++k) {
        const double gap = positions[k] - positions[k - 1];
        step = step == 0.0 ? gap : std::min(step, gap);
    }
    int slices = 1;
    if (positions.size() > 1) {
        const double count = (positions.back() - positions.front()) / step;
        slices = static_cast<int>(std::lround(count)) + 1;
        if (slices > 100000) {
            throw FormatError(file, "the frame positions span too many slices");
        }
    }
    const auto slice = [&](double along) {
        if (positions.size() == 1) {
            return 0;
        }
        const double t = (along - positions.front()) / step;
        const long k = std::lround(t);
        if (std::abs(t - static_cast<double>(k)) > 0.05) {
            throw FormatError(file, "frame position " + describe(along) +
                                        " mm is off the slice grid (step " + describe(step) +
                                        " mm)");
        }
        return static_cast<int>(k);
    };
    // The first slice's in-plane origin: the position of a frame on it.
    const SegFrame& first =
        *std::min_element(list.begin(), list.end(),
                          [](const SegFrame& a, const SegFrame& b) { return a.along < b.along; });
    glm::dvec3 origin = first.position;
    for (const SegFrame& f : list) {
        const glm::dvec3 inPlane = f.position - origin - (f.along - first.along) * normal;
        if (glm::length(inPlane) > 0.01 * std::min(spacing.x, spacing.y) + 1e-6) {
            throw FormatError(file,
                              "frames are shifted in plane (gantry tilt is not supported "
                              "for DICOM SEG)");
        }
    }

    const glm::ivec3 dims(columns, rows, slices);
    glm::dmat4 indexToWorld(1.0);
    indexToWorld[0] = glm::dvec4(row * spacing.y, 0.0);
    indexToWorld[1] = glm::dvec4(col * spacing.x, 0.0);
    indexToWorld[2] = glm::dvec4(normal * (positions.size() > 1 ? step : 1.0), 0.0);
    indexToWorld[3] = glm::dvec4(origin, 1.0);
    const double voxelVolume = spacing.x * spacing.y * (positions.size() > 1 ? step : 1.0);

    std::vector<scene::LabelMap> maps(segments);
    for (std::size_t s = 0; s < segments; ++s) {
        scene::LabelMap& map = maps[s];
        map.dims = dims;
        map.indexToWorld = indexToWorld;
        map.labels.assign(static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                              static_cast<std::size_t>(dims.z),
                          0);
        OFString label;
        DcmSegment* segment = seg->getSegment(s + 1);
        if (segment == nullptr || segment->getSegmentLabel(label).bad() || label.empty()) {
            label = ("segment " + std::to_string(s + 1)).c_str();
        }
        map.segmentNames.emplace_back(label.c_str());
    }
    const std::size_t pixels = static_cast<std::size_t>(rows) * columns;
    for (std::size_t n = 0; n < list.size(); ++n) {
        progress.report(0.3 + 0.7 * static_cast<double>(n) / static_cast<double>(list.size()),
                        kStage);
        const SegFrame& f = list[n];
        const DcmIODTypes::Frame* frame = seg->getFrame(f.frame);
        if (frame == nullptr || frame->pixData == nullptr) {
            throw FormatError(file, "frame " + std::to_string(f.frame + 1) + " has no pixel data");
        }
        std::unique_ptr<DcmIODTypes::Frame> unpacked;
        const Uint8* data = frame->pixData;
        if (binary) {
            if (frame->length * 8 < pixels) {
                throw FormatError(file, "frame " + std::to_string(f.frame + 1) + " is truncated");
            }
            unpacked.reset(DcmSegUtils::unpackBinaryFrame(frame, rows, columns));
            if (!unpacked || unpacked->pixData == nullptr || unpacked->length < pixels) {
                throw FormatError(file,
                                  "frame " + std::to_string(f.frame + 1) + " cannot be unpacked");
            }
            data = unpacked->pixData;
        } else if (frame->length < pixels) {
            throw FormatError(file, "frame " + std::to_string(f.frame + 1) + " is truncated");
        }
        const int k = slice(f.along);
        scene::LabelMap& map = maps[f.segment - 1];
        const unsigned threshold = binary ? 1U : (static_cast<unsigned>(maxFraction) + 1U) / 2U;
        for (std::size_t p = 0; p < pixels; ++p) {
            if (data[p] >= threshold) {
                map.labels[static_cast<std::size_t>(k) * pixels + p] = 1;
            }
        }
    }
    for (scene::LabelMap& map : maps) {
        const auto voxels = static_cast<std::size_t>(
            std::count(map.labels.begin(), map.labels.end(), std::uint8_t{1}));
        map.components.push_back(
            scene::SegmentComponent{1, voxels, static_cast<double>(voxels) * voxelVolume});
    }
    progress.report(1.0, kStage);
    return maps;
}

}  // namespace vv::dicom
