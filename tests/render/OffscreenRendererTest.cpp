// SPDX-License-Identifier: GPL-3.0-or-later
// Offscreen rendering through a real OpenGL 4.1 context. Needs a display:
// run under `xvfb-run -a` with QT_QPA_PLATFORM=xcb. Without a GL context the
// tests fail (they never skip): CI always has Xvfb.
#include <gtest/gtest.h>

#include <QGuiApplication>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <set>

#include "RenderTestUtil.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/core/Error.h"
#include "vv/render/OffscreenRenderer.h"

namespace {

using vv::render::OffscreenOptions;
using vv::render::OffscreenRenderer;

/// A UV sphere of `radius` around `center` with a "wss" array equal to z.
vv::scene::Mesh makeSphere(float radius, glm::vec3 center, int slices = 48, int stacks = 24) {
    vv::scene::Mesh mesh;
    mesh.name = "sphere";
    vv::scene::DataArray wss{"wss", "Pa", 1, {}, false, false};
    for (int i = 0; i <= stacks; ++i) {
        const float theta =
            std::numbers::pi_v<float> * static_cast<float>(i) / static_cast<float>(stacks);
        for (int j = 0; j <= slices; ++j) {
            const float phi = 2.0F * std::numbers::pi_v<float> * static_cast<float>(j) /
                              static_cast<float>(slices);
            const glm::vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta)};
            mesh.positions.push_back(center + radius * n);
            mesh.normals.push_back(n);
            wss.values.push_back(n.z);
        }
    }
    const auto row = static_cast<std::uint32_t>(slices + 1);
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const auto a = static_cast<std::uint32_t>(i) * row + static_cast<std::uint32_t>(j);
            const auto b = a + row;
            mesh.indices.insert(mesh.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    }
    mesh.pointArrays.push_back(std::move(wss));
    return mesh;
}

/// An open tube along x from 0 to `length` with a "wss" array rising along it
/// from 0 to 10 and a "pressure" array that is NaN everywhere.
vv::scene::Mesh makeTube(float radius, float length, int segments = 32, int rings = 40) {
    vv::scene::Mesh mesh =
        vv::render::test::makeTube(radius, 0.0F, length, 0.0F, 0.0F, segments, rings);
    vv::scene::DataArray wss{"wss", "Pa", 1, {}, false, false};
    vv::scene::DataArray pressure{"pressure", "mmHg", 1, {}, false, false};
    for (int i = 0; i <= rings; ++i) {
        const float s = static_cast<float>(i) / static_cast<float>(rings);
        for (int j = 0; j < segments; ++j) {
            wss.values.push_back(10.0F * s);
            pressure.values.push_back(std::numeric_limits<float>::quiet_NaN());
        }
    }
    mesh.pointArrays.push_back(std::move(wss));
    mesh.pointArrays.push_back(std::move(pressure));
    return mesh;
}

using vv::render::test::toVec;

QRgb toRgb(const glm::vec3& c) {
    const auto u = vv::colormaps::toRgba8(c);
    return qRgb(u.r, u.g, u.b);
}

int channelDistance(QRgb a, QRgb b) {
    return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                     std::abs(qBlue(a) - qBlue(b))});
}

/// Pixels whose 3x3 neighbourhood is all non-background (no anti-aliased edges).
std::vector<QPoint> interiorPixels(const QImage& image, QRgb background) {
    std::vector<QPoint> out;
    for (int y = 1; y + 1 < image.height(); ++y) {
        for (int x = 1; x + 1 < image.width(); ++x) {
            bool inside = true;
            for (int dy = -1; dy <= 1 && inside; ++dy) {
                for (int dx = -1; dx <= 1 && inside; ++dx) {
                    inside = channelDistance(image.pixel(x + dx, y + dy), background) > 0;
                }
            }
            if (inside) {
                out.emplace_back(x, y);
            }
        }
    }
    return out;
}

class OffscreenRendererTest : public vv::render::test::GlRenderTest {
  protected:
    /// Saves `image` under VV_TEST_TMP for people to look at.
    static void keep(const QImage& image, const char* name) {
        vv::render::test::saveImage(image, "render-", name);
    }

    /// Options of the given size that show the vessels against the background.
    static OffscreenOptions flatOptions(int width, int height) {
        OffscreenOptions options = vv::render::test::exactOptions(width, height);
        options.display.vss.enabled =
            false;  // these tests check the vessels against the background
        return options;
    }
};

TEST_F(OffscreenRendererTest, ContextIsOpenGl41OrNewer) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    EXPECT_NE(renderer->glDescription().find("OpenGL"), std::string::npos);
}

TEST_F(OffscreenRendererTest, SphereIsDrawnCentredWithPlausibleCoverage) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeSphere(5.0F, {100.0F, -20.0F, 3.0F}));
    OffscreenOptions options = flatOptions(200, 150);
    const QImage image = renderer->render(scene, options);
    keep(image, "sphere");
    ASSERT_EQ(image.size(), QSize(200, 150));
    ASSERT_EQ(image.format(), QImage::Format_RGB32);

    long count = 0;
    double sumX = 0.0;
    double sumY = 0.0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (channelDistance(image.pixel(x, y), backgroundRgb_) > 2) {
                ++count;
                sumX += x + 0.5;
                sumY += y + 0.5;
            }
        }
    }
    // Fitted tightly to its bounding box, the sphere's disc has a radius of
    // about 0.77 of the half-height: ~ 58 px, ~ 10500 px or 35 % in area.
    const double fraction = static_cast<double>(count) / (200.0 * 150.0);
    EXPECT_GT(fraction, 0.2) << count;
    EXPECT_LT(fraction, 0.5) << count;
    ASSERT_GT(count, 0);
    EXPECT_NEAR(sumX / static_cast<double>(count), 100.0, 2.0);
    EXPECT_NEAR(sumY / static_cast<double>(count), 75.0, 2.0);
    // Lit: the disc is not one flat colour.
    std::set<QRgb> colours;
    for (const auto& p : interiorPixels(image, backgroundRgb_)) {
        colours.insert(image.pixel(p));
    }
    EXPECT_GT(colours.size(), 30U);
    // Corners stay background.
    EXPECT_EQ(image.pixel(0, 0), backgroundRgb_);
    EXPECT_EQ(image.pixel(199, 149), backgroundRgb_);
}

TEST_F(OffscreenRendererTest, ColourMappedPixelsAreLutColours) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeTube(1.0F, 20.0F));
    OffscreenOptions options = flatOptions(320, 120);
    options.display.style.array = "wss";
    options.display.style.lighting = false;  // exact map colours
    const QImage image = renderer->render(scene, options);
    keep(image, "tube-unlit");
    ASSERT_TRUE(renderer->lastRange().has_value());
    EXPECT_FLOAT_EQ(renderer->lastRange()->first, 0.0F);
    EXPECT_FLOAT_EQ(renderer->lastRange()->second, 10.0F);

    const auto lut = vv::colormaps::lut(vv::colormaps::ColorMap::Viridis, 256);
    const auto pixels = interiorPixels(image, backgroundRgb_);
    ASSERT_GT(pixels.size(), 2000U);
    std::set<int> usedEntries;
    int worst = 0;
    for (const auto& p : pixels) {
        const QRgb c = image.pixel(p);
        int best = 256;
        int bestIndex = -1;
        for (int i = 0; i < 256; ++i) {
            const auto& e = lut[static_cast<std::size_t>(i)];
            const int d = channelDistance(c, qRgb(e.r, e.g, e.b));
            if (d < best) {
                best = d;
                bestIndex = i;
            }
        }
        worst = std::max(worst, best);
        usedEntries.insert(bestIndex);
    }
    EXPECT_LE(worst, 3);                  // texture filtering between neighbours, rounding
    EXPECT_GT(usedEntries.size(), 100U);  // the whole ramp shows
    // wss rises along +x: the left end is dark (start of viridis), the right end light.
    const int midY = image.height() / 2;
    int left = -1;
    int right = -1;
    for (int x = 0; x < image.width(); ++x) {
        if (channelDistance(image.pixel(x, midY), backgroundRgb_) > 0) {
            right = x;
            if (left < 0) {
                left = x;
            }
        }
    }
    ASSERT_GE(left, 0);
    const float lLeft = vv::colormaps::cieLightness(toVec(image.pixel(left + 3, midY)));
    const float lRight = vv::colormaps::cieLightness(toVec(image.pixel(right - 3, midY)));
    EXPECT_LT(lLeft, 30.0F);
    EXPECT_GT(lRight, 80.0F);
}

TEST_F(OffscreenRendererTest, LitColourMappedRenderShowsManyHues) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeTube(1.0F, 20.0F));
    OffscreenOptions options = flatOptions(320, 120);
    options.display.style.array = "wss";
    const QImage mapped = renderer->render(scene, options);
    options.display.style.array.clear();
    const QImage neutral = renderer->render(scene, options);
    keep(mapped, "tube-lit");
    keep(neutral, "tube-neutral");

    const auto hues = [&](const QImage& image) {
        std::set<int> bins;
        for (const auto& p : interiorPixels(image, backgroundRgb_)) {
            const QColor c(image.pixel(p));
            if (c.hsvSaturation() > 40) {
                bins.insert(c.hsvHue() / 10);
            }
        }
        return bins.size();
    };
    EXPECT_GE(hues(mapped), 6U);   // purple, blue, teal, green, yellow
    EXPECT_LE(hues(neutral), 2U);  // one material
}

TEST_F(OffscreenRendererTest, NanValuesShowTheNoDataColour) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeTube(1.0F, 20.0F));
    OffscreenOptions options = flatOptions(160, 80);
    options.display.style.array = "pressure";  // all NaN
    options.display.style.lighting = false;
    const QImage image = renderer->render(scene, options);
    keep(image, "tube-nan");
    EXPECT_FALSE(renderer->lastRange().has_value());
    const QRgb noData = toRgb(vv::colormaps::noDataColor(vv::colormaps::ColorMap::Viridis));
    const auto pixels = interiorPixels(image, backgroundRgb_);
    ASSERT_GT(pixels.size(), 100U);
    for (const auto& p : pixels) {
        ASSERT_LE(channelDistance(image.pixel(p), noData), 1) << p.x() << "," << p.y();
    }
}

TEST_F(OffscreenRendererTest, PartlyMissingValuesShowNoDataOnlyWhereMissing) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    vv::scene::Mesh tube = makeTube(1.0F, 20.0F);
    // NaN on the right half only.
    for (std::size_t i = 0; i < tube.vertexCount(); ++i) {
        if (tube.positions[i].x > 10.5F) {
            tube.pointArrays[0].values[i] = std::numeric_limits<float>::quiet_NaN();
        }
    }
    scene.meshes.push_back(std::move(tube));
    OffscreenOptions options = flatOptions(320, 120);
    options.display.style.array = "wss";
    options.display.style.lighting = false;
    const QImage image = renderer->render(scene, options);
    keep(image, "tube-half-nan");
    const QRgb noData = toRgb(vv::colormaps::noDataColor(vv::colormaps::ColorMap::Viridis));
    const auto pixels = interiorPixels(image, backgroundRgb_);
    ASSERT_FALSE(pixels.empty());
    int minX = image.width();
    int maxX = 0;
    for (const auto& p : pixels) {
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
    }
    const int third = (maxX - minX) / 3;
    int noDataLeft = 0;
    int noDataRight = 0;
    int left = 0;
    int right = 0;
    for (const auto& p : pixels) {
        const bool isNoData = channelDistance(image.pixel(p), noData) <= 1;
        if (p.x() < minX + third) {
            noDataLeft += isNoData ? 1 : 0;
            ++left;
        } else if (p.x() > maxX - third) {
            noDataRight += isNoData ? 1 : 0;
            ++right;
        }
    }
    EXPECT_GT(left, 500);
    EXPECT_EQ(noDataLeft, 0);
    EXPECT_EQ(noDataRight, right);
    EXPECT_GT(right, 500);
}

TEST_F(OffscreenRendererTest, ExplicitRangeClampsValues) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeTube(1.0F, 20.0F));
    OffscreenOptions options = flatOptions(160, 80);
    options.display.style.array = "wss";
    options.display.style.lighting = false;
    options.display.style.colorMap = vv::colormaps::ColorMap::Cividis;
    options.display.style.range = std::make_pair(100.0F, 200.0F);  // every value (0..10) is below
    const QImage image = renderer->render(scene, options);
    const QRgb first = toRgb(vv::colormaps::sample(vv::colormaps::ColorMap::Cividis, 0.0F));
    const auto pixels = interiorPixels(image, backgroundRgb_);
    ASSERT_GT(pixels.size(), 100U);
    for (const auto& p : pixels) {
        ASSERT_LE(channelDistance(image.pixel(p), first), 1);
    }
}

TEST_F(OffscreenRendererTest, EmptySceneIsAllBackground) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const vv::scene::Scene scene;
    OffscreenOptions options;
    options.width = 64;
    options.height = 48;
    options.display.background = {1.0F, 0.5F, 0.0F};
    const QImage image = renderer->render(scene, options);
    ASSERT_EQ(image.size(), QSize(64, 48));
    const QRgb expected = toRgb(options.display.background);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            ASSERT_EQ(image.pixel(x, y), expected) << x << "," << y;
        }
    }
}

TEST_F(OffscreenRendererTest, RendererIsReusableAcrossSizes) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeSphere(1.0F, {0, 0, 0}));
    OffscreenOptions options = flatOptions(32, 32);  // the size is set per frame below
    for (const auto& size : {QSize(32, 32), QSize(400, 100), QSize(17, 301)}) {
        options.width = size.width();
        options.height = size.height();
        const QImage image = renderer->render(scene, options);
        ASSERT_EQ(image.size(), size);
        const QRgb centre = image.pixel(size.width() / 2, size.height() / 2);
        EXPECT_GT(channelDistance(centre, backgroundRgb_), 10);
    }
}

TEST_F(OffscreenRendererTest, GivenCameraIsUsed) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeSphere(1.0F, {0, 0, 0}));
    OffscreenOptions options = flatOptions(100, 100);
    vv::render::Camera camera;
    camera.setViewport(100, 100);
    camera.fit(scene.bounds());
    camera.pan({1000.0F, 0.0F});  // the sphere leaves the view
    options.camera = camera;
    const QImage image = renderer->render(scene, options);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            ASSERT_EQ(image.pixel(x, y), backgroundRgb_);
        }
    }
}

TEST_F(OffscreenRendererTest, BadSizesAreRejected) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    const vv::scene::Scene scene;
    OffscreenOptions options;
    options.width = 0;
    EXPECT_THROW((void)renderer->render(scene, options), vv::InvalidArgumentError);
    options.width = 100;
    options.height = 20000;
    EXPECT_THROW((void)renderer->render(scene, options), vv::InvalidArgumentError);
}

TEST_F(OffscreenRendererTest, MeshWithBadIndexIsRejected) {
    auto renderer = makeRenderer();
    ASSERT_TRUE(renderer);
    vv::scene::Scene scene;
    scene.meshes.push_back(makeSphere(1.0F, {0, 0, 0}));
    scene.meshes[0].indices.back() = 1000000;
    OffscreenOptions options;
    options.width = 32;
    options.height = 32;
    EXPECT_THROW((void)renderer->render(scene, options), vv::InvalidArgumentError);
    // And the renderer still works afterwards.
    scene.meshes[0] = makeSphere(1.0F, {0, 0, 0});
    EXPECT_NO_THROW((void)renderer->render(scene, options));
}

TEST(ArrayHelpersTest, DefaultArrayIsWssIgnoringCase) {
    vv::scene::Scene scene;
    scene.meshes.push_back(makeTube(1.0F, 2.0F, 4, 2));
    EXPECT_EQ(vv::render::defaultArrayName(scene), "wss");
    scene.meshes[0].pointArrays[0].name = "WSS";
    EXPECT_EQ(vv::render::defaultArrayName(scene), "WSS");
    scene.meshes[0].pointArrays[0].name = "speed";
    EXPECT_EQ(vv::render::defaultArrayName(scene), "");
    const auto names = vv::render::pointArrayNames(scene);
    ASSERT_EQ(names.size(), 2U);
    EXPECT_EQ(names[0], "speed");
    EXPECT_EQ(names[1], "pressure");
    EXPECT_FALSE(vv::render::arrayRange(scene, "pressure").has_value());  // all NaN
    const auto range = vv::render::arrayRange(scene, "speed");
    ASSERT_TRUE(range.has_value());
    EXPECT_FLOAT_EQ(range->first, 0.0F);
    EXPECT_FLOAT_EQ(range->second, 10.0F);
}

}  // namespace
