// SPDX-License-Identifier: GPL-3.0-or-later
#include "PreparedSurface.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "vv/analysis/AnalysisError.h"
#include "vv/core/NumberText.h"

namespace vv::analysis::detail {
namespace {

[[noreturn]] void fail(const scene::Mesh& mesh, const std::string& problem) {
    throw AnalysisError(mesh.source, (mesh.source.empty() ? mesh.name + ": " : "") + problem);
}

void checkInput(const scene::Mesh& mesh) {
    if (mesh.indices.empty() || mesh.positions.empty()) {
        fail(mesh, "the surface has no triangles");
    }
    if (mesh.indices.size() % 3 != 0) {
        fail(mesh, "the triangle index count is not a multiple of 3");
    }
    for (const std::uint32_t index : mesh.indices) {
        if (index >= mesh.positions.size()) {
            fail(mesh, "a triangle refers to point " + std::to_string(index) + " of " +
                           std::to_string(mesh.positions.size()));
        }
    }
    for (const glm::vec3& p : mesh.positions) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            fail(mesh, "the surface has points with non-finite coordinates");
        }
    }
}

struct PositionKey {
    std::uint32_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};
struct PositionHash {
    std::size_t operator()(const PositionKey& k) const noexcept {
        return (static_cast<std::size_t>(k.x) * 73856093U) ^
               (static_cast<std::size_t>(k.y) * 19349663U) ^
               (static_cast<std::size_t>(k.z) * 83492791U);
    }
};

/// Points at the same position become one; returns old index -> new index.
/// Points in the same cube of side `cell` become the cube's first point;
/// returns old index -> new index.
std::vector<std::uint32_t> cluster(const scene::Mesh& mesh, double cell,
                                   std::vector<glm::dvec3>& positions) {
    struct CellHash {
        std::size_t operator()(const glm::i64vec3& c) const noexcept {
            return (static_cast<std::size_t>(c.x) * 73856093U) ^
                   (static_cast<std::size_t>(c.y) * 19349663U) ^
                   (static_cast<std::size_t>(c.z) * 83492791U);
        }
    };
    std::unordered_map<glm::i64vec3, std::uint32_t, CellHash> seen;
    seen.reserve(mesh.positions.size() / 2);
    std::vector<std::uint32_t> map(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::dvec3 p(mesh.positions[i]);
        const glm::i64vec3 key(glm::floor(p / cell));
        const auto [it, added] =
            seen.try_emplace(key, static_cast<std::uint32_t>(positions.size()));
        if (added) {
            positions.push_back(p);
        }
        map[i] = it->second;
    }
    return map;
}

/// The cube side that leaves about `maxTriangles` triangles of `mesh`: a
/// surface of area A cut into cubes of side c has about 2 A / c^2 triangles.
double clusterCell(const scene::Mesh& mesh, std::size_t maxTriangles) {
    double area = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
        const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    return std::sqrt(2.0 * area / static_cast<double>(maxTriangles));
}

std::vector<std::uint32_t> weld(const scene::Mesh& mesh, std::vector<glm::dvec3>& positions) {
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> seen;
    seen.reserve(mesh.positions.size());
    std::vector<std::uint32_t> map(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p = mesh.positions[i] + glm::vec3(0.0F);  // -0 -> +0
        const PositionKey key{std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y),
                              std::bit_cast<std::uint32_t>(p.z)};
        const auto [it, added] =
            seen.try_emplace(key, static_cast<std::uint32_t>(positions.size()));
        if (added) {
            positions.emplace_back(p);
        }
        map[i] = it->second;
    }
    return map;
}

double diagonalOf(const std::vector<glm::dvec3>& points) {
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (const auto& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return points.empty() ? 0.0 : glm::length(hi - lo);
}

/// Welded triangles without degenerate (repeated point, no area) and
/// repeated ones; the counts dropped go to `notes`.
std::vector<Triangle> cleanTriangles(const scene::Mesh& mesh, const std::vector<std::uint32_t>& map,
                                     const std::vector<glm::dvec3>& positions,
                                     std::vector<std::string>& notes) {
    const double diagonal = diagonalOf(positions);
    const double minArea2 = std::pow(1e-12 * diagonal * diagonal, 2.0);
    struct TriangleHash {
        std::size_t operator()(const Triangle& t) const noexcept {
            return (static_cast<std::size_t>(t[0]) * 73856093U) ^
                   (static_cast<std::size_t>(t[1]) * 19349663U) ^
                   (static_cast<std::size_t>(t[2]) * 83492791U);
        }
    };
    std::unordered_set<Triangle, TriangleHash> seen;
    seen.reserve(mesh.indices.size() / 3);
    std::vector<Triangle> triangles;
    triangles.reserve(mesh.indices.size() / 3);
    std::size_t degenerate = 0;
    std::size_t repeated = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Triangle tri{map[mesh.indices[t]], map[mesh.indices[t + 1]],
                           map[mesh.indices[t + 2]]};
        const glm::dvec3 n = glm::cross(positions[tri[1]] - positions[tri[0]],
                                        positions[tri[2]] - positions[tri[0]]);
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
            glm::dot(n, n) <= minArea2) {
            ++degenerate;
            continue;
        }
        Triangle key = tri;
        std::sort(key.begin(), key.end());
        if (!seen.insert(key).second) {
            ++repeated;
            continue;
        }
        triangles.push_back(tri);
    }
    if (degenerate > 0) {
        notes.push_back(std::to_string(degenerate) + " degenerate triangles were left out.");
    }
    if (repeated > 0) {
        notes.push_back(std::to_string(repeated) + " repeated triangles were left out.");
    }
    return triangles;
}

class UnionFind {
  public:
    explicit UnionFind(std::size_t n) : parent_(n) {
        std::iota(parent_.begin(), parent_.end(), 0U);
    }
    std::uint32_t find(std::uint32_t a) {
        while (parent_[a] != a) {
            parent_[a] = parent_[parent_[a]];
            a = parent_[a];
        }
        return a;
    }
    void unite(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }

  private:
    std::vector<std::uint32_t> parent_;
};

/// Keeps the connected piece `anchor` is nearest to (or the largest) and
/// renumbers its points.
void keepOnePiece(PreparedSurface& s, const std::optional<glm::dvec3>& anchor) {
    UnionFind sets(s.positions.size());
    for (const Triangle& t : s.triangles) {
        sets.unite(t[0], t[1]);
        sets.unite(t[1], t[2]);
    }
    std::map<std::uint32_t, std::size_t> sizes;
    for (const Triangle& t : s.triangles) {
        ++sizes[sets.find(t[0])];
    }
    std::uint32_t keep = sizes.begin()->first;
    if (anchor) {
        double best = std::numeric_limits<double>::max();
        for (const Triangle& t : s.triangles) {
            const double d = glm::length(s.positions[t[0]] - *anchor);
            if (d < best) {
                best = d;
                keep = sets.find(t[0]);
            }
        }
    } else {
        for (const auto& [root, count] : sizes) {
            if (count > sizes[keep]) {
                keep = root;
            }
        }
    }
    if (sizes.size() > 1) {
        s.notes.push_back("The surface has " + std::to_string(sizes.size()) +
                          " separate pieces; the one with " + std::to_string(sizes[keep]) +
                          " triangles" + (anchor ? " that the source lies on" : ", the largest,") +
                          " was analysed.");
    }
    std::vector<std::uint32_t> renumber(s.positions.size(), UINT32_MAX);
    std::vector<glm::dvec3> kept;
    std::vector<Triangle> triangles;
    for (Triangle t : s.triangles) {
        if (sets.find(t[0]) != keep) {
            continue;
        }
        for (std::uint32_t& v : t) {
            if (renumber[v] == UINT32_MAX) {
                renumber[v] = static_cast<std::uint32_t>(kept.size());
                kept.push_back(s.positions[v]);
            }
            v = renumber[v];
        }
        triangles.push_back(t);
    }
    // Held to the end of the analysis: no spare capacity (up to half
    // again of their size, after push_back).
    kept.shrink_to_fit();
    triangles.shrink_to_fit();
    s.positions = std::move(kept);
    s.triangles = std::move(triangles);
}

using EdgeKey = std::uint64_t;
EdgeKey undirected(std::uint32_t a, std::uint32_t b) {
    return a < b ? (static_cast<EdgeKey>(a) << 32U) | b : (static_cast<EdgeKey>(b) << 32U) | a;
}

/// Per triangle, its three edges (by key) and the triangle across each:
/// kBoundary when no other triangle has the edge, kNonManifold when more
/// than one does. Built once from a sorted list of the edges.
constexpr std::uint32_t kBoundary = UINT32_MAX;
constexpr std::uint32_t kNonManifold = UINT32_MAX - 1;

struct EdgeNeighbours {
    std::vector<std::array<EdgeKey, 3>> keys;
    std::vector<std::array<std::uint32_t, 3>> across;

    /// The triangle across edge (a, b) of triangle t.
    [[nodiscard]] std::uint32_t acrossEdge(std::uint32_t t, std::uint32_t a,
                                           std::uint32_t b) const {
        const EdgeKey key = undirected(a, b);
        for (std::size_t e = 0; e < 3; ++e) {
            if (keys[t][e] == key) {
                return across[t][e];
            }
        }
        return kBoundary;
    }
};

EdgeNeighbours edgeNeighbours(const std::vector<Triangle>& triangles) {
    EdgeNeighbours n;
    n.keys.resize(triangles.size());
    n.across.resize(triangles.size());
    std::vector<std::pair<EdgeKey, std::uint32_t>> uses;  // (edge, triangle * 3 + edge index)
    uses.reserve(triangles.size() * 3);
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
        for (std::uint32_t e = 0; e < 3; ++e) {
            const EdgeKey key = undirected(triangles[t][e], triangles[t][(e + 1) % 3]);
            n.keys[t][e] = key;
            uses.emplace_back(key, t * 3 + e);
        }
    }
    std::sort(uses.begin(), uses.end());
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i;
        while (j < uses.size() && uses[j].first == uses[i].first) {
            ++j;
        }
        for (std::size_t k = i; k < j; ++k) {
            const std::uint32_t use = uses[k].second;
            std::uint32_t other = kBoundary;
            if (j - i == 2) {
                other = uses[k == i ? i + 1 : i].second / 3;
            } else if (j - i > 2) {
                other = kNonManifold;
            }
            n.across[use / 3][use % 3] = other;
        }
        i = j;
    }
    return n;
}

/// Winds neighbouring triangles alike (across edges two triangles share),
/// piece by piece from its first triangle. Returns how many it flipped.
std::size_t windConsistently(std::vector<Triangle>& triangles, const EdgeNeighbours& neighbours) {
    const auto runsForward = [&](std::uint32_t t, std::uint32_t a, std::uint32_t b) {
        for (int e = 0; e < 3; ++e) {
            if (triangles[t][e] == a && triangles[t][(e + 1) % 3] == b) {
                return true;
            }
        }
        return false;
    };
    std::vector<char> done(triangles.size(), 0);
    std::size_t flipped = 0;
    for (std::uint32_t start = 0; start < triangles.size(); ++start) {
        if (done[start] != 0) {
            continue;
        }
        done[start] = 1;
        std::queue<std::uint32_t> queue;
        queue.push(start);
        while (!queue.empty()) {
            const std::uint32_t t = queue.front();
            queue.pop();
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t a = triangles[t][e];
                const std::uint32_t b = triangles[t][(e + 1) % 3];
                const std::uint32_t n = neighbours.acrossEdge(t, a, b);
                if (n == kBoundary || n == kNonManifold || done[n] != 0) {
                    continue;  // no single neighbour to follow, or already wound
                }
                done[n] = 1;
                if (runsForward(n, a, b)) {
                    std::swap(triangles[n][1], triangles[n][2]);
                    ++flipped;
                }
                queue.push(n);
            }
        }
    }
    return flipped;
}

/// The boundary loops: chains of edges that only one triangle has.
std::vector<BoundaryLoop> findLoops(const PreparedSurface& s, const EdgeNeighbours& neighbours) {
    std::multimap<std::uint32_t, std::uint32_t> next;  // boundary half-edges a -> b
    for (std::uint32_t t = 0; t < s.triangles.size(); ++t) {
        const Triangle& tri = s.triangles[t];
        for (int e = 0; e < 3; ++e) {
            if (neighbours.acrossEdge(t, tri[e], tri[(e + 1) % 3]) == kBoundary) {
                next.emplace(tri[e], tri[(e + 1) % 3]);
            }
        }
    }
    std::vector<BoundaryLoop> loops;
    while (!next.empty()) {
        BoundaryLoop loop;
        const std::uint32_t first = next.begin()->first;
        std::uint32_t at = first;
        while (true) {
            const auto it = next.find(at);
            if (it == next.end()) {
                break;  // an open chain (non-manifold boundary): ends here
            }
            loop.vertices.push_back(at);
            at = it->second;
            next.erase(it);
            if (at == first) {
                break;
            }
        }
        if (loop.vertices.size() >= 3) {
            loops.push_back(std::move(loop));
        }
    }
    return loops;
}

void measureLoop(BoundaryLoop& loop, const std::vector<glm::dvec3>& positions) {
    glm::dvec3 weighted(0.0);
    glm::dvec3 newell(0.0);
    double perimeter = 0.0;
    const std::size_t n = loop.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& a = positions[loop.vertices[i]];
        const glm::dvec3& b = positions[loop.vertices[(i + 1) % n]];
        const double length = glm::length(b - a);
        weighted += length * 0.5 * (a + b);
        perimeter += length;
        newell += glm::cross(a, b);
    }
    loop.centre = perimeter > 0.0 ? weighted / perimeter : positions[loop.vertices[0]];
    loop.inward = glm::length(newell) > 0.0 ? glm::normalize(newell) : glm::dvec3(0.0);
    double radius = 0.0;
    for (const std::uint32_t v : loop.vertices) {
        radius += glm::length(positions[v] - loop.centre);
    }
    loop.radiusMm = radius / static_cast<double>(n);
}

void capLoops(PreparedSurface& s) {
    s.cappedPositions = s.positions;
    s.cappedTriangles = s.triangles;
    for (BoundaryLoop& loop : s.loops) {
        loop.capCentre = static_cast<std::uint32_t>(s.cappedPositions.size());
        s.cappedPositions.push_back(loop.centre);
        const std::size_t n = loop.vertices.size();
        for (std::size_t i = 0; i < n; ++i) {
            // The surface runs a -> b along this edge; the cap runs b -> a.
            s.cappedTriangles.push_back(
                {loop.capCentre, loop.vertices[(i + 1) % n], loop.vertices[i]});
        }
    }
}

double signedVolume(const std::vector<glm::dvec3>& p, const std::vector<Triangle>& triangles) {
    double volume = 0.0;
    for (const Triangle& t : triangles) {
        volume += glm::dot(p[t[0]], glm::cross(p[t[1]], p[t[2]]));
    }
    return volume / 6.0;
}

void flipAll(PreparedSurface& s) {
    for (Triangle& t : s.triangles) {
        std::swap(t[1], t[2]);
    }
    for (Triangle& t : s.cappedTriangles) {
        std::swap(t[1], t[2]);
    }
    for (BoundaryLoop& loop : s.loops) {
        std::reverse(loop.vertices.begin(), loop.vertices.end());
        loop.inward = -loop.inward;
    }
}

void computeCappedNormals(PreparedSurface& s) {
    s.cappedNormals.assign(s.cappedPositions.size(), glm::dvec3(0.0));
    for (const Triangle& t : s.cappedTriangles) {
        const glm::dvec3 n = glm::cross(s.cappedPositions[t[1]] - s.cappedPositions[t[0]],
                                        s.cappedPositions[t[2]] - s.cappedPositions[t[0]]);
        for (const std::uint32_t v : t) {
            s.cappedNormals[v] += n;
        }
    }
    for (glm::dvec3& n : s.cappedNormals) {
        const double length = glm::length(n);
        n = length > 0.0 ? n / length : glm::dvec3(0.0);
    }
}

}  // namespace

void movePositions(PreparedSurface& s, std::vector<glm::dvec3> positions) {
    s.positions = std::move(positions);
    for (BoundaryLoop& loop : s.loops) {
        measureLoop(loop, s.positions);
    }
    std::copy(s.positions.begin(), s.positions.end(), s.cappedPositions.begin());
    for (const BoundaryLoop& loop : s.loops) {
        s.cappedPositions[loop.capCentre] = loop.centre;
    }
    computeCappedNormals(s);
    s.diagonalMm = diagonalOf(s.positions);
}

std::string meshLabel(const PreparedSurface& surface) {
    return surface.source.empty() ? surface.name : surface.source.string();
}

PreparedSurface prepareSurface(const scene::Mesh& mesh, const std::optional<glm::dvec3>& anchor,
                               const Progress& progress, std::size_t maxTriangles) {
    checkInput(mesh);
    PreparedSurface s;
    s.source = mesh.source;
    s.name = mesh.name;
    std::vector<std::uint32_t> map;
    const bool coarsened = mesh.triangleCount() > maxTriangles;
    const double cell = coarsened ? clusterCell(mesh, maxTriangles) : 0.0;
    map = coarsened ? cluster(mesh, cell, s.positions) : weld(mesh, s.positions);
    progress.throwIfCancelled();
    std::vector<std::string> cleaning;
    s.triangles = cleanTriangles(mesh, map, s.positions, coarsened ? cleaning : s.notes);
    if (coarsened) {  // the merge's own dropped triangles are its doing, not the file's
        s.notes.push_back("the surface's " + std::to_string(mesh.triangleCount()) +
                          " triangles are more than the analysis needs (at most " +
                          std::to_string(maxTriangles) + "): its points were merged in cubes of " +
                          fixedText(cell, 3) + " mm (each moved at most " +
                          fixedText(cell * std::sqrt(3.0), 3) + " mm), leaving " +
                          std::to_string(s.triangles.size()) + " triangles");
    }
    if (s.triangles.empty()) {
        fail(mesh, "the surface has no triangle with an area");
    }
    keepOnePiece(s, anchor);
    progress.throwIfCancelled();
    const EdgeNeighbours neighbours = edgeNeighbours(s.triangles);
    if (windConsistently(s.triangles, neighbours) > 0) {
        s.notes.emplace_back("Triangles wound against their neighbours were turned round.");
    }
    s.loops = findLoops(s, neighbours);
    for (BoundaryLoop& loop : s.loops) {
        measureLoop(loop, s.positions);
    }
    capLoops(s);
    if (signedVolume(s.cappedPositions, s.cappedTriangles) < 0.0) {
        flipAll(s);
    }
    computeCappedNormals(s);
    s.diagonalMm = diagonalOf(s.positions);
    return s;
}

}  // namespace vv::analysis::detail
