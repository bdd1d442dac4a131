// SPDX-License-Identifier: GPL-3.0-or-later
// A CT-angiography-like volume of the synthetic demo tree for the
// segmentation / surface round-trip tests: lumen ~400 HU, tissue ~40 HU with
// Gaussian noise, a bone-like block ~1000 HU beside the tree, partial volume
// at every edge, on an oblique (rotated about the patient axis) grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <random>
#include <vector>

#include "vv/io/DemoTree.h"
#include "vv/io/Volume.h"

namespace vv::test {

struct SyntheticCta {
    vv::io::VesselTree tree;
    vv::io::DemoTreeOptions treeOptions;
    vv::io::Volume volume;    ///< Int16, HU, modality CT
    glm::dmat3 frame{1.0};    ///< columns: row direction, column direction, normal
    glm::dvec3 boneMin{0.0};  ///< the bone block in frame coordinates (u, v, w), mm
    glm::dvec3 boneMax{0.0};
    /// True when world point `p` lies in the bone block grown by `margin` mm.
    [[nodiscard]] bool inBone(const glm::dvec3& p, double margin) const {
        const glm::dvec3 q = glm::transpose(frame) * p;
        return glm::all(glm::greaterThanEqual(q, boneMin - margin)) &&
               glm::all(glm::lessThanEqual(q, boneMax + margin));
    }
};

/// Distance from `p` to the segment [a, b].
inline double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

/// The tree of `generations` generations voxelised into a `dims` volume whose
/// rows are rotated by `angleDegrees` about the superior axis. Deterministic.
inline SyntheticCta makeSyntheticCta(glm::ivec3 dims = {96, 96, 80}, int generations = 4,
                                     double angleDegrees = 20.0, double noiseSigma = 15.0) {
    SyntheticCta cta;
    cta.treeOptions.generations = generations;
    cta.treeOptions.rootRadiusMm = 3.0;
    cta.tree = vv::io::generateVesselTree(cta.treeOptions);

    const double a = glm::radians(angleDegrees);
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
    cta.volume = vv::io::Volume(dims, vv::io::VoxelType::Int16);
    cta.volume.setIndexToWorld(m);
    cta.volume.setModality("CT");
    cta.volume.setUnit("HU");
    const glm::dmat4 toIndex = glm::inverse(m);

    // Signed distance to the union of tubes, in each centreline piece's box.
    std::vector<float> sd(cta.volume.voxelCount(), std::numeric_limits<float>::max());
    const double h = std::cbrt(inPlane * inPlane * step);  // a voxel's size
    for (const auto& segment : cta.tree.segments) {
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

    std::mt19937 random(20240611U);
    std::normal_distribution<double> noise(0.0, noiseSigma);
    for (int k = 0; k < dims.z; ++k) {
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
                cta.volume.setValueAt(
                    n, static_cast<float>(40.0 + 360.0 * lumen + 960.0 * bone + noise(random)));
            }
        }
    }
    return cta;
}

}  // namespace vv::test
