// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/segmentation/SegmentationPipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "vv/core/Error.h"

namespace vv::segmentation {

namespace {

/// The smallest axis a preview may leave.
constexpr int kMinPreviewAxis = 8;
int ceilDiv(int a, int b) {
    return (a + b - 1) / b;
}

}  // namespace

scene::Volume downsampledVolume(const scene::Volume& volume, int step) {
    if (step < 1) {
        throw InvalidArgumentError("the downsampling step must be >= 1, got " +
                                   std::to_string(step));
    }
    if (volume.empty()) {
        throw InvalidArgumentError("cannot downsample an empty volume");
    }
    const glm::ivec3 dims = volume.dims();
    const glm::ivec3 coarseDims(ceilDiv(dims.x, step), ceilDiv(dims.y, step),
                                ceilDiv(dims.z, step));
    scene::Volume coarse(coarseDims, volume.voxelType());
    std::size_t n = 0;
    for (int k = 0; k < coarseDims.z; ++k) {
        for (int j = 0; j < coarseDims.y; ++j) {
            for (int i = 0; i < coarseDims.x; ++i) {
                coarse.setValueAt(n++, volume.value(i * step, j * step, k * step));
            }
        }
    }
    // Coarse index c is fine index step * c: scale the linear part.
    glm::dmat4 m = volume.indexToWorld();
    for (int c = 0; c < 3; ++c) {
        m[c] *= static_cast<double>(step);
    }
    coarse.setIndexToWorld(m);
    coarse.setModality(volume.modality());
    coarse.setUnit(volume.unit());
    return coarse;
}

int previewStep(glm::ivec3 dims, std::size_t voxelBudget) noexcept {
    const int smallest = std::min({dims.x, dims.y, dims.z});
    if (ceilDiv(smallest, 2) < kMinPreviewAxis) {
        return 1;
    }
    const auto count = [&](int s) {
        return static_cast<std::size_t>(ceilDiv(dims.x, s)) *
               static_cast<std::size_t>(ceilDiv(dims.y, s)) *
               static_cast<std::size_t>(ceilDiv(dims.z, s));
    };
    int step = 2;
    while (count(step) > voxelBudget && ceilDiv(smallest, step + 1) >= kMinPreviewAxis) {
        ++step;
    }
    return step;
}

std::optional<glm::ivec3> nearestVoxelInRange(const scene::Volume& volume, const glm::dvec3& ijk,
                                              float lower, float upper, int radius,
                                              const GainField* gain) {
    if (volume.empty() || !std::isfinite(ijk.x) || !std::isfinite(ijk.y) || !std::isfinite(ijk.z)) {
        return std::nullopt;
    }
    const glm::ivec3 dims = volume.dims();
    const glm::ivec3 centre(static_cast<int>(std::lround(ijk.x)),
                            static_cast<int>(std::lround(ijk.y)),
                            static_cast<int>(std::lround(ijk.z)));
    std::optional<glm::ivec3> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    const glm::ivec3 from = glm::max(centre - radius, glm::ivec3(0));
    const glm::ivec3 to = glm::min(centre + radius, dims - 1);
    for (int k = from.z; k <= to.z; ++k) {
        for (int j = from.y; j <= to.y; ++j) {
            for (int i = from.x; i <= to.x; ++i) {
                const float v =
                    gain != nullptr
                        ? static_cast<float>(volume.value(i, j, k) /
                                             gain->at(volume.worldPosition(glm::dvec3(i, j, k))))
                        : volume.value(i, j, k);
                if (v < lower || v > upper) {
                    continue;
                }
                const glm::dvec3 d = glm::dvec3(i, j, k) - ijk;
                const double distance = glm::dot(d, d);
                if (distance < bestDistance) {
                    bestDistance = distance;
                    best = glm::ivec3(i, j, k);
                }
            }
        }
    }
    return best;
}

SegmentationOutcome runSegmentation(const SegmentationRequest& request, const Progress& progress) {
    if (!request.volume || request.volume->empty()) {
        throw InvalidArgumentError("there is no volume to segment");
    }
    const auto started = std::chrono::steady_clock::now();
    const scene::Volume& full = *request.volume;
    SegmentationOptions options = request.segmentation;
    const bool correct = correctsIntensity(full, options);
    if (!options.range && !correct) {
        options.range = defaultThresholdRange(full);
    }
    const int step = std::max(1, request.step);
    scene::Volume coarse;
    if (step > 1) {
        coarse = downsampledVolume(full, step);
    }
    // The intensity correction is divided out here, before the seed is
    // looked for: the range applies to the corrected values.
    SegmentationOutcome outcome;
    scene::Volume corrected;
    if (correct) {
        const scene::Volume& sampled = step > 1 ? coarse : full;
        const GainField gain = options.gainField
                                   ? *options.gainField
                                   : estimateGainField(sampled, {}, progress.sub(0.0, 0.05));
        corrected = correctedVolume(sampled, gain, progress.sub(0.05, 0.1));
        options.correctIntensity = false;
        options.gainField.reset();
        outcome.intensityCorrected = true;
        outcome.gainLowest = gain.lowest();
        outcome.gainHighest = gain.highest();
        if (!options.range) {
            options.range = defaultThresholdRange(corrected);
        }
    }
    const scene::Volume& volume = correct ? corrected : step > 1 ? coarse : full;
    if (step > 1 && options.seed) {
        const glm::dvec3 at = glm::dvec3(*options.seed) / static_cast<double>(step);
        options.seed =
            nearestVoxelInRange(volume, at, options.range->lower, options.range->upper, 1);
        if (!options.seed) {
            throw InvalidArgumentError(
                "the structure under the seed is too thin for the preview of every " +
                std::to_string(step) + "th voxel; Apply segments it at full resolution");
        }
    }
    Segmentation segmented =
        segmentVessels(volume, options, progress.sub(correct ? 0.1 : 0.0, 0.5));
    scene::Mesh mesh =
        extractSurface(segmented.labelMap, {}, request.surface, progress.sub(0.5, 1.0));
    mesh.name = step > 1 ? "vessels (preview)" : "vessels";

    outcome.range = segmented.range;
    outcome.componentsFound = segmented.componentsFound;
    outcome.componentsKept = segmented.labelMap.components.size();
    outcome.boneComponents = segmented.boneComponents;
    outcome.cutOff = std::move(segmented.cutOff);
    outcome.triangles = mesh.triangleCount();
    outcome.step = step;
    auto scene = std::make_shared<scene::Scene>();
    scene->meshes.push_back(std::move(mesh));
    scene->frame = scene::SceneFrame::PatientLps;  // surfaces of a volume: LPS mm
    outcome.scene = std::move(scene);
    outcome.labelMap = std::make_shared<const scene::LabelMap>(std::move(segmented.labelMap));
    outcome.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    return outcome;
}

}  // namespace vv::segmentation
