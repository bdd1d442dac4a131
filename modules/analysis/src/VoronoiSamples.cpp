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
}  // namespace

VoronoiSamples chooseVoronoiSamples(const PreparedSurface& s, const Progress& progress) {
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
    const auto forEachEdge = [&](const auto& visit) {
        for (const Triangle& t : s.triangles) {
            for (std::size_t k = 0; k < 3; ++k) {
                visit(t[k], t[(k + 1) % 3]);
            }
        }
    };
    // Normals averaged over their neighbours (kNormalSmoothingPasses times): a jittered wall's
    // normals scatter from triangle to triangle, its vessel's do not.
    std::vector<glm::dvec3> normals(s.cappedNormals.begin(),
                                    s.cappedNormals.begin() + static_cast<std::ptrdiff_t>(n));
    for (int pass = 0; pass < kNormalSmoothingPasses; ++pass) {
        std::vector<glm::dvec3> sum = normals;
        forEachEdge([&](std::uint32_t a, std::uint32_t b) {
            sum[a] += normals[b];
            sum[b] += normals[a];
        });
        for (std::size_t v = 0; v < n; ++v) {
            const double length = glm::length(sum[v]);
            normals[v] = length > 0.0 ? sum[v] / length : normals[v];
        }
    }
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
    std::vector<double> radius(n, std::numeric_limits<double>::infinity());
    forEachEdge([&](std::uint32_t a, std::uint32_t b) {
        const double r = 1.0 / std::max({curvature[a], curvature[b], 1e-12});
        radius[a] = std::min(radius[a], r);
        radius[b] = std::min(radius[b], r);
    });

    // The cell each vertex may share: kSpacingPerRadius of the local radius,
    // 0 (kept alone) where that is no coarser than the surface already is.
    std::vector<double> cell(capped, 0.0);
    double finest = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v < n; ++v) {
        // A rough wall (its normal far from its neighbourhood's) keeps every
        // point: sparse points on it give spiky inscribed spheres.
        if (glm::dot(s.cappedNormals[v], normals[v]) < kRoughCosine) {
            continue;
        }
        const double size = kSpacingPerRadius * radius[v];
        if (std::isfinite(size) && size < s.diagonalMm && size > kCoarserThan * edge[v]) {
            cell[v] = size;
            finest = std::min(finest, size);
        }
    }
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
    std::unordered_map<Key, std::uint32_t, KeyHash> owner;
    owner.reserve(n / 4);
    samples.kept.clear();
    for (std::uint32_t v = 0; v < capped; ++v) {
        if (cell[v] <= 0.0) {
            samples.kept.push_back(v);
            continue;
        }
        const int level = static_cast<int>(std::floor(std::log2(cell[v] / finest)));
        const double side = finest * std::exp2(level);
        const glm::dvec3 c = glm::floor(s.cappedPositions[v] / side);
        const Key key{level, static_cast<std::int64_t>(c.x), static_cast<std::int64_t>(c.y),
                      static_cast<std::int64_t>(c.z)};
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

}  // namespace vv::analysis::detail
