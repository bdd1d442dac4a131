// SPDX-License-Identifier: GPL-3.0-or-later
// meshio's Loop subdivision on a coarse closed cylinder (a faceted vessel):
// four triangles for one per level, the faceted wall brought towards the
// round one it stands for, the deviation it reports is the one measured,
// the arrays taken from the input where each point lies over it (labels
// stay labels, no data stays where it was); bad levels and bad meshes are
// refused with messages naming them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "RingGrid.h"
#include "vv/core/Error.h"
#include "vv/meshio/MeshSubdivide.h"

namespace vv::meshio::mesh_subdivide_test {
using scene::DataArray;
using scene::Mesh;
namespace {

constexpr int kAround = 8;  // an octagon: facets as long as 0.77 radii
constexpr int kAlong = 10;
constexpr double kRadius = 10.0;
constexpr double kLength = 100.0;

/// An octagonal tube along z, its points on the circle of kRadius, closed
/// at both ends by a centre point; with the array "linear" = x + 2 y + 3 z.
Mesh coarseTube() {
    Mesh mesh;
    mesh.name = "coarse tube";
    DataArray linear{
        .name = "linear", .unit = "mm", .components = 1, .values = {}, .integer = false};
    for (int j = 0; j <= kAlong; ++j) {
        for (int i = 0; i < kAround; ++i) {
            const double phi = 2.0 * std::numbers::pi * i / kAround;
            mesh.positions.emplace_back(kRadius * std::cos(phi), kRadius * std::sin(phi),
                                        kLength * j / kAlong);
        }
    }
    test::addRingGridTriangles(mesh, kAround, kAlong);
    const auto at = [](int j, int i) {
        return static_cast<std::uint32_t>(j * kAround + (i % kAround));
    };
    const auto bottom = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(0.0F, 0.0F, 0.0F);
    const auto top = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(0.0F, 0.0F, static_cast<float>(kLength));
    for (int i = 0; i < kAround; ++i) {
        mesh.indices.insert(mesh.indices.end(), {bottom, at(0, i + 1), at(0, i)});
        mesh.indices.insert(mesh.indices.end(), {top, at(kAlong, i), at(kAlong, i + 1)});
    }
    for (const glm::vec3& p : mesh.positions) {
        linear.values.push_back(p.x + 2.0F * p.y + 3.0F * p.z);
    }
    mesh.pointArrays = {linear};
    computeNormals(mesh);
    return mesh;
}

double radiusOf(const glm::vec3& p) {
    return std::hypot(static_cast<double>(p.x), static_cast<double>(p.y));
}

TEST(MeshSubdivide, RefinesAFacetedTubeTowardsTheRoundOne) {
    const Mesh tube = coarseTube();
    // The octagon's facets lie as far inside the circle as 1 - cos(pi / 8)
    // of its radius at their middles: 7.6 % at most.
    const double sag = kRadius * (1.0 - std::cos(std::numbers::pi / kAround));
    const SubdividedMesh one = subdividedMesh(tube, 1);
    const SubdividedMesh two = subdividedMesh(tube, 2);
    EXPECT_EQ(one.mesh.triangleCount(), 4 * tube.triangleCount());
    EXPECT_EQ(two.mesh.triangleCount(), 16 * tube.triangleCount());
    EXPECT_EQ(one.mesh.name, tube.name);
    ASSERT_EQ(one.mesh.normals.size(), one.mesh.positions.size());
    // Along the middle of the tube (away from the caps, which round it off)
    // the points of the refined wall lie closer to one circle than the
    // octagon's points and facets do to theirs: the spread of their radii
    // is a fraction of the facets' sag.
    for (const SubdividedMesh* s : {&one, &two}) {
        double lo = kRadius;
        double hi = 0.0;
        for (const glm::vec3& p : s->mesh.positions) {
            if (p.z > 30.0F && p.z < 70.0F) {
                lo = std::min(lo, radiusOf(p));
                hi = std::max(hi, radiusOf(p));
            }
        }
        EXPECT_LT(hi - lo, 0.5 * sag);
        EXPECT_GT(lo, kRadius - 2.0 * sag);
    }
    // The deviation it reports: positive, under the facets' sag along the
    // tube and the caps' rounding, the mean under the largest.
    EXPECT_GT(one.largestDeviation, 0.0);
    EXPECT_LT(one.largestDeviation, 0.25 * kRadius);
    EXPECT_GT(one.meanDeviation, 0.0);
    EXPECT_LT(one.meanDeviation, one.largestDeviation);
    // Each point takes the input's values where it lies over the input: a
    // point array linear in the position differs from its value at the
    // point by at most its gradient (sqrt 14) times the point's distance
    // from the input, and is exact where the point lies on it.
    ASSERT_EQ(two.mesh.pointArrays.size(), 1U);
    const DataArray& linear = two.mesh.pointArrays.front();
    ASSERT_EQ(linear.values.size(), two.mesh.positions.size());
    int off = 0;
    for (std::size_t i = 0; i < linear.values.size(); ++i) {
        const glm::vec3& p = two.mesh.positions[i];
        const double exact = p.x + 2.0 * p.y + 3.0 * p.z;
        EXPECT_LE(std::abs(linear.values[i] - exact), std::sqrt(14.0) * two.largestDeviation + 1e-3)
            << i;
        off += std::abs(linear.values[i] - exact) > 1e-3 ? 1 : 0;
    }
    EXPECT_GT(off, 0);  // the points moved off the input, and the values stayed its
}

/// Distance from `p` to the segment [a, b].
double segmentDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}

/// Distance from `p` to the triangle (a, b, c): to its plane where the foot
/// lies inside it, else to its nearest edge.
double triangleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                        const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, n) > 0.0) {
        const glm::dvec3 unit = glm::normalize(n);
        const glm::dvec3 foot = p - glm::dot(p - a, unit) * unit;
        const bool inside = glm::dot(glm::cross(b - a, foot - a), n) >= 0.0 &&
                            glm::dot(glm::cross(c - b, foot - b), n) >= 0.0 &&
                            glm::dot(glm::cross(a - c, foot - c), n) >= 0.0;
        if (inside) {
            return std::abs(glm::dot(p - a, unit));
        }
    }
    return std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
}

TEST(MeshSubdivide, TheLargestDeviationIsTheHausdorffDistanceBothWays) {
    // The caps' centres stand out of the refined surface (Loop rounds them
    // off) by more than any refined point lies from the octagon's facets.
    const Mesh tube = coarseTube();
    const SubdividedMesh one = subdividedMesh(tube, 1);
    const auto fromRefined = [&](const glm::vec3& q) {
        double d = std::numeric_limits<double>::max();
        const auto& r = one.mesh;
        for (std::size_t t = 0; t + 2 < r.indices.size(); t += 3) {
            d = std::min(
                d, triangleDistance(q, r.positions[r.indices[t]], r.positions[r.indices[t + 1]],
                                    r.positions[r.indices[t + 2]]));
        }
        return d;
    };
    double outward = 0.0;
    for (const glm::vec3& q : tube.positions) {
        outward = std::max(outward, fromRefined(q));
    }
    EXPECT_GT(outward, 0.0);
    EXPECT_GE(one.largestDeviation, outward - 1e-4);
    EXPECT_LE(one.largestDeviation, 0.25 * kRadius);
}

TEST(MeshSubdivide, LabelsStayLabelsAndNoDataStaysWhereItWas) {
    Mesh tube = coarseTube();
    // A label per half of the tube, and one vertex without data.
    DataArray label{
        .name = "segment_id", .unit = "", .components = 1, .values = {}, .integer = true};
    DataArray gaps{.name = "wss", .unit = "Pa", .components = 1, .values = {}, .integer = false};
    for (const glm::vec3& p : tube.positions) {
        label.values.push_back(p.z < 0.5F * kLength ? 3.0F : 7.0F);
        gaps.values.push_back(1.0F);
    }
    const std::size_t hole = 5 * kAround + 2;  // ring 5, the tube's middle
    gaps.values[hole] = std::numeric_limits<float>::quiet_NaN();
    tube.pointArrays = {label, gaps};
    const SubdividedMesh two = subdividedMesh(tube, 2);
    ASSERT_EQ(two.mesh.pointArrays.size(), 2U);
    const DataArray& labels = two.mesh.pointArrays[0];
    const DataArray& values = two.mesh.pointArrays[1];
    EXPECT_TRUE(labels.integer);
    int nan = 0;
    // The longest edge of a triangle at the hole: its quads' diagonal.
    const double edge =
        std::hypot(glm::length(tube.positions[1] - tube.positions[0]), kLength / kAlong);
    for (std::size_t i = 0; i < labels.values.size(); ++i) {
        const glm::vec3& p = two.mesh.positions[i];
        // Never a mix of 3 and 7; each half keeps its own away from the cut.
        EXPECT_TRUE(labels.values[i] == 3.0F || labels.values[i] == 7.0F) << labels.values[i];
        if (p.z < 0.4F * kLength) {
            EXPECT_EQ(labels.values[i], 3.0F) << i;
        } else if (p.z > 0.6F * kLength) {
            EXPECT_EQ(labels.values[i], 7.0F) << i;
        }
        if (std::isnan(values.values[i])) {
            ++nan;
            EXPECT_LT(glm::length(p - tube.positions[hole]), edge) << i;
        } else {
            EXPECT_EQ(values.values[i], 1.0F) << i;
        }
    }
    EXPECT_GT(nan, 0);
}

TEST(MeshSubdivide, BadLevelsAndBadMeshesAreRefusedByName) {
    const Mesh tube = coarseTube();
    EXPECT_THROW(static_cast<void>(subdividedMesh(tube, 0)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(subdividedMesh(tube, 4)), InvalidArgumentError);
    Mesh empty;
    empty.name = "nothing";
    try {
        static_cast<void>(subdividedMesh(empty, 1));
        ADD_FAILURE() << "an empty mesh was subdivided";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("nothing"), std::string::npos) << e.what();
    }
    Mesh broken = tube;
    broken.positions[3].y = std::nanf("");
    EXPECT_THROW(static_cast<void>(subdividedMesh(broken, 1)), FormatError);
    Mesh outOfRange = tube;
    outOfRange.indices[5] = 10'000;
    EXPECT_THROW(static_cast<void>(subdividedMesh(outOfRange, 1)), FormatError);
}

}  // namespace
}  // namespace vv::meshio::mesh_subdivide_test
