// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/demo/DemoCtSeries.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <system_error>
#include <vector>

#include "vv/core/Error.h"

namespace vv::demo {

namespace {

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

}  // namespace

bool DemoCt::inBone(const glm::dvec3& p, double margin) const {
    const glm::dvec3 q = glm::transpose(frame) * p;
    return glm::all(glm::greaterThanEqual(q, boneMin - margin)) &&
           glm::all(glm::lessThanEqual(q, boneMax + margin));
}

DemoCt generateDemoCt(const DemoCtOptions& options, const Progress& progress) {
    const glm::ivec3 dims = options.dims;
    if (glm::any(glm::lessThan(dims, glm::ivec3(8))) ||
        glm::any(glm::greaterThan(dims, glm::ivec3(2048)))) {
        throw InvalidArgumentError("demo CT: dimensions must be 8..2048 voxels");
    }
    if (!(options.noiseSigma >= 0.0) || !std::isfinite(options.noiseSigma) ||
        !std::isfinite(options.angleDegrees)) {
        throw InvalidArgumentError("demo CT: noise and angle must be finite, noise >= 0");
    }
    const char* stage = "Voxelising the demo tree";
    progress.report(0.0, stage);
    DemoCt cta;
    cta.treeOptions.generations = options.generations;
    cta.treeOptions.rootRadiusMm = 3.0;
    cta.tree = generateVesselTree(cta.treeOptions);  // validates generations

    const double a = glm::radians(options.angleDegrees);
    const glm::dvec3 row(std::cos(a), std::sin(a), 0.0);
    const glm::dvec3 column(-std::sin(a), std::cos(a), 0.0);
    const glm::dvec3 normal = glm::cross(row, column);
    cta.frame = glm::dmat3(row, column, normal);
    const glm::dmat3 toFrame = glm::transpose(cta.frame);

    // The tree's extent in frame coordinates, with a margin; the bone block
    // goes beside it on the +u side.
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (const auto& segment : cta.tree.segments) {
        for (const glm::vec3& p : segment.centerline) {
            const glm::dvec3 q = toFrame * glm::dvec3(p);
            lo = glm::min(lo, q - segment.radiusMm);
            hi = glm::max(hi, q + segment.radiusMm);
        }
    }
    const double margin = 4.0;
    lo -= margin;
    hi += margin;
    const glm::dvec3 extent = hi - lo;
    const double block = 0.3 * std::min(extent.y, extent.z);
    cta.boneMin = glm::dvec3(hi.x + 2.0, lo.y + 0.35 * extent.y, lo.z + 0.35 * extent.z);
    cta.boneMax = cta.boneMin + block;
    hi.x = cta.boneMax.x + margin;

    const double inPlane = std::max((hi.x - lo.x) / (dims.x - 1), (hi.y - lo.y) / (dims.y - 1));
    const double step = (hi.z - lo.z) / (dims.z - 1);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(row * inPlane, 0.0);
    m[1] = glm::dvec4(column * inPlane, 0.0);
    m[2] = glm::dvec4(normal * step, 0.0);
    m[3] = glm::dvec4(cta.frame * lo, 1.0);
    cta.volume = scene::Volume(dims, scene::VoxelType::Int16);
    cta.volume.setIndexToWorld(m);
    cta.volume.setModality("CT");
    cta.volume.setUnit("HU");
    const glm::dmat4 toIndex = glm::inverse(m);

    // Signed distance to the union of tubes, in each centreline piece's box.
    std::vector<float> sd(cta.volume.voxelCount(), std::numeric_limits<float>::max());
    const double h = std::cbrt(inPlane * inPlane * step);  // a voxel's size
    for (std::size_t s = 0; s < cta.tree.segments.size(); ++s) {
        const auto& segment = cta.tree.segments[s];
        progress.report(
            0.5 * static_cast<double>(s) / static_cast<double>(cta.tree.segments.size()), stage);
        const double r = segment.radiusMm;
        for (std::size_t n = 0; n + 1 < segment.centerline.size(); ++n) {
            const glm::dvec3 p0(segment.centerline[n]);
            const glm::dvec3 p1(segment.centerline[n + 1]);
            const glm::dvec3 bmin = glm::min(p0, p1) - (r + 2.0 * h);
            const glm::dvec3 bmax = glm::max(p0, p1) + (r + 2.0 * h);
            glm::dvec3 imin(std::numeric_limits<double>::max());
            glm::dvec3 imax(std::numeric_limits<double>::lowest());
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? bmax.x : bmin.x, (c & 2) ? bmax.y : bmin.y,
                                        (c & 4) ? bmax.z : bmin.z);
                const glm::dvec3 idx(toIndex * glm::dvec4(corner, 1.0));
                imin = glm::min(imin, idx);
                imax = glm::max(imax, idx);
            }
            const glm::ivec3 i0 = glm::max(glm::ivec3(glm::floor(imin)), glm::ivec3(0));
            const glm::ivec3 i1 = glm::min(glm::ivec3(glm::ceil(imax)), dims - 1);
            for (int k = i0.z; k <= i1.z; ++k) {
                for (int j = i0.y; j <= i1.y; ++j) {
                    for (int i = i0.x; i <= i1.x; ++i) {
                        const glm::dvec3 p = cta.volume.worldPosition(glm::dvec3(i, j, k));
                        float& d = sd[cta.volume.index(i, j, k)];
                        d = std::min(d, static_cast<float>(distanceToSegment(p, p0, p1) - r));
                    }
                }
            }
        }
    }

    std::mt19937 random(options.noiseSeed);
    std::normal_distribution<double> noise(0.0, options.noiseSigma);
    for (int k = 0; k < dims.z; ++k) {
        progress.report(0.5 + 0.5 * k / dims.z, stage);
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const std::size_t n = cta.volume.index(i, j, k);
                const double lumen = std::clamp(0.5 - static_cast<double>(sd[n]) / h, 0.0, 1.0);
                // Box signed distance (outside part) in frame coordinates.
                const glm::dvec3 q = toFrame * cta.volume.worldPosition(glm::dvec3(i, j, k));
                const glm::dvec3 outside =
                    glm::max(glm::max(cta.boneMin - q, q - cta.boneMax), glm::dvec3(0.0));
                const glm::dvec3 inside = glm::min(q - cta.boneMin, cta.boneMax - q);
                const double boxSd = glm::length(outside) > 0.0
                                         ? glm::length(outside)
                                         : -std::min({inside.x, inside.y, inside.z});
                const double bone = std::clamp(0.5 - boxSd / h, 0.0, 1.0);
                const double n0 = options.noiseSigma > 0.0 ? noise(random) : 0.0;
                cta.volume.setValueAt(n,
                                      static_cast<float>(40.0 + 360.0 * lumen + 960.0 * bone + n0));
            }
        }
    }
    progress.report(1.0, stage);
    return cta;
}

}  // namespace vv::demo
