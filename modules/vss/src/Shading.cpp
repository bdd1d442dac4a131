// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/vss/Shading.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ContourSamples.h"
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

using detail::kContourReach;
using detail::kContourStride;
using detail::nearGaps;
using detail::SampleRing;

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

/// The slope of the least-squares plane of `m`, or nothing when the sums do
/// not determine one (no pixel, or ill-conditioned).
std::optional<glm::dvec2> planeSlope(const PlaneMoments& m) {
    if (m.sw <= 0.0) {
        return std::nullopt;
    }
    // One division each for 1 / sw and 1 / det: divisions dominate this
    // function's cost, and it runs on every void pixel.
    const double inv = 1.0 / m.sw;
    const double mx = m.sx * inv;
    const double my = m.sy * inv;
    const double cxx = m.sxx - m.sx * mx;
    const double cxy = m.sxy - m.sx * my;
    const double cyy = m.syy - m.sy * my;
    const double cxh = m.sxh - mx * m.sh;
    const double cyh = m.syh - my * m.sh;
    const double det = cxx * cyy - cxy * cxy;
    if (!(det >= 0.05 * std::max(cxx * cyy, 1e-12))) {
        return std::nullopt;
    }
    const double invDet = 1.0 / det;
    return glm::dvec2((cyy * cxh - cxy * cyh) * invDet, (cxx * cyh - cxy * cxh) * invDet);
}

/// The plane fit over the 5x5 window of `samples` (SampleRing) `stride`
/// pixels apart, summed directly (for the pixels next to contours);
/// `support` receives the window's support.
std::optional<glm::dvec2> directSlope(const SampleRing& samples, int px, int py, int stride,
                                      double& support) {
    PlaneMoments m;
    double total = 0.0;
    for (int dy = -kFitRadius; dy <= kFitRadius; ++dy) {
        const int y = py + dy * stride;
        if (y < 0 || y >= samples.height()) {
            continue;
        }
        for (int dx = -kFitRadius; dx <= kFitRadius; ++dx) {
            const int x = px + dx * stride;
            if (x < 0 || x >= samples.width()) {
                continue;
            }
            const double w = kFitTaps[static_cast<std::size_t>(dx + kFitRadius)] *
                             kFitTaps[static_cast<std::size_t>(dy + kFitRadius)];
            total += w;
            const glm::vec3 q = samples.row(y)[x];
            if (!std::isfinite(q.z)) {
                continue;  // not fittable
            }
            const double ox = dx * stride + static_cast<double>(q.x);
            const double oy = dy * stride + static_cast<double>(q.y);
            const double hv = q.z;
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
    support = total > 0.0 ? m.sw / total : 0.0;
    return planeSlope(m);
}

/// The separable fit's sums along x of the rows a band needs, five rows at a
/// time: row r lives in slot r mod 5, so each row is summed once per band
/// and the ring stays in cache (whole-band buffers of a 4K frame were
/// megabytes per band, allocated and page-faulted again for every band).
class RowSumRing {
  public:
    explicit RowSumRing(int width)
        : width_(static_cast<std::size_t>(width)),
          sums_(kRows * kArrays * width_, 0.0),
          mask_(width_ + 2 * kFitRadius, 0.0),
          maskedHeight_(width_ + 2 * kFitRadius, 0.0) {}

    /// sum g m {1, dx, dx^2, h, dx h} of row r (index 0..4), r any integer.
    [[nodiscard]] const double* sum(int r, int index) const {
        return sums_.data() + (slot(r) * kArrays + static_cast<std::size_t>(index)) * width_;
    }

    /// Sums row r of the image into its slot; zeros for rows outside it.
    void load(ImageView<const float> height, ImageView<const std::uint8_t> vessels, int r) {
        double* out = sums_.data() + slot(r) * kArrays * width_;
        if (r < 0 || r >= height.height()) {
            std::fill(out, out + kArrays * width_, 0.0);
            return;
        }
        const float* hr = height.row(r);
        const std::uint8_t* vr = vessels.row(r);
        // Padded with two zero columns on either side, so the loop needs
        // no bounds (a zero term changes no sum).
        for (std::size_t x = 0; x < width_; ++x) {
            const bool fit = vr[x] == 0 && std::isfinite(hr[x]);
            mask_[x + kFitRadius] = fit ? 1.0 : 0.0;
            maskedHeight_[x + kFitRadius] = fit ? static_cast<double>(hr[x]) : 0.0;
        }
        double* a0 = out;
        double* a1 = out + width_;
        double* a2 = out + 2 * width_;
        double* h0 = out + 3 * width_;
        double* h1 = out + 4 * width_;
        const double* mp = mask_.data();
        const double* hp = maskedHeight_.data();
        const std::size_t n = width_;
#pragma omp simd
        for (std::size_t x = 0; x < n; ++x) {
            double s0 = 0.0;
            double s1 = 0.0;
            double s2 = 0.0;
            double t0 = 0.0;
            double t1 = 0.0;
            for (int k = 0; k <= 2 * kFitRadius; ++k) {
                const double dx = k - kFitRadius;
                const double g = kFitTaps[static_cast<std::size_t>(k)];
                const double gm = g * mp[x + static_cast<std::size_t>(k)];
                const double gh = g * hp[x + static_cast<std::size_t>(k)];
                s0 += gm;
                s1 += gm * dx;
                s2 += gm * dx * dx;
                t0 += gh;
                t1 += gh * dx;
            }
            a0[x] = s0;
            a1[x] = s1;
            a2[x] = s2;
            h0[x] = t0;
            h1[x] = t1;
        }
    }

  private:
    static constexpr std::size_t kRows = 2 * kFitRadius + 1;
    static constexpr std::size_t kArrays = 5;
    [[nodiscard]] static std::size_t slot(int r) {
        return static_cast<std::size_t>(((r % 5) + 5) % 5);
    }
    std::size_t width_;
    std::vector<double> sums_;
    std::vector<double> mask_;
    std::vector<double> maskedHeight_;
};

/// One image row's PlaneMoments, one entry per pixel (structure of arrays,
/// so the sums and the plane solve run as vector loops).
struct RowFits {
    std::vector<double> sw, sx, sy, sxx, sxy, syy, sh, sxh, syh;
    std::vector<double> slopeX, slopeY;
    std::vector<std::uint8_t> fitted;  // 1 where planeSlope() would give a slope
    explicit RowFits(std::size_t n) {
        for (auto* v : {&sw, &sx, &sy, &sxx, &sxy, &syy, &sh, &sxh, &syh, &slopeX, &slopeY}) {
            v->assign(n, 0.0);
        }
        fitted.assign(n, 0);
    }

    /// The PlaneMoments of each pixel of row y from the row sums of rows
    /// y - 2 .. y + 2, then planeSlope() of each, branch-free: the same
    /// operations in the same order, so the same bits.
    void fit(const RowSumRing& ring, int y) {
        for (auto* v : {&sw, &sx, &sy, &sxx, &sxy, &syy, &sh, &sxh, &syh}) {
            std::fill(v->begin(), v->end(), 0.0);
        }
        const std::size_t n = sw.size();
        for (int dy = -kFitRadius; dy <= kFitRadius; ++dy) {
            const double g = kFitTaps[static_cast<std::size_t>(dy + kFitRadius)];
            const double* a0 = ring.sum(y + dy, 0);
            const double* a1 = ring.sum(y + dy, 1);
            const double* a2 = ring.sum(y + dy, 2);
            const double* h0 = ring.sum(y + dy, 3);
            const double* h1 = ring.sum(y + dy, 4);
            const double fy = dy;
#pragma omp simd
            for (std::size_t x = 0; x < n; ++x) {
                const double b0 = g * a0[x];
                const double b1 = g * a1[x];
                const double c0 = g * h0[x];
                sw[x] += b0;
                sx[x] += b1;
                sy[x] += b0 * fy;
                sxx[x] += g * a2[x];
                sxy[x] += b1 * fy;
                syy[x] += b0 * fy * fy;
                sh[x] += c0;
                sxh[x] += g * h1[x];
                syh[x] += c0 * fy;
            }
        }
#pragma omp simd
        for (std::size_t i = 0; i < n; ++i) {
            const bool some = sw[i] > 0.0;
            const double inv = 1.0 / (some ? sw[i] : 1.0);
            const double mx = sx[i] * inv;
            const double my = sy[i] * inv;
            const double cxx = sxx[i] - sx[i] * mx;
            const double cxy = sxy[i] - sx[i] * my;
            const double cyy = syy[i] - sy[i] * my;
            const double cxh = sxh[i] - mx * sh[i];
            const double cyh = syh[i] - my * sh[i];
            const double det = cxx * cyy - cxy * cxy;
            const double product = cxx * cyy;
            const bool ok = some && det >= 0.05 * (product < 1e-12 ? 1e-12 : product);
            const double invDet = 1.0 / (ok ? det : 1.0);
            slopeX[i] = (cyy * cxh - cxy * cyh) * invDet;
            slopeY[i] = (cxx * cyh - cxy * cxh) * invDet;
            fitted[i] = ok ? 1 : 0;
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
    // Every pixel is written below, by the band that owns its row.
    Image<glm::vec4> slopes(w, h, UninitialisedPixels{});
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
    const Image<std::uint8_t> nearContour = nearGaps(height, vessels);
    // Bands of 64 rows: each sums 4 rows beyond its own again.
    constexpr long kBand = 64;
    parallelFor(
        0, h, kBand,
        [&](long begin, long end) {
            const int y0 = static_cast<int>(begin);
            const int y1 = static_cast<int>(end);
            const auto uw = static_cast<std::size_t>(w);
            RowSumRing ring(w);
            for (int r = y0 - kFitRadius; r < y0 + kFitRadius; ++r) {
                ring.load(height, vessels, r);
            }
            RowFits pm(uw);
            // The wide fit's sample rows y - kContourReach .. y + kContourReach.
            SampleRing samples(height, vessels);
            samples.start(y0 - kContourReach);
            for (int j = y0 - kContourReach; j < y0 + kContourReach; ++j) {
                samples.advance(j);
            }
            for (int y = y0; y < y1; ++y) {
                if (stop.stop_requested()) {
                    return;  // parallelFor throws CancelledError
                }
                const float* hr = height.row(y);
                const std::uint8_t* vr = vessels.row(y);
                glm::vec4* out = slopes.row(y);
                double rowTotal = 0.0;
                for (int dy = -kFitRadius; dy <= kFitRadius; ++dy) {
                    if (y + dy >= 0 && y + dy < h) {
                        rowTotal += kFitTaps[static_cast<std::size_t>(dy + kFitRadius)];
                    }
                }
                ring.load(height, vessels, y + kFitRadius);
                pm.fit(ring, y);
                samples.advance(y + kContourReach);
                for (int x = 0; x < w; ++x) {
                    if (vr[x] != 0 || !std::isfinite(hr[x])) {
                        out[x] = glm::vec4(0.0F);  // vessel or no VSS
                        continue;
                    }
                    const auto i = static_cast<std::size_t>(x);
                    const double total = columnTotal[i] * rowTotal;
                    const double support = total > 0.0 ? pm.sw[i] / total : 0.0;
                    std::optional<glm::dvec2> fit;
                    if (pm.fitted[i] != 0) {
                        fit = glm::dvec2(pm.slopeX[i], pm.slopeY[i]);
                    }
                    if (nearContour(x, y) != 0) {
                        // Next to a contour: the wider window over the staircase.
                        double wideSupport = 1.0;
                        const std::optional<glm::dvec2> wide =
                            directSlope(samples, x, y, kContourStride, wideSupport);
                        if (wide && wideSupport < 0.999) {
                            fit = wide;
                        }
                    }
                    // Else the one-pixel difference (vessel neighbours count here).
                    const glm::dvec2 slope =
                        fit ? *fit
                            : glm::dvec2(
                                  derivative(x, w,
                                             [&](int j) { return static_cast<double>(hr[j]); }),
                                  derivative(y, h, [&](int j) {
                                      return static_cast<double>(height(x, j));
                                  }));
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

namespace {

constexpr int kCoherenceReach = 3;  // the neighbours are 3 pixels away

/// The central differences of the VSS that the coherence reads, as planes
/// x, y and a weight (1 where the pixel has a normal, 0 where it has none:
/// a vessel, no VSS at it or a neighbour, or within a pixel of the border;
/// its difference stays 0), for the 2 * reach + 1 rows around the current
/// one: row r lives in slot r mod 7, so each row is differenced once per band
/// and nothing of the image's size is allocated.
class DiffRing {
  public:
    explicit DiffRing(int width)
        : width_(static_cast<std::size_t>(width)), planes_(kRows * 3 * width_, 0.0F) {}

    [[nodiscard]] const float* x(int r) const { return plane(r, 0); }
    [[nodiscard]] const float* y(int r) const { return plane(r, 1); }
    [[nodiscard]] const float* weight(int r) const { return plane(r, 2); }

    /// Differences row r of `height` into its slot (zeros outside 1..h-2).
    void load(ImageView<const float> height, ImageView<const std::uint8_t> vessels, int r) {
        float* dx = mutablePlane(r, 0);
        float* dy = mutablePlane(r, 1);
        float* dw = mutablePlane(r, 2);
        std::fill(dx, dx + width_, 0.0F);
        std::fill(dy, dy + width_, 0.0F);
        std::fill(dw, dw + width_, 0.0F);
        if (r < 1 || r + 1 >= height.height()) {
            return;
        }
        const float* above = height.row(r - 1);
        const float* row = height.row(r);
        const float* below = height.row(r + 1);
        const std::uint8_t* vr = vessels.row(r);
        const int w = static_cast<int>(width_);
        for (int x = 1; x + 1 < w; ++x) {
            if (vr[x] != 0 || !std::isfinite(row[x]) || !std::isfinite(row[x - 1]) ||
                !std::isfinite(row[x + 1]) || !std::isfinite(above[x]) ||
                !std::isfinite(below[x])) {
                continue;
            }
            dx[x] = 0.5F * (row[x + 1] - row[x - 1]);
            dy[x] = 0.5F * (below[x] - above[x]);
            dw[x] = 1.0F;
        }
    }

  private:
    static constexpr std::size_t kRows = 2 * kCoherenceReach + 1;
    [[nodiscard]] static std::size_t slot(int r) {
        constexpr int n = static_cast<int>(kRows);
        return static_cast<std::size_t>(((r % n) + n) % n);
    }
    [[nodiscard]] const float* plane(int r, std::size_t index) const {
        return planes_.data() + (slot(r) * 3 + index) * width_;
    }
    [[nodiscard]] float* mutablePlane(int r, std::size_t index) {
        return planes_.data() + (slot(r) * 3 + index) * width_;
    }
    std::size_t width_;
    std::vector<float> planes_;
};

}  // namespace

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
    // Per row, branch-free loops over planes (the compiler vectorises them):
    // float, since this runs five times per void pixel and the coherence
    // only scales a highlight.
    constexpr int kReach = kCoherenceReach;
    // Bands of 64 rows: each differences 6 rows beyond its own again.
    parallelFor(0, h, 64, [&](long begin, long end) {
        DiffRing diffs(w);
        for (int r = static_cast<int>(begin) - kReach; r < static_cast<int>(begin) + kReach; ++r) {
            diffs.load(height, vessels, r);
        }
        std::vector<float> k(static_cast<std::size_t>(w));
        std::vector<float> sx(static_cast<std::size_t>(w));
        std::vector<float> sy(static_cast<std::size_t>(w));
        std::vector<float> sz(static_cast<std::size_t>(w));
        const std::vector<float> one(static_cast<std::size_t>(w), 1.0F);
        std::vector<float> cx(static_cast<std::size_t>(w));  // the centre's slope
        std::vector<float> cy(static_cast<std::size_t>(w));
        // Adds gw times the unit normal of (gx, gy) * k over [x0, x1).
        const auto addUnits = [&](const float* gx, const float* gy, const float* gw, int x0,
                                  int x1) {
            float* ox = sx.data();
            float* oy = sy.data();
            float* oz = sz.data();
            const float* kk = k.data();
#pragma omp simd
            for (int x = x0; x < x1; ++x) {
                const float ax = gx[x] * kk[x];
                const float ay = gy[x] * kk[x];
                const float inv = gw[x] / std::sqrt(ax * ax + ay * ay + 1.0F);
                ox[x] += ax * inv;
                oy[x] += ay * inv;
                oz[x] += inv;
            }
        };
        for (int y = static_cast<int>(begin); y < static_cast<int>(end); ++y) {
            diffs.load(height, vessels, y + kReach);
            glm::vec4* out = slopes.row(y);
            const float* row = height.row(y);
            for (int x = 0; x < w; ++x) {
                const auto i = static_cast<std::size_t>(x);
                const double t = std::clamp(static_cast<double>(row[x]), 0.0, 1.0);
                const double pixel = std::max((scale.dmin + t * range) * scale.pixelScale, 1e-12);
                k[i] = static_cast<float>(range / pixel);
                cx[i] = out[x].x;
                cy[i] = out[x].y;
                sx[i] = 0.0F;
                sy[i] = 0.0F;
                sz[i] = 0.0F;
            }
            addUnits(cx.data(), cy.data(), one.data(), 0, w);
            const bool upIn = y - kReach >= 1;
            const bool downIn = y + kReach < h - 1;
            if (upIn) {
                addUnits(diffs.x(y - kReach), diffs.y(y - kReach), diffs.weight(y - kReach), 0, w);
            }
            if (downIn) {
                addUnits(diffs.x(y + kReach), diffs.y(y + kReach), diffs.weight(y + kReach), 0, w);
            }
            // Left and right neighbours: shifted planes, in range only.
            addUnits(diffs.x(y) - kReach, diffs.y(y) - kReach, diffs.weight(y) - kReach, 1 + kReach,
                     w);
            addUnits(diffs.x(y) + kReach, diffs.y(y) + kReach, diffs.weight(y) + kReach, 0,
                     w - 1 - kReach);
            // How many neighbours count (those within a pixel of the border
            // are left out): above and below need an inner column, left and
            // right an inner row.
            const bool innerRow = y >= 1 && y < h - 1;
            const float verticalCount = (upIn ? 1.0F : 0.0F) + (downIn ? 1.0F : 0.0F);
            for (int x = 0; x < w; ++x) {
                if (out[x].w == 0.0F) {
                    continue;  // no fitted slope: stays 0
                }
                const auto i = static_cast<std::size_t>(x);
                const bool innerColumn = x >= 1 && x < w - 1;
                const float horizontalCount =
                    innerRow ? (x - kReach >= 1 ? 1.0F : 0.0F) + (x + kReach < w - 1 ? 1.0F : 0.0F)
                             : 0.0F;
                const float count = 1.0F + horizontalCount + (innerColumn ? verticalCount : 0.0F);
                const float length = std::sqrt(sx[i] * sx[i] + sy[i] * sy[i] + sz[i] * sz[i]);
                out[x].w = std::clamp(length / count, 1e-3F, 1.0F);
            }
        }
    });
}

}  // namespace vv::vss
