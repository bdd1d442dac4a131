// SPDX-License-Identifier: GPL-3.0-or-later
// meshio's windowed-sinc smoothing on an open cylinder with radial noise:
// the noise goes, the radius stays (no shrinking), the open ends stay where
// they are unless asked, points, triangles and arrays keep their order; bad
// options and bad meshes are refused, a stop request stops it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stop_token>

#include "RingGrid.h"
#include "vv/core/Error.h"
#include "vv/meshio/MeshSmooth.h"

namespace vv::meshio::mesh_smooth_test {
using scene::DataArray;
using scene::Mesh;
namespace {

constexpr int kAround = 160;
constexpr int kAlong = 200;
constexpr double kRadius = 10.0;
constexpr double kLength = 100.0;

/// An open cylinder along z, its points pushed out or in by up to `noise` mm
/// (uniform, seeded), with an array holding each point's index.
Mesh noisyCylinder(double noise) {
    Mesh mesh;
    mesh.name = "noisy cylinder";
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-noise, noise);
    DataArray index{.name = "index", .unit = "", .components = 1, .values = {}, .integer = true};
    for (int j = 0; j <= kAlong; ++j) {
        for (int i = 0; i < kAround; ++i) {
            const double phi = 2.0 * std::numbers::pi * i / kAround;
            const double r = kRadius + jitter(random);
            mesh.positions.emplace_back(r * std::cos(phi), r * std::sin(phi), kLength * j / kAlong);
            index.values.push_back(static_cast<float>(mesh.positions.size() - 1));
        }
    }
    test::addRingGridTriangles(mesh, kAround, kAlong);
    mesh.pointArrays = {index};
    computeNormals(mesh);
    return mesh;
}

double radiusOf(const glm::vec3& p) {
    return std::hypot(static_cast<double>(p.x), static_cast<double>(p.y));
}

struct RadiusStats {
    double mean = 0.0;
    double rms = 0.0;  ///< of the distance from kRadius
};

/// Over the points away from the open ends (a tenth of the length).
RadiusStats interiorRadii(const Mesh& mesh) {
    RadiusStats stats;
    int count = 0;
    for (const glm::vec3& p : mesh.positions) {
        if (p.z < 0.1 * kLength || p.z > 0.9 * kLength) {
            continue;
        }
        const double r = radiusOf(p);
        stats.mean += r;
        stats.rms += (r - kRadius) * (r - kRadius);
        ++count;
    }
    stats.mean /= count;
    stats.rms = std::sqrt(stats.rms / count);
    return stats;
}

TEST(MeshSmooth, TheNoiseGoesAndTheRadiusStays) {
    const Mesh noisy = noisyCylinder(0.5);
    const Mesh smooth = smoothedMesh(noisy);
    ASSERT_EQ(smooth.vertexCount(), noisy.vertexCount());
    EXPECT_EQ(smooth.indices, noisy.indices);
    EXPECT_EQ(smooth.name, noisy.name);
    ASSERT_EQ(smooth.pointArrays.size(), 1U);
    EXPECT_EQ(smooth.pointArrays[0].values, noisy.pointArrays[0].values);
    const RadiusStats before = interiorRadii(noisy);
    const RadiusStats after = interiorRadii(smooth);
    // Uniform noise of +-0.5 mm: 0.29 mm RMS; smoothed, under a third (what
    // varies over a few vertices stays in part).
    EXPECT_GT(before.rms, 0.25);
    EXPECT_LT(after.rms, before.rms / 3.0);
    // No shrinking: the mean radius within 0.05 % (Laplacian smoothing of
    // this strength pulls it in by several per cent; VTK 9.1's filter alone,
    // by 0.16 %).
    EXPECT_NEAR(after.mean, before.mean, 0.0005 * kRadius);
    for (std::size_t v = 0; v < smooth.vertexCount(); ++v) {
        EXPECT_NEAR(glm::length(smooth.normals[v]), 1.0F, 1e-4F);
        // The open ends' rims are kept.
        if (noisy.positions[v].z == 0.0F || noisy.positions[v].z == static_cast<float>(kLength)) {
            EXPECT_LT(glm::length(smooth.positions[v] - noisy.positions[v]), 1e-4F)
                << "vertex " << v;
        }
    }
}

TEST(MeshSmooth, TheRimsMoveWhenAllowedTo) {
    const Mesh noisy = noisyCylinder(0.5);
    SmoothingOptions options;
    options.keepBoundary = false;
    const Mesh smooth = smoothedMesh(noisy, options);
    std::size_t moved = 0;
    for (std::size_t v = 0; v < kAround; ++v) {  // the rim at z = 0
        moved += smooth.positions[v] != noisy.positions[v] ? 1 : 0;
    }
    EXPECT_GT(moved, kAround / 2);
}

TEST(MeshSmooth, BadOptionsAndMeshesAreRefused) {
    const Mesh noisy = noisyCylinder(0.1);
    for (const int iterations : {0, 501}) {
        SmoothingOptions options;
        options.iterations = iterations;
        EXPECT_THROW(static_cast<void>(smoothedMesh(noisy, options)), InvalidArgumentError);
    }
    for (const double band : {0.0, 2.0, std::nan("")}) {
        SmoothingOptions options;
        options.passBand = band;
        EXPECT_THROW(static_cast<void>(smoothedMesh(noisy, options)), InvalidArgumentError);
    }
    const auto refusedFor = [](const Mesh& mesh, const std::string& words) {
        try {
            static_cast<void>(smoothedMesh(mesh));
            ADD_FAILURE() << "smoothed a mesh that should be refused (" << words << ")";
        } catch (const FormatError& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("noisy cylinder"), std::string::npos) << e.what();
        }
    };
    Mesh outOfRange = noisy;
    outOfRange.indices[5] = static_cast<std::uint32_t>(outOfRange.vertexCount());
    refusedFor(outOfRange, "refers to vertex");
    Mesh notFinite = noisy;
    notFinite.positions[3].y = std::nanf("");
    refusedFor(notFinite, "not finite");
    Mesh empty = noisy;
    empty.indices.clear();
    refusedFor(empty, "no triangles");
}

TEST(MeshSmooth, AStopRequestStopsIt) {
    std::stop_source stop;
    stop.request_stop();
    const Progress cancelled([](double, std::string_view) {}, stop.get_token());
    EXPECT_THROW(static_cast<void>(smoothedMesh(noisyCylinder(0.1), {}, cancelled)),
                 CancelledError);
}

}  // namespace
}  // namespace vv::meshio::mesh_smooth_test
