// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/segmentation/VolumeSegmentation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "Histogram.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::segmentation {

namespace {

constexpr const char* kStage = "Segmenting";
/// MR default threshold: a bright Otsu class at most this large is vessels.
constexpr double kBrightFraction = 0.1;

bool isCt(const scene::Volume& volume) {
    return volume.modality() == "CT" || volume.unit() == "HU";
}

std::string text(float v) {
    return significantText(static_cast<double>(v), 6);
}

/// Connected components of `mask` (non-zero voxels): `ids` gets 0 for
/// background and 1..n per component, the result holds each component's
/// voxel count (index 0 unused). Flood fill with an explicit queue.
std::vector<std::size_t> labelComponents(const std::vector<std::uint8_t>& mask, glm::ivec3 dims,
                                         Connectivity connectivity, std::vector<std::uint32_t>& ids,
                                         const Progress& progress) {
    ids.assign(mask.size(), 0U);
    std::vector<glm::ivec3> offsets;
    for (int dz = -1; dz <= 1; ++dz) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int n = std::abs(dx) + std::abs(dy) + std::abs(dz);
                if (n == 0 || (connectivity == Connectivity::Face6 && n != 1)) {
                    continue;
                }
                offsets.emplace_back(dx, dy, dz);
            }
        }
    }
    const auto sx = static_cast<std::size_t>(dims.x);
    const auto sxy = sx * static_cast<std::size_t>(dims.y);
    std::vector<std::size_t> sizes{0};
    std::vector<std::size_t> queue;
    for (int k = 0; k < dims.z; ++k) {
        progress.report(static_cast<double>(k) / static_cast<double>(dims.z), kStage);
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const std::size_t start = static_cast<std::size_t>(k) * sxy +
                                          static_cast<std::size_t>(j) * sx +
                                          static_cast<std::size_t>(i);
                if (mask[start] == 0 || ids[start] != 0) {
                    continue;
                }
                if (sizes.size() >= std::numeric_limits<std::uint32_t>::max()) {
                    throw FormatError("too many connected components");
                }
                const auto id = static_cast<std::uint32_t>(sizes.size());
                std::size_t count = 0;
                queue.clear();
                queue.push_back(start);
                ids[start] = id;
                while (!queue.empty()) {
                    const std::size_t n = queue.back();
                    queue.pop_back();
                    ++count;
                    const auto z = static_cast<int>(n / sxy);
                    const auto y = static_cast<int>((n % sxy) / sx);
                    const auto x = static_cast<int>(n % sx);
                    for (const glm::ivec3& o : offsets) {
                        const int nx = x + o.x;
                        const int ny = y + o.y;
                        const int nz = z + o.z;
                        if (nx < 0 || ny < 0 || nz < 0 || nx >= dims.x || ny >= dims.y ||
                            nz >= dims.z) {
                            continue;
                        }
                        const std::size_t m = static_cast<std::size_t>(nz) * sxy +
                                              static_cast<std::size_t>(ny) * sx +
                                              static_cast<std::size_t>(nx);
                        if (mask[m] != 0 && ids[m] == 0) {
                            ids[m] = id;
                            queue.push_back(m);
                        }
                    }
                }
                sizes.push_back(count);
            }
        }
    }
    return sizes;
}

}  // namespace

ThresholdRange defaultThresholdRange(const scene::Volume& volume) {
    if (volume.empty()) {
        throw InvalidArgumentError("cannot choose a threshold for an empty volume");
    }
    if (isCt(volume)) {
        return {200.0F, 700.0F, "CT angiography default 200..700 HU"};
    }
    const auto [lo, hi] = volume.valueRange();
    if (!(hi > lo)) {
        return {lo, hi, "constant volume: its only value"};
    }
    constexpr std::size_t kBins = 4096;
    const double scale = static_cast<double>(kBins) / (static_cast<double>(hi) - lo);
    std::vector<std::size_t> histogram(kBins, 0);
    std::size_t total = 0;
    for (std::size_t n = 0; n < volume.voxelCount(); ++n) {
        const double v = volume.valueAt(n);
        if (!std::isfinite(v)) {
            continue;  // NaN in a Float32 volume: no value
        }
        const auto b = static_cast<std::size_t>(std::max(0.0, (v - lo) * scale));
        ++histogram[std::min(b, kBins - 1)];
        ++total;
    }
    const auto binValue = [&](std::size_t bin) {
        return static_cast<float>(lo + static_cast<double>(bin) / scale);
    };
    const std::size_t first = detail::otsuBin(histogram);
    const std::size_t above = std::accumulate(
        histogram.begin() + static_cast<std::ptrdiff_t>(first), histogram.end(), std::size_t{0});
    if (static_cast<double>(above) <= kBrightFraction * static_cast<double>(total)) {
        // The bright class is small: it is the vessels already.
        return {binValue(first), hi,
                "histogram: Otsu threshold (the voxels above it are " +
                    text(static_cast<float>(100.0 * static_cast<double>(above) /
                                            static_cast<double>(total))) +
                    "% of the volume)"};
    }
    // The bright class is the body: split it again.
    std::vector<std::size_t> body(histogram.size(), 0);
    std::copy(histogram.begin() + static_cast<std::ptrdiff_t>(first), histogram.end(),
              body.begin() + static_cast<std::ptrdiff_t>(first));
    const std::size_t second = std::max(detail::otsuBin(body), first);
    return {binValue(second), hi,
            "histogram: Otsu threshold of the voxels above the background's Otsu threshold (" +
                text(binValue(first)) + ")"};
}

namespace {

/// segmentVessels() on the values to threshold: range, bone removal, components.
Segmentation thresholdAndLabel(const scene::Volume& volume, const SegmentationOptions& options,
                               const Progress& progress) {
    Segmentation result;
    result.range = options.range ? *options.range : defaultThresholdRange(volume);
    const float lower = result.range.lower;
    const float upper = result.range.upper;
    if (!std::isfinite(lower) || !std::isfinite(upper) || lower > upper) {
        throw InvalidArgumentError("invalid threshold range " + text(lower) + ".." + text(upper) +
                                   " (need finite lower <= upper)");
    }
    if (!options.seed && (options.keepComponents < 1 || options.keepComponents > 255)) {
        throw InvalidArgumentError("the number of components to keep must be within 1..255, got " +
                                   std::to_string(options.keepComponents));
    }
    if (!(options.boneFraction > 0.0) || options.boneFraction > 1.0) {
        throw InvalidArgumentError("the bone fraction must be within (0, 1]");
    }
    const glm::ivec3 dims = volume.dims();
    if (options.seed) {
        const glm::ivec3 s = *options.seed;
        if (glm::any(glm::lessThan(s, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(s, dims))) {
            throw InvalidArgumentError("seed voxel (" + std::to_string(s.x) + ", " +
                                       std::to_string(s.y) + ", " + std::to_string(s.z) +
                                       ") is outside the volume");
        }
        const float v = volume.value(s.x, s.y, s.z);
        if (v < lower || v > upper) {
            throw InvalidArgumentError("seed voxel (" + std::to_string(s.x) + ", " +
                                       std::to_string(s.y) + ", " + std::to_string(s.z) +
                                       ") has value " + text(v) + ", outside the threshold range " +
                                       text(lower) + ".." + text(upper));
        }
    }
    const std::size_t count = volume.voxelCount();
    const bool removeBone = options.removeBone.value_or(isCt(volume));
    result.boneRemoved = removeBone;

    std::vector<std::uint8_t> mask(count, 0);
    std::vector<std::uint32_t> ids;
    if (removeBone) {
        // Bright components; those mostly made of bone-dense voxels are dropped.
        for (std::size_t n = 0; n < count; ++n) {
            mask[n] = volume.valueAt(n) >= lower ? 1 : 0;
        }
        const auto sizes =
            labelComponents(mask, dims, options.connectivity, ids, progress.sub(0.0, 0.4));
        std::vector<std::size_t> bony(sizes.size(), 0);
        for (std::size_t n = 0; n < count; ++n) {
            if (ids[n] != 0 && volume.valueAt(n) >= options.boneThreshold) {
                ++bony[ids[n]];
            }
        }
        std::vector<std::uint8_t> isBone(sizes.size(), 0);
        for (std::size_t c = 1; c < sizes.size(); ++c) {
            if (static_cast<double>(bony[c]) >
                options.boneFraction * static_cast<double>(sizes[c])) {
                isBone[c] = 1;
                ++result.boneComponents;
            }
        }
        for (std::size_t n = 0; n < count; ++n) {
            const float v = volume.valueAt(n);
            mask[n] = (v >= lower && v <= upper && isBone[ids[n]] == 0) ? 1 : 0;
        }
    } else {
        for (std::size_t n = 0; n < count; ++n) {
            const float v = volume.valueAt(n);
            mask[n] = (v >= lower && v <= upper) ? 1 : 0;
        }
    }
    if (std::find(mask.begin(), mask.end(), std::uint8_t{1}) == mask.end()) {
        throw FormatError("no voxel within the threshold range " + text(lower) + ".." +
                          text(upper) + (removeBone ? " outside bone" : ""));
    }
    const Progress labelProgress = removeBone ? progress.sub(0.4, 0.9) : progress.sub(0.0, 0.9);
    const auto sizes = labelComponents(mask, dims, options.connectivity, ids, labelProgress);
    result.componentsFound = sizes.size() - 1;

    // The kept components, largest first (ties: lower id first).
    std::vector<std::uint32_t> kept;
    if (options.seed) {
        const glm::ivec3 s = *options.seed;
        const std::uint32_t id = ids[volume.index(s.x, s.y, s.z)];
        if (id == 0) {
            throw InvalidArgumentError("seed voxel (" + std::to_string(s.x) + ", " +
                                       std::to_string(s.y) + ", " + std::to_string(s.z) +
                                       ") lies in a component removed as bone");
        }
        kept.push_back(id);
    } else {
        std::vector<std::uint32_t> order(sizes.size() - 1);
        std::iota(order.begin(), order.end(), 1U);
        const std::size_t n =
            std::min(order.size(), static_cast<std::size_t>(options.keepComponents));
        std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n),
                          order.end(), [&](std::uint32_t a, std::uint32_t b) {
                              return sizes[a] != sizes[b] ? sizes[a] > sizes[b] : a < b;
                          });
        kept.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n));
    }
    std::vector<std::uint8_t> labelOf(sizes.size(), 0);
    const glm::dmat3 m(volume.indexToWorld());
    const double voxelVolume = std::abs(glm::determinant(m));
    scene::LabelMap& map = result.labelMap;
    for (std::size_t r = 0; r < kept.size(); ++r) {
        labelOf[kept[r]] = static_cast<std::uint8_t>(r + 1);
        scene::SegmentComponent c;
        c.label = static_cast<std::uint8_t>(r + 1);
        c.voxels = sizes[kept[r]];
        c.volumeMm3 = static_cast<double>(c.voxels) * voxelVolume;
        map.components.push_back(c);
    }
    map.dims = dims;
    map.indexToWorld = volume.indexToWorld();
    map.labels.assign(count, 0);
    for (std::size_t n = 0; n < count; ++n) {
        map.labels[n] = labelOf[ids[n]];
    }
    progress.report(1.0, kStage);
    return result;
}

}  // namespace

bool intensityCorrectionDefault(const scene::Volume& volume) noexcept {
    return volume.modality() == "MR";
}

bool correctsIntensity(const scene::Volume& volume, const SegmentationOptions& options) {
    const bool correct = options.correctIntensity.value_or(intensityCorrectionDefault(volume));
    if (correct && isCt(volume)) {
        throw InvalidArgumentError(
            "the intensity correction is for MR signal; CT values (HU) have no receive gain");
    }
    return correct;
}

Segmentation segmentVessels(const scene::Volume& volume, const SegmentationOptions& options,
                            const Progress& progress) {
    if (volume.empty()) {
        throw InvalidArgumentError("cannot segment an empty volume");
    }
    if (!correctsIntensity(volume, options)) {
        Segmentation result = thresholdAndLabel(volume, options, progress.sub(0.0, 0.9));
        result.cutOff =
            findCutOffVessels(volume, result.labelMap, result.range, {}, progress.sub(0.9, 1.0));
        return result;
    }
    const GainField gain = options.gainField
                               ? *options.gainField
                               : estimateGainField(volume, {}, progress.sub(0.0, 0.1));
    const scene::Volume corrected = correctedVolume(volume, gain, progress.sub(0.1, 0.2));
    SegmentationOptions inner = options;
    inner.correctIntensity = false;
    Segmentation result = thresholdAndLabel(corrected, inner, progress.sub(0.2, 0.9));
    result.intensityCorrected = true;
    result.gainLowest = gain.lowest();
    result.gainHighest = gain.highest();
    result.cutOff =
        findCutOffVessels(corrected, result.labelMap, result.range, {}, progress.sub(0.9, 1.0));
    return result;
}

}  // namespace vv::segmentation
