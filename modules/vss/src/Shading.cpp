// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/Shading.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::vss {

IsoLevel isoLevel(float z, int lineCount) {
    if (lineCount < 1) {
        throw InvalidArgumentError("isoLevel: the number of iso-lines must be >= 1, got " +
                                   std::to_string(lineCount));
    }
    IsoLevel level;
    if (!std::isfinite(z)) {
        level.band = -1;
        level.distance = std::numeric_limits<float>::quiet_NaN();
        return level;
    }
    const double s = std::clamp(static_cast<double>(z), 0.0, 1.0) * lineCount;
    level.band = std::min(lineCount - 1, static_cast<int>(std::floor(s)));
    level.distance = static_cast<float>(std::abs(s - std::round(s)));
    return level;
}

namespace {

/// dh along one axis at index i of a line of n samples read by at(j).
template <typename At>
double derivative(int i, int n, const At& at) {
    const double c = at(i);
    const bool left = i > 0 && std::isfinite(at(i - 1));
    const bool right = i + 1 < n && std::isfinite(at(i + 1));
    if (left && right) {
        return 0.5 * (at(i + 1) - at(i - 1));
    }
    if (right) {
        return at(i + 1) - c;
    }
    if (left) {
        return c - at(i - 1);
    }
    return 0.0;
}

}  // namespace

Image<glm::vec3> heightFieldNormals(ImageView<const float> height, double depthScale,
                                    double pixelSize) {
    if (!std::isfinite(depthScale) || depthScale < 0.0) {
        throw InvalidArgumentError("heightFieldNormals: depthScale must be finite and >= 0, got " +
                                   std::to_string(depthScale));
    }
    if (!std::isfinite(pixelSize) || pixelSize <= 0.0) {
        throw InvalidArgumentError("heightFieldNormals: pixelSize must be finite and > 0, got " +
                                   std::to_string(pixelSize));
    }
    const int w = height.width();
    const int h = height.height();
    Image<glm::vec3> normals(w, h, glm::vec3(0.0F, 0.0F, -1.0F));
    const double k = depthScale / pixelSize;
    parallelFor(0, h, 64, [&](long b, long e) {
        for (int y = static_cast<int>(b); y < static_cast<int>(e); ++y) {
            const float* row = height.row(y);
            glm::vec3* n = normals.row(y);
            for (int x = 0; x < w; ++x) {
                if (!std::isfinite(row[x])) {
                    continue;
                }
                const double gx =
                    k * derivative(x, w, [&](int j) { return static_cast<double>(row[j]); });
                const double gy =
                    k * derivative(y, h, [&](int j) { return static_cast<double>(height(x, j)); });
                // Clamped so the squares below stay finite for any input.
                const double cx = std::clamp(std::isnan(gx) ? 0.0 : gx, -1e150, 1e150);
                const double cy = std::clamp(std::isnan(gy) ? 0.0 : gy, -1e150, 1e150);
                const double len = std::sqrt(cx * cx + cy * cy + 1.0);
                n[x] = glm::vec3(static_cast<float>(cx / len), static_cast<float>(cy / len),
                                 static_cast<float>(-1.0 / len));
            }
        }
    });
    return normals;
}

namespace {

constexpr int kFitRadius = 2;  // a 5x5 window

/// exp(-d^2 / 4) for d = -2..2: the fit's Gaussian weight per axis.
constexpr std::array<double, 5> kFitTaps = {0.36787944117144233, 0.77880078307140488, 1.0,
                                            0.77880078307140488, 0.36787944117144233};

/// Weighted sums over the fitted pixels (x, y: offsets from the centre in
/// pixels; h: their heights). Raw sums: the plane's offset drops out below.
struct PlaneMoments {
    double sw = 0.0;
    double sx = 0.0;
    double sy = 0.0;
    double sxx = 0.0;
    double sxy = 0.0;
    double syy = 0.0;
    double sh = 0.0;
    double sxh = 0.0;
    double syh = 0.0;
};

/// The slope of the least-squares plane of `m`, or `fallback` when the sums
/// do not determine one (no pixel, or ill-conditioned).
glm::dvec2 planeSlope(const PlaneMoments& m, glm::dvec2 fallback) {
    if (m.sw <= 0.0) {
        return fallback;
    }
    const double cxx = m.sxx - m.sx * m.sx / m.sw;
    const double cxy = m.sxy - m.sx * m.sy / m.sw;
    const double cyy = m.syy - m.sy * m.sy / m.sw;
    const double cxh = m.sxh - m.sx * m.sh / m.sw;
    const double cyh = m.syh - m.sy * m.sh / m.sw;
    const double det = cxx * cyy - cxy * cxy;
    if (!(det >= 0.05 * std::max(cxx * cyy, 1e-12))) {
        return fallback;
    }
    return {(cyy * cxh - cxy * cyh) / det, (cxx * cyh - cxy * cxh) / det};
}

/// True where the plane fit may use the pixel: a void pixel with a VSS.
bool fittable(ImageView<const float> height, ImageView<const std::uint8_t> vessels, int x, int y) {
    return vessels(x, y) == 0 && std::isfinite(height(x, y));
}

/// The plane fit over the 5x5 window of samples `stride` pixels apart,
/// summed directly (for the few pixels that need the wide window).
glm::dvec2 directSlope(ImageView<const float> height, ImageView<const std::uint8_t> vessels, int px,
                       int py, int stride, glm::dvec2 fallback) {
    PlaneMoments m;
    for (int dy = -kFitRadius; dy <= kFitRadius; ++dy) {
        const int y = py + dy * stride;
        if (y < 0 || y >= height.height()) {
            continue;
        }
        for (int dx = -kFitRadius; dx <= kFitRadius; ++dx) {
            const int x = px + dx * stride;
            if (x < 0 || x >= height.width() || !fittable(height, vessels, x, y)) {
                continue;
            }
            const double w = kFitTaps[static_cast<std::size_t>(dx + kFitRadius)] *
                             kFitTaps[static_cast<std::size_t>(dy + kFitRadius)];
            const double ox = dx * stride;
            const double oy = dy * stride;
            const double hv = height(x, y);
            m.sw += w;
            m.sx += w * ox;
            m.sy += w * oy;
            m.sxx += w * ox * ox;
            m.sxy += w * ox * oy;
            m.syy += w * oy * oy;
            m.sh += w * hv;
            m.sxh += w * ox * hv;
            m.syh += w * oy * hv;
        }
    }
    return planeSlope(m, fallback);
}

/// Per-row sums along x of the separable fit (structure of arrays).
struct RowSums {
    std::vector<double> a0, a1, a2, h0, h1;  // sum g m {1, dx, dx^2, h, dx h}
    void resize(std::size_t n) {
        for (auto* v : {&a0, &a1, &a2, &h0, &h1}) {
            v->assign(n, 0.0);
        }
    }
};

}  // namespace

Image<glm::vec4> fittedSlopes(ImageView<const float> height, ImageView<const std::uint8_t> vessels,
                              const std::stop_token& stop) {
    if (height.width() != vessels.width() || height.height() != vessels.height()) {
        throw InvalidArgumentError(
            "fittedSlopes: the vessel mask is " + std::to_string(vessels.width()) + "x" +
            std::to_string(vessels.height()) + ", the height " + std::to_string(height.width()) +
            "x" + std::to_string(height.height()));
    }
    const int w = height.width();
    const int h = height.height();
    Image<glm::vec4> slopes(w, h, glm::vec4(0.0F));
    if (w == 0 || h == 0) {
        return slopes;
    }
    // The in-image weight along x of each column's window.
    std::vector<double> columnTotal(static_cast<std::size_t>(w), 0.0);
    for (int x = 0; x < w; ++x) {
        for (int dx = -kFitRadius; dx <= kFitRadius; ++dx) {
            if (x + dx >= 0 && x + dx < w) {
                columnTotal[static_cast<std::size_t>(x)] +=
                    kFitTaps[static_cast<std::size_t>(dx + kFitRadius)];
            }
        }
    }
    constexpr long kBand = 32;
    parallelFor(
        0, h, kBand,
        [&](long begin, long end) {
            const int y0 = static_cast<int>(begin);
            const int y1 = static_cast<int>(end);
            // Rows y0 - 2 .. y1 + 1 (inside the image) summed along x.
            const int r0 = std::max(0, y0 - kFitRadius);
            const int r1 = std::min(h, y1 + kFitRadius);
            RowSums sums;
            sums.resize(static_cast<std::size_t>(r1 - r0) * static_cast<std::size_t>(w));
            std::vector<double> m(static_cast<std::size_t>(w));
            std::vector<double> mh(static_cast<std::size_t>(w));
            for (int r = r0; r < r1; ++r) {
                const float* hr = height.row(r);
                const std::uint8_t* vr = vessels.row(r);
                for (int x = 0; x < w; ++x) {
                    const bool fit = vr[x] == 0 && std::isfinite(hr[x]);
                    m[static_cast<std::size_t>(x)] = fit ? 1.0 : 0.0;
                    mh[static_cast<std::size_t>(x)] = fit ? static_cast<double>(hr[x]) : 0.0;
                }
                const std::size_t base =
                    static_cast<std::size_t>(r - r0) * static_cast<std::size_t>(w);
                for (int x = 0; x < w; ++x) {
                    double a0 = 0.0;
                    double a1 = 0.0;
                    double a2 = 0.0;
                    double h0 = 0.0;
                    double h1 = 0.0;
                    const int lo = std::max(-kFitRadius, -x);
                    const int hi = std::min(kFitRadius, w - 1 - x);
                    for (int dx = lo; dx <= hi; ++dx) {
                        const auto q = static_cast<std::size_t>(x + dx);
                        const double g = kFitTaps[static_cast<std::size_t>(dx + kFitRadius)];
                        const double gm = g * m[q];
                        const double gh = g * mh[q];
                        a0 += gm;
                        a1 += gm * dx;
                        a2 += gm * dx * dx;
                        h0 += gh;
                        h1 += gh * dx;
                    }
                    sums.a0[base + static_cast<std::size_t>(x)] = a0;
                    sums.a1[base + static_cast<std::size_t>(x)] = a1;
                    sums.a2[base + static_cast<std::size_t>(x)] = a2;
                    sums.h0[base + static_cast<std::size_t>(x)] = h0;
                    sums.h1[base + static_cast<std::size_t>(x)] = h1;
                }
            }
            for (int y = y0; y < y1; ++y) {
                if (stop.stop_requested()) {
                    return;  // parallelFor throws CancelledError
                }
                const float* hr = height.row(y);
                const std::uint8_t* vr = vessels.row(y);
                glm::vec4* out = slopes.row(y);
                const int lo = std::max(-kFitRadius, -y);
                const int hi = std::min(kFitRadius, h - 1 - y);
                double rowTotal = 0.0;
                for (int dy = lo; dy <= hi; ++dy) {
                    rowTotal += kFitTaps[static_cast<std::size_t>(dy + kFitRadius)];
                }
                for (int x = 0; x < w; ++x) {
                    if (vr[x] != 0 || !std::isfinite(hr[x])) {
                        continue;  // vessel or no VSS: (0, 0, 0, 0)
                    }
                    PlaneMoments pm;
                    for (int dy = lo; dy <= hi; ++dy) {
                        const double g = kFitTaps[static_cast<std::size_t>(dy + kFitRadius)];
                        const std::size_t i =
                            static_cast<std::size_t>(y + dy - r0) * static_cast<std::size_t>(w) +
                            static_cast<std::size_t>(x);
                        const double a0 = g * sums.a0[i];
                        const double a1 = g * sums.a1[i];
                        const double h0 = g * sums.h0[i];
                        pm.sw += a0;
                        pm.sx += a1;
                        pm.sy += a0 * dy;
                        pm.sxx += g * sums.a2[i];
                        pm.sxy += a1 * dy;
                        pm.syy += a0 * dy * dy;
                        pm.sh += h0;
                        pm.sxh += g * sums.h1[i];
                        pm.syh += h0 * dy;
                    }
                    const double total = columnTotal[static_cast<std::size_t>(x)] * rowTotal;
                    const double support = total > 0.0 ? pm.sw / total : 0.0;
                    // The one-pixel difference (vessel neighbours count here).
                    const glm::dvec2 difference(
                        derivative(x, w, [&](int j) { return static_cast<double>(hr[j]); }),
                        derivative(y, h, [&](int j) { return static_cast<double>(height(x, j)); }));
                    glm::dvec2 slope = planeSlope(pm, difference);
                    if (support < 0.999) {
                        // Next to a contour: the wider window over the staircase.
                        slope = directSlope(height, vessels, x, y, 2, slope);
                    }
                    out[x] = glm::vec4(static_cast<float>(slope.x), static_cast<float>(slope.y),
                                       static_cast<float>(support), 1.0F);
                }
            }
        },
        stop);
    if (stop.stop_requested()) {
        throw CancelledError();
    }
    return slopes;
}

void addNormalCoherence(Image<glm::vec4>& slopes, ImageView<const float> height,
                        ImageView<const std::uint8_t> vessels, const SlopeScale& scale) {
    const int w = height.width();
    const int h = height.height();
    if (slopes.width() != w || slopes.height() != h || vessels.width() != w ||
        vessels.height() != h) {
        throw InvalidArgumentError(
            "addNormalCoherence: slopes, height and vessel mask differ in size");
    }
    if (!std::isfinite(scale.dmin) || !std::isfinite(scale.dmax) ||
        !std::isfinite(scale.pixelScale) || scale.pixelScale <= 0.0) {
        throw InvalidArgumentError(
            "addNormalCoherence: needs a finite depth range and pixelScale > 0");
    }
    const double range = std::max(scale.dmax - scale.dmin, 0.0);
    const auto unit = [](double gx, double gy) {
        const double len = std::sqrt(gx * gx + gy * gy + 1.0);
        return glm::dvec3(gx / len, gy / len, 1.0 / len);
    };
    constexpr std::array<std::array<int, 2>, 4> kAround = {{{3, 0}, {-3, 0}, {0, 3}, {0, -3}}};
    parallelFor(0, h, 32, [&](long begin, long end) {
        for (int y = static_cast<int>(begin); y < static_cast<int>(end); ++y) {
            glm::vec4* out = slopes.row(y);
            for (int x = 0; x < w; ++x) {
                if (out[x].w == 0.0F) {
                    continue;
                }
                const double t = std::clamp(static_cast<double>(height(x, y)), 0.0, 1.0);
                const double pixel = std::max((scale.dmin + t * range) * scale.pixelScale, 1e-12);
                const double k = range / pixel;
                glm::dvec3 sum = unit(out[x].x * k, out[x].y * k);
                double count = 1.0;
                for (const auto& o : kAround) {
                    const int qx = x + o[0];
                    const int qy = y + o[1];
                    if (qx < 1 || qy < 1 || qx >= w - 1 || qy >= h - 1) {
                        continue;  // off the image: left out
                    }
                    count += 1.0;
                    const float c = height(qx, qy);
                    const float xm = height(qx - 1, qy);
                    const float xp = height(qx + 1, qy);
                    const float ym = height(qx, qy - 1);
                    const float yp = height(qx, qy + 1);
                    if (vessels(qx, qy) != 0 || !std::isfinite(c) || !std::isfinite(xm) ||
                        !std::isfinite(xp) || !std::isfinite(ym) || !std::isfinite(yp)) {
                        continue;  // no normal there: a zero one
                    }
                    sum += unit(0.5 * (static_cast<double>(xp) - xm) * k,
                                0.5 * (static_cast<double>(yp) - ym) * k);
                }
                out[x].w = static_cast<float>(std::clamp(glm::length(sum) / count, 1e-3, 1.0));
            }
        }
    });
}

}  // namespace vv::vss
