// SPDX-License-Identifier: GPL-3.0-or-later
// The surface of a vessel tree: a narrow-band signed distance field (smooth
// union of tubes along the centrelines) sampled slab by slab, flying edges at
// 0, windowed-sinc smoothing, outward normals (FieldSurface.h); the per-vertex flow data come
// from DemoFlowFields.cpp. Also generateDemoMesh: the tree (DemoTree.cpp) and
// its surface. See docs/demo-data.md.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "DemoSurfaceDetail.h"
#include "DemoValidation.h"
#include "FieldSurface.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"
#include "vv/demo/DemoTree.h"

namespace vv::demo {

namespace {

using detail::Bins;
using detail::kBandVoxels;
using detail::kZeroGuardVoxels;
using detail::Piece;
using detail::pieceDistance2;
using detail::smoothMin;

// Grid and field (see docs/demo-data.md).
constexpr int kBinVoxels = 8;                   // bins of 8^3 voxels for the narrow band
constexpr int kMaxAxisVoxels = 4096;            // keeps float index coordinates exact enough
constexpr double kMaxVoxels = 256e6;            // bounds the time; slabs bound the memory
constexpr double kTargetTriangles = 300000.0;   // the automatic voxel size aims here
constexpr double kTrianglesPerVoxelArea = 2.9;  // flying edges, measured: per h^2 of surface
constexpr double kVoxelsPerRadius = 2.0;        // automatic: >= 4 voxels across a diameter
constexpr double kMinRadiusVoxels = 1.25;       // thinner vessels are drawn this thick
constexpr double kBlendPerRadius = 0.6;         // smooth-union width / radius of the added tube
constexpr float kFar = 1e30F;

// Progress of the stages. Extraction may run up to kMaxExtractions times,
// each on a coarser grid, to stay within the triangle limit; attempt i
// reports in [kExtractEnds[i], kExtractEnds[i + 1]].
constexpr int kMaxExtractions = 4;
constexpr std::array<double, kMaxExtractions + 1> kExtractEnds = {0.0, 0.45, 0.5, 0.53, 0.55};
constexpr double kSmoothEnd = 0.85;
constexpr double kNormalsEnd = 0.9;

using Grid = detail::FieldGrid;

bool tooLarge(const Grid& grid) {
    return grid.voxelCount() > kMaxVoxels || std::max({grid.nx, grid.ny, grid.nz}) > kMaxAxisVoxels;
}

double drawnRadius(double radius, double spacing) {
    return std::max(radius, kMinRadiusVoxels * spacing);
}

/// The grid around the tree for a voxel size: the centrelines' box padded by
/// the thickest drawn radius, the blend width, the band and two voxels.
Grid makeGrid(const VesselTree& tree, double spacing) {
    Aabb box;
    double padding = 0.0;
    for (const auto& s : tree.segments) {
        box.extend(boundsOf(s.centerline));
        const double r = drawnRadius(s.radiusMm, spacing);
        padding = std::max(padding, r * (1.0 + kBlendPerRadius));
    }
    padding += (kBandVoxels + 2.0) * spacing;
    Grid grid;
    grid.spacing = spacing;
    grid.origin = glm::dvec3(box.min) - padding;
    const glm::dvec3 size = glm::dvec3(box.max) - glm::dvec3(box.min) + 2.0 * padding;
    const auto cells = [&](double extent) {
        const double n = std::ceil(extent / spacing) + 1.0;
        if (n > 1e6) {
            throw InvalidArgumentError("vessel surface: voxel size " + std::to_string(spacing) +
                                       " mm is far too small for a tree " + std::to_string(extent) +
                                       " mm across");
        }
        return static_cast<int>(n);
    };
    grid.nx = cells(size.x);
    grid.ny = cells(size.y);
    grid.nz = cells(size.z);
    return grid;
}

/// Triangles flying edges makes for the tree's tubes at a voxel size (estimate).
double expectedTriangles(double area, double spacing) {
    return kTrianglesPerVoxelArea * area / (spacing * spacing);
}

/// The automatic voxel size: kVoxelsPerRadius across the thinnest radius, or
/// finer if that is needed for about kTargetTriangles; then coarser if needed
/// to stay below 90 % of maxTriangles (when not 0) and within the grid limits.
double automaticVoxelSize(const VesselTree& tree, int maxTriangles) {
    double thinnest = std::numeric_limits<double>::max();
    double area = 0.0;
    for (const auto& s : tree.segments) {
        thinnest = std::min(thinnest, s.radiusMm);
        area += 2.0 * std::numbers::pi * s.radiusMm * s.lengthMm;
    }
    double spacing = std::min(thinnest / kVoxelsPerRadius,
                              std::sqrt(kTrianglesPerVoxelArea * area / kTargetTriangles));
    if (maxTriangles > 0 && expectedTriangles(area, spacing) > 0.9 * maxTriangles) {
        spacing = std::sqrt(kTrianglesPerVoxelArea * area / (0.9 * maxTriangles));
    }
    for (int i = 0; i < 16; ++i) {
        const Grid grid = makeGrid(tree, spacing);
        if (!tooLarge(grid)) {
            break;
        }
        const double longest = std::max({grid.nx, grid.ny, grid.nz});
        spacing *=
            1.01 * std::max(std::cbrt(grid.voxelCount() / kMaxVoxels), longest / kMaxAxisVoxels);
    }
    return spacing;
}

std::vector<Piece> makePieces(const VesselTree& tree, double spacing) {
    std::vector<Piece> pieces;
    for (const auto& s : tree.segments) {
        const auto radius = static_cast<float>(drawnRadius(s.radiusMm, spacing));
        double arc = 0.0;
        for (std::size_t i = 0; i + 1 < s.centerline.size(); ++i) {
            Piece p;
            p.a = s.centerline[i];
            p.ab = s.centerline[i + 1] - s.centerline[i];
            const double length = glm::length(glm::dvec3(p.ab));
            p.length = static_cast<float>(length);
            p.invLength2 = length > 0.0 ? static_cast<float>(1.0 / (length * length)) : 0.0F;
            p.arcStart = static_cast<float>(arc);
            p.radius = radius;
            p.blend = static_cast<float>(kBlendPerRadius) * radius;
            p.segment = s.id;
            pieces.push_back(p);
            arc += length;
        }
    }
    return pieces;
}

Bins makeBins(const Grid& grid, const std::vector<Piece>& pieces, double band) {
    Bins bins;
    bins.origin = grid.origin - 0.5 * grid.spacing;  // bin edges between voxel centres
    bins.size = kBinVoxels * grid.spacing;
    bins.nx = (grid.nx + kBinVoxels - 1) / kBinVoxels;
    bins.ny = (grid.ny + kBinVoxels - 1) / kBinVoxels;
    bins.nz = (grid.nz + kBinVoxels - 1) / kBinVoxels;

    struct Range {
        int x0, x1, y0, y1, z0, z1;
    };
    std::vector<Range> ranges(pieces.size());
    const auto clampBin = [&](double v, double o, int n) {
        return static_cast<int>(
            std::clamp(std::floor((v - o) / bins.size), 0.0, static_cast<double>(n - 1)));
    };
    std::vector<std::uint32_t> counts(static_cast<std::size_t>(bins.count()) + 1, 0);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Piece& p = pieces[i];
        const glm::dvec3 a(p.a);
        const glm::dvec3 b = a + glm::dvec3(p.ab);
        const double pad = static_cast<double>(p.radius) + static_cast<double>(p.blend) + band;
        const glm::dvec3 lo = glm::min(a, b) - pad;
        const glm::dvec3 hi = glm::max(a, b) + pad;
        Range& r = ranges[i];
        r = {clampBin(lo.x, bins.origin.x, bins.nx), clampBin(hi.x, bins.origin.x, bins.nx),
             clampBin(lo.y, bins.origin.y, bins.ny), clampBin(hi.y, bins.origin.y, bins.ny),
             clampBin(lo.z, bins.origin.z, bins.nz), clampBin(hi.z, bins.origin.z, bins.nz)};
        for (int z = r.z0; z <= r.z1; ++z) {
            for (int y = r.y0; y <= r.y1; ++y) {
                for (int x = r.x0; x <= r.x1; ++x) {
                    ++counts[static_cast<std::size_t>(
                        x + bins.nx * (y + static_cast<long>(bins.ny) * z))];
                }
            }
        }
    }
    bins.start.assign(counts.size(), 0);
    std::uint64_t total = 0;
    for (std::size_t b = 0; b + 1 < counts.size(); ++b) {
        bins.start[b] = static_cast<std::uint32_t>(total);
        total += counts[b];
        if (total > std::numeric_limits<std::uint32_t>::max()) {
            throw InvalidArgumentError("vessel surface: too many centreline pieces per bin");
        }
    }
    bins.start.back() = static_cast<std::uint32_t>(total);
    bins.items.resize(static_cast<std::size_t>(total));
    std::vector<std::uint32_t> fill(bins.start.begin(), bins.start.end() - 1);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const Range& r = ranges[i];
        for (int z = r.z0; z <= r.z1; ++z) {
            for (int y = r.y0; y <= r.y1; ++y) {
                for (int x = r.x0; x <= r.x1; ++x) {
                    const auto b = static_cast<std::size_t>(
                        x + bins.nx * (y + static_cast<long>(bins.ny) * z));
                    bins.items[fill[b]++] = static_cast<std::uint32_t>(i);
                }
            }
        }
    }
    // Pieces were listed in piece order, so each bin's items come grouped by
    // segment, in segment order.
    bins.runStart.assign(counts.size(), 0);
    for (std::size_t b = 0; b + 1 < counts.size(); ++b) {
        bins.runStart[b] = static_cast<std::uint32_t>(bins.runs.size());
        for (std::uint32_t k = bins.start[b]; k < bins.start[b + 1]; ++k) {
            const int segment = pieces[bins.items[k]].segment;
            if (bins.runs.size() == bins.runStart[b] || bins.runs.back().segment != segment) {
                bins.runs.push_back({segment, k, k});
            }
            bins.runs.back().end = k + 1;
        }
        bins.maxRunsPerBin =
            std::max<std::size_t>(bins.maxRunsPerBin, bins.runs.size() - bins.runStart[b]);
    }
    bins.runStart.back() = static_cast<std::uint32_t>(bins.runs.size());
    return bins;
}

/// What the field needs to know about a segment besides its pieces.
struct SegmentShape {
    int parent = -1;
    float blend = 0.0F;  // smooth-union width, mm
};

std::vector<SegmentShape> makeShapes(const VesselTree& tree, double spacing) {
    std::vector<SegmentShape> shapes;
    shapes.reserve(tree.segments.size());
    for (const auto& s : tree.segments) {
        // As in makePieces, bit for bit: the bins are padded with the pieces' blend.
        const auto radius = static_cast<float>(drawnRadius(s.radiusMm, spacing));
        shapes.push_back({s.parent, static_cast<float>(kBlendPerRadius) * radius});
    }
    return shapes;
}

/// The field at p from the pieces of one bin. Per segment the exact distance
/// d to its tube (minimum over its pieces); then the minimum over the terms
/// smin(d_child, d_parent, k_child) and smin(d_a, d_b, min(k_a, k_b)) for
/// siblings a, b: every pair of segments meeting at a junction is blended,
/// everything else joined by a plain minimum. A pair term changes only where
/// both members are within band + k, which is why a segment missing from the
/// bin (further than band + k) cannot change the clamped field: the narrow
/// band is exact. `distance` has room for the bin's runs. kFar for no runs.
inline float fieldAt(const glm::vec3& p, std::span<const Bins::Run> runs,
                     const std::vector<std::uint32_t>& items, const std::vector<Piece>& pieces,
                     const std::vector<SegmentShape>& shapes, float* distance) {
    const std::size_t n = runs.size();
    for (std::size_t a = 0; a < n; ++a) {
        float d = kFar;
        for (std::uint32_t k = runs[a].begin; k < runs[a].end; ++k) {
            const Piece& piece = pieces[items[k]];
            float t = 0.0F;
            d = std::min(d, std::sqrt(pieceDistance2(piece, p, t)) - piece.radius);
        }
        distance[a] = d;
    }
    float result = kFar;
    for (std::size_t a = 0; a < n; ++a) {
        const SegmentShape& shape = shapes[static_cast<std::size_t>(runs[a].segment)];
        float term = distance[a];
        // Runs are in segment order and parents come first: look before a.
        for (std::size_t b = 0; b < a; ++b) {
            if (runs[b].segment == shape.parent) {
                term = smoothMin(distance[a], distance[b], shape.blend);
                break;
            }
        }
        result = std::min(result, term);
        if (shape.parent < 0) {
            continue;
        }
        for (std::size_t b = a + 1; b < n; ++b) {
            const SegmentShape& other = shapes[static_cast<std::size_t>(runs[b].segment)];
            if (other.parent == shape.parent) {
                result = std::min(result, smoothMin(distance[a], distance[b],
                                                    std::min(shape.blend, other.blend)));
            }
        }
    }
    return result;
}

/// Samples the field for the voxel layers z0..z1 (all x and y) into values,
/// x fastest, as detail::SlabSampler: false when no piece reaches the slab.
bool sampleSlab(const Grid& grid, const std::vector<Piece>& pieces, const Bins& bins,
                const std::vector<SegmentShape>& shapes, float band, int z0, int z1, float* values,
                const std::stop_token& stop) {
    const long nx = grid.nx;
    const long ny = grid.ny;
    const glm::vec3 origin(grid.origin);
    const auto h = static_cast<float>(grid.spacing);
    const float guard = static_cast<float>(kZeroGuardVoxels) * h;
    const long layer0 = z0 / kBinVoxels;
    const long layer1 = z1 / kBinVoxels;
    const long binsPerLayer = static_cast<long>(bins.nx) * bins.ny;
    if (bins.start[static_cast<std::size_t>(binsPerLayer * layer0)] ==
        bins.start[static_cast<std::size_t>(binsPerLayer * (layer1 + 1))]) {
        return false;
    }
    const auto body = [&](long begin, long end) {
        std::vector<float> distance(bins.maxRunsPerBin);
        for (long i = begin; i < end; ++i) {
            const long layer = layer0 + i / binsPerLayer;
            const long bx = (i % binsPerLayer) % bins.nx;
            const long by = (i % binsPerLayer) / bins.nx;
            const auto runs = bins.runsAt(bx + bins.nx * (by + bins.ny * layer));
            const long x0 = bx * kBinVoxels;
            const long y0 = by * kBinVoxels;
            const long x1 = std::min(nx, x0 + kBinVoxels);
            const long y1 = std::min(ny, y0 + kBinVoxels);
            const long zBegin = std::max<long>(z0, layer * kBinVoxels);
            const long zEnd = std::min<long>(z1 + 1, (layer + 1) * kBinVoxels);
            for (long z = zBegin; z < zEnd; ++z) {
                for (long y = y0; y < y1; ++y) {
                    float* row = values + ((z - z0) * ny + y) * nx;
                    if (runs.empty()) {
                        std::fill(row + x0, row + x1, band);
                        continue;
                    }
                    for (long x = x0; x < x1; ++x) {
                        const glm::vec3 p =
                            origin + h * glm::vec3(static_cast<float>(x), static_cast<float>(y),
                                                   static_cast<float>(z));
                        row[x] = detail::guardedFieldValue(
                            fieldAt(p, runs, bins.items, pieces, shapes, distance.data()), band,
                            guard);
                    }
                }
            }
        }
    };
    parallelFor(0, binsPerLayer * (layer1 - layer0 + 1), 4, body, stop);
    return true;
}

/// Everything one extraction at a voxel size needs and makes; the pieces and
/// bins are used again for the point data.
struct Extraction {
    std::vector<Piece> pieces;
    Bins bins;
    vtkSmartPointer<vtkPolyData> surface;
};

Extraction extractAt(const VesselTree& tree, double spacing, const Progress& progress) {
    const Grid grid = makeGrid(tree, spacing);
    if (tooLarge(grid)) {
        throw InvalidArgumentError(
            "vessel surface: voxel size " + std::to_string(spacing) + " mm needs a grid of " +
            std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " x " +
            std::to_string(grid.nz) + " voxels, more than the limit of " +
            std::to_string(static_cast<long long>(kMaxVoxels)) + " voxels or " +
            std::to_string(kMaxAxisVoxels) + " along an axis; use a larger voxel size");
    }
    const auto band = static_cast<float>(detail::kBandVoxels * spacing);
    Extraction extraction;
    extraction.pieces = makePieces(tree, spacing);
    extraction.bins = makeBins(grid, extraction.pieces, static_cast<double>(band));
    const std::vector<SegmentShape> shapes = makeShapes(tree, spacing);
    extraction.surface = detail::extractZeroLevel(
        grid,
        [&](int z0, int z1, float* values) {
            return sampleSlab(grid, extraction.pieces, extraction.bins, shapes, band, z0, z1,
                              values, progress.stopToken());
        },
        progress);
    if (extraction.surface->GetNumberOfPolys() == 0) {
        throw Error("vessel surface: the distance field has no zero level (empty surface)");
    }
    return extraction;
}

}  // namespace

scene::Mesh buildVesselSurface(const VesselTree& tree, const DemoTreeOptions& options,
                               const Progress& progress) {
    detail::validateDemoOptions(options);
    detail::validateVesselTree(tree);
    progress.throwIfCancelled();

    // Extract; over the triangle limit, extract again on a coarser grid (a
    // fresh flying-edges surface stays watertight, unlike a decimated one).
    double spacing = options.voxelSizeMm > 0.0 ? options.voxelSizeMm
                                               : automaticVoxelSize(tree, options.maxTriangles);
    Extraction extraction;
    for (int attempt = 0;; ++attempt) {
        const auto i = static_cast<std::size_t>(attempt);
        extraction = extractAt(tree, spacing, progress.sub(kExtractEnds[i], kExtractEnds[i + 1]));
        const auto triangles = static_cast<double>(extraction.surface->GetNumberOfPolys());
        if (options.maxTriangles == 0 || triangles <= options.maxTriangles) {
            break;
        }
        if (attempt + 1 == kMaxExtractions) {
            throw Error("vessel surface: could not get below " +
                        std::to_string(options.maxTriangles) + " triangles (still " +
                        std::to_string(static_cast<long long>(triangles)) + ")");
        }
        spacing *= 1.02 * std::sqrt(triangles / (0.95 * options.maxTriangles));
    }
    vtkSmartPointer<vtkPolyData> surface = std::move(extraction.surface);
    progress.report(kExtractEnds.back(), "Extracting surface");

    if (options.smooth) {
        surface = detail::smoothSurface(surface, progress.sub(kExtractEnds.back(), kSmoothEnd));
    }
    scene::Mesh mesh =
        detail::finishSurface(std::move(surface), progress.sub(kSmoothEnd, kNormalsEnd));
    mesh.name = "vessel tree";
    detail::addFlowFields(mesh, tree, extraction.pieces, extraction.bins,
                          progress.sub(kNormalsEnd, 1.0));
    return mesh;
}

scene::Mesh generateDemoMesh(const DemoTreeOptions& options, const Progress& progress) {
    progress.report(0.0, "Generating vessel tree");
    const VesselTree tree = generateVesselTree(options);
    progress.report(0.02, "Generating vessel tree");
    scene::Mesh mesh = buildVesselSurface(tree, options, progress.sub(0.02, 1.0));
    mesh.name = "demo vessel tree";
    return mesh;
}

}  // namespace vv::demo
