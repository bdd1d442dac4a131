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

/// What every frame of a segmentation shares.
struct SegLayout {
    std::size_t frames = 0;
    std::size_t segments = 0;
    bool binary = false;  ///< BINARY; else FRACTIONAL
    Uint16 maxFraction = 255;
    Uint16 rows = 0;
    Uint16 columns = 0;

    [[nodiscard]] std::size_t pixels() const { return static_cast<std::size_t>(rows) * columns; }
};

/// The plane the frames share: row and column directions as stored, pixel
/// spacing in DICOM order (between rows, between columns).
struct SegPlane {
    glm::dvec3 row{0.0};
    glm::dvec3 col{0.0};
    glm::dvec2 spacing{0.0};
};

/// Reads `file` into `ff`, decoding compressed (e.g. RLE) pixel data before
/// dcmseg reads frames. Throws FormatError when either fails.
void readSegFile(DcmFileFormat& ff, const fs::path& file) {
    const OFCondition read = ff.loadFile(file.c_str());
    if (read.bad()) {
        throw FormatError(file, std::string("cannot read the file: ") + read.text());
    }
    DcmDataset* dataset = ff.getDataset();
    if (DcmXfer(dataset->getOriginalXfer()).isEncapsulated() &&
        (dataset->chooseRepresentation(EXS_LittleEndianExplicit, nullptr).bad() ||
         !dataset->canWriteXfer(EXS_LittleEndianExplicit))) {
        throw FormatError(file, std::string("cannot decode the pixel data (") +
                                    DcmXfer(dataset->getOriginalXfer()).getXferName() + ")");
    }
}

/// dcmseg's segmentation of a data set; throws FormatError when it cannot read it.
std::unique_ptr<DcmSegmentation> readSegmentation(DcmDataset& dataset, const fs::path& file) {
    DcmSegmentation* raw = nullptr;
    const OFCondition loaded = DcmSegmentation::loadDataset(dataset, raw);
    std::unique_ptr<DcmSegmentation> seg(raw);
    if (loaded.bad() || !seg) {
        throw FormatError(file, std::string("cannot read the segmentation: ") + loaded.text());
    }
    return seg;
}

/// The layout of `seg`; throws FormatError when it has no frames or
/// segments, a type other than BINARY or FRACTIONAL, no rows or columns, or
/// (FRACTIONAL) a Maximum Fractional Value of 0.
SegLayout segLayout(DcmSegmentation& seg, DcmDataset& dataset, Uint16 maxFraction,
                    const fs::path& file) {
    SegLayout layout;
    layout.frames = seg.getNumberOfFrames();
    layout.segments = seg.getNumberOfSegments();
    if (layout.frames == 0 || layout.segments == 0) {
        throw FormatError(file, "the segmentation has no frames or no segments");
    }
    layout.binary = seg.getSegmentationType() == DcmSegTypes::ST_BINARY;
    const bool fractional = seg.getSegmentationType() == DcmSegTypes::ST_FRACTIONAL;
    if (!layout.binary && !fractional) {
        throw FormatError(file, "unsupported segmentation type (neither BINARY nor FRACTIONAL)");
    }
    dataset.findAndGetUint16(DCM_Rows, layout.rows);
    dataset.findAndGetUint16(DCM_Columns, layout.columns);
    if (layout.rows == 0 || layout.columns == 0) {
        throw FormatError(file, "the segmentation has no rows or columns");
    }
    if (fractional && maxFraction == 0) {
        throw FormatError(file, "Maximum Fractional Value is 0");
    }
    layout.maxFraction = maxFraction;
    return layout;
}

/// Frame `f`: its segment number and position. Its orientation and pixel
/// spacing set `plane` (frame 0) or must agree with it. Throws FormatError
/// when a functional group is missing or unreadable, the plane differs, or
/// the segment does not exist.
SegFrame readSegFrame(FGInterface& groups, std::size_t f, std::size_t segments,
                      const fs::path& file, SegPlane& plane) {
    const auto n = static_cast<Uint32>(f);
    auto* orient =
        dynamic_cast<FGPlaneOrientationPatient*>(groups.get(n, DcmFGTypes::EFG_PLANEORIENTPATIENT));
    auto* measures = dynamic_cast<FGPixelMeasures*>(groups.get(n, DcmFGTypes::EFG_PIXELMEASURES));
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
        throw FormatError(
            file, "frame " + std::to_string(f + 1) + ": unreadable Image Orientation (Patient)");
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
        plane = SegPlane{r, c, {sy, sx}};
    } else if (glm::length(r - plane.row) > 1e-4 || glm::length(c - plane.col) > 1e-4 ||
               std::abs(sy - plane.spacing.x) > 1e-6 || std::abs(sx - plane.spacing.y) > 1e-6) {
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
        throw FormatError(
            file, "frame " + std::to_string(f + 1) + " refers to a segment that does not exist");
    }
    return SegFrame{f, number, glm::dvec3(px, py, pz), 0.0};
}

/// The slice grid of the frames' positions along the normal: the distinct
/// positions (within a tolerance), a step of the smallest gap between them.
class SegSliceGrid {
  public:
    /// Throws FormatError when the positions span more than 100000 slices.
    SegSliceGrid(const std::vector<SegFrame>& frames, double tolerance, fs::path file)
        : file_(std::move(file)) {
        for (const SegFrame& f : frames) {
            positions_.push_back(f.along);
        }
        std::sort(positions_.begin(), positions_.end());
        positions_.erase(
            std::unique(positions_.begin(), positions_.end(),
                        [&](double a, double b) { return std::abs(a - b) <= tolerance; }),
            positions_.end());
        for (std::size_t k = 1; k < positions_.size(); ++k) {
            const double gap = positions_[k] - positions_[k - 1];
            step_ = step_ == 0.0 ? gap : std::min(step_, gap);
        }
        if (positions_.size() > 1) {
            const double count = (positions_.back() - positions_.front()) / step_;
            slices_ = static_cast<int>(std::lround(count)) + 1;
            if (slices_ > 100000) {
                throw FormatError(file_, "the frame positions span too many slices");
            }
        }
    }

    [[nodiscard]] int slices() const { return slices_; }

    /// The distance between slices: the step, 1 for a single slice.
    [[nodiscard]] double spacing() const { return positions_.size() > 1 ? step_ : 1.0; }

    /// The slice at `along`; throws FormatError when it is off the grid.
    [[nodiscard]] int slice(double along) const {
        if (positions_.size() == 1) {
            return 0;
        }
        const double t = (along - positions_.front()) / step_;
        const long k = std::lround(t);
        if (std::abs(t - static_cast<double>(k)) > 0.05) {
            throw FormatError(file_, "frame position " + describe(along) +
                                         " mm is off the slice grid (step " + describe(step_) +
                                         " mm)");
        }
        return static_cast<int>(k);
    }

  private:
    fs::path file_;
    std::vector<double> positions_;
    double step_ = 0.0;
    int slices_ = 1;
};

/// The first slice's in-plane origin: the position of a frame on it. Throws
/// FormatError when frames are shifted in plane (gantry tilt).
glm::dvec3 segOrigin(const std::vector<SegFrame>& list, const glm::dvec3& normal,
                     const glm::dvec2& spacing, const fs::path& file) {
    const SegFrame& first =
        *std::min_element(list.begin(), list.end(),
                          [](const SegFrame& a, const SegFrame& b) { return a.along < b.along; });
    const glm::dvec3 origin = first.position;
    for (const SegFrame& f : list) {
        const glm::dvec3 inPlane = f.position - origin - (f.along - first.along) * normal;
        if (glm::length(inPlane) > 0.01 * std::min(spacing.x, spacing.y) + 1e-6) {
            throw FormatError(file,
                              "frames are shifted in plane (gantry tilt is not supported "
                              "for DICOM SEG)");
        }
    }
    return origin;
}

/// One empty label map per segment on the grid, named by the segment's label
/// ("segment N" when it has none).
std::vector<scene::LabelMap> emptyMaps(DcmSegmentation& seg, std::size_t segments,
                                       const glm::ivec3& dims, const glm::dmat4& indexToWorld) {
    std::vector<scene::LabelMap> maps(segments);
    for (std::size_t s = 0; s < segments; ++s) {
        scene::LabelMap& map = maps[s];
        map.dims = dims;
        map.indexToWorld = indexToWorld;
        map.labels.assign(static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                              static_cast<std::size_t>(dims.z),
                          0);
        OFString label;
        DcmSegment* segment = seg.getSegment(s + 1);
        if (segment == nullptr || segment->getSegmentLabel(label).bad() || label.empty()) {
            label = ("segment " + std::to_string(s + 1)).c_str();
        }
        map.segmentNames.emplace_back(label.c_str());
    }
    return maps;
}

/// Frame `frame`'s pixels, one byte each (a BINARY frame unpacked into
/// `unpacked`). Throws FormatError when it has no pixel data, is truncated or
/// cannot be unpacked.
const Uint8* framePixels(DcmSegmentation& seg, std::size_t frame, const SegLayout& layout,
                         std::unique_ptr<DcmIODTypes::Frame>& unpacked, const fs::path& file) {
    const DcmIODTypes::Frame* data = seg.getFrame(frame);
    const std::string name = "frame " + std::to_string(frame + 1);
    if (data == nullptr || data->pixData == nullptr) {
        throw FormatError(file, name + " has no pixel data");
    }
    const std::size_t pixels = layout.pixels();
    if (!layout.binary) {
        if (data->length < pixels) {
            throw FormatError(file, name + " is truncated");
        }
        return data->pixData;
    }
    if (data->length * 8 < pixels) {
        throw FormatError(file, name + " is truncated");
    }
    unpacked.reset(DcmSegUtils::unpackBinaryFrame(data, layout.rows, layout.columns));
    if (!unpacked || unpacked->pixData == nullptr || unpacked->length < pixels) {
        throw FormatError(file, name + " cannot be unpacked");
    }
    return unpacked->pixData;
}

/// Marks in its segment's map, at its slice, the pixels of every frame at or
/// above the threshold: 1 for BINARY, half the Maximum Fractional Value
/// (rounded up) for FRACTIONAL. Reports progress from 0.3 to 1.
void paintFrames(DcmSegmentation& seg, const std::vector<SegFrame>& list, const SegLayout& layout,
                 const SegSliceGrid& grid, std::vector<scene::LabelMap>& maps, const fs::path& file,
                 const Progress& progress) {
    const std::size_t pixels = layout.pixels();
    const unsigned threshold =
        layout.binary ? 1U : (static_cast<unsigned>(layout.maxFraction) + 1U) / 2U;
    for (std::size_t n = 0; n < list.size(); ++n) {
        progress.report(0.3 + 0.7 * static_cast<double>(n) / static_cast<double>(list.size()),
                        kStage);
        const SegFrame& f = list[n];
        std::unique_ptr<DcmIODTypes::Frame> unpacked;
        const Uint8* data = framePixels(seg, f.frame, layout, unpacked, file);
        const int k = grid.slice(f.along);
        scene::LabelMap& map = maps[f.segment - 1];
        for (std::size_t p = 0; p < pixels; ++p) {
            if (data[p] >= threshold) {
                map.labels[static_cast<std::size_t>(k) * pixels + p] = 1;
            }
        }
    }
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
    readSegFile(ff, file);
    DcmDataset& dataset = *ff.getDataset();
    Uint16 maxFraction = 255;
    dataset.findAndGetUint16(DCM_MaximumFractionalValue, maxFraction);
    const std::unique_ptr<DcmSegmentation> seg = readSegmentation(dataset, file);
    progress.report(0.3, kStage);
    const SegLayout layout = segLayout(*seg, dataset, maxFraction, file);

    // Geometry: orientation and spacing (shared or per frame, must agree),
    // positions per frame.
    FGInterface& groups = seg->getFunctionalGroups();
    std::vector<SegFrame> list(layout.frames);
    SegPlane plane;
    for (std::size_t f = 0; f < layout.frames; ++f) {
        list[f] = readSegFrame(groups, f, layout.segments, file, plane);
    }
    if (!(glm::length(plane.row) > 0.5) || !(glm::length(plane.col) > 0.5)) {
        throw FormatError(file, "invalid Image Orientation (Patient)");
    }
    const glm::dvec3 row = glm::normalize(plane.row);
    const glm::dvec3 col = glm::normalize(plane.col);
    const glm::dvec3 normal = glm::normalize(glm::cross(row, col));
    for (SegFrame& f : list) {
        f.along = glm::dot(f.position, normal);
    }
    const glm::dvec2 spacing = plane.spacing;
    const SegSliceGrid grid(list, 1e-3 * std::min(spacing.x, spacing.y), file);
    const glm::dvec3 origin = segOrigin(list, normal, spacing, file);

    const glm::ivec3 dims(layout.columns, layout.rows, grid.slices());
    glm::dmat4 indexToWorld(1.0);
    indexToWorld[0] = glm::dvec4(row * spacing.y, 0.0);
    indexToWorld[1] = glm::dvec4(col * spacing.x, 0.0);
    indexToWorld[2] = glm::dvec4(normal * grid.spacing(), 0.0);
    indexToWorld[3] = glm::dvec4(origin, 1.0);
    const double voxelVolume = spacing.x * spacing.y * grid.spacing();

    std::vector<scene::LabelMap> maps = emptyMaps(*seg, layout.segments, dims, indexToWorld);
    paintFrames(*seg, list, layout, grid, maps, file, progress);
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
