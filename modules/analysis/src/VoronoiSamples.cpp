// SPDX-License-Identifier: GPL-3.0-or-later
#include "VoronoiSamples.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <tuple>
#include <unordered_map>

namespace vv::analysis::detail {
namespace {
/// How often the normals are averaged over their neighbours before their
/// turn is measured.
constexpr int kNormalSmoothingPasses = 4;
/// A vertex shares a cell only where the cell is this many times its
/// shortest edge: where the surface is at least that much finer than needed.
constexpr double kCoarserThan = 2.0;
/// A vertex whose normal is more than 15 degrees from its averaged normal
/// lies on a rough wall.
const double kRoughCosine = std::cos(15.0 * std::numbers::pi / 180.0);
/// A grid cell: its level (side = finest * 2^level) and its integer
/// coordinates.
using Key = std::tuple<int, std::int64_t, std::int64_t, std::int64_t>;
struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
        const auto [l, x, y, z] = k;
        auto h = static_cast<std::size_t>(l);
        for (const std::int64_t c : {x, y, z}) {
            h = h * 0x9E3779B97F4A7C15ULL + static_cast<std::size_t>(c);
        }
        return h;
    }
};

/// Cells of sides finest * 2^level, the level of a size rounded down: the
/// grid both the reduction and the added points keep one point per cell of.
class LevelGrid {
  public:
    explicit LevelGrid(double finest) : finest_(finest) {}

    [[nodiscard]] int levelOf(double size) const {
        return static_cast<int>(std::floor(std::log2(size / finest_)));
    }
    [[nodiscard]] Key cellOf(const glm::dvec3& p, int level) const {
        const glm::dvec3 c = glm::floor(p / (finest_ * std::exp2(level)));
        return Key{level, static_cast<std::int64_t>(c.x), static_cast<std::int64_t>(c.y),
                   static_cast<std::int64_t>(c.z)};
    }

  private:
    double finest_;
};

/// What the reduction learns of each surface vertex: its local radius, and
/// whether it lies on a rough wall (its normal more than 15 degrees from its
/// averaged one).
struct LocalShape {
    std::vector<double> radius;
    std::vector<char> rough;
};

/// Calls visit(a, b) for each triangle's edges (an edge two triangles share,
/// twice).
template <typename Visit>
void forEachEdgeOf(const std::vector<Triangle>& triangles, const Visit& visit) {
    for (const Triangle& t : triangles) {
        for (std::size_t k = 0; k < 3; ++k) {
            visit(t[k], t[(k + 1) % 3]);
        }
    }
}

/// Per surface vertex, its normal averaged over its neighbours
/// (kNormalSmoothingPasses times, unit): a jittered wall's normals scatter
/// from triangle to triangle, its vessel's do not.
std::vector<glm::dvec3> neighbourhoodNormals(const PreparedSurface& s) {
    const std::size_t n = s.positions.size();
    std::vector<glm::dvec3> normals(s.cappedNormals.begin(),
                                    s.cappedNormals.begin() + static_cast<std::ptrdiff_t>(n));
    for (int pass = 0; pass < kNormalSmoothingPasses; ++pass) {
        std::vector<glm::dvec3> sum = normals;
        forEachEdgeOf(s.triangles, [&](std::uint32_t a, std::uint32_t b) {
            sum[a] += normals[b];
            sum[b] += normals[a];
        });
        for (std::size_t v = 0; v < n; ++v) {
            const double length = glm::length(sum[v]);
            normals[v] = length > 0.0 ? sum[v] / length : normals[v];
        }
    }
    return normals;
}

/// Whether the wall folds over itself at a vertex: its own normal points
/// against its neighbourhood's (`averaged`).
bool foldedAt(const PreparedSurface& s, const glm::dvec3& averaged, std::size_t v) {
    return glm::dot(s.cappedNormals[v], averaged) < 0.0;
}

/// The reduction part of chooseVoronoiSamples(); `shape` receives what it
/// learns of the vertices.
VoronoiSamples reducedSamples(const PreparedSurface& s, LocalShape& shape,
                              const Progress& progress) {
    std::vector<double>& radius = shape.radius;
    const std::size_t capped = s.cappedPositions.size();
    const std::size_t n = s.positions.size();
    VoronoiSamples samples;
    samples.representative.resize(capped);
    std::iota(samples.representative.begin(), samples.representative.end(), 0U);
    const auto keepAll = [&] {
        samples.kept.resize(capped);
        std::iota(samples.kept.begin(), samples.kept.end(), 0U);
        samples.reduced = false;
        samples.largestGapMm = 0.0;
        std::iota(samples.representative.begin(), samples.representative.end(), 0U);
        return samples;
    };

    // Each vertex's shortest edge, and its largest curvature as its edges
    // see it: how fast the normal turns along them (1/r across a tube of
    // radius r; more on a rough surface, which keeps more points).
    std::vector<double> edge(n, std::numeric_limits<double>::infinity());
    std::vector<double> curvature(n, 0.0);
    const auto forEachEdge = [&](const auto& visit) { forEachEdgeOf(s.triangles, visit); };
    const std::vector<glm::dvec3> normals = neighbourhoodNormals(s);
    forEachEdge([&](std::uint32_t a, std::uint32_t b) {
        const double length = glm::length(s.positions[a] - s.positions[b]);
        if (!(length > 0.0)) {
            return;
        }
        const double turn = glm::length(normals[a] - normals[b]) / length;
        for (const std::uint32_t v : {a, b}) {
            edge[v] = std::min(edge[v], length);
            curvature[v] = std::max(curvature[v], turn);
        }
    });
    progress.throwIfCancelled();
    // The local radius: the smallest over the vertex and its neighbours.
    radius.assign(n, std::numeric_limits<double>::infinity());
    shape.rough.assign(n, 0);
    forEachEdge([&](std::uint32_t a, std::uint32_t b) {
        const double r = 1.0 / std::max({curvature[a], curvature[b], 1e-12});
        radius[a] = std::min(radius[a], r);
        radius[b] = std::min(radius[b], r);
    });

    // The cell each vertex may share: kSpacingPerRadius of the local radius,
    // 0 (kept alone) where that is no coarser than the surface already is.
    std::vector<double> cell(capped, 0.0);
    double finest = std::numeric_limits<double>::infinity();
    std::size_t folded = 0;
    for (std::size_t v = 0; v < n; ++v) {
        // A rough wall (its normal far from its neighbourhood's) keeps every
        // point: sparse points on it give spiky inscribed spheres. Where it
        // points against it, the wall folds over itself.
        const double agreement = glm::dot(s.cappedNormals[v], normals[v]);
        folded += foldedAt(s, normals[v], v) ? 1 : 0;
        if (agreement < kRoughCosine) {
            shape.rough[v] = 1;
            continue;
        }
        const double size = kSpacingPerRadius * radius[v];
        if (std::isfinite(size) && size < s.diagonalMm && size > kCoarserThan * edge[v]) {
            cell[v] = size;
            finest = std::min(finest, size);
        }
    }
    samples.foldedFraction = static_cast<double>(folded) / static_cast<double>(n);
    for (const BoundaryLoop& loop : s.loops) {
        for (const std::uint32_t v : loop.vertices) {
            cell[v] = 0.0;  // the rims decide the open ends' centres
        }
    }
    if (!std::isfinite(finest)) {
        return keepAll();
    }

    // One vertex per cell of a grid of side finest * 2^level; the first
    // vertex of a cell (in index order) stands for the cell.
    const LevelGrid grid(finest);
    std::unordered_map<Key, std::uint32_t, KeyHash> owner;
    owner.reserve(n / 4);
    samples.kept.clear();
    for (std::uint32_t v = 0; v < capped; ++v) {
        if (cell[v] <= 0.0) {
            samples.kept.push_back(v);
            continue;
        }
        const Key key = grid.cellOf(s.cappedPositions[v], grid.levelOf(cell[v]));
        const auto [at, inserted] = owner.try_emplace(key, v);
        if (inserted) {
            samples.kept.push_back(v);
        } else {
            samples.representative[v] = at->second;
            samples.largestGapMm =
                std::max(samples.largestGapMm,
                         glm::length(s.cappedPositions[v] - s.cappedPositions[at->second]));
        }
    }
    if (samples.kept.size() * 5 > capped * 4) {
        return keepAll();
    }
    samples.reduced = true;
    return samples;
}

/// A coarse facet: its index in the wall's triangles and the spacing its
/// added points keep.
struct CoarseFacet {
    std::size_t triangle;
    double longest;  ///< its longest edge, mm
    double spacing;
};

/// Over this fraction of rough vertices, a wall is sampled finer than its
/// roughness (a jittered 300k tube: 52 %; every coarse, decimated or
/// segmented phantom: at most 13 %).
constexpr double kRoughWallFraction = 0.25;

/// The wall's facets coarser than kCoarseFacetRadii (`shape`: the local
/// radius per surface vertex), with the spacing for each, and the number of
/// points they would take (about their area over the spacing squared). On a
/// rough wall, and on and next to a rim, the curvature measures the
/// roughness or the turn onto the cap, not the vessel (a jittered 1M
/// aneurysm got 4 s of needless points): a mostly rough wall
/// (kRoughWallFraction) and a facet whose three vertices are rough get none,
/// and on and next to a rim the loop's radius is the vessel's.
std::vector<CoarseFacet> coarseFacets(const PreparedSurface& s, const LocalShape& shape,
                                      double& expectedPoints) {
    std::vector<CoarseFacet> facets;
    expectedPoints = 0.0;
    const auto rough = static_cast<double>(std::count(shape.rough.begin(), shape.rough.end(), 1));
    if (rough > kRoughWallFraction * static_cast<double>(shape.rough.size())) {
        return facets;
    }
    std::vector<double> radius = shape.radius;
    std::vector<double> rimRadius(s.positions.size(), 0.0);
    for (const BoundaryLoop& loop : s.loops) {
        for (const std::uint32_t v : loop.vertices) {
            rimRadius[v] = std::max(rimRadius[v], loop.radiusMm);
        }
    }
    for (const Triangle& tri : s.triangles) {
        const double r = std::max({rimRadius[tri[0]], rimRadius[tri[1]], rimRadius[tri[2]]});
        if (r > 0.0) {
            for (const std::uint32_t v : tri) {
                radius[v] = r;
            }
        }
    }
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        const Triangle& tri = s.triangles[t];
        if (shape.rough[tri[0]] != 0 && shape.rough[tri[1]] != 0 && shape.rough[tri[2]] != 0) {
            continue;
        }
        const glm::dvec3& a = s.positions[tri[0]];
        const glm::dvec3& b = s.positions[tri[1]];
        const glm::dvec3& c = s.positions[tri[2]];
        const double ab = glm::length(b - a);
        const double bc = glm::length(c - b);
        const double ca = glm::length(a - c);
        const double longest = std::max({ab, bc, ca});
        const double r = std::max(std::min({radius[tri[0]], radius[tri[1]], radius[tri[2]]}),
                                  std::min({ab, bc, ca}));
        if (!std::isfinite(r) || !(r > 0.0) || !(longest > kCoarseFacetRadii * r)) {
            continue;
        }
        const double spacing = std::max(kDenseSpacingPerRadius * r, longest / kMaxFacetSteps);
        facets.push_back({t, longest, spacing});
        expectedPoints += 0.5 * glm::length(glm::cross(b - a, c - a)) / (spacing * spacing);
    }
    return facets;
}

/// Adds points on the wall's coarse facets (coarseFacets()), at most about
/// kMaxAddedPoints: one per grid cell of a facet's spacing that holds no
/// vertex of the surface (the cells of a grid as fine as the finest spacing,
/// by level, as in the reduction).
void addPointsOnCoarseFacets(const PreparedSurface& s, const LocalShape& shape,
                             VoronoiSamples& samples, const Progress& progress) {
    double expected = 0.0;
    std::vector<CoarseFacet> facets = coarseFacets(s, shape, expected);
    if (facets.empty()) {
        return;
    }
    // Over the budget, every spacing grows alike.
    samples.addedSpacingScale = std::max(1.0, std::sqrt(expected / kMaxAddedPoints));
    double finest = std::numeric_limits<double>::infinity();
    for (CoarseFacet& facet : facets) {
        facet.spacing *= samples.addedSpacingScale;
        finest = std::min(finest, facet.spacing);
    }
    const LevelGrid grid(finest);
    // The cells the surface's vertices hold, at each level a facet uses.
    std::vector<int> levels;
    levels.reserve(facets.size());
    for (const CoarseFacet& facet : facets) {
        levels.push_back(grid.levelOf(facet.spacing));
    }
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    std::unordered_map<Key, char, KeyHash> taken;
    for (const glm::dvec3& p : s.cappedPositions) {
        for (const int level : levels) {
            taken.emplace(grid.cellOf(p, level), 0);
        }
    }
    const auto firstId = static_cast<std::uint32_t>(s.cappedPositions.size());
    for (std::size_t f = 0; f < facets.size(); ++f) {
        if (f % 1024 == 0) {
            progress.throwIfCancelled();
        }
        const Triangle& tri = s.triangles[facets[f].triangle];
        const double spacing = facets[f].spacing;
        const int level = grid.levelOf(spacing);
        const glm::dvec3& a = s.positions[tri[0]];
        const glm::dvec3& b = s.positions[tri[1]];
        const glm::dvec3& c = s.positions[tri[2]];
        // A barycentric lattice the spacing apart along the longest edge,
        // corners left out (they are the surface's own vertices).
        const auto steps =
            std::min(kMaxFacetSteps, static_cast<int>(std::ceil(facets[f].longest / spacing)));
        for (int i = 0; i <= steps; ++i) {
            for (int j = 0; i + j <= steps; ++j) {
                const int k = steps - i - j;
                if (i == steps || j == steps || k == steps) {
                    continue;
                }
                const double u = static_cast<double>(i) / steps;
                const double v = static_cast<double>(j) / steps;
                const double w = static_cast<double>(k) / steps;
                const glm::dvec3 point = u * a + v * b + w * c;
                if (!taken.emplace(grid.cellOf(point, level), 0).second) {
                    continue;
                }
                const glm::dvec3 normal = u * s.cappedNormals[tri[0]] +
                                          v * s.cappedNormals[tri[1]] + w * s.cappedNormals[tri[2]];
                const double length = glm::length(normal);
                if (!(length > 0.0)) {
                    continue;
                }
                samples.kept.push_back(firstId +
                                       static_cast<std::uint32_t>(samples.addedPositions.size()));
                samples.addedPositions.push_back(point);
                samples.addedNormals.push_back(normal / length);
            }
        }
    }
}

}  // namespace

VoronoiSamples chooseVoronoiSamples(const PreparedSurface& s, const Progress& progress) {
    LocalShape shape;
    VoronoiSamples samples = reducedSamples(s, shape, progress);
    samples.wallRadiusMm.resize(shape.radius.size());
    for (std::size_t v = 0; v < shape.radius.size(); ++v) {
        samples.wallRadiusMm[v] = shape.rough[v] != 0 ? 0.0F : static_cast<float>(shape.radius[v]);
    }
    addPointsOnCoarseFacets(s, shape, samples, progress);
    return samples;
}

double foldedFractionOf(const PreparedSurface& s) {
    const std::vector<glm::dvec3> normals = neighbourhoodNormals(s);
    std::size_t folded = 0;
    for (std::size_t v = 0; v < normals.size(); ++v) {
        folded += foldedAt(s, normals[v], v) ? 1 : 0;
    }
    return normals.empty() ? 0.0
                           : static_cast<double>(folded) / static_cast<double>(normals.size());
}

}  // namespace vv::analysis::detail
