// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/Image.h"
#include "vv/render/Camera.h"
#include "vv/render/DepthRasterizer.h"

namespace {

using vv::Image;
using vv::render::rasterizeDepth;
using vv::render::TriangleList;

constexpr float kInf = std::numeric_limits<float>::infinity();

/// A projection with a 90° field of view and aspect 1 written out by hand, so
/// that screen coordinates are exact: for a point at view depth w,
/// screen x = (x / w * 0.5 + 0.5) * W and screen y = (0.5 - y / w * 0.5) * H.
glm::mat4 exactProjection(float nearPlane, float farPlane) {
    glm::mat4 p(0.0F);
    p[0][0] = 1.0F;
    p[1][1] = 1.0F;
    p[2][2] = -(farPlane + nearPlane) / (farPlane - nearPlane);
    p[2][3] = -1.0F;
    p[3][2] = -2.0F * farPlane * nearPlane / (farPlane - nearPlane);
    return p;
}

/// A mesh in view space (the view matrix is the identity).
struct Soup {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;

    void triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        const auto base = static_cast<std::uint32_t>(positions.size());
        positions.insert(positions.end(), {a, b, c});
        indices.insert(indices.end(), {base, base + 1, base + 2});
    }
    /// Two triangles a-b-c, a-c-d sharing the diagonal a-c.
    void quad(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d) {
        const auto base = static_cast<std::uint32_t>(positions.size());
        positions.insert(positions.end(), {a, b, c, d});
        indices.insert(indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    [[nodiscard]] TriangleList list() const { return {positions, indices}; }
};

Image<float> draw(const Soup& soup, int w, int h, const glm::mat4& projection,
                  const glm::mat4& view = glm::mat4(1.0F)) {
    const TriangleList list = soup.list();
    return rasterizeDepth(std::span<const TriangleList>(&list, 1), view, projection, w, h);
}

/// The view-space point of screen position (sx, sy) at view depth w (exactProjection).
glm::vec3 unproject(double sx, double sy, double w, int width, int height) {
    const double ndcX = sx / width * 2.0 - 1.0;
    const double ndcY = 1.0 - sy / height * 2.0;
    return {static_cast<float>(ndcX * w), static_cast<float>(ndcY * w), static_cast<float>(-w)};
}

std::int64_t coveredCount(const Image<float>& depth) {
    std::int64_t n = 0;
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            n += std::isfinite(depth(x, y)) ? 1 : 0;
        }
    }
    return n;
}

/// Sets VV_THREADS for the lifetime of the object.
class ThreadsOverride {
  public:
    explicit ThreadsOverride(int n) {
        if (const char* old = std::getenv("VV_THREADS")) {
            old_ = old;
        }
        setenv("VV_THREADS", std::to_string(n).c_str(), 1);
    }
    ThreadsOverride(const ThreadsOverride&) = delete;
    ThreadsOverride& operator=(const ThreadsOverride&) = delete;
    ~ThreadsOverride() {
        if (old_) {
            setenv("VV_THREADS", old_->c_str(), 1);
        } else {
            unsetenv("VV_THREADS");
        }
    }

  private:
    std::optional<std::string> old_;
};

TEST(DepthRasterizerTest, QuadAtKnownDepthGivesThatDepthExactly) {
    for (const float d : {0.5F, 3.0F, 7.25F, 1234.5678F}) {
        Soup soup;
        // Much larger than the view: every pixel is covered.
        const float s = 10.0F * d;
        soup.quad({-s, -s, -d}, {s, -s, -d}, {s, s, -d}, {-s, s, -d});
        const Image<float> depth = draw(soup, 37, 23, exactProjection(0.1F, 1e5F));
        for (int y = 0; y < depth.height(); ++y) {
            for (int x = 0; x < depth.width(); ++x) {
                ASSERT_EQ(depth(x, y), d) << "at " << x << "," << y;
            }
        }
    }
}

TEST(DepthRasterizerTest, CameraOverloadGivesTheDistanceToAFacingQuad) {
    vv::render::Camera camera;
    camera.setViewport(64, 48);
    vv::Aabb bounds;
    bounds.extend(glm::vec3(-1.0F));
    bounds.extend(glm::vec3(1.0F));
    camera.fit(bounds);
    camera.setTarget(glm::vec3(0.0F));
    camera.setDistance(6.0F);
    vv::scene::Scene scene;
    vv::scene::Mesh mesh;
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(mesh);
    const Image<float> depth = rasterizeDepth(scene, camera);
    ASSERT_EQ(depth.width(), 64);
    ASSERT_EQ(depth.height(), 48);
    EXPECT_EQ(depth(32, 24), 6.0F);
    EXPECT_EQ(depth(31, 23), 6.0F);
    EXPECT_EQ(depth(0, 0), kInf);  // the quad does not reach the corners
    EXPECT_EQ(depth(63, 47), kInf);
}

TEST(DepthRasterizerTest, TiltedPlaneHasTheExactPerspectiveDepth) {
    // The view-space plane z = -5 - 0.15 x + 0.1 y, large enough to cover the view.
    const auto planeZ = [](float x, float y) { return -5.0F - 0.15F * x + 0.1F * y; };
    const float s = 8.0F;
    Soup soup;
    soup.quad({-s, -s, planeZ(-s, -s)}, {s, -s, planeZ(s, -s)}, {s, s, planeZ(s, s)},
              {-s, s, planeZ(-s, s)});
    const int w = 48;
    const int h = 40;
    const Image<float> depth = draw(soup, w, h, exactProjection(0.1F, 100.0F));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // The ray through the pixel centre: (nx t, ny t, -t) hits the plane at
            // -t = -5 - 0.15 nx t + 0.1 ny t.
            const double nx = (x + 0.5) / w * 2.0 - 1.0;
            const double ny = 1.0 - (y + 0.5) / h * 2.0;
            const double expected = 5.0 / (1.0 - 0.15 * nx + 0.1 * ny);
            ASSERT_NEAR(depth(x, y), expected, 2e-6 * expected) << "at " << x << "," << y;
            // The unprojected point lies on the plane: depth is linear along it.
            const glm::vec3 p = unproject(x + 0.5, y + 0.5, depth(x, y), w, h);
            EXPECT_NEAR(p.z, planeZ(p.x, p.y), 1e-5);
        }
    }
    // 1 / depth is affine in screen space: its second differences vanish.
    for (int y = 0; y < h; ++y) {
        for (int x = 1; x + 1 < w; ++x) {
            const double second = 1.0 / depth(x - 1, y) - 2.0 / depth(x, y) + 1.0 / depth(x + 1, y);
            EXPECT_NEAR(second, 0.0, 2e-7);
        }
    }
    // And depth itself is not (a plane seen in perspective).
    EXPECT_GT(std::abs(depth(0, h / 2) - 2.0F * depth(w / 2, h / 2) + depth(w - 1, h / 2)), 1e-3);
}

TEST(DepthRasterizerTest, CoverageMatchesTheTriangleUpToItsEdges) {
    const int w = 200;
    const int h = 160;
    const double d = 2.0;
    // Screen-space vertices (pixels), placed at view depth d.
    const std::vector<std::vector<glm::dvec2>> triangles{
        {{13.2, 7.9}, {181.7, 40.3}, {57.1, 150.6}},
        {{190.0, 150.0}, {5.3, 120.25}, {100.5, 3.5}},
        {{20.0, 20.0}, {21.5, 140.0}, {22.0, 60.0}},  // a sliver
    };
    for (const auto& t : triangles) {
        Soup soup;
        soup.triangle(unproject(t[0].x, t[0].y, d, w, h), unproject(t[1].x, t[1].y, d, w, h),
                      unproject(t[2].x, t[2].y, d, w, h));
        const Image<float> depth = draw(soup, w, h, exactProjection(0.1F, 100.0F));
        const double area = std::abs((t[1].x - t[0].x) * (t[2].y - t[0].y) -
                                     (t[2].x - t[0].x) * (t[1].y - t[0].y)) /
                            2.0;
        double perimeter = 0.0;
        for (std::size_t i = 0; i < 3; ++i) {
            perimeter += glm::length(t[(i + 1) % 3] - t[i]);
        }
        const auto count = static_cast<double>(coveredCount(depth));
        EXPECT_NEAR(count, area, 0.5 * perimeter) << "area " << area;
        // Pixel by pixel: a centre clearly inside is covered, one clearly outside is not.
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const glm::dvec2 c(x + 0.5, y + 0.5);
                double minDistance = std::numeric_limits<double>::infinity();
                int positive = 0;
                for (std::size_t i = 0; i < 3; ++i) {
                    const glm::dvec2 a = t[i];
                    const glm::dvec2 b = t[(i + 1) % 3];
                    const glm::dvec2 e = b - a;
                    const double cross = e.x * (c.y - a.y) - e.y * (c.x - a.x);
                    minDistance = std::min(minDistance, std::abs(cross) / glm::length(e));
                    positive += cross > 0.0 ? 1 : (cross < 0.0 ? -1 : 0);
                }
                const bool inside = positive == 3 || positive == -3;
                if (minDistance > 1e-3) {
                    ASSERT_EQ(std::isfinite(depth(x, y)), inside) << "at " << x << "," << y;
                }
                if (inside) {
                    ASSERT_NEAR(depth(x, y), d, 1e-6);
                }
            }
        }
    }
}

TEST(DepthRasterizerTest, SharedEdgesThroughPixelCentresAreCoveredExactlyOnce) {
    const int w = 64;
    const int h = 64;
    const double d = 2.0;
    // A square whose diagonal and sides run through pixel centres.
    const glm::dvec2 a(10.5, 10.5);
    const glm::dvec2 b(50.5, 10.5);
    const glm::dvec2 c(50.5, 50.5);
    const glm::dvec2 e(10.5, 50.5);
    const auto at = [&](const glm::dvec2& s) { return unproject(s.x, s.y, d, w, h); };
    Soup first;
    first.triangle(at(a), at(b), at(c));
    Soup second;
    second.triangle(at(a), at(c), at(e));
    const glm::mat4 projection = exactProjection(0.1F, 100.0F);
    const Image<float> one = draw(first, w, h, projection);
    const Image<float> two = draw(second, w, h, projection);
    Soup both;
    both.triangle(at(a), at(b), at(c));
    both.triangle(at(a), at(c), at(e));
    const Image<float> square = draw(both, w, h, projection);
    int doubly = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const bool inOne = std::isfinite(one(x, y));
            const bool inTwo = std::isfinite(two(x, y));
            doubly += inOne && inTwo ? 1 : 0;
            // Every pixel strictly inside the square (its diagonal included) is covered.
            if (x >= 11 && x <= 49 && y >= 11 && y <= 49) {
                ASSERT_TRUE(inOne || inTwo) << "crack at " << x << "," << y;
            }
            ASSERT_EQ(std::isfinite(square(x, y)), inOne || inTwo);
        }
    }
    EXPECT_EQ(doubly, 0);
    // The diagonal's pixels (x == y) went to exactly one triangle: all of them covered.
    for (int k = 11; k <= 49; ++k) {
        EXPECT_TRUE(std::isfinite(square(k, k)));
    }
}

TEST(DepthRasterizerTest, NearerSurfacesOccludeFartherOnesInAnyOrder) {
    const glm::mat4 projection = exactProjection(0.1F, 100.0F);
    const auto quadAt = [](Soup& soup, float x0, float x1, float depth) {
        // x range in view units at this depth; full height.
        soup.quad({x0 * depth, -depth, -depth}, {x1 * depth, -depth, -depth},
                  {x1 * depth, depth, -depth}, {x0 * depth, depth, -depth});
    };
    Soup nearFirst;
    quadAt(nearFirst, -1.0F, 0.5F, 3.0F);
    quadAt(nearFirst, -0.5F, 1.0F, 5.0F);
    Soup farFirst;
    quadAt(farFirst, -0.5F, 1.0F, 5.0F);
    quadAt(farFirst, -1.0F, 0.5F, 3.0F);
    const Image<float> a = draw(nearFirst, 40, 10, projection);
    const Image<float> b = draw(farFirst, 40, 10, projection);
    ASSERT_EQ(std::memcmp(a.data(), b.data(), a.pixelCount() * sizeof(float)), 0);
    // Screen x of ndc -0.5 and 0.5: 10 and 30.
    for (int y = 0; y < 10; ++y) {
        EXPECT_EQ(a(5, y), 3.0F);   // near only
        EXPECT_EQ(a(20, y), 3.0F);  // both: the near one wins
        EXPECT_EQ(a(35, y), 5.0F);  // far only
    }
    // Interpenetrating planes: the nearer one at each pixel.
    Soup crossing;
    crossing.quad({-20, -20, -10 + 2}, {20, -20, -10 - 2}, {20, 20, -10 - 2}, {-20, 20, -10 + 2});
    crossing.quad({-20, -20, -10 - 2}, {20, -20, -10 + 2}, {20, 20, -10 + 2}, {-20, 20, -10 - 2});
    const Image<float> c = draw(crossing, 40, 10, projection);
    for (int x = 0; x < 40; ++x) {
        // Both planes meet at x = 0 (depth 10); elsewhere the nearer is below 10.
        EXPECT_LE(c(x, 5), 10.0F + 1e-5F);
        EXPECT_GT(c(x, 5), 8.0F);
    }
    EXPECT_LT(c(0, 5), 9.9F);
    EXPECT_LT(c(39, 5), 9.9F);
}

TEST(DepthRasterizerTest, BackgroundIsInfinite) {
    const glm::mat4 projection = exactProjection(0.1F, 100.0F);
    const Image<float> empty = rasterizeDepth({}, glm::mat4(1.0F), projection, 17, 9);
    EXPECT_EQ(coveredCount(empty), 0);
    EXPECT_EQ(empty(3, 4), kInf);
    Soup offScreen;  // beside the view
    offScreen.triangle({10, 0, -2}, {12, 0, -2}, {11, 1, -2});
    Soup behind;  // behind the camera
    behind.triangle({-1, -1, 2}, {1, -1, 2}, {0, 1, 2});
    Soup degenerate;  // zero area
    degenerate.triangle({-1, -1, -2}, {0, 0, -2}, {1, 1, -2});
    Soup notFinite;
    notFinite.triangle({-1, -1, -2}, {1, -1, -2}, {0, std::nanf(""), -2});
    for (const Soup* s : {&offScreen, &behind, &degenerate, &notFinite}) {
        const Image<float> depth = draw(*s, 17, 9, projection);
        EXPECT_EQ(coveredCount(depth), 0);
        for (int y = 0; y < depth.height(); ++y) {
            for (int x = 0; x < depth.width(); ++x) {
                ASSERT_TRUE(std::isinf(depth(x, y)) && depth(x, y) > 0.0F);
            }
        }
    }
    // A small triangle in the middle leaves the rest at +Inf.
    Soup small;
    small.triangle(unproject(8, 3, 2, 17, 9), unproject(10, 3, 2, 17, 9),
                   unproject(9, 6, 2, 17, 9));
    const Image<float> depth = draw(small, 17, 9, projection);
    EXPECT_GT(coveredCount(depth), 0);
    EXPECT_LT(coveredCount(depth), 10);
    EXPECT_EQ(depth(0, 0), kInf);
}

TEST(DepthRasterizerTest, TrianglesCrossingTheNearPlaneAreClippedNotDropped) {
    const float nearPlane = 1.0F;
    const glm::mat4 projection = exactProjection(nearPlane, 1000.0F);
    const int w = 64;
    const int h = 64;
    // A floor y = -1 from behind the camera (z = +10) to far ahead (z = -200):
    // every one of its triangles crosses the near plane.
    Soup floor;
    floor.quad({-200, -1, 10}, {200, -1, 10}, {200, -1, -200}, {-200, -1, -200});
    const Image<float> depth = draw(floor, w, h, projection);
    int checked = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double ny = 1.0 - (y + 0.5) / h * 2.0;
            const double nx = (x + 0.5) / w * 2.0 - 1.0;
            const double t = ny < 0.0 ? 1.0 / -ny : std::numeric_limits<double>::infinity();
            // Visible where the ray meets the floor in front of the near plane and
            // before the floor ends.
            if (std::isfinite(t) && t >= nearPlane * 1.01 && t <= 190.0 &&
                std::abs(nx * t) < 190.0) {
                ASSERT_NEAR(depth(x, y), t, 1e-5 * t) << "at " << x << "," << y;
                ++checked;
            } else if (ny > 0.0) {
                ASSERT_EQ(depth(x, y), kInf);  // above the horizon
            }
            if (std::isfinite(depth(x, y))) {
                ASSERT_GE(depth(x, y), nearPlane * (1.0F - 1e-6F));
            }
        }
    }
    EXPECT_GT(checked, w * h / 3);

    // A single triangle with one vertex behind the camera and one in front of it:
    // the part in front is drawn, nothing nearer than the near plane.
    Soup one;
    one.triangle({-3, -3, 2}, {3, -3, -8}, {0, 3, -8});
    const Image<float> clipped = draw(one, w, h, projection);
    EXPECT_GT(coveredCount(clipped), w * h / 10);
    float nearest = kInf;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            nearest = std::min(nearest, clipped(x, y));
        }
    }
    EXPECT_GE(nearest, nearPlane * (1.0F - 1e-6F));
    EXPECT_LT(nearest, 8.0F);
}

TEST(DepthRasterizerTest, ResultDoesNotDependOnTheThreadCount) {
    // Many random overlapping triangles, some crossing the near plane or the border.
    std::mt19937 random(7);
    std::uniform_real_distribution<float> xy(-6.0F, 6.0F);
    std::uniform_real_distribution<float> z(-20.0F, 0.5F);
    Soup soup;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 c(xy(random), xy(random), z(random));
        soup.triangle(c, c + glm::vec3(xy(random), xy(random), z(random)) * 0.2F,
                      c + glm::vec3(xy(random), xy(random), z(random)) * 0.2F);
    }
    const glm::mat4 view = glm::mat4(1.0F);
    const glm::mat4 projection = exactProjection(0.2F, 50.0F);
    std::vector<Image<float>> results;
    for (const int threads : {1, 2, 5}) {
        const ThreadsOverride override(threads);
        results.push_back(draw(soup, 301, 211, projection, view));
    }
    ASSERT_GT(coveredCount(results[0]), 301 * 211 / 2);
    for (std::size_t i = 1; i < results.size(); ++i) {
        EXPECT_EQ(std::memcmp(results[0].data(), results[i].data(),
                              results[0].pixelCount() * sizeof(float)),
                  0);
    }
}

TEST(DepthRasterizerTest, RefusesBadArguments) {
    const glm::mat4 projection = exactProjection(0.1F, 100.0F);
    Soup soup;
    soup.triangle({-1, -1, -2}, {1, -1, -2}, {0, 1, -2});
    EXPECT_THROW((void)draw(soup, 0, 10, projection), vv::InvalidArgumentError);
    EXPECT_THROW((void)draw(soup, 10, -1, projection), vv::InvalidArgumentError);
    EXPECT_THROW((void)draw(soup, 40000, 10, projection), vv::InvalidArgumentError);
    Soup badIndex = soup;
    badIndex.indices[2] = 3;
    EXPECT_THROW((void)draw(badIndex, 10, 10, projection), vv::InvalidArgumentError);
    Soup notTriangles = soup;
    notTriangles.indices.pop_back();
    EXPECT_THROW((void)draw(notTriangles, 10, 10, projection), vv::InvalidArgumentError);
    std::stop_source stop;
    stop.request_stop();
    const TriangleList list = soup.list();
    EXPECT_THROW((void)rasterizeDepth(std::span<const TriangleList>(&list, 1), glm::mat4(1.0F),
                                      projection, 10, 10, stop.get_token()),
                 vv::CancelledError);
}

}  // namespace
