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
    const auto warn = [&](DicomWarning::Kind kind, std::string message) {
        log::warning(kLog, message);
        result.warnings.push_back({kind, std::move(message)});
    };

    // 1. Headers (pixel data stays on disk).
    const Progress headerProgress = progress.sub(0.0, 0.05);
    std::vector<detail::FileHeader> headers;
    headers.reserve(series.files.size());
    for (std::size_t i = 0; i < series.files.size(); ++i) {
        headerProgress.report(static_cast<double>(i) / static_cast<double>(series.files.size()),
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

    // 2. One size for all images.
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
    const std::uint64_t sliceVoxels =
        static_cast<std::uint64_t>(rows) * static_cast<std::uint64_t>(columns);
    std::uint64_t imageCount = 0;
    for (const auto& h : headers) {
        imageCount += h.frames;
    }

    // 3. Memory, coarse: before the slice list is built (a header may declare
    // absurd frame counts).
    std::uint64_t limit = options.memoryLimitBytes;
    if (limit == 0) {
        limit = availableMemoryBytes();
    }
    const auto checkMemory = [&](std::uint64_t slices, scene::VoxelType type) {
        const std::uint64_t volumeBytes = scene::Volume::byteSize(
            static_cast<std::uint64_t>(columns), static_cast<std::uint64_t>(rows), slices, type);
        const std::uint64_t overhead =
            imageCount * sizeof(Slice) + 3 * sliceVoxels * sizeof(float) + 4 * sliceVoxels;
        const std::uint64_t need =
            volumeBytes > std::numeric_limits<std::uint64_t>::max() - overhead
                ? std::numeric_limits<std::uint64_t>::max()
                : volumeBytes + overhead;
        if (limit != 0 && need > limit) {
            throw scene::MemoryError(headers.front().file,
                                     label + ": the volume of " + std::to_string(columns) + " x " +
                                         std::to_string(rows) + " x " + std::to_string(slices) +
                                         " voxels needs " + detail::humanBytes(need) +
                                         " but only " + detail::humanBytes(limit) +
                                         " of memory is available; it was not loaded");
        }
    };
    checkMemory(imageCount,
                options.allowInt16 ? scene::VoxelType::Int16 : scene::VoxelType::Float32);

    // 4. Slices with positions and rescale.
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
    const std::size_t n = slices.size();

    // Orientation: one for all.
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
    glm::dvec3 rowDir(1, 0, 0);
    glm::dvec3 colDir(0, 1, 0);
    if (orientation) {
        const auto& o = *orientation;
        const glm::dvec3 r(o[0], o[1], o[2]);
        const glm::dvec3 c(o[3], o[4], o[5]);
        if (glm::length(r) > 0.5 && glm::length(c) > 0.5 &&
            std::abs(glm::dot(glm::normalize(r), glm::normalize(c))) < 1e-2) {
            rowDir = glm::normalize(r);
            colDir = glm::normalize(c - glm::dot(c, rowDir) * rowDir);
        } else {
            warn(DicomWarning::Kind::NoGeometry,
                 label + ": Image Orientation (Patient) is degenerate; axial orientation assumed");
        }
    } else {
        warn(DicomWarning::Kind::NoGeometry,
             label + ": no Image Orientation (Patient); axial orientation assumed");
    }
    const glm::dvec3 normal = glm::normalize(glm::cross(rowDir, colDir));

    // Positions: all or none.
    const auto withPosition = static_cast<std::size_t>(std::count_if(
        slices.begin(), slices.end(), [](const Slice& s) { return s.position.has_value(); }));
    const auto& first = headers.front();
    const double declaredSpacing = first.spacingBetweenSlices > 0 ? first.spacingBetweenSlices
                                   : first.sliceThickness > 0     ? first.sliceThickness
                                                                  : 1.0;
    if (withPosition != 0 && withPosition != n) {
        throw FormatError(first.file, label + ": " + std::to_string(n - withPosition) + " of " +
                                          std::to_string(n) +
                                          " images have no Image Position (Patient)");
    }
    if (withPosition == 0) {
        if (n == 1) {
            slices[0].position = first.shared.position.value_or(glm::dvec3(0.0));
            if (!first.shared.position) {
                warn(DicomWarning::Kind::NoGeometry,
                     label + ": no Image Position (Patient); the image is placed at the origin");
            }
        } else if (headers.size() == 1) {
            // One multi-frame file without frame positions: frame order is
            // the only order there is.
            const glm::dvec3 origin = first.shared.position.value_or(glm::dvec3(0.0));
            for (std::size_t i = 0; i < n; ++i) {
                slices[i].position = origin + static_cast<double>(i) * declaredSpacing * normal;
            }
            warn(DicomWarning::Kind::NoGeometry,
                 label + ": the " + std::to_string(n) +
                     " frames have no positions; stacked in frame order " + fmt(declaredSpacing) +
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

    // Several images at one position: echoes, phases, acquisitions.
    std::size_t duplicates = 0;
    for (std::size_t i = 1; i < n; ++i) {
        if (slices[i].along - slices[i - 1].along < 1e-3) {
            ++duplicates;
        }
    }
    if (duplicates > 0) {
        throw FormatError(first.file,
                          label + ": " + std::to_string(duplicates) +
                              " images lie at the position of another image (several echoes, "
                              "phases or acquisitions in one series?); one volume needs one image "
                              "per position");
    }

    // Pixel spacing.
    glm::dvec2 pixelSpacing(1.0);
    {
        const detail::FrameInfo& fi =
            first.perFrame.empty() ? first.shared : first.perFrame.front();
        if (fi.pixelSpacing) {
            pixelSpacing = *fi.pixelSpacing;
        } else {
            warn(DicomWarning::Kind::NoGeometry, label + ": no Pixel Spacing; 1 mm assumed");
        }
    }

    // 5. The slice grid: uniform spacing from the positions.
    std::size_t gridSlices = n;
    glm::dvec3 step = normal * declaredSpacing;
    double stepAlong = declaredSpacing;
    bool resample = false;
    if (n >= 2) {
        std::vector<double> gaps(n - 1);
        for (std::size_t i = 0; i + 1 < n; ++i) {
            gaps[i] = slices[i + 1].along - slices[i].along;
        }
        const double base = median(gaps);
        const double extent = slices.back().along - slices.front().along;
        const double count = std::nearbyint(extent / base);
        if (count + 1 > 4.0 * static_cast<double>(n) + 4.0) {
            throw FormatError(first.file, label + ": the slices span " + fmt(extent) +
                                              " mm with a usual gap of " + fmt(base) +
                                              " mm; most slices would be missing");
        }
        gridSlices = static_cast<std::size_t>(count) + 1;
        stepAlong = extent / static_cast<double>(gridSlices - 1);
        const double tolerance = std::max(0.01, 0.01 * base);
        std::size_t missing = 0;
        std::string missingAt;
        double minGap = gaps.front();
        double maxGap = gaps.front();
        bool nonUniform = false;
        for (std::size_t i = 0; i < gaps.size(); ++i) {
            minGap = std::min(minGap, gaps[i]);
            maxGap = std::max(maxGap, gaps[i]);
            const double ratio = gaps[i] / base;
            if (ratio >= 1.5 && std::abs(ratio - std::nearbyint(ratio)) <= 0.2) {
                const auto k = static_cast<std::size_t>(std::nearbyint(ratio)) - 1;
                missing += k;
                if (missingAt.size() < 200) {
                    missingAt += (missingAt.empty() ? "" : ", ") + std::to_string(k) + " after " +
                                 fmt(slices[i].along, 6) + " mm";
                }
            } else if (std::abs(gaps[i] - base) > tolerance) {
                nonUniform = true;
            }
        }
        if (missing > 0) {
            resample = true;
            warn(DicomWarning::Kind::MissingSlices,
                 label + ": " + std::to_string(missing) + " missing slice" +
                     (missing == 1 ? "" : "s") + " (" + missingAt +
                     " along the normal); filled by linear interpolation");
        }
        if (nonUniform) {
            resample = true;
            warn(DicomWarning::Kind::NonUniformSpacing,
                 label + ": non-uniform slice spacing (gaps " + fmt(minGap) + " to " + fmt(maxGap) +
                     " mm); resampled to " + std::to_string(gridSlices) + " slices " +
                     fmt(stepAlong) + " mm apart by linear interpolation");
        }
        if (!resample && (gridSlices != n || std::abs(stepAlong - base) > tolerance)) {
            resample = true;
        }
        // Gantry tilt: positions drift in-plane from slice to slice.
        const glm::dvec3 d = *slices.back().position - *slices.front().position;
        const double dAlong = glm::dot(d, normal);
        const double drift = glm::length(d - dAlong * normal);
        const double degrees = std::atan2(drift, std::abs(dAlong)) * 180.0 / 3.14159265358979323846;
        if (degrees > 0.05) {
            step = d / static_cast<double>(gridSlices - 1);
            warn(DicomWarning::Kind::GantryTilt,
                 label + ": gantry tilt of " + fmt(degrees) + " degrees (slice positions drift " +
                     fmt(drift) +
                     " mm in-plane); the volume keeps the sheared grid in its index-to-world "
                     "transform");
        } else {
            step = normal * stepAlong;
        }
    }

    // 6. Voxel type: Int16 when every rescaled value is an integer (integer
    // slope and intercept) and fits; decided from the stored range when that
    // suffices, else from the values themselves while decoding (a value out
    // of range restarts the decode as Float32, after the Int16 volume is freed).
    scene::VoxelType type =
        options.allowInt16 ? scene::VoxelType::Int16 : scene::VoxelType::Float32;
    bool rangeKnownToFit = true;
    if (type == scene::VoxelType::Int16) {
        for (const auto& s : slices) {
            if (!isInteger(s.slope) || !isInteger(s.intercept)) {
                type = scene::VoxelType::Float32;
                break;
            }
            const auto [lo, hi] = storedRange(headers[s.header]);
            const double a = lo * s.slope + s.intercept;
            const double b = hi * s.slope + s.intercept;
            if (std::min(a, b) < -32768.0 || std::max(a, b) > 32767.0) {
                rangeKnownToFit = false;
            }
        }
    }
    checkMemory(gridSlices, type);

    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(rowDir * pixelSpacing.x, 0.0);
    m[1] = glm::dvec4(colDir * pixelSpacing.y, 0.0);
    m[2] = glm::dvec4(step, 0.0);
    m[3] = glm::dvec4(*slices.front().position, 1.0);
    for (const auto& h : headers) {
        if (h.hasModalityLut) {
            warn(DicomWarning::Kind::Other,
                 label + ": the Modality LUT Sequence is not applied; stored values are used");
            break;
        }
    }

    // 7. Decode, slice by slice, holding at most two decoded images.
    const Progress loadProgress = progress.sub(0.05, 1.0);
    const auto perSlice = static_cast<std::size_t>(sliceVoxels);
    /// Fills `volume`; false when an Int16 volume met a value that does not fit.
    const auto fill = [&](scene::Volume& volume, bool checkRange) {
        detail::FrameReader reader;
        std::array<std::size_t, 2> cachedIndex{SIZE_MAX, SIZE_MAX};
        std::array<std::vector<float>, 2> cached;
        const auto decoded = [&](std::size_t i, std::size_t keep) -> const std::vector<float>& {
            for (int c = 0; c < 2; ++c) {
                if (cachedIndex[c] == i) {
                    return cached[c];
                }
            }
            const int slot = cachedIndex[0] == keep ? 1 : 0;
            const Slice& s = slices[i];
            reader.read(headers[s.header], s.frame, s.slope, s.intercept, cached[slot]);
            cachedIndex[slot] = i;
            return cached[slot];
        };
        const auto fits = [](const std::vector<float>& v) {
            return std::all_of(v.begin(), v.end(),
                               [](float x) { return x >= -32768.5F && x <= 32767.5F; });
        };
        std::size_t below = 0;  // slices[below].along <= z
        for (std::size_t k = 0; k < gridSlices; ++k) {
            loadProgress.report(static_cast<double>(k) / static_cast<double>(gridSlices),
                                "Loading DICOM series");
            const std::size_t offset = k * perSlice;
            std::size_t a = k;
            std::size_t b = k;
            double t = 0.0;
            if (resample) {
                const double z = slices.front().along + static_cast<double>(k) * stepAlong;
                while (below + 1 < n && slices[below + 1].along <= z + 1e-6) {
                    ++below;
                }
                a = below;
                b = below;
                const double snap = 1e-4 * stepAlong + 1e-6;
                if (std::abs(z - slices[below].along) > snap && below + 1 < n) {
                    b = below + 1;
                    t = (z - slices[a].along) / (slices[b].along - slices[a].along);
                }
            }
            const auto& va = decoded(a, b);
            if (checkRange && !fits(va)) {
                return false;
            }
            if (a == b) {
                for (std::size_t p = 0; p < perSlice; ++p) {
                    volume.setValueAt(offset + p, va[p]);
                }
                continue;
            }
            const auto& vb = decoded(b, a);
            if (checkRange && !fits(vb)) {
                return false;
            }
            const auto tf = static_cast<float>(t);
            for (std::size_t p = 0; p < perSlice; ++p) {
                volume.setValueAt(offset + p, va[p] + (vb[p] - va[p]) * tf);
            }
        }
        loadProgress.report(1.0, "Loading DICOM series");
        return true;
    };
    if (gridSlices > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        throw FormatError(first.file, label + ": " + std::to_string(gridSlices) +
                                          " slices are more than a volume can hold");
    }
    const glm::ivec3 dims(columns, rows, static_cast<int>(gridSlices));
    scene::Volume volume(dims, type);
    if (!fill(volume, type == scene::VoxelType::Int16 && !rangeKnownToFit)) {
        log::info(kLog, label + ": values beyond 16 bits; loading as 32-bit floats");
        volume = scene::Volume();
        type = scene::VoxelType::Float32;
        checkMemory(gridSlices, type);
        volume = scene::Volume(dims, type);
        fill(volume, false);
    }
    volume.setIndexToWorld(m);
    volume.setModality(series.modality.empty() ? first.modality : series.modality);
    if (volume.modality() == "CT") {
        volume.setUnit("HU");
    }

    result.sourceImages = n;
    result.volume = std::move(volume);
    log::info(kLog, label + ": " + std::to_string(columns) + " x " + std::to_string(rows) + " x " +
                        std::to_string(gridSlices) + " voxels loaded from " + std::to_string(n) +
                        " images");
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
