// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <optional>
#include <random>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "vv/core/Error.h"
#include "vv/vss/Shading.h"

namespace vv::vss {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(IsoLevelTest, BandsAndDistanceToTheNearestLine) {
    // Lines at k / 4: 0, 0.25, 0.5, 0.75, 1.
    EXPECT_EQ(isoLevel(0.0F, 4).band, 0);
    EXPECT_FLOAT_EQ(isoLevel(0.0F, 4).distance, 0.0F);
    EXPECT_EQ(isoLevel(0.3F, 4).band, 1);
    EXPECT_NEAR(isoLevel(0.3F, 4).distance, 0.2F, 1e-6);    // 0.3 * 4 = 1.2
    EXPECT_NEAR(isoLevel(0.45F, 4).distance, 0.2F, 1e-6);   // 1.8: 0.2 below line 2
    EXPECT_NEAR(isoLevel(0.125F, 4).distance, 0.5F, 1e-6);  // the middle of a band
    EXPECT_EQ(isoLevel(1.0F, 4).band, 3);
    EXPECT_FLOAT_EQ(isoLevel(1.0F, 4).distance, 0.0F);
    // Clamped outside [0, 1].
    EXPECT_EQ(isoLevel(-0.5F, 4).band, 0);
    EXPECT_EQ(isoLevel(7.0F, 4).band, 3);
    // No VSS.
    EXPECT_EQ(isoLevel(kNaN, 4).band, -1);
    EXPECT_TRUE(std::isnan(isoLevel(kNaN, 4).distance));
    EXPECT_EQ(isoLevel(0.99F, 1).band, 0);
    EXPECT_THROW(static_cast<void>(isoLevel(0.5F, 0)), InvalidArgumentError);
    // Distance is always in [0, 0.5].
    for (int i = 0; i <= 1000; ++i) {
        const auto l = isoLevel(static_cast<float>(i) / 1000.0F, 7);
        EXPECT_GE(l.distance, 0.0F);
        EXPECT_LE(l.distance, 0.5F);
        EXPECT_GE(l.band, 0);
        EXPECT_LT(l.band, 7);
    }
}

TEST(HeightFieldNormalsTest, TiltedPlaneInSceneUnits) {
    // h = z * scale with z = 0.01 x + 0.02 y; scale 10 mm, pixel 0.5 mm:
    // dh/dx = 0.1 / 0.5 = 0.2, dh/dy = 0.4.
    Image<float> z(6, 5);
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 6; ++x) {
            z(x, y) = 0.01F * x + 0.02F * y;
        }
    }
    const auto n = heightFieldNormals(z.view(), 10.0, 0.5);
    const glm::vec3 expected = glm::normalize(glm::vec3(0.2F, 0.4F, -1.0F));
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 6; ++x) {  // borders included: one-sided differences
            EXPECT_NEAR(n(x, y).x, expected.x, 1e-5) << x << ", " << y;
            EXPECT_NEAR(n(x, y).y, expected.y, 1e-5);
            EXPECT_NEAR(n(x, y).z, expected.z, 1e-5);
            EXPECT_NEAR(glm::length(n(x, y)), 1.0F, 1e-6);
        }
    }
}

TEST(HeightFieldNormalsTest, CentralDifferencesInside) {
    // h = x^2: central difference at x = 2 is ((9 - 1) / 2) = 4, one-sided at 0 is 1.
    Image<float> z(5, 1);
    for (int x = 0; x < 5; ++x) {
        z(x, 0) = static_cast<float>(x * x);
    }
    const auto n = heightFieldNormals(z.view(), 1.0, 1.0);
    EXPECT_NEAR(n(2, 0).x / -n(2, 0).z, 4.0F, 1e-5);
    EXPECT_NEAR(n(0, 0).x / -n(0, 0).z, 1.0F, 1e-5);
    EXPECT_NEAR(n(4, 0).x / -n(4, 0).z, 7.0F, 1e-5);
    EXPECT_EQ(n(2, 0).y, 0.0F);  // a single row: no y derivative
}

TEST(HeightFieldNormalsTest, OneSidedNextToNaNAndNeverNaN) {
    Image<float> z(5, 3, 0.0F);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            z(x, y) = 0.1F * x;
        }
    }
    z(3, 1) = kNaN;
    z(0, 2) = kNaN;
    z(1, 2) = std::numeric_limits<float>::infinity();
    const auto n = heightFieldNormals(z.view(), 1.0, 1.0);
    // (2, 1): right neighbour missing, left difference 0.1.
    EXPECT_NEAR(n(2, 1).x / -n(2, 1).z, 0.1F, 1e-6);
    // (4, 1): left neighbour missing and at the border: no x derivative.
    EXPECT_EQ(n(4, 1).x, 0.0F);
    // No VSS: facing the viewer.
    EXPECT_EQ(n(3, 1), glm::vec3(0.0F, 0.0F, -1.0F));
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x) {
            EXPECT_FALSE(std::isnan(n(x, y).x) || std::isnan(n(x, y).y) || std::isnan(n(x, y).z));
        }
    }
}

TEST(HeightFieldNormalsTest, FlatAndExtremeScales) {
    Image<float> z(4, 4, 0.5F);
    z(1, 1) = 0.7F;
    const auto flat = heightFieldNormals(z.view(), 0.0, 1.0);  // flat scene: dmax = dmin
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            EXPECT_EQ(flat(x, y), glm::vec3(0.0F, 0.0F, -1.0F));
        }
    }
    const auto steep = heightFieldNormals(z.view(), 1e300, 1e-300);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            EXPECT_TRUE(std::isfinite(steep(x, y).x) && std::isfinite(steep(x, y).z));
        }
    }
    EXPECT_THROW(static_cast<void>(heightFieldNormals(z.view(), -1.0, 1.0)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(heightFieldNormals(z.view(), 1.0, 0.0)), InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(heightFieldNormals(z.view(), std::nan(""), 1.0)),
                 InvalidArgumentError);
}

// --- fittedSlopes ------------------------------------------------------------

/// The plane fit written out per pixel, as the VSS shader did it: the
/// reference the separable implementation must reproduce.
glm::dvec3 referenceSlope(const Image<float>& height, const Image<std::uint8_t>& vessels, int px,
                          int py) {
    const int w = height.width();
    const int h = height.height();
    const auto has = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && std::isfinite(height(x, y));
    };
    const auto diff = [&](bool m, bool p, double minus, double centre, double plus) {
        if (m && p) {
            return 0.5 * (plus - minus);
        }
        if (p) {
            return plus - centre;
        }
        if (m) {
            return centre - minus;
        }
        return 0.0;
    };
    const double z = height(px, py);
    glm::dvec2 grad(
        diff(has(px - 1, py), has(px + 1, py), has(px - 1, py) ? height(px - 1, py) : 0.0, z,
             has(px + 1, py) ? height(px + 1, py) : 0.0),
        diff(has(px, py - 1), has(px, py + 1), has(px, py - 1) ? height(px, py - 1) : 0.0, z,
             has(px, py + 1) ? height(px, py + 1) : 0.0));
    const auto fits = [&](int x, int y) { return has(x, y) && vessels(x, y) == 0; };
    // Next to contours each sample is the mean offset and height of the
    // fittable pixels among the 5x5 around it.
    const auto sample = [&](int qx, int qy, int stride) {
        if (stride == 1) {
            return glm::dvec3(0.0, 0.0, height(qx, qy));
        }
        glm::dvec3 sum(0.0);
        int count = 0;
        for (int j = -2; j <= 2; ++j) {
            for (int i = -2; i <= 2; ++i) {
                if (fits(qx + i, qy + j)) {
                    sum += glm::dvec3(i, j, height(qx + i, qy + j));
                    ++count;
                }
            }
        }
        return sum / static_cast<double>(count);
    };
    double support = 0.0;
    for (const int stride : {1, 4}) {
        double sw = 0, sx = 0, sy = 0, sh = 0, sxx = 0, sxy = 0, syy = 0, sxh = 0, syh = 0;
        double total = 0;
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                const int qx = px + dx * stride;
                const int qy = py + dy * stride;
                if (qx < 0 || qy < 0 || qx >= w || qy >= h) {
                    continue;
                }
                const double wt = std::exp(-0.25 * (dx * dx + dy * dy));
                total += wt;
                if (!std::isfinite(height(qx, qy)) || vessels(qx, qy) != 0) {
                    continue;
                }
                const glm::dvec3 q = sample(qx, qy, stride);
                const double x = dx * stride + q.x;
                const double y = dy * stride + q.y;
                const double d = q.z - z;
                sw += wt;
                sx += wt * x;
                sy += wt * y;
                sh += wt * d;
                sxx += wt * x * x;
                sxy += wt * x * y;
                syy += wt * y * y;
                sxh += wt * x * d;
                syh += wt * y * d;
            }
        }
        if (stride == 1) {
            support = sw / total;
        }
        // The wide window only next to a contour: where it misses samples.
        if (sw > 0 && (stride == 1 || sw / total < 0.999)) {
            const double cxx = sxx - sx * sx / sw;
            const double cxy = sxy - sx * sy / sw;
            const double cyy = syy - sy * sy / sw;
            const double cxh = sxh - sx * sh / sw;
            const double cyh = syh - sy * sh / sw;
            const double det = cxx * cyy - cxy * cxy;
            if (det >= 0.05 * std::max(cxx * cyy, 1e-12)) {
                grad = {(cyy * cxh - cxy * cyh) / det, (cxx * cyh - cxy * cxh) / det};
            }
        }
    }
    return glm::dvec3(grad, support);
}

TEST(FittedSlopesTest, ATiltedPlaneHasItsSlopeEverywhere) {
    Image<float> z(40, 30);
    Image<std::uint8_t> vessels(40, 30, 0);
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 40; ++x) {
            z(x, y) = 0.2F + 0.01F * x - 0.004F * y;
        }
    }
    const auto s = fittedSlopes(z.view(), vessels.view());
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 40; ++x) {
            EXPECT_NEAR(s(x, y).x, 0.01F, 1e-6) << x << "," << y;
            EXPECT_NEAR(s(x, y).y, -0.004F, 1e-6) << x << "," << y;
            EXPECT_FLOAT_EQ(s(x, y).z, 1.0F);  // the image border is no contour
            EXPECT_EQ(s(x, y).w, 1.0F);
        }
    }
}

TEST(FittedSlopesTest, NeverReachesAcrossAContour) {
    // A disc of vessel pixels whose depth is far off the VSS's plane.
    Image<float> z(48, 48);
    Image<std::uint8_t> vessels(48, 48, 0);
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 48; ++x) {
            const bool vessel = (x - 24) * (x - 24) + (y - 20) * (y - 20) < 64;
            vessels(x, y) = vessel ? 1 : 0;
            z(x, y) = vessel ? 5.0F : 0.5F + 0.003F * x + 0.002F * y;
        }
    }
    const auto s = fittedSlopes(z.view(), vessels.view());
    int nearContour = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 48; ++x) {
            if (vessels(x, y) != 0) {
                EXPECT_EQ(s(x, y), glm::vec4(0.0F)) << x << "," << y;
                continue;
            }
            EXPECT_NEAR(s(x, y).x, 0.003F, 1e-5) << x << "," << y;
            EXPECT_NEAR(s(x, y).y, 0.002F, 1e-5) << x << "," << y;
            nearContour += s(x, y).z < 0.999F ? 1 : 0;
        }
    }
    EXPECT_GT(nearContour, 40);  // the ring next to the disc has less support
}

/// A smooth VSS with random vessel blobs (random depths) and a few holes
/// without a VSS, of size (37 + 11 i) x (29 + 5 i) for scene i.
struct RandomScene {
    Image<float> z;
    Image<std::uint8_t> vessels;
};

/// A random scene of w x h with `blobs` vessel blobs (see randomScene()).
RandomScene randomSceneOfSize(int w, int h, int scene, int blobs, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0F, 1.0F);
    RandomScene out{Image<float>(w, h), Image<std::uint8_t>(w, h, 0)};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            out.z(x, y) = 0.5F + 0.3F * std::sin(0.21F * x + scene) * std::cos(0.17F * y);
        }
    }
    for (int blob = 0; blob < blobs; ++blob) {
        const int cx = static_cast<int>(u(rng) * w);
        const int cy = static_cast<int>(u(rng) * h);
        const int r = 2 + static_cast<int>(u(rng) * 5);
        for (int y = std::max(0, cy - r); y <= std::min(h - 1, cy + r); ++y) {
            for (int x = std::max(0, cx - r); x <= std::min(w - 1, cx + r); ++x) {
                if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) {
                    out.vessels(x, y) = 1;
                    out.z(x, y) = u(rng);
                }
            }
        }
    }
    for (int hole = 0; hole < 10; ++hole) {
        out.z(static_cast<int>(u(rng) * w), static_cast<int>(u(rng) * h)) = kNaN;
    }
    return out;
}

RandomScene randomScene(int scene, std::mt19937& rng) {
    return randomSceneOfSize(37 + scene * 11, 29 + scene * 5, scene, 6, rng);
}

TEST(FittedSlopesTest, EqualsThePerPixelFitOnRandomScenes) {
    std::mt19937 rng(7);
    for (int scene = 0; scene < 4; ++scene) {
        const auto [z, vessels] = randomScene(scene, rng);
        const int w = z.width();
        const int h = z.height();
        const auto s = fittedSlopes(z.view(), vessels.view());
        double worst = 0.0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                if (vessels(x, y) != 0 || !std::isfinite(z(x, y))) {
                    EXPECT_EQ(s(x, y), glm::vec4(0.0F));
                    continue;
                }
                const glm::dvec3 ref = referenceSlope(z, vessels, x, y);
                worst = std::max({worst, std::abs(s(x, y).x - ref.x), std::abs(s(x, y).y - ref.y),
                                  std::abs(s(x, y).z - ref.z)});
                EXPECT_EQ(s(x, y).w, 1.0F);
            }
        }
        EXPECT_LT(worst, 2e-6) << "scene " << scene;
    }
}

TEST(FittedSlopesTest, RejectsMismatchedSizesAndStops) {
    Image<float> z(8, 8, 0.5F);
    Image<std::uint8_t> vessels(8, 7, 0);
    EXPECT_THROW(static_cast<void>(fittedSlopes(z.view(), vessels.view())), InvalidArgumentError);
    Image<std::uint8_t> fits(8, 8, 0);
    std::stop_source stop;
    stop.request_stop();
    EXPECT_THROW(static_cast<void>(fittedSlopes(z.view(), fits.view(), stop.get_token())),
                 CancelledError);
    const auto empty = fittedSlopes(Image<float>(0, 0).view(), Image<std::uint8_t>(0, 0).view());
    EXPECT_EQ(empty.width(), 0);
}

/// Toksvig's coherence at (x, y) literally as Shading.h defines it, in double.
double referenceCoherence(const Image<float>& z, const Image<std::uint8_t>& vessels,
                          const glm::vec4& slope, int x, int y, const SlopeScale& scale) {
    const int w = z.width();
    const int h = z.height();
    const double range = scale.dmax - scale.dmin;
    const double depth = scale.dmin + std::clamp(static_cast<double>(z(x, y)), 0.0, 1.0) * range;
    const double k = range / (depth * scale.pixelScale);
    const auto unit = [](double gx, double gy) {
        return glm::dvec3(gx, gy, 1.0) / std::sqrt(gx * gx + gy * gy + 1.0);
    };
    glm::dvec3 sum = unit(slope.x * k, slope.y * k);
    int count = 1;
    for (const auto& [dx, dy] : {std::pair{3, 0}, {-3, 0}, {0, 3}, {0, -3}}) {
        const int qx = x + dx;
        const int qy = y + dy;
        if (qx < 1 || qy < 1 || qx > w - 2 || qy > h - 2) {
            continue;
        }
        ++count;
        bool normal = vessels(qx, qy) == 0;
        for (const auto& [ox, oy] : {std::pair{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            normal = normal && std::isfinite(z(qx + ox, qy + oy));
        }
        if (normal) {
            sum += unit(0.5 * (static_cast<double>(z(qx + 1, qy)) - z(qx - 1, qy)) * k,
                        0.5 * (static_cast<double>(z(qx, qy + 1)) - z(qx, qy - 1)) * k);
        }
    }
    return std::clamp(glm::length(sum) / count, 1e-3, 1.0);
}

TEST(NormalCoherenceTest, EqualsTheDefinitionOnRandomScenes) {
    std::mt19937 rng(11);
    for (int scene = 0; scene < 4; ++scene) {
        const auto [z, vessels] = randomScene(scene, rng);
        const auto slopes = fittedSlopes(z.view(), vessels.view());
        auto coherent = slopes;
        // Steep enough in scene units that the normals differ visibly.
        const SlopeScale scale{20.0, 80.0 + 40.0 * scene, 0.01};
        addNormalCoherence(coherent, z.view(), vessels.view(), scale);
        double worst = 0.0;
        int below = 0;
        for (int y = 0; y < z.height(); ++y) {
            for (int x = 0; x < z.width(); ++x) {
                const glm::vec4 s = slopes(x, y);
                const glm::vec4 c = coherent(x, y);
                EXPECT_EQ(glm::vec3(c), glm::vec3(s)) << "only w changes";
                if (s.w == 0.0F) {
                    EXPECT_EQ(c.w, 0.0F);
                    continue;
                }
                const double ref = referenceCoherence(z, vessels, s, x, y, scale);
                worst = std::max(worst, std::abs(c.w - ref));
                below += ref < 0.99 ? 1 : 0;
            }
        }
        EXPECT_LT(worst, 2e-5) << "scene " << scene;
        EXPECT_GT(below, 50) << "scene " << scene << ": too few pixels test the sum";
    }
}

TEST(NormalCoherenceTest, OneOnAPlaneLessWhereANeighbourIsAVessel) {
    Image<float> z(40, 40);
    Image<std::uint8_t> vessels(40, 40, 0);
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) {
            // A vessel column at x = 20..21 (its depth far off the plane).
            vessels(x, y) = (x == 20 || x == 21) ? 1 : 0;
            z(x, y) = vessels(x, y) != 0 ? 3.0F : 0.3F + 0.01F * x + 0.005F * y;
        }
    }
    auto slopes = fittedSlopes(z.view(), vessels.view());
    addNormalCoherence(slopes, z.view(), vessels.view(), SlopeScale{10.0, 60.0, 0.002});
    for (int y = 0; y < 40; ++y) {
        for (int x = 0; x < 40; ++x) {
            const float c = slopes(x, y).w;
            if (vessels(x, y) != 0) {
                EXPECT_EQ(c, 0.0F);
            } else if (x <= 15 || x >= 26) {
                // All normals around are the plane's (or off the image).
                EXPECT_NEAR(c, 1.0F, 1e-6) << x << "," << y;
            } else if ((x == 18 || x == 23) && y >= 1 && y <= 38) {
                // 3 px away lies a vessel pixel: a zero normal of five (or four;
                // rows 0 and 39 leave out neighbours within a pixel of the border).
                EXPECT_LE(c, 0.8F + 1e-6F) << x << "," << y;
                EXPECT_GT(c, 0.5F) << x << "," << y;
            }
        }
    }
    EXPECT_THROW(addNormalCoherence(slopes, z.view(), vessels.view(), SlopeScale{0.0, 1.0, 0.0}),
                 InvalidArgumentError);
    Image<std::uint8_t> small(4, 4, 0);
    EXPECT_THROW(addNormalCoherence(slopes, z.view(), small.view(), SlopeScale{0.0, 1.0, 1.0}),
                 InvalidArgumentError);
}

// --- Bands, sizes and threads (issue 19: slopes and coherence at 4K) ----------

/// Sets VV_THREADS (parallelFor's worker count) for its lifetime.
class ScopedThreads {
  public:
    explicit ScopedThreads(const char* threads) {
        if (const char* old = std::getenv("VV_THREADS")) {
            old_ = old;
        }
        ::setenv("VV_THREADS", threads, 1);
    }
    ~ScopedThreads() {
        if (old_) {
            ::setenv("VV_THREADS", old_->c_str(), 1);
        } else {
            ::unsetenv("VV_THREADS");
        }
    }
    ScopedThreads(const ScopedThreads&) = delete;
    ScopedThreads& operator=(const ScopedThreads&) = delete;
    ScopedThreads(ScopedThreads&&) = delete;
    ScopedThreads& operator=(ScopedThreads&&) = delete;

  private:
    std::optional<std::string> old_;
};

/// fittedSlopes then addNormalCoherence of `scene`.
Image<glm::vec4> slopesWithCoherence(const RandomScene& scene, const SlopeScale& scale) {
    auto slopes = fittedSlopes(scene.z.view(), scene.vessels.view());
    addNormalCoherence(slopes, scene.z.view(), scene.vessels.view(), scale);
    return slopes;
}

/// The largest differences from referenceSlope() (x, y, support) and
/// referenceCoherence() over the pixels of `rows`.
struct ReferenceError {
    double slope = 0.0;
    double coherence = 0.0;
    int pixels = 0;
};

ReferenceError errorAgainstTheDefinition(const RandomScene& scene, const SlopeScale& scale,
                                         const std::vector<int>& rows) {
    const auto slopes = fittedSlopes(scene.z.view(), scene.vessels.view());
    auto coherent = slopes;
    addNormalCoherence(coherent, scene.z.view(), scene.vessels.view(), scale);
    ReferenceError e;
    for (const int y : rows) {
        for (int x = 0; x < scene.z.width(); ++x) {
            if (scene.vessels(x, y) != 0 || !std::isfinite(scene.z(x, y))) {
                EXPECT_EQ(coherent(x, y), glm::vec4(0.0F)) << x << "," << y;
                continue;
            }
            const glm::dvec3 ref = referenceSlope(scene.z, scene.vessels, x, y);
            const glm::vec4 s = slopes(x, y);
            e.slope = std::max(
                {e.slope, std::abs(s.x - ref.x), std::abs(s.y - ref.y), std::abs(s.z - ref.z)});
            e.coherence = std::max(
                e.coherence, std::abs(coherent(x, y).w -
                                      referenceCoherence(scene.z, scene.vessels, s, x, y, scale)));
            ++e.pixels;
        }
    }
    return e;
}

std::vector<int> allRows(int h) {
    std::vector<int> rows(static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y) {
        rows[static_cast<std::size_t>(y)] = y;
    }
    return rows;
}

TEST(FittedSlopesTest, EqualsTheDefinitionAtOddSizesAcrossRowBands) {
    // Taller than a band of rows (the implementation works in bands and
    // keeps a few rows around each): every row of every band matches.
    std::mt19937 rng(19);
    const SlopeScale scale{20.0, 100.0, 0.01};
    for (const auto& [w, h] : {std::pair{333, 217}, {23, 301}, {401, 65}, {129, 128}, {31, 7}}) {
        const RandomScene scene = randomSceneOfSize(w, h, w % 7, 1 + w * h / 600, rng);
        const ReferenceError e = errorAgainstTheDefinition(scene, scale, allRows(h));
        EXPECT_LT(e.slope, 2e-6) << w << "x" << h;
        EXPECT_LT(e.coherence, 2e-5) << w << "x" << h;
        EXPECT_GT(e.pixels, w * h / 4) << w << "x" << h;
    }
}

TEST(FittedSlopesTest, EqualsTheDefinitionOnASynthetic4kFrame) {
    std::mt19937 rng(4);
    const RandomScene scene = randomSceneOfSize(3840, 2160, 3, 4000, rng);
    // Rows around band edges (every 32nd row and its neighbours) and a few
    // others: the reference is slow (O(50) per pixel, in double).
    std::vector<int> rows;
    for (int y = 0; y < 2160; y += 32) {
        for (const int r : {y - 3, y - 1, y, y + 2}) {
            if (r >= 0 && r < 2160) {
                rows.push_back(r);
            }
        }
    }
    rows.push_back(2159);
    const ReferenceError e =
        errorAgainstTheDefinition(scene, SlopeScale{20.0, 100.0, 0.0005}, rows);
    EXPECT_LT(e.slope, 2e-6);
    EXPECT_LT(e.coherence, 2e-5);
    EXPECT_GT(e.pixels, 3840 * static_cast<int>(rows.size()) / 2);
}

TEST(FittedSlopesTest, ParallelEqualsSerialBitForBit) {
    std::mt19937 rng(23);
    for (const auto& [w, h] : {std::pair{333, 217}, {3840, 2160}}) {
        const RandomScene scene = randomSceneOfSize(w, h, 1, 1 + w * h / 2000, rng);
        const SlopeScale scale{20.0, 100.0, 2.0 * 0.268 / h};
        Image<glm::vec4> serial;
        {
            const ScopedThreads one("1");
            serial = slopesWithCoherence(scene, scale);
        }
        for (const char* threads : {"2", "3", "8"}) {
            const ScopedThreads many(threads);
            const Image<glm::vec4> parallel = slopesWithCoherence(scene, scale);
            EXPECT_EQ(std::memcmp(serial.data(), parallel.data(),
                                  serial.pixelCount() * sizeof(glm::vec4)),
                      0)
                << w << "x" << h << " on " << threads << " threads";
        }
    }
}

}  // namespace
}  // namespace vv::vss
