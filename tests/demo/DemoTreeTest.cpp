// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <numeric>
#include <stop_token>
#include <string>
#include <unordered_map>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Progress.h"
#include "vv/demo/DemoTree.h"
#include "vv/scene/MeshTopology.h"

namespace {

using vv::demo::DemoTreeOptions;
using vv::demo::VesselSegment;
using vv::demo::VesselTree;
using vv::scene::Mesh;

constexpr double kPi = std::numbers::pi;
constexpr double kPascalPerMmHg = 133.322387415;

/// A smaller and coarser surface than the default, to keep tests fast.
DemoTreeOptions coarseOptions() {
    DemoTreeOptions options;
    options.generations = 4;
    options.voxelSizeMm = 0.5;
    return options;
}

double relativeDifference(double a, double b) {
    const double scale = std::max(std::abs(a), std::abs(b));
    return scale > 0.0 ? std::abs(a - b) / scale : 0.0;
}

bool sameTree(const VesselTree& a, const VesselTree& b) {
    if (a.segments.size() != b.segments.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.segments.size(); ++i) {
        const VesselSegment& s = a.segments[i];
        const VesselSegment& t = b.segments[i];
        if (s.parent != t.parent || s.children != t.children || s.generation != t.generation ||
            s.centerline != t.centerline || s.radiusMm != t.radiusMm || s.lengthMm != t.lengthMm ||
            s.resistance != t.resistance || s.flowMlPerS != t.flowMlPerS ||
            s.pressureInMmHg != t.pressureInMmHg || s.pressureOutMmHg != t.pressureOutMmHg ||
            s.wssPa != t.wssPa) {
            return false;
        }
    }
    return true;
}

bool sameMesh(const Mesh& a, const Mesh& b) {
    if (a.positions != b.positions || a.normals != b.normals || a.indices != b.indices ||
        a.pointArrays.size() != b.pointArrays.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.pointArrays.size(); ++i) {
        if (a.pointArrays[i].name != b.pointArrays[i].name ||
            a.pointArrays[i].values != b.pointArrays[i].values) {
            return false;
        }
    }
    return true;
}

/// Largest distance of a centreline point from the chord front() -> back().
double chordDeviation(const std::vector<glm::vec3>& line) {
    const glm::dvec3 a(line.front());
    const glm::dvec3 ab = glm::dvec3(line.back()) - a;
    const double len2 = glm::dot(ab, ab);
    double worst = 0.0;
    for (const auto& point : line) {
        const glm::dvec3 p(point);
        const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
        worst = std::max(worst, glm::length(p - (a + ab * t)));
    }
    return worst;
}

struct SurfaceTopology {
    std::size_t boundaryOrNonManifoldEdges = 0;  // undirected edges not in exactly 2 triangles
    std::size_t inconsistentEdges = 0;           // directed edges used more than once
    std::size_t components = 0;                  // connected components of triangles
    std::size_t unusedVertices = 0;
};

SurfaceTopology topologyOf(const Mesh& mesh) {
    SurfaceTopology topology;
    std::unordered_map<std::uint64_t, int> undirected;
    std::unordered_map<std::uint64_t, int> directed;
    undirected.reserve(mesh.indices.size());
    directed.reserve(mesh.indices.size());
    const auto key = [](std::uint32_t a, std::uint32_t b) {
        return (static_cast<std::uint64_t>(a) << 32U) | b;
    };
    // Union-find over vertices.
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0U);
    const auto find = [&](std::uint32_t v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    };
    std::vector<bool> used(mesh.positions.size(), false);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[t + static_cast<std::size_t>(k)];
            const std::uint32_t b = mesh.indices[t + static_cast<std::size_t>((k + 1) % 3)];
            ++directed[key(a, b)];
            ++undirected[key(std::min(a, b), std::max(a, b))];
            used[a] = true;
            parent[find(a)] = find(b);
        }
    }
    for (const auto& [edge, count] : undirected) {
        if (count != 2) {
            ++topology.boundaryOrNonManifoldEdges;
        }
    }
    for (const auto& [edge, count] : directed) {
        if (count != 1) {
            ++topology.inconsistentEdges;
        }
    }
    for (std::uint32_t v = 0; v < parent.size(); ++v) {
        if (!used[v]) {
            ++topology.unusedVertices;
        } else if (find(v) == v) {
            ++topology.components;
        }
    }
    return topology;
}

/// The tube volume sum(pi r^2 L), ignoring overlaps at the junctions.
double tubeVolume(const VesselTree& tree) {
    double volume = 0.0;
    for (const auto& s : tree.segments) {
        volume += kPi * s.radiusMm * s.radiusMm * s.lengthMm;
    }
    return volume;
}

/// Checks everything a vessel surface must satisfy.
void expectValidSurface(const Mesh& mesh, const VesselTree& tree, const DemoTreeOptions& options) {
    ASSERT_GT(mesh.triangleCount(), 1000U);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());

    const SurfaceTopology topology = topologyOf(mesh);
    EXPECT_EQ(topology.boundaryOrNonManifoldEdges, 0U) << "not watertight";
    EXPECT_EQ(topology.inconsistentEdges, 0U) << "triangles not consistently oriented";
    EXPECT_EQ(topology.components, 1U);
    EXPECT_EQ(topology.unusedVertices, 0U);

    // Outward: positive enclosed volume, close to the tubes' volume, and vertex
    // normals agreeing with the triangles' winding.
    const double volume = vv::scene::signedVolume(mesh);
    EXPECT_GT(volume, 0.0);
    EXPECT_NEAR(volume / tubeVolume(tree), 1.0, 0.3);
    std::vector<glm::dvec3> faceSum(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        for (int k = 0; k < 3; ++k) {
            faceSum[mesh.indices[t + static_cast<std::size_t>(k)]] += n;
        }
    }
    std::size_t agreeing = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        EXPECT_NEAR(glm::length(mesh.normals[v]), 1.0F, 1e-3F);
        if (glm::dot(glm::dvec3(mesh.normals[v]), faceSum[v]) > 0.0) {
            ++agreeing;
        }
    }
    EXPECT_GE(static_cast<double>(agreeing), 0.999 * static_cast<double>(mesh.positions.size()));

    // Point arrays.
    const double inlet = options.inletPressureMmHg;
    double outlet = inlet;
    for (const auto& s : tree.segments) {
        outlet = std::min(outlet, s.pressureOutMmHg);
    }
    const auto* pressure = mesh.pointArray("pressure");
    const auto* wss = mesh.pointArray("wss");
    const auto* segmentId = mesh.pointArray("segment_id");
    const auto* generation = mesh.pointArray("generation");
    ASSERT_NE(pressure, nullptr);
    ASSERT_NE(wss, nullptr);
    ASSERT_NE(segmentId, nullptr);
    ASSERT_NE(generation, nullptr);
    EXPECT_EQ(pressure->unit, "mmHg");
    EXPECT_EQ(wss->unit, "Pa");
    EXPECT_EQ(segmentId->unit, "");
    EXPECT_EQ(generation->unit, "");
    EXPECT_FALSE(pressure->integer);
    EXPECT_FALSE(wss->integer);
    EXPECT_TRUE(segmentId->integer);
    EXPECT_TRUE(generation->integer);
    double maxWss = 0.0;
    for (const auto& s : tree.segments) {
        maxWss = std::max(maxWss, s.wssPa);
    }
    std::vector<std::size_t> verticesPerSegment(tree.segments.size(), 0);
    for (const auto* array : {pressure, wss, segmentId, generation}) {
        EXPECT_EQ(array->components, 1);
        EXPECT_EQ(array->tupleCount(), mesh.vertexCount()) << array->name;
        EXPECT_EQ(array->nonFiniteCount(), 0U) << array->name;
    }
    const auto eps = 1e-4;
    double lowestWssFactor = 1.0;
    double highestWssFactor = 1.0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const double p = pressure->values[v];
        ASSERT_GE(p, outlet - eps);
        ASSERT_LE(p, inlet + eps);
        const double w = wss->values[v];
        ASSERT_GT(w, 0.0);
        ASSERT_LE(w, maxWss * 1.16);
        const float id = segmentId->values[v];
        ASSERT_EQ(id, std::round(id));
        ASSERT_GE(id, 0.0F);
        ASSERT_LT(id, static_cast<float>(tree.segments.size()));
        const auto& s = tree.segments[static_cast<std::size_t>(id)];
        ASSERT_EQ(generation->values[v], static_cast<float>(s.generation));
        // The vertex's values are its segment's.
        ASSERT_GE(p, s.pressureOutMmHg - eps);
        ASSERT_LE(p, s.pressureInMmHg + eps);
        ASSERT_GE(w, s.wssPa * 0.85 * 0.85 - 1e-6);
        ASSERT_LE(w, s.wssPa * 1.15 + 1e-6);
        lowestWssFactor = std::min(lowestWssFactor, w / s.wssPa);
        highestWssFactor = std::max(highestWssFactor, w / s.wssPa);
        ++verticesPerSegment[static_cast<std::size_t>(id)];
    }
    // Pressure runs from the inlet to the outlet; wall shear stress varies
    // near the junctions.
    const auto pressureRange = pressure->finiteRange();
    ASSERT_TRUE(pressureRange.has_value());
    EXPECT_NEAR(pressureRange->first, outlet, 0.01 * (inlet - outlet));
    EXPECT_NEAR(pressureRange->second, inlet, 0.01 * (inlet - outlet));
    EXPECT_LT(lowestWssFactor, 0.9);
    EXPECT_GT(highestWssFactor, 1.1);
    for (std::size_t i = 0; i < verticesPerSegment.size(); ++i) {
        EXPECT_GT(verticesPerSegment[i], 0U) << "segment " << i << " has no surface";
    }
}

}  // namespace

TEST(DemoTree, SameSeedGivesTheSameTreeAndAnotherSeedAnother) {
    const DemoTreeOptions options;
    const VesselTree a = vv::demo::generateVesselTree(options);
    const VesselTree b = vv::demo::generateVesselTree(options);
    EXPECT_TRUE(sameTree(a, b));
    DemoTreeOptions other = options;
    other.seed = options.seed + 1;
    const VesselTree c = vv::demo::generateVesselTree(other);
    EXPECT_FALSE(sameTree(a, c));
    ASSERT_FALSE(c.segments.empty());
    EXPECT_NE(a.segments.back().centerline.back(), c.segments.back().centerline.back());
}

TEST(DemoTree, DefaultTreeIsLargeDeepAndOrdered) {
    const DemoTreeOptions options;
    const VesselTree tree = vv::demo::generateVesselTree(options);
    const auto& segments = tree.segments;
    ASSERT_GE(segments.size(), 60U);
    int deepest = 0;
    int bifurcations = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto& s = segments[i];
        EXPECT_EQ(s.id, static_cast<int>(i));
        deepest = std::max(deepest, s.generation);
        if (i == 0) {
            EXPECT_EQ(s.parent, -1);
            EXPECT_EQ(s.generation, 0);
            EXPECT_DOUBLE_EQ(s.radiusMm, options.rootRadiusMm);
        } else {
            ASSERT_GE(s.parent, 0);
            ASSERT_LT(s.parent, static_cast<int>(i)) << "parents before children";
            const auto& parent = segments[static_cast<std::size_t>(s.parent)];
            EXPECT_EQ(s.generation, parent.generation + 1);
            EXPECT_EQ(std::count(parent.children.begin(), parent.children.end(), s.id), 1);
            // The child starts where the parent ends.
            EXPECT_EQ(s.centerline.front(), parent.centerline.back());
        }
        for (const int c : s.children) {
            EXPECT_GT(c, static_cast<int>(i));
        }
        if (s.children.size() == 2) {
            ++bifurcations;
        }
        if (s.generation < options.generations - 1) {
            EXPECT_GE(s.children.size(), 2U) << "segment " << i;
        } else {
            EXPECT_TRUE(s.children.empty());
        }
        ASSERT_GE(s.centerline.size(), 2U);
        double polyline = 0.0;
        for (std::size_t k = 0; k + 1 < s.centerline.size(); ++k) {
            polyline += glm::length(glm::dvec3(s.centerline[k + 1]) - glm::dvec3(s.centerline[k]));
        }
        EXPECT_NEAR(s.lengthMm, polyline, 1e-9 * polyline);
    }
    EXPECT_EQ(deepest, options.generations - 1);
    EXPECT_GE(deepest, 4);
    int branchings = 0;
    for (const auto& s : segments) {
        branchings += s.children.empty() ? 0 : 1;
    }
    EXPECT_GE(bifurcations, branchings * 3 / 4) << "mostly bifurcations";
}

TEST(DemoTree, RadiiFollowMurraysLawAndLengthsShrink) {
    const VesselTree tree = vv::demo::generateVesselTree({});
    bool asymmetric = false;
    for (const auto& s : tree.segments) {
        EXPECT_GT(s.radiusMm, 0.0);
        if (s.children.empty()) {
            continue;
        }
        double cubes = 0.0;
        for (const int c : s.children) {
            const auto& child = tree.segments[static_cast<std::size_t>(c)];
            cubes += child.radiusMm * child.radiusMm * child.radiusMm;
            EXPECT_LT(child.radiusMm, s.radiusMm);
            if (std::abs(child.radiusMm -
                         tree.segments[static_cast<std::size_t>(s.children[0])].radiusMm) >
                0.02 * s.radiusMm) {
                asymmetric = true;
            }
        }
        EXPECT_LT(relativeDifference(s.radiusMm * s.radiusMm * s.radiusMm, cubes), 1e-9)
            << "segment " << s.id;
    }
    EXPECT_TRUE(asymmetric);
    // Length shrinks with radius: mean length per generation decreases.
    std::vector<double> sum(6, 0.0);
    std::vector<int> count(6, 0);
    for (const auto& s : tree.segments) {
        sum[static_cast<std::size_t>(s.generation)] += s.lengthMm;
        ++count[static_cast<std::size_t>(s.generation)];
    }
    for (std::size_t g = 1; g < sum.size(); ++g) {
        EXPECT_LT(sum[g] / count[g], sum[g - 1] / count[g - 1]) << "generation " << g;
    }
}

TEST(DemoTree, CentrelinesAreCurvedAndSpreadInDepth) {
    const VesselTree tree = vv::demo::generateVesselTree({});
    vv::Aabb box;
    double meanBend = 0.0;
    for (const auto& s : tree.segments) {
        const double deviation = chordDeviation(s.centerline);
        EXPECT_GT(deviation, 0.02 * s.lengthMm) << "segment " << s.id << " is nearly straight";
        meanBend += deviation / s.lengthMm;
        box.extend(vv::boundsOf(s.centerline));
    }
    meanBend /= static_cast<double>(tree.segments.size());
    EXPECT_GT(meanBend, 0.04);
    const glm::vec3 size = box.size();
    EXPECT_GT(size.z, 0.3F * std::max(size.x, size.y)) << "no depth";
    EXPECT_GT(size.x, 0.3F * std::max(size.y, size.z));
    EXPECT_GT(size.y, 0.3F * std::max(size.x, size.z));
}

TEST(DemoTree, BranchingAnglesArePlausible) {
    const VesselTree tree = vv::demo::generateVesselTree({});
    for (const auto& s : tree.segments) {
        if (s.parent < 0) {
            continue;
        }
        const auto& parent = tree.segments[static_cast<std::size_t>(s.parent)];
        const auto& pl = parent.centerline;
        const glm::dvec3 into =
            glm::normalize(glm::dvec3(pl[pl.size() - 1]) - glm::dvec3(pl[pl.size() - 2]));
        const glm::dvec3 out =
            glm::normalize(glm::dvec3(s.centerline[1]) - glm::dvec3(s.centerline[0]));
        const double angle = std::acos(std::clamp(glm::dot(into, out), -1.0, 1.0)) * 180.0 / kPi;
        EXPECT_GT(angle, 10.0) << "segment " << s.id;
        EXPECT_LT(angle, 85.0) << "segment " << s.id;
    }
}

TEST(DemoTree, SegmentsDoNotRunThroughEachOther) {
    // The walls of segments that do not meet at a junction (all but parent,
    // child and siblings) stay apart, for the default and a few other seeds.
    for (const std::uint64_t seed :
         {std::uint64_t{20181021}, std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}}) {
        DemoTreeOptions options;
        options.seed = seed;
        const VesselTree tree = vv::demo::generateVesselTree(options);
        const auto& segments = tree.segments;
        const auto related = [&](const VesselSegment& a, const VesselSegment& b) {
            return a.parent == b.id || b.parent == a.id || (a.parent >= 0 && a.parent == b.parent);
        };
        for (const auto& a : segments) {
            for (const auto& b : segments) {
                if (a.id >= b.id || related(a, b)) {
                    continue;
                }
                double closest = 1e30;
                for (const auto& p : a.centerline) {
                    for (std::size_t k = 0; k + 1 < b.centerline.size(); ++k) {
                        const glm::dvec3 q0(b.centerline[k]);
                        const glm::dvec3 d = glm::dvec3(b.centerline[k + 1]) - q0;
                        const double t =
                            std::clamp(glm::dot(glm::dvec3(p) - q0, d) / glm::dot(d, d), 0.0, 1.0);
                        closest = std::min(closest, glm::length(glm::dvec3(p) - (q0 + d * t)));
                    }
                }
                EXPECT_GT(closest, a.radiusMm + b.radiusMm)
                    << "seed " << seed << ": segments " << a.id << " and " << b.id << " intersect";
            }
        }
    }
}

TEST(DemoTree, FlowIsConservedAndPressureFallsToOneOutletPressure) {
    const DemoTreeOptions options;
    const VesselTree tree = vv::demo::generateVesselTree(options);
    const auto& segments = tree.segments;
    EXPECT_DOUBLE_EQ(segments[0].flowMlPerS, options.inletFlowMlPerS);
    EXPECT_DOUBLE_EQ(segments[0].pressureInMmHg, 100.0);
    double leafFlow = 0.0;
    double outlet = 0.0;
    bool first = true;
    for (const auto& s : segments) {
        EXPECT_GT(s.flowMlPerS, 0.0);
        EXPECT_LT(s.pressureOutMmHg, s.pressureInMmHg) << "segment " << s.id;
        if (s.parent >= 0) {
            EXPECT_EQ(s.pressureInMmHg,
                      segments[static_cast<std::size_t>(s.parent)].pressureOutMmHg);
        }
        if (s.children.empty()) {
            leafFlow += s.flowMlPerS;
            if (first) {
                outlet = s.pressureOutMmHg;
                first = false;
            }
            EXPECT_NEAR(s.pressureOutMmHg, outlet, 1e-9) << "leaf " << s.id;
        } else {
            double childFlow = 0.0;
            for (const int c : s.children) {
                childFlow += segments[static_cast<std::size_t>(c)].flowMlPerS;
            }
            EXPECT_LT(relativeDifference(childFlow, s.flowMlPerS), 1e-12) << "segment " << s.id;
        }
    }
    EXPECT_LT(relativeDifference(leafFlow, options.inletFlowMlPerS), 1e-12);
    EXPECT_LT(outlet, options.inletPressureMmHg);
}

TEST(DemoTree, PoiseuilleResistancePressureDropAndWallShearStress) {
    const DemoTreeOptions options;
    const VesselTree tree = vv::demo::generateVesselTree(options);
    const double mu = options.viscosityPaS;
    for (const auto& s : tree.segments) {
        const double r = s.radiusMm * 1e-3;
        const double length = s.lengthMm * 1e-3;
        const double q = s.flowMlPerS * 1e-6;
        const double resistance = 8.0 * mu * length / (kPi * std::pow(r, 4));
        EXPECT_LT(relativeDifference(s.resistance, resistance), 1e-12) << "segment " << s.id;
        const double drop = (s.pressureInMmHg - s.pressureOutMmHg) * kPascalPerMmHg;
        EXPECT_LT(relativeDifference(drop, q * resistance), 1e-6) << "segment " << s.id;
        const double wss = 4.0 * mu * q / (kPi * std::pow(r, 3));
        EXPECT_LT(relativeDifference(s.wssPa, wss), 1e-12) << "segment " << s.id;
    }
    // The split follows the subtree resistances: siblings' subtrees see the
    // same pressure drop, so flow * subtree resistance is equal among them.
    std::vector<double> subtree(tree.segments.size());
    for (std::size_t i = tree.segments.size(); i-- > 0;) {
        const auto& s = tree.segments[i];
        double conductance = 0.0;
        for (const int c : s.children) {
            conductance += 1.0 / subtree[static_cast<std::size_t>(c)];
        }
        subtree[i] = s.resistance + (s.children.empty() ? 0.0 : 1.0 / conductance);
    }
    const double total = tree.segments[0].flowMlPerS * 1e-6 * subtree[0] / kPascalPerMmHg;
    for (const auto& s : tree.segments) {
        if (s.children.empty()) {
            EXPECT_NEAR(s.pressureOutMmHg, options.inletPressureMmHg - total, 1e-9);
        }
    }
}

TEST(DemoTree, InvalidOptionsThrow) {
    const auto expectInvalid = [](auto change) {
        DemoTreeOptions options;
        change(options);
        EXPECT_THROW((void)vv::demo::generateVesselTree(options), vv::InvalidArgumentError);
        EXPECT_THROW((void)vv::demo::generateDemoMesh(options), vv::InvalidArgumentError);
    };
    expectInvalid([](DemoTreeOptions& o) { o.generations = 0; });
    expectInvalid([](DemoTreeOptions& o) { o.generations = 11; });
    expectInvalid([](DemoTreeOptions& o) { o.rootRadiusMm = 0.0; });
    expectInvalid([](DemoTreeOptions& o) { o.rootRadiusMm = std::nan(""); });
    expectInvalid([](DemoTreeOptions& o) { o.rootLengthMm = -1.0; });
    expectInvalid([](DemoTreeOptions& o) { o.rootLengthMm = 5.0; });  // < 2 radii
    expectInvalid([](DemoTreeOptions& o) { o.inletFlowMlPerS = 0.0; });
    expectInvalid([](DemoTreeOptions& o) { o.viscosityPaS = -3.5e-3; });
    expectInvalid([](DemoTreeOptions& o) { o.inletPressureMmHg = INFINITY; });
    expectInvalid([](DemoTreeOptions& o) { o.voxelSizeMm = -0.1; });
    expectInvalid([](DemoTreeOptions& o) { o.maxTriangles = -1; });
    expectInvalid([](DemoTreeOptions& o) { o.maxTriangles = 9999; });

    // A voxel size needing an enormous grid, and broken trees.
    DemoTreeOptions tiny;
    tiny.voxelSizeMm = 0.01;
    const VesselTree tree = vv::demo::generateVesselTree({});
    EXPECT_THROW((void)vv::demo::buildVesselSurface(tree, tiny), vv::InvalidArgumentError);
    EXPECT_THROW((void)vv::demo::buildVesselSurface(VesselTree{}, {}), vv::InvalidArgumentError);
    VesselTree broken = tree;
    broken.segments[5].radiusMm = 0.0;
    EXPECT_THROW((void)vv::demo::buildVesselSurface(broken, {}), vv::InvalidArgumentError);
    broken = tree;
    broken.segments[3].parent = 7;
    EXPECT_THROW((void)vv::demo::buildVesselSurface(broken, {}), vv::InvalidArgumentError);
    broken = tree;
    broken.segments[2].centerline.resize(1);
    EXPECT_THROW((void)vv::demo::buildVesselSurface(broken, {}), vv::InvalidArgumentError);
}

TEST(DemoTree, SurfaceIsWatertightOutwardAndCarriesTheData) {
    const DemoTreeOptions options = coarseOptions();
    const VesselTree tree = vv::demo::generateVesselTree(options);
    const Mesh mesh = vv::demo::buildVesselSurface(tree, options);
    expectValidSurface(mesh, tree, options);
}

TEST(DemoTree, SurfaceIsDeterministicAndDependsOnTheSeed) {
    DemoTreeOptions options = coarseOptions();
    options.generations = 3;
    const Mesh a = vv::demo::generateDemoMesh(options);
    const Mesh b = vv::demo::generateDemoMesh(options);
    EXPECT_TRUE(sameMesh(a, b));
    {
        // The same with one worker thread.
        const char* previous = std::getenv("VV_THREADS");
        const std::string saved = previous != nullptr ? previous : "";
        ::setenv("VV_THREADS", "1", 1);
        const Mesh single = vv::demo::generateDemoMesh(options);
        if (previous != nullptr) {
            ::setenv("VV_THREADS", saved.c_str(), 1);
        } else {
            ::unsetenv("VV_THREADS");
        }
        EXPECT_TRUE(sameMesh(a, single));
    }
    options.seed += 1;
    const Mesh c = vv::demo::generateDemoMesh(options);
    EXPECT_FALSE(sameMesh(a, c));
}

TEST(DemoTree, UnsmoothedSurfaceIsAlsoWatertight) {
    DemoTreeOptions options = coarseOptions();
    options.smooth = false;
    const VesselTree tree = vv::demo::generateVesselTree(options);
    const Mesh mesh = vv::demo::buildVesselSurface(tree, options);
    expectValidSurface(mesh, tree, options);
}

TEST(DemoTree, StaysWithinTheTriangleLimit) {
    // A voxel size giving ~50k triangles, a limit of 20k: extracted again on a
    // coarser grid, still a valid surface.
    DemoTreeOptions options = coarseOptions();
    const VesselTree tree = vv::demo::generateVesselTree(options);
    const Mesh fine = vv::demo::buildVesselSurface(tree, options);
    ASSERT_GT(fine.triangleCount(), 30000U);
    options.maxTriangles = 20000;
    const Mesh mesh = vv::demo::buildVesselSurface(tree, options);
    EXPECT_LE(mesh.triangleCount(), 20000U);
    EXPECT_GT(mesh.triangleCount(), 12000U);
    expectValidSurface(mesh, tree, options);
}

TEST(DemoTree, DefaultDemoMeshHasTheTargetSize) {
    const DemoTreeOptions options;
    std::vector<double> fractions;
    const vv::Progress progress([&](double f, std::string_view) { fractions.push_back(f); },
                                std::stop_token{});
    const auto start = std::chrono::steady_clock::now();
    const Mesh mesh = vv::demo::generateDemoMesh(options, progress);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("seconds", std::to_string(seconds));
    std::printf("default demo: %.2f s, %zu triangles, %zu vertices\n", seconds,
                mesh.triangleCount(), mesh.vertexCount());
    EXPECT_EQ(mesh.name, "demo vessel tree");
    EXPECT_TRUE(mesh.source.empty());
    EXPECT_GE(mesh.triangleCount(), 200000U);
    EXPECT_LE(mesh.triangleCount(), 500000U);
    ASSERT_FALSE(fractions.empty());
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
    expectValidSurface(mesh, vv::demo::generateVesselTree(options), options);
}

TEST(DemoTree, StoppedBeforeStartThrowsCancelled) {
    std::stop_source stop;
    stop.request_stop();
    const vv::Progress progress({}, stop.get_token());
    EXPECT_THROW((void)vv::demo::generateDemoMesh(coarseOptions(), progress), vv::CancelledError);
}

TEST(DemoTree, StoppedMidwayThrowsCancelled) {
    // Stop during each stage in turn (extraction, smoothing, normals, point
    // data); every one must notice.
    DemoTreeOptions options = coarseOptions();
    options.generations = 2;
    for (const double at : {0.1, 0.45, 0.6, 0.87, 0.95}) {
        std::stop_source stop;
        double last = 0.0;
        const vv::Progress progress(
            [&](double f, std::string_view) {
                last = f;
                if (f >= at) {
                    stop.request_stop();
                }
            },
            stop.get_token());
        EXPECT_THROW((void)vv::demo::generateDemoMesh(options, progress), vv::CancelledError)
            << "stop at " << at;
        EXPECT_LT(last, 1.0);
    }
}
