// SPDX-License-Identifier: GPL-3.0-or-later
// loadDicomSeries: sorted slices -> one Volume with its patient geometry.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>

#include "DicomHeader.h"
#include "DicomPixels.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/dicom/Dicom.h"

namespace vv::dicom {

namespace fs = std::filesystem;

namespace {

const log::Category kLog("vv.dicom");

/// One image of the series: a frame of a file, where it lies, its rescale.
struct Slice {
    std::size_t header = 0;
    std::uint64_t frame = 0;
    std::optional<glm::dvec3> position;
    double along = 0.0;  ///< position projected on the slice normal
    double slope = 1.0;
    double intercept = 0.0;
};

using Headers = std::vector<detail::FileHeader>;
using Warnings = std::vector<DicomWarning>;

std::string fmt(double v, int digits = 3) {
    std::ostringstream out;
    out << std::setprecision(digits) << v;
    return out.str();
}

bool isInteger(double v) {
    return std::abs(v - std::nearbyint(v)) < 1e-9;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Range of stored values a header allows.
std::pair<double, double> storedRange(const detail::FileHeader& h) {
    if (h.bitsAllocated == 1) {
        return {0.0, 1.0};
    }
    const double span = std::ldexp(1.0, h.bitsStored);
    if (h.pixelRepresentation == 1) {
        return {-span / 2, span / 2 - 1};
    }
    return {0.0, span - 1};
}

/// Logs `message` as a warning and keeps it among the load's warnings.
void warn(Warnings& warnings, DicomWarning::Kind kind, std::string message) {
    log::warning(kLog, message);
    warnings.push_back({kind, std::move(message)});
}

/// Step 1: every file's header, in the series' order (pixel data stays on
/// disk). Throws FormatError for a file that is no image or cannot be decoded.
Headers readSeriesHeaders(const DicomSeries& series, const Progress& progress) {
    Headers headers;
    headers.reserve(series.files.size());
    for (std::size_t i = 0; i < series.files.size(); ++i) {
        progress.report(static_cast<double>(i) / static_cast<double>(series.files.size()),
                        "Reading DICOM headers");
        detail::FileHeader h = detail::readHeader(series.files[i]);
        if (!h.skipReason.empty()) {
            throw FormatError(h.file, h.skipReason);
        }
        if (!h.unsupportedReason.empty()) {
            throw FormatError(h.file, h.unsupportedReason);
        }
        headers.push_back(std::move(h));
    }
    return headers;
}

/// The size of every image of the series.
struct ImageSize {
    int rows = 0;
    int columns = 0;

    [[nodiscard]] std::uint64_t voxels() const {
        return static_cast<std::uint64_t>(rows) * static_cast<std::uint64_t>(columns);
    }
};

/// Step 2: the one image size of all headers; throws FormatError, counting
/// the images of each size, when they differ.
ImageSize commonImageSize(const Headers& headers, const std::string& label) {
    const int rows = headers.front().rows;
    const int columns = headers.front().columns;
    for (const auto& h : headers) {
        if (h.rows != rows || h.columns != columns) {
            std::size_t same = 0;
            std::size_t other = 0;
            for (const auto& g : headers) {
                (g.rows == rows && g.columns == columns ? same : other) += g.frames;
            }
            throw FormatError(
                h.file, label + " mixes image sizes: " + std::to_string(columns) + " x " +
                            std::to_string(rows) + " (" + std::to_string(same) + " images) and " +
                            std::to_string(h.columns) + " x " + std::to_string(h.rows) +
                            " (and others, " + std::to_string(other) +
                            " images); one volume needs one image size");
        }
    }
    return {rows, columns};
}

/// Step 3: refuses a volume that would not fit in `limit` bytes (0: no
/// limit), counting what the loader holds besides the volume.
class MemoryBudget {
  public:
    MemoryBudget(std::uint64_t limit, ImageSize size, std::uint64_t imageCount, fs::path file,
                 std::string label)
        : limit_(limit),
          size_(size),
          imageCount_(imageCount),
          file_(std::move(file)),
          label_(std::move(label)) {}

    /// Throws scene::MemoryError when `slices` slices of `type` need more than the limit.
    void check(std::uint64_t slices, scene::VoxelType type) const {
        const std::uint64_t volumeBytes =
            scene::Volume::byteSize(static_cast<std::uint64_t>(size_.columns),
                                    static_cast<std::uint64_t>(size_.rows), slices, type);
        const std::uint64_t sliceVoxels = size_.voxels();
        const std::uint64_t overhead =
            imageCount_ * sizeof(Slice) + 3 * sliceVoxels * sizeof(float) + 4 * sliceVoxels;
        const std::uint64_t need =
            volumeBytes > std::numeric_limits<std::uint64_t>::max() - overhead
                ? std::numeric_limits<std::uint64_t>::max()
                : volumeBytes + overhead;
        if (limit_ != 0 && need > limit_) {
            throw scene::MemoryError(
                file_, label_ + ": the volume of " + std::to_string(size_.columns) + " x " +
                           std::to_string(size_.rows) + " x " + std::to_string(slices) +
                           " voxels needs " + detail::humanBytes(need) + " but only " +
                           detail::humanBytes(limit_) +
                           " of memory is available; it was not loaded");
        }
    }

  private:
    std::uint64_t limit_;
    ImageSize size_;
    std::uint64_t imageCount_;
    fs::path file_;
    std::string label_;
};

/// Step 4: one Slice per frame of every file, in file order, with its
/// position where the header gives one and its rescale (slope 1 where the
/// slope is unusable).
std::vector<Slice> listSlices(const Headers& headers, std::uint64_t imageCount) {
    std::vector<Slice> slices;
    slices.reserve(static_cast<std::size_t>(imageCount));
    for (std::size_t hi = 0; hi < headers.size(); ++hi) {
        const auto& h = headers[hi];
        for (std::uint64_t f = 0; f < h.frames; ++f) {
            const detail::FrameInfo& fi = h.perFrame.empty() ? h.shared : h.perFrame[f];
            Slice s;
            s.header = hi;
            s.frame = f;
            // Frames without geometry keep no position (stacked below).
            if (!h.framesWithoutGeometry && !h.perFrame.empty()) {
                s.position = fi.position;
            } else if (!h.framesWithoutGeometry && h.shared.position) {
                s.position = *h.shared.position +
                             static_cast<double>(f) * h.frameStep.value_or(glm::dvec3(0.0));
            }
            s.slope = fi.slope.value_or(1.0);
            s.intercept = fi.intercept.value_or(0.0);
            if (!std::isfinite(s.slope) || s.slope == 0.0) {
                s.slope = 1.0;
            }
            slices.push_back(s);
        }
    }
    return slices;
}

/// The one Image Orientation (Patient) of all files and frames, none when no
/// header gives one; throws FormatError when two differ (a localizer).
std::optional<std::array<double, 6>> commonOrientation(const Headers& headers,
                                                       const std::string& label) {
    std::optional<std::array<double, 6>> orientation;
    for (const auto& h : headers) {
        const auto check = [&](const std::optional<std::array<double, 6>>& o) {
            if (!o) {
                return;
            }
            if (!orientation) {
                orientation = o;
                return;
            }
            double diff = 0.0;
            for (int k = 0; k < 6; ++k) {
                diff = std::max(diff, std::abs((*o)[k] - (*orientation)[k]));
            }
            if (diff > 1e-3) {
                throw FormatError(h.file,
                                  label +
                                      " has slices of different orientations (a localizer?); "
                                      "one volume needs one orientation");
            }
        };
        check(h.shared.orientation);
        for (const auto& f : h.perFrame) {
            check(f.orientation);
        }
    }
    return orientation;
}

/// The images' plane: unit row and column directions, orthogonal, and the
/// slice normal (row x column).
struct Axes {
    glm::dvec3 row{1, 0, 0};
    glm::dvec3 column{0, 1, 0};
    glm::dvec3 normal{0, 0, 1};
};

/// The axes an orientation gives; axial, with a warning, when it is missing
/// or degenerate.
Axes sliceAxes(const std::optional<std::array<double, 6>>& orientation, const std::string& label,
               Warnings& warnings) {
    Axes axes;
    if (orientation) {
        const auto& o = *orientation;
        const glm::dvec3 r(o[0], o[1], o[2]);
        const glm::dvec3 c(o[3], o[4], o[5]);
        if (glm::length(r) > 0.5 && glm::length(c) > 0.5 &&
            std::abs(glm::dot(glm::normalize(r), glm::normalize(c))) < 1e-2) {
            axes.row = glm::normalize(r);
            axes.column = glm::normalize(c - glm::dot(c, axes.row) * axes.row);
        } else {
            warn(warnings, DicomWarning::Kind::NoGeometry,
                 label + ": Image Orientation (Patient) is degenerate; axial orientation assumed");
        }
    } else {
        warn(warnings, DicomWarning::Kind::NoGeometry,
             label + ": no Image Orientation (Patient); axial orientation assumed");
    }
    axes.normal = glm::normalize(glm::cross(axes.row, axes.column));
    return axes;
}

/// The distance between slices a header declares: Spacing Between Slices,
/// else Slice Thickness, else 1 mm.
double declaredSpacing(const detail::FileHeader& first) {
    return first.spacingBetweenSlices > 0 ? first.spacingBetweenSlices
           : first.sliceThickness > 0     ? first.sliceThickness
                                          : 1.0;
}

/// Gives every slice a position and sorts the slices along `normal` (stable:
/// file and frame order among equals). Positions are all given, or none: then
/// a single image lies at the file's position (the origin, with a warning)
/// and the frames of a single multi-frame file are stacked `spacing` apart in
/// frame order (with a warning). Throws FormatError when only some images
/// have a position, or several files have none.
void placeSlices(std::vector<Slice>& slices, const Headers& headers, const glm::dvec3& normal,
                 double spacing, const std::string& label, Warnings& warnings) {
    const std::size_t n = slices.size();
    const auto withPosition = static_cast<std::size_t>(std::count_if(
        slices.begin(), slices.end(), [](const Slice& s) { return s.position.has_value(); }));
    const auto& first = headers.front();
    if (withPosition != 0 && withPosition != n) {
        throw FormatError(first.file, label + ": " + std::to_string(n - withPosition) + " of " +
                                          std::to_string(n) +
                                          " images have no Image Position (Patient)");
    }
    if (withPosition == 0) {
        if (n == 1) {
            slices[0].position = first.shared.position.value_or(glm::dvec3(0.0));
            if (!first.shared.position) {
                warn(warnings, DicomWarning::Kind::NoGeometry,
                     label + ": no Image Position (Patient); the image is placed at the origin");
            }
        } else if (headers.size() == 1) {
            // One multi-frame file without frame positions: frame order is
            // the only order there is.
            const glm::dvec3 origin = first.shared.position.value_or(glm::dvec3(0.0));
            for (std::size_t i = 0; i < n; ++i) {
                slices[i].position = origin + static_cast<double>(i) * spacing * normal;
            }
            warn(warnings, DicomWarning::Kind::NoGeometry,
                 label + ": the " + std::to_string(n) +
                     " frames have no positions; stacked in frame order " + fmt(spacing) +
                     " mm apart");
        } else {
            throw FormatError(first.file,
                              label + ": " + std::to_string(n) +
                                  " images have no Image Position (Patient); VesselView orders "
                                  "slices by position only, never by instance number or file name");
        }
    }
    for (auto& s : slices) {
        s.along = glm::dot(*s.position, normal);
    }
    std::stable_sort(slices.begin(), slices.end(),
                     [](const Slice& a, const Slice& b) { return a.along < b.along; });
}

/// Throws FormatError when sorted slices share a position: several echoes,
/// phases or acquisitions in one series.
void refuseSharedPositions(const std::vector<Slice>& slices, const fs::path& file,
                           const std::string& label) {
    std::size_t duplicates = 0;
    for (std::size_t i = 1; i < slices.size(); ++i) {
        if (slices[i].along - slices[i - 1].along < 1e-3) {
            ++duplicates;
        }
    }
    if (duplicates > 0) {
        throw FormatError(file,
                          label + ": " + std::to_string(duplicates) +
                              " images lie at the position of another image (several echoes, "
                              "phases or acquisitions in one series?); one volume needs one image "
                              "per position");
    }
}

/// The first image's pixel spacing (column spacing, row spacing); 1 mm, with
/// a warning, when it has none.
glm::dvec2 pixelSpacing(const detail::FileHeader& first, const std::string& label,
                        Warnings& warnings) {
    const detail::FrameInfo& fi = first.perFrame.empty() ? first.shared : first.perFrame.front();
    if (fi.pixelSpacing) {
        return *fi.pixelSpacing;
    }
    warn(warnings, DicomWarning::Kind::NoGeometry, label + ": no Pixel Spacing; 1 mm assumed");
    return glm::dvec2(1.0);
}

/// The volume's slices: uniformly spaced, from the first image to the last.
struct SliceGrid {
    std::size_t slices = 0;  ///< how many
    glm::dvec3 step{0.0};    ///< from one slice to the next, in patient space
    double stepAlong = 0.0;  ///< from one slice to the next, along the normal
    bool resample = false;   ///< slices are interpolated, not the images as they are
};

/// What the gaps between sorted slices say, measured against the usual gap.
struct GapSurvey {
    std::size_t missing = 0;  ///< slices missing where a gap is a multiple of the usual one
    std::string missingAt;    ///< where they are missing (cut after about 200 characters)
    double minGap = 0.0;
    double maxGap = 0.0;
    bool nonUniform = false;  ///< a gap is neither the usual one nor a multiple of it
};

/// Surveys `gaps` (between neighbours of the sorted `slices`) against `base`,
/// the usual gap, with `tolerance` (mm).
GapSurvey surveyGaps(const std::vector<double>& gaps, double base, double tolerance,
                     const std::vector<Slice>& slices) {
    GapSurvey survey;
    survey.minGap = gaps.front();
    survey.maxGap = gaps.front();
    for (std::size_t i = 0; i < gaps.size(); ++i) {
        survey.minGap = std::min(survey.minGap, gaps[i]);
        survey.maxGap = std::max(survey.maxGap, gaps[i]);
        const double ratio = gaps[i] / base;
        if (ratio >= 1.5 && std::abs(ratio - std::nearbyint(ratio)) <= 0.2) {
            const auto k = static_cast<std::size_t>(std::nearbyint(ratio)) - 1;
            survey.missing += k;
            if (survey.missingAt.size() < 200) {
                survey.missingAt += (survey.missingAt.empty() ? "" : ", ") + std::to_string(k) +
                                    " after " + fmt(slices[i].along, 6) + " mm";
            }
        } else if (std::abs(gaps[i] - base) > tolerance) {
            survey.nonUniform = true;
        }
    }
    return survey;
}

/// The step between grid slices: along the normal, or, when the positions
/// drift in-plane from slice to slice (gantry tilt, with a warning), along the
/// line from the first position to the last.
glm::dvec3 gridStep(const std::vector<Slice>& slices, const glm::dvec3& normal,
                    const SliceGrid& grid, const std::string& label, Warnings& warnings) {
    const glm::dvec3 d = *slices.back().position - *slices.front().position;
    const double dAlong = glm::dot(d, normal);
    const double drift = glm::length(d - dAlong * normal);
    const double degrees = std::atan2(drift, std::abs(dAlong)) * 180.0 / 3.14159265358979323846;
    if (degrees > 0.05) {
        warn(warnings, DicomWarning::Kind::GantryTilt,
             label + ": gantry tilt of " + fmt(degrees) + " degrees (slice positions drift " +
                 fmt(drift) +
                 " mm in-plane); the volume keeps the sheared grid in its index-to-world "
                 "transform");
        return d / static_cast<double>(grid.slices - 1);
    }
    return normal * grid.stepAlong;
}

/// Step 5: the slice grid, uniform spacing from the sorted positions; missing
/// slices and non-uniform gaps are filled by interpolation (with warnings).
/// A single slice lies in a grid of `spacing`. Throws FormatError when most
/// of the grid's slices would be missing.
SliceGrid sliceGrid(const std::vector<Slice>& slices, const glm::dvec3& normal, double spacing,
                    const fs::path& file, const std::string& label, Warnings& warnings) {
    const std::size_t n = slices.size();
    SliceGrid grid{n, normal * spacing, spacing, false};
    if (n < 2) {
        return grid;
    }
    std::vector<double> gaps(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        gaps[i] = slices[i + 1].along - slices[i].along;
    }
    const double base = median(gaps);
    const double extent = slices.back().along - slices.front().along;
    const double count = std::nearbyint(extent / base);
    if (count + 1 > 4.0 * static_cast<double>(n) + 4.0) {
        throw FormatError(file, label + ": the slices span " + fmt(extent) +
                                    " mm with a usual gap of " + fmt(base) +
                                    " mm; most slices would be missing");
    }
    grid.slices = static_cast<std::size_t>(count) + 1;
    grid.stepAlong = extent / static_cast<double>(grid.slices - 1);
    const double tolerance = std::max(0.01, 0.01 * base);
    const GapSurvey survey = surveyGaps(gaps, base, tolerance, slices);
    if (survey.missing > 0) {
        grid.resample = true;
        warn(warnings, DicomWarning::Kind::MissingSlices,
             label + ": " + std::to_string(survey.missing) + " missing slice" +
                 (survey.missing == 1 ? "" : "s") + " (" + survey.missingAt +
                 " along the normal); filled by linear interpolation");
    }
    if (survey.nonUniform) {
        grid.resample = true;
        warn(warnings, DicomWarning::Kind::NonUniformSpacing,
             label + ": non-uniform slice spacing (gaps " + fmt(survey.minGap) + " to " +
                 fmt(survey.maxGap) + " mm); resampled to " + std::to_string(grid.slices) +
                 " slices " + fmt(grid.stepAlong) + " mm apart by linear interpolation");
    }
    if (!grid.resample && (grid.slices != n || std::abs(grid.stepAlong - base) > tolerance)) {
        grid.resample = true;
    }
    grid.step = gridStep(slices, normal, grid, label, warnings);
    return grid;
}

/// The voxel type of the volume and whether the stored ranges alone prove
/// that every rescaled value fits it.
struct VoxelChoice {
    scene::VoxelType type = scene::VoxelType::Float32;
    bool rangeKnownToFit = true;
};

/// Step 6: Int16 when allowed and every rescaled value is an integer
/// (integer slope and intercept); `rangeKnownToFit` when the stored ranges
/// show that they fit, else the values themselves are checked while decoding.
VoxelChoice chooseVoxelType(const std::vector<Slice>& slices, const Headers& headers,
                            bool allowInt16) {
    VoxelChoice choice{allowInt16 ? scene::VoxelType::Int16 : scene::VoxelType::Float32, true};
    if (choice.type != scene::VoxelType::Int16) {
        return choice;
    }
    for (const auto& s : slices) {
        if (!isInteger(s.slope) || !isInteger(s.intercept)) {
            choice.type = scene::VoxelType::Float32;
            break;
        }
        const auto [lo, hi] = storedRange(headers[s.header]);
        const double a = lo * s.slope + s.intercept;
        const double b = hi * s.slope + s.intercept;
        if (std::min(a, b) < -32768.0 || std::max(a, b) > 32767.0) {
            choice.rangeKnownToFit = false;
        }
    }
    return choice;
}

/// Index to patient space: columns along the row direction, rows along the
/// column direction, slices by the grid's step, voxel (0, 0, 0) at `origin`.
glm::dmat4 indexToWorld(const Axes& axes, const glm::dvec2& pixelSpacing, const SliceGrid& grid,
                        const glm::dvec3& origin) {
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(axes.row * pixelSpacing.x, 0.0);
    m[1] = glm::dvec4(axes.column * pixelSpacing.y, 0.0);
    m[2] = glm::dvec4(grid.step, 0.0);
    m[3] = glm::dvec4(origin, 1.0);
    return m;
}

/// Warns once when a file has a Modality LUT Sequence (it is not applied).
void warnOfModalityLut(const Headers& headers, const std::string& label, Warnings& warnings) {
    const bool any = std::any_of(headers.begin(), headers.end(),
                                 [](const detail::FileHeader& h) { return h.hasModalityLut; });
    if (any) {
        warn(warnings, DicomWarning::Kind::Other,
             label + ": the Modality LUT Sequence is not applied; stored values are used");
    }
}

/// Rescaled images of sorted slices, decoded on demand; holds the last two.
class DecodedSlices {
  public:
    DecodedSlices(const std::vector<Slice>& slices, const Headers& headers)
        : slices_(&slices), headers_(&headers) {}

    /// The image of slice `i`; decoding it replaces a held image other than `keep`'s.
    const std::vector<float>& get(std::size_t i, std::size_t keep) {
        for (int c = 0; c < 2; ++c) {
            if (index_[c] == i) {
                return images_[c];
            }
        }
        const int slot = index_[0] == keep ? 1 : 0;
        const Slice& s = (*slices_)[i];
        reader_.read((*headers_)[s.header], s.frame, s.slope, s.intercept, images_[slot]);
        index_[slot] = i;
        return images_[slot];
    }

  private:
    const std::vector<Slice>* slices_;
    const Headers* headers_;
    detail::FrameReader reader_;
    std::array<std::size_t, 2> index_{SIZE_MAX, SIZE_MAX};
    std::array<std::vector<float>, 2> images_;
};

/// Whether every value of an image fits Int16 once rounded.
bool fitsInt16(const std::vector<float>& v) {
    return std::all_of(v.begin(), v.end(), [](float x) { return x >= -32768.5F && x <= 32767.5F; });
}

/// Step 7: fills `volume` slice by slice, holding at most two decoded images;
/// a grid slice between two images interpolates them linearly. False when
/// `checkRange` and an image has a value beyond Int16.
bool fillVolume(scene::Volume& volume, const std::vector<Slice>& slices, const Headers& headers,
                const SliceGrid& grid, std::size_t perSlice, bool checkRange,
                const Progress& progress) {
    DecodedSlices decoded(slices, headers);
    const std::size_t n = slices.size();
    std::size_t below = 0;  // slices[below].along <= z
    for (std::size_t k = 0; k < grid.slices; ++k) {
        progress.report(static_cast<double>(k) / static_cast<double>(grid.slices),
                        "Loading DICOM series");
        const std::size_t offset = k * perSlice;
        std::size_t a = k;
        std::size_t b = k;
        double t = 0.0;
        if (grid.resample) {
            const double z = slices.front().along + static_cast<double>(k) * grid.stepAlong;
            while (below + 1 < n && slices[below + 1].along <= z + 1e-6) {
                ++below;
            }
            a = below;
            b = below;
            const double snap = 1e-4 * grid.stepAlong + 1e-6;
            if (std::abs(z - slices[below].along) > snap && below + 1 < n) {
                b = below + 1;
                t = (z - slices[a].along) / (slices[b].along - slices[a].along);
            }
        }
        const auto& va = decoded.get(a, b);
        if (checkRange && !fitsInt16(va)) {
            return false;
        }
        if (a == b) {
            for (std::size_t p = 0; p < perSlice; ++p) {
                volume.setValueAt(offset + p, va[p]);
            }
            continue;
        }
        const auto& vb = decoded.get(b, a);
        if (checkRange && !fitsInt16(vb)) {
            return false;
        }
        const auto tf = static_cast<float>(t);
        for (std::size_t p = 0; p < perSlice; ++p) {
            volume.setValueAt(offset + p, va[p] + (vb[p] - va[p]) * tf);
        }
    }
    progress.report(1.0, "Loading DICOM series");
    return true;
}

/// The decoded volume of the grid. An Int16 volume that meets a value beyond
/// 16 bits is freed and decoded again as Float32 (after a fresh memory
/// check). Throws FormatError when the grid has more slices than a volume holds.
scene::Volume decodeVolume(const std::vector<Slice>& slices, const Headers& headers,
                           const SliceGrid& grid, ImageSize size, VoxelChoice voxels,
                           const MemoryBudget& memory, const std::string& label,
                           const Progress& progress) {
    if (grid.slices > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        throw FormatError(headers.front().file, label + ": " + std::to_string(grid.slices) +
                                                    " slices are more than a volume can hold");
    }
    const auto perSlice = static_cast<std::size_t>(size.voxels());
    const glm::ivec3 dims(size.columns, size.rows, static_cast<int>(grid.slices));
    scene::Volume volume(dims, voxels.type);
    const bool checkRange = voxels.type == scene::VoxelType::Int16 && !voxels.rangeKnownToFit;
    if (!fillVolume(volume, slices, headers, grid, perSlice, checkRange, progress)) {
        log::info(kLog, label + ": values beyond 16 bits; loading as 32-bit floats");
        volume = scene::Volume();
        memory.check(grid.slices, scene::VoxelType::Float32);
        volume = scene::Volume(dims, scene::VoxelType::Float32);
        fillVolume(volume, slices, headers, grid, perSlice, false, progress);
    }
    return volume;
}

}  // namespace

DicomVolume loadDicomSeries(const DicomSeries& series, const DicomLoadOptions& options,
                            const Progress& progress) {
    detail::ensureCodecs();
    const std::string label =
        "series " +
        (series.seriesInstanceUid.empty() ? std::string("(no UID)") : series.seriesInstanceUid);
    if (series.files.empty()) {
        throw FormatError(label + " has no files");
    }
    DicomVolume result;
    result.seriesInstanceUid = series.seriesInstanceUid;
    result.studyInstanceUid = series.studyInstanceUid;
    result.frameOfReferenceUid = series.frameOfReferenceUid;
    Warnings& warnings = result.warnings;

    // 1. Headers (pixel data stays on disk).
    const Headers headers = readSeriesHeaders(series, progress.sub(0.0, 0.05));
    const detail::FileHeader& first = headers.front();

    // 2. One size for all images.
    const ImageSize size = commonImageSize(headers, label);
    std::uint64_t imageCount = 0;
    for (const auto& h : headers) {
        imageCount += h.frames;
    }

    // 3. Memory, coarse: before the slice list is built (a header may declare
    // absurd frame counts).
    const std::uint64_t limit =
        options.memoryLimitBytes != 0 ? options.memoryLimitBytes : availableMemoryBytes();
    const MemoryBudget memory(limit, size, imageCount, first.file, label);
    memory.check(imageCount,
                 options.allowInt16 ? scene::VoxelType::Int16 : scene::VoxelType::Float32);

    // 4. Slices with positions and rescale, in one orientation, sorted along
    // its normal, one per position.
    std::vector<Slice> slices = listSlices(headers, imageCount);
    const Axes axes = sliceAxes(commonOrientation(headers, label), label, warnings);
    const double spacing = declaredSpacing(first);
    placeSlices(slices, headers, axes.normal, spacing, label, warnings);
    refuseSharedPositions(slices, first.file, label);
    const glm::dvec2 pixel = pixelSpacing(first, label, warnings);

    // 5. The slice grid: uniform spacing from the positions.
    const SliceGrid grid = sliceGrid(slices, axes.normal, spacing, first.file, label, warnings);

    // 6. Voxel type, then the fine memory check.
    const VoxelChoice voxels = chooseVoxelType(slices, headers, options.allowInt16);
    memory.check(grid.slices, voxels.type);
    const glm::dmat4 m = indexToWorld(axes, pixel, grid, *slices.front().position);
    warnOfModalityLut(headers, label, warnings);

    // 7. Decode, slice by slice.
    scene::Volume volume =
        decodeVolume(slices, headers, grid, size, voxels, memory, label, progress.sub(0.05, 1.0));
    volume.setIndexToWorld(m);
    volume.setModality(series.modality.empty() ? first.modality : series.modality);
    if (volume.modality() == "CT") {
        volume.setUnit("HU");
    }

    result.sourceImages = slices.size();
    result.volume = std::move(volume);
    log::info(kLog, label + ": " + std::to_string(size.columns) + " x " +
                        std::to_string(size.rows) + " x " + std::to_string(grid.slices) +
                        " voxels loaded from " + std::to_string(slices.size()) + " images");
    return result;
}

DicomVolume loadDicomVolume(const fs::path& path, std::string_view seriesInstanceUid,
                            const DicomLoadOptions& options, const Progress& progress) {
    const DicomScanResult scan = scanDicom(path, progress.sub(0.0, 0.1));
    const std::vector<const DicomSeries*> all = scan.allSeries();
    const DicomSeries* series = nullptr;
    if (seriesInstanceUid.empty()) {
        if (all.empty()) {
            std::string why = "holds no image series";
            if (scan.skipped.size() == 1) {
                why += ": " + scan.skipped.front().reason;
            } else if (!scan.skipped.empty()) {
                why += " (" + std::to_string(scan.skipped.size()) + " files skipped)";
            }
            throw FormatError(path, why);
        }
        if (all.size() > 1) {
            std::string list;
            for (const auto* s : all) {
                list += "\n  " + (s->seriesInstanceUid.empty() ? std::string("(no UID)")
                                                               : s->seriesInstanceUid);
            }
            throw FormatError(path, "holds " + std::to_string(all.size()) +
                                        " series; choose one by its Series Instance UID:" + list);
        }
        series = all.front();
    } else {
        series = scan.findSeries(seriesInstanceUid);
        if (series == nullptr) {
            throw FormatError(path, "holds no series with UID " + std::string(seriesInstanceUid));
        }
    }
    return loadDicomSeries(*series, options, progress.sub(0.1, 1.0));
}

}  // namespace vv::dicom
