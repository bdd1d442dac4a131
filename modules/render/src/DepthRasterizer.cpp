// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/DepthRasterizer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::render {

namespace {

constexpr int kMaxSide = 32768;
/// Tiles are the unit of parallel work; their size does not change the result.
constexpr int kTileSize = 32;
/// Triangles are set up in fixed blocks (not per thread), so the order of the
/// set-up list never depends on the thread count.
constexpr std::size_t kSetupBlock = 8192;

/// A vertex in clip space with its linear view depth.
struct ClipVertex {
    glm::dvec4 clip;
    double depth = 0.0;
};

/// An edge function on a canonically ordered edge: value(p) = sign * ((b - a) x (p - a))
/// with a before b in (y, x) order. Two triangles sharing the edge evaluate the
/// same product and differ only in sign, so a pixel centre exactly on the edge
/// goes to exactly one of them (the one with sign > 0).
struct Edge {
    double ax = 0.0;
    double ay = 0.0;
    double dx = 0.0;
    double dy = 0.0;
    double sign = 1.0;

    [[nodiscard]] bool covers(double px, double py) const noexcept {
        const double e = sign * (dx * (py - ay) - dy * (px - ax));
        return e > 0.0 || (e == 0.0 && sign > 0.0);
    }
};

Edge makeEdge(const glm::dvec2& from, const glm::dvec2& to) noexcept {
    const bool swapped = from.y > to.y || (from.y == to.y && from.x > to.x);
    const glm::dvec2& a = swapped ? to : from;
    const glm::dvec2& b = swapped ? from : to;
    return Edge{a.x, a.y, b.x - a.x, b.y - a.y, swapped ? -1.0 : 1.0};
}

/// A screen-space triangle ready to rasterise.
struct SetupTriangle {
    std::array<Edge, 3> edges;
    // Two planes over the screen: f(p) = f0 + fx (px - x0) + fy (py - y0) for
    // 1 / w and for depth / w; both are affine in screen space.
    double x0 = 0.0;
    double y0 = 0.0;
    double inv0 = 0.0;
    double invX = 0.0;
    double invY = 0.0;
    double dep0 = 0.0;
    double depX = 0.0;
    double depY = 0.0;
    // Inclusive pixel range of its bounding box, inside the image.
    int minX = 0;
    int minY = 0;
    int maxX = -1;
    int maxY = -1;
};

struct Viewport {
    int width = 0;
    int height = 0;
};

/// Sets up the screen triangle of three clip vertices in front of the near
/// plane; appends nothing when it is degenerate, not finite or off-screen.
void setupTriangle(const ClipVertex& c0, const ClipVertex& c1, const ClipVertex& c2,
                   const Viewport& vp, std::vector<SetupTriangle>& out) {
    std::array<const ClipVertex*, 3> v{&c0, &c1, &c2};
    std::array<glm::dvec2, 3> s{};
    std::array<double, 3> inv{};
    std::array<double, 3> dep{};
    const double w = vp.width;
    const double h = vp.height;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec4& c = v[static_cast<std::size_t>(i)]->clip;
        if (!(c.w > 0.0)) {
            return;
        }
        const double iw = 1.0 / c.w;
        s[static_cast<std::size_t>(i)] = {(c.x * iw * 0.5 + 0.5) * w, (0.5 - c.y * iw * 0.5) * h};
        inv[static_cast<std::size_t>(i)] = iw;
        dep[static_cast<std::size_t>(i)] = v[static_cast<std::size_t>(i)]->depth * iw;
        if (!std::isfinite(s[static_cast<std::size_t>(i)].x) ||
            !std::isfinite(s[static_cast<std::size_t>(i)].y) ||
            !std::isfinite(dep[static_cast<std::size_t>(i)])) {
            return;
        }
    }
    double area2 = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y);
    if (!(area2 != 0.0) || !std::isfinite(area2)) {
        return;
    }
    if (area2 < 0.0) {
        // One winding for all: interior points have positive edge functions.
        std::swap(s[1], s[2]);
        std::swap(inv[1], inv[2]);
        std::swap(dep[1], dep[2]);
        area2 = -area2;
    }
    const double minXf = std::min({s[0].x, s[1].x, s[2].x});
    const double maxXf = std::max({s[0].x, s[1].x, s[2].x});
    const double minYf = std::min({s[0].y, s[1].y, s[2].y});
    const double maxYf = std::max({s[0].y, s[1].y, s[2].y});
    // Pixel x is sampled at x + 0.5: the covered columns are ceil(min - 0.5) .. floor(max - 0.5).
    const double lastX = w - 1.0;
    const double lastY = h - 1.0;
    const double x0 = std::clamp(std::ceil(minXf - 0.5), 0.0, w);
    const double x1 = std::clamp(std::floor(maxXf - 0.5), -1.0, lastX);
    const double y0 = std::clamp(std::ceil(minYf - 0.5), 0.0, h);
    const double y1 = std::clamp(std::floor(maxYf - 0.5), -1.0, lastY);
    if (x0 > x1 || y0 > y1) {
        return;
    }
    SetupTriangle t;
    t.minX = static_cast<int>(x0);
    t.maxX = static_cast<int>(x1);
    t.minY = static_cast<int>(y0);
    t.maxY = static_cast<int>(y1);
    t.edges = {makeEdge(s[0], s[1]), makeEdge(s[1], s[2]), makeEdge(s[2], s[0])};
    const double ax = s[1].x - s[0].x;
    const double ay = s[1].y - s[0].y;
    const double bx = s[2].x - s[0].x;
    const double by = s[2].y - s[0].y;
    const auto gradient = [&](const std::array<double, 3>& f, double& gx, double& gy) {
        const double f1 = f[1] - f[0];
        const double f2 = f[2] - f[0];
        gx = (f1 * by - f2 * ay) / area2;
        gy = (f2 * ax - f1 * bx) / area2;
    };
    t.x0 = s[0].x;
    t.y0 = s[0].y;
    t.inv0 = inv[0];
    t.dep0 = dep[0];
    gradient(inv, t.invX, t.invY);
    gradient(dep, t.depX, t.depY);
    if (!std::isfinite(t.invX) || !std::isfinite(t.invY) || !std::isfinite(t.depX) ||
        !std::isfinite(t.depY)) {
        return;
    }
    out.push_back(t);
}

/// Clips a triangle against the near plane (z + w >= 0, OpenGL clip space) and
/// sets up the one or two triangles that remain.
void clipAndSetup(const std::array<ClipVertex, 3>& tri, const Viewport& vp,
                  std::vector<SetupTriangle>& out) {
    std::array<double, 3> dist{};
    int inside = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        dist[i] = tri[i].clip.z + tri[i].clip.w;
        if (!std::isfinite(dist[i]) || !std::isfinite(tri[i].clip.x) ||
            !std::isfinite(tri[i].clip.y) || !std::isfinite(tri[i].depth)) {
            return;
        }
        inside += dist[i] >= 0.0 ? 1 : 0;
    }
    if (inside == 3) {
        setupTriangle(tri[0], tri[1], tri[2], vp, out);
        return;
    }
    if (inside == 0) {
        return;
    }
    // Sutherland-Hodgman against one plane: a triangle becomes a triangle or a quad.
    std::array<ClipVertex, 4> poly{};
    int n = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t j = (i + 1) % 3;
        const bool inI = dist[i] >= 0.0;
        const bool inJ = dist[j] >= 0.0;
        if (inI) {
            poly[static_cast<std::size_t>(n++)] = tri[i];
        }
        if (inI != inJ) {
            const double t = dist[i] / (dist[i] - dist[j]);
            ClipVertex c;
            c.clip = tri[i].clip + t * (tri[j].clip - tri[i].clip);
            c.depth = tri[i].depth + t * (tri[j].depth - tri[i].depth);
            poly[static_cast<std::size_t>(n++)] = c;
        }
    }
    for (int k = 1; k + 1 < n; ++k) {
        setupTriangle(poly[0], poly[static_cast<std::size_t>(k)],
                      poly[static_cast<std::size_t>(k + 1)], vp, out);
    }
}

void checkSize(int width, int height) {
    if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) {
        throw InvalidArgumentError("rasterizeDepth: image size must be within 1x1.." +
                                   std::to_string(kMaxSide) + "x" + std::to_string(kMaxSide) +
                                   ", got " + std::to_string(width) + "x" + std::to_string(height));
    }
}

}  // namespace

Image<float> rasterizeDepth(std::span<const TriangleList> lists, const glm::mat4& view,
                            const glm::mat4& projection, int width, int height,
                            const std::stop_token& stop) {
    checkSize(width, height);
    // Validate before any parallel work, so the error does not depend on threads.
    std::vector<std::size_t> firstTriangle;  // prefix sums of triangle counts per list
    firstTriangle.reserve(lists.size() + 1);
    firstTriangle.push_back(0);
    for (std::size_t l = 0; l < lists.size(); ++l) {
        const TriangleList& list = lists[l];
        if (list.indices.size() % 3 != 0) {
            throw InvalidArgumentError("rasterizeDepth: triangle list " + std::to_string(l) +
                                       " has " + std::to_string(list.indices.size()) +
                                       " indices, not a multiple of 3");
        }
        const std::size_t count = list.positions.size();
        for (const std::uint32_t index : list.indices) {
            if (index >= count) {
                throw InvalidArgumentError("rasterizeDepth: triangle list " + std::to_string(l) +
                                           " has index " + std::to_string(index) + " but only " +
                                           std::to_string(count) + " positions");
            }
        }
        firstTriangle.push_back(firstTriangle.back() + list.indices.size() / 3);
    }
    const std::size_t triangleCount = firstTriangle.back();

    const glm::dmat4 viewD(view);
    const glm::dmat4 projectionD(projection);
    const Viewport vp{width, height};

    // 1. Transform, clip and set up triangles in fixed blocks.
    const std::size_t blockCount = (triangleCount + kSetupBlock - 1) / kSetupBlock;
    std::vector<std::vector<SetupTriangle>> blocks(blockCount);
    parallelFor(
        0, static_cast<long>(blockCount), 1,
        [&](long b0, long b1) {
            for (long b = b0; b < b1; ++b) {
                const std::size_t begin = static_cast<std::size_t>(b) * kSetupBlock;
                const std::size_t end = std::min(triangleCount, begin + kSetupBlock);
                std::vector<SetupTriangle>& out = blocks[static_cast<std::size_t>(b)];
                out.reserve(end - begin);
                std::size_t l = static_cast<std::size_t>(
                    std::upper_bound(firstTriangle.begin(), firstTriangle.end(), begin) -
                    firstTriangle.begin() - 1);
                for (std::size_t t = begin; t < end; ++t) {
                    while (t >= firstTriangle[l + 1]) {
                        ++l;
                    }
                    const TriangleList& list = lists[l];
                    const std::size_t local = t - firstTriangle[l];
                    std::array<ClipVertex, 3> tri{};
                    for (std::size_t k = 0; k < 3; ++k) {
                        const glm::vec3& p = list.positions[list.indices[3 * local + k]];
                        const glm::dvec4 eye = viewD * glm::dvec4(p, 1.0);
                        tri[k].clip = projectionD * eye;
                        tri[k].depth = -eye.z;
                    }
                    clipAndSetup(tri, vp, out);
                }
            }
        },
        stop);

    std::vector<SetupTriangle> triangles;
    {
        std::size_t total = 0;
        for (const auto& b : blocks) {
            total += b.size();
        }
        triangles.reserve(total);
        for (auto& b : blocks) {
            triangles.insert(triangles.end(), b.begin(), b.end());
            std::vector<SetupTriangle>().swap(b);
        }
    }

    // 2. Bin triangles into tiles (in triangle order).
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    std::vector<std::vector<std::uint32_t>> bins(static_cast<std::size_t>(tilesX) *
                                                 static_cast<std::size_t>(tilesY));
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const SetupTriangle& t = triangles[i];
        for (int ty = t.minY / kTileSize; ty <= t.maxY / kTileSize; ++ty) {
            for (int tx = t.minX / kTileSize; tx <= t.maxX / kTileSize; ++tx) {
                bins[static_cast<std::size_t>(ty) * static_cast<std::size_t>(tilesX) +
                     static_cast<std::size_t>(tx)]
                    .push_back(static_cast<std::uint32_t>(i));
            }
        }
    }
    if (stop.stop_requested()) {
        throw CancelledError();
    }

    // 3. Rasterise every tile: each pixel belongs to one tile, so tiles never race.
    Image<float> depth(width, height, std::numeric_limits<float>::infinity());
    const ImageView<float> out = depth.view();
    parallelForTiles(
        width, height, kTileSize,
        [&](const Tile& tile) {
            const auto& bin = bins[static_cast<std::size_t>(tile.y0 / kTileSize) *
                                       static_cast<std::size_t>(tilesX) +
                                   static_cast<std::size_t>(tile.x0 / kTileSize)];
            for (const std::uint32_t index : bin) {
                const SetupTriangle& t = triangles[index];
                const int xb = std::max(t.minX, tile.x0);
                const int xe = std::min(t.maxX + 1, tile.x1);
                const int yb = std::max(t.minY, tile.y0);
                const int ye = std::min(t.maxY + 1, tile.y1);
                for (int y = yb; y < ye; ++y) {
                    const double py = y + 0.5;
                    float* row = out.row(y);
                    for (int x = xb; x < xe; ++x) {
                        const double px = x + 0.5;
                        if (!t.edges[0].covers(px, py) || !t.edges[1].covers(px, py) ||
                            !t.edges[2].covers(px, py)) {
                            continue;
                        }
                        const double ddx = px - t.x0;
                        const double ddy = py - t.y0;
                        const double inv = t.inv0 + t.invX * ddx + t.invY * ddy;
                        if (!(inv > 0.0)) {
                            continue;
                        }
                        const double d = (t.dep0 + t.depX * ddx + t.depY * ddy) / inv;
                        const auto df = static_cast<float>(d);
                        if (df < row[x]) {
                            row[x] = df;
                        }
                    }
                }
            }
        },
        stop);
    return depth;
}

Image<float> rasterizeDepth(const scene::Scene& scene, const Camera& camera,
                            const std::stop_token& stop) {
    std::vector<TriangleList> lists;
    lists.reserve(scene.meshes.size());
    for (const scene::Mesh& mesh : scene.meshes) {
        lists.push_back(TriangleList{mesh.positions, mesh.indices});
    }
    return rasterizeDepth(lists, camera.viewMatrix(), camera.projectionMatrix(),
                          camera.viewportWidth(), camera.viewportHeight(), stop);
}

}  // namespace vv::render
