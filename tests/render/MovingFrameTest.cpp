// SPDX-License-Identifier: GPL-3.0-or-later
// What a person sees while the camera moves: a moving frame (reduced render
// size, preview solve, no occlusion, no FXAA: RefinementPolicy's moving
// settings) of the demo tree looks like the settled frame of the same view
// (exact VSS, occlusion, FXAA) at the same window size, by SSIM; and the
// VSS's iso-lines keep their width in window pixels instead of growing with
// the reduction; and the vessels' silhouettes stay sharp and straight
// instead of showing the render pixels' blurred steps. Needs a display
// (xvfb-run, QT_QPA_PLATFORM=xcb).
#include <gtest/gtest.h>

#include <QImage>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "ImageCompare.h"
#include "RenderTestUtil.h"
#include "TestMeshes.h"
#include "evaluation/ArtefactScore.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/render/RefinementPolicy.h"

namespace vv::render {
namespace {

/// The demo tree, a little smaller than the bundled one (its look at a
/// window's size is the same; it is made faster).
const scene::Scene& demoTree() {
    static const scene::Scene tree = [] {
        demo::DemoTreeOptions options;
        options.generations = 5;
        options.maxTriangles = 100000;
        scene::Scene scene;
        scene.meshes.push_back(demo::generateDemoMesh(options));
        return scene;
    }();
    return tree;
}

/// The display settings of the viewer: VSS with iso-lines, AO and FXAA on.
FrameSettings displaySettings() {
    FrameSettings settings;
    settings.vss.isoLines = 8;
    return settings;
}

/// The settings of a moving frame at `scale` (RefinementPolicy, camera
/// moving), its VSS at `vssScale` of the window (default: `scale`).
FrameSettings movingSettings(float scale,
                             float vssScale = std::numeric_limits<float>::quiet_NaN()) {
    RefinementPolicy policy;
    policy.setInteractiveScale(scale, vssScale);
    EXPECT_TRUE(policy.cameraMoved());
    return policy.frameSettings(displaySettings());
}

class MovingFrameTest : public test::GlRenderTest {
  protected:
    void SetUp() override {
        harness_ = std::make_unique<test::FrameHarness>(kWidth, kHeight);
        harness_->setScene(demoTree());
    }
    void TearDown() override { harness_.reset(); }

    QImage render(const FrameSettings& settings) { return harness_->render(style_, settings); }

    static constexpr int kWidth = 1280;
    static constexpr int kHeight = 720;
    std::unique_ptr<test::FrameHarness> harness_;
    MeshStyle style_;
};

TEST_F(MovingFrameTest, AMovingFrameLooksLikeTheSettledFrameOfTheSameView) {
    const QImage settled = render(displaySettings());
    // The floor of dynamic resolution, where moving frames look worst.
    const QImage moving = render(movingSettings(RefinementPolicy::kMinInteractiveScale));
    ASSERT_EQ(harness_->renderer().lastRenderSize(), glm::ivec2(kWidth / 4, kHeight / 4));
    test::saveImage(settled, "moving-frame-", "settled");
    test::saveImage(moving, "moving-frame-", "moving");
    const vv::test::ImageComparison c = vv::test::compareImages(moving, settled);
    std::printf("moving frame at %.2f against the settled frame: %s\n",
                static_cast<double>(RefinementPolicy::kMinInteractiveScale), c.message.c_str());
    // 0.912 when the reduced frame solved its VSS from the depth as read
    // (every contour depth nearer than at the window's size, see
    // silhouetteDepth); 0.933 from the silhouette depth.
    EXPECT_GE(1.0 - c.difference, 0.925) << c.message;
}

/// The VSS height (z') of a frame on its void pixels, with the depth its
/// solve read (to tell vessel pixels apart).
struct ShownVss {
    Image<float> height;
    Image<float> depth;
};

TEST_F(MovingFrameTest, AMovingFramesVssLiesWhereTheSettledFramesDoes) {
    // Where the far field's iso-lines lie: its z' against the settled one's,
    // averaged over the void pixels of the moving frame. Its flat parts move
    // an iso-line by tens of pixels for a few thousandths of z'.
    static_cast<void>(render(displaySettings()));
    const ShownVss settled{harness_->renderer().shownHeight(),
                           harness_->renderer().lastSolvedDepth()};
    static_cast<void>(render(movingSettings(RefinementPolicy::kMinInteractiveScale)));
    const ShownVss moving{harness_->renderer().shownHeight(),
                          harness_->renderer().lastSolvedDepth()};
    ASSERT_EQ(moving.height.width(), kWidth / 4);
    ASSERT_EQ(settled.height.width(), kWidth);
    double sum = 0.0;
    long n = 0;
    for (int y = 0; y < moving.height.height(); ++y) {
        for (int x = 0; x < moving.height.width(); ++x) {
            // The settled pixel at the centre of the moving pixel's 4x4 block.
            const int sx = 4 * x + 2;
            const int sy = 4 * y + 2;
            if (std::isfinite(moving.depth(x, y)) || std::isfinite(settled.depth(sx, sy)) ||
                !std::isfinite(moving.height(x, y)) || !std::isfinite(settled.height(sx, sy))) {
                continue;
            }
            sum += moving.height(x, y) - settled.height(sx, sy);
            ++n;
        }
    }
    ASSERT_GT(n, moving.height.width() * moving.height.height() / 2);
    const double offset = sum / static_cast<double>(n);
    std::printf("moving frame's z' - settled frame's z', mean over %ld void pixels: %.5f\n", n,
                offset);
    // -0.0051 from the depth as read: the whole far field nearer.
    EXPECT_LT(std::abs(offset), 0.002);
}

/// RMS of the second differences `step` px apart, along x and along y, of
/// value(x, y) over the pixels of a w x h image at least `margin` (>= step)
/// from its border where keep(x, y) holds; expects them to be over a
/// quarter of the image.
template <class Keep, class Value>
double rmsSecondDifference(int w, int h, int step, int margin, Keep keep, Value value) {
    double sum = 0.0;
    long n = 0;
    for (int y = margin; y + margin < h; ++y) {
        for (int x = margin; x + margin < w; ++x) {
            if (!keep(x, y)) {
                continue;
            }
            const double ddx = value(x - step, y) - 2.0 * value(x, y) + value(x + step, y);
            const double ddy = value(x, y - step) - 2.0 * value(x, y) + value(x, y + step);
            sum += ddx * ddx + ddy * ddy;
            n += 2;
        }
    }
    EXPECT_GT(n, static_cast<long>(w) * h / 4);
    return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

/// RMS over the void pixels at least 3 px from every vessel pixel of the
/// second differences (along x and along y) of `a` - `b`: how much the
/// difference of two VSS heights of the same size kinks from pixel to pixel,
/// which the lighting (one-pixel slopes while moving) turns into seams.
double seamRms(const ShownVss& a, const ShownVss& b) {
    const int w = a.height.width();
    const int h = a.height.height();
    const auto isVoid = [&](int x, int y) {
        for (int dy = -3; dy <= 3; ++dy) {
            for (int dx = -3; dx <= 3; ++dx) {
                const int px = std::clamp(x + dx, 0, w - 1);
                const int py = std::clamp(y + dy, 0, h - 1);
                if (std::isfinite(a.depth(px, py)) || !std::isfinite(a.height(px, py)) ||
                    !std::isfinite(b.height(px, py))) {
                    return false;
                }
            }
        }
        return true;
    };
    const auto e = [&](int x, int y) {
        return static_cast<double>(a.height(x, y)) - static_cast<double>(b.height(x, y));
    };
    return rmsSecondDifference(w, h, 1, 1, isVoid, e);
}

TEST_F(MovingFrameTest, AMovingFramesVssHasNoSeamsFromThePreviewSolve) {
    // The preview solve's tolerance sets how far its interpolation (coarse,
    // near and band boxes) may bend z' between samples; a one-pixel slope of
    // the lit VSS shows each cell's kinks as faint seams, rows and columns
    // of them across the void while moving (8/255 showed them; 2/255 does
    // not). Measured against an exact solve of the same size.
    const FrameSettings moving = movingSettings(0.42F);
    ASSERT_TRUE(moving.vss.preview);
    static_cast<void>(render(moving));
    const ShownVss preview{harness_->renderer().shownHeight(),
                           harness_->renderer().lastSolvedDepth()};
    FrameSettings exact = moving;
    exact.vss.preview = false;
    static_cast<void>(render(exact));
    const ShownVss reference{harness_->renderer().shownHeight(),
                             harness_->renderer().lastSolvedDepth()};
    ASSERT_EQ(preview.height.width(), reference.height.width());
    ASSERT_EQ(preview.height.width(), 538);
    const double rms = seamRms(preview, reference);
    std::printf("preview z' - exact z', RMS second difference: %.3g (tolerance %.3g)\n", rms,
                moving.vss.previewTolerance);
    // 2.61e-4 at 8/255, 2.11e-4 at 4/255, 1.56e-4 at 2/255, 1.03e-4 at 1/255.
    EXPECT_LT(rms, 1.9e-4);
}

/// The settled frame's and the moving frame's (at 0.42) settings for
/// comparing the light on the VSS: iso-lines and occlusion off.
std::pair<FrameSettings, FrameSettings> litVssFrames() {
    FrameSettings settled = displaySettings();
    settled.vss.isoLines = 0;
    settled.ao.enabled = false;
    FrameSettings moving = movingSettings(0.42F);
    moving.vss.isoLines = 0;
    return {settled, moving};
}

/// Luma (0-255) of an sRGB pixel.
double luma(QRgb c) {
    return 0.299 * qRed(c) + 0.587 * qGreen(c) + 0.114 * qBlue(c);
}

/// RMS of the second differences (2 px apart, along x and along y) of the
/// luma of `image` over the pixels whose 9x9 neighbourhood has no vessel
/// (objectIds, top-down rows, 0 = none): how much the lit VSS ripples.
double vssRipple(const QImage& image, const std::vector<std::uint32_t>& ids) {
    const int w = image.width();
    const auto clear = [&](int x, int y) {
        for (int dy = -4; dy <= 4; ++dy) {
            for (int dx = -4; dx <= 4; ++dx) {
                if (ids[static_cast<std::size_t>(y + dy) * w + (x + dx)] != 0U) {
                    return false;
                }
            }
        }
        return true;
    };
    const auto value = [&](int x, int y) { return luma(image.pixel(x, y)); };
    return rmsSecondDifference(w, image.height(), 2, 4, clear, value);
}

TEST_F(MovingFrameTest, AMovingFramesLitVssDoesNotRippleMoreThanTheSettledFrames) {
    // Moving frames light the VSS with slopes from a few pixels around
    // (the settled frame's 5x5 plane fit is too costly per frame): with
    // one-pixel differences the preview solve's cells showed as seams, and
    // the specular switched on and off next to the silhouettes.
    const auto [settled, moving] = litVssFrames();
    const QImage still = render(settled);
    const double stillRipple = vssRipple(still, harness_->objectIds());
    const QImage frame = render(moving);
    test::saveImage(frame, "moving-frame-", "lit-vss");
    // The vessels of the settled frame: the moving frame's edges differ by a
    // pixel at most, which the 9x9 neighbourhood leaves out.
    static_cast<void>(render(settled));
    const double movingRipple = vssRipple(frame, harness_->objectIds());
    std::printf("lit VSS ripple (RMS second difference of luma): settled %.3f, moving %.3f\n",
                stillRipple, movingRipple);
    // 1.45 x the settled frame's with one-pixel slopes, 1.28 x with the
    // mean of the 1 and 2 px differences, 1.01 x with the specular fading
    // by the share of the eight samples with VSS (not on / off by all four
    // neighbours, which flickered along the silhouettes' staircase); 1.10 x
    // with the plane fit next to contours.
    EXPECT_LT(movingRipple, 1.15 * stillRipple);
}

/// The artefact score (app/evaluation/ArtefactScore.h) of `image`'s luma along the
/// silhouettes of `ids` (objectIds, top-down rows, 0 = none), 2-10 px out:
/// from 2 px, so that the moving frame's edges (a pixel off the settled
/// frame's at most) stay out of the band.
evaluation::ArtefactScore teethScore(const QImage& image, const std::vector<std::uint32_t>& ids) {
    const int w = image.width();
    const int h = image.height();
    Image<float> lumas(w, h);
    Image<std::uint8_t> vessels(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const bool vessel = ids[static_cast<std::size_t>(y) * w + x] != 0U;
            vessels(x, y) = vessel ? 1 : 0;
            lumas(x, y) = static_cast<float>(luma(image.pixel(x, y)) / 255.0);
        }
    }
    evaluation::ArtefactScoreOptions options;
    options.bandNear = 2.0;
    options.bandFar = 10.0;
    return evaluation::artefactScore(lumas.view(), vessels.view(), options);
}

/// The teeth scores (teethScore) of the settled and of the moving frame
/// (at 0.42) of the harness's scene, both along the settled frame's
/// vessels.
std::pair<double, double> teethScores(test::FrameHarness& harness, const MeshStyle& style) {
    const auto [settled, moving] = litVssFrames();
    const QImage frame = harness.render(style, moving);
    test::saveImage(frame, "moving-frame-", "teeth");
    const QImage still = harness.render(style, settled);
    const std::vector<std::uint32_t> ids = harness.objectIds();
    const evaluation::ArtefactScore stillScore = teethScore(still, ids);
    const evaluation::ArtefactScore movingScore = teethScore(frame, ids);
    EXPECT_GT(stillScore.bandPixels, 10000);
    std::printf(
        "teeth along the silhouettes (RMS second difference of luma, 3 px apart, "
        "2-10 px out): settled %.5f, moving %.5f (%lld px)\n",
        stillScore.rms, movingScore.rms, static_cast<long long>(movingScore.bandPixels));
    return {stillScore.rms, movingScore.rms};
}

TEST_F(MovingFrameTest, AMovingFramesLitVssHasNoTeethAlongTheSilhouettes) {
    // The silhouette's pixel staircase ripples z' next to it (issue 19,
    // part 1); the settled frame's plane fit over samples 4 px apart keeps
    // that ripple out of the light. A moving frame's few-pixel slopes lit
    // it: light and dark teeth along every slanted silhouette, one per
    // render pixel's step. Its slopes next to a contour (2 px) come from a
    // plane fit too (5 x 5 samples 2 px apart).
    const auto [still, moving] = teethScores(*harness_, style_);
    // 2.36 x the settled frame's with slopes from the 1 and 2 px
    // differences only; 1.59 x with the fit where one of the eight samples
    // is missing (2 px, kept); 1.10 x with it within 3 px (~3 ms more a
    // frame on llvmpipe: the rotation fell below 30 fps).
    EXPECT_LT(moving, 1.8 * still);
}

TEST_F(MovingFrameTest, AMovingFramesLitVssHasNoTeethOnAFacetedMesh) {
    // The same on a coarse segmentation's kind of surface: the demo tree
    // decimated to 10k triangles, whose facets add their own steps to the
    // silhouettes.
    static const scene::Scene faceted = meshio::simplifiedScene(demoTree(), 10000);
    harness_->setScene(faceted);
    const auto [still, moving] = teethScores(*harness_, style_);
    // 2.26 x the settled frame's (0.01247 / 0.00551) with the 1 and 2 px
    // differences only; 1.59 x with the fit.
    EXPECT_LT(moving, 1.8 * still);
}

/// Pixels where `with` and `without` differ by more than 40 of 255 in some
/// channel: where the iso-lines are drawn.
long linePixels(const QImage& with, const QImage& without) {
    // differenceImage: the largest channel difference, 4 times, as grey.
    const QImage difference = vv::test::differenceImage(with, without);
    long n = 0;
    for (int y = 0; y < difference.height(); ++y) {
        for (int x = 0; x < difference.width(); ++x) {
            n += qRed(difference.pixel(x, y)) > 4 * 40 ? 1 : 0;
        }
    }
    return n;
}

TEST_F(MovingFrameTest, IsoLinesKeepTheirWidthInWindowPixelsWhileMoving) {
    // Two tubes at different depths: the VSS between them is a ramp that
    // many iso-lines cross. AO and FXAA off in both frames: only the lines
    // and the size differ.
    harness_->setScene(test::twoTubes(1.5F, 8.0F, 32, 32));
    FrameSettings display = displaySettings();
    display.vss.isoLines = 16;
    display.ao.enabled = false;
    display.antialiasing = false;
    FrameSettings noLines = display;
    noLines.vss.isoLines = 0;
    RefinementPolicy policy;
    policy.setInteractiveScale(RefinementPolicy::kMinInteractiveScale);
    ASSERT_TRUE(policy.cameraMoved());

    const long settled = linePixels(render(display), render(noLines));
    const QImage moving = render(policy.frameSettings(display));
    const long whileMoving = linePixels(moving, render(policy.frameSettings(noLines)));
    test::saveImage(moving, "moving-frame-", "iso-lines");
    ASSERT_GT(settled, 1000) << "no iso-lines drawn";
    // Drawn at the reduced size they were 4 times as wide (and blurred).
    std::printf("iso-line pixels: settled %ld, moving %ld\n", settled, whileMoving);
    EXPECT_GT(whileMoving, settled / 2);
    EXPECT_LT(whileMoving, settled * 3 / 2)
        << "iso-lines wider while moving: " << whileMoving << " line pixels against " << settled;
}

TEST_F(MovingFrameTest, VesselsDrawnAtHalfSizeOverAVssAtAQuarterLookLikeTheSettledFrame) {
    const QImage settled = render(displaySettings());
    // The step of dynamic resolution between half and a quarter: the vessels
    // at half the window's size, the VSS at a quarter.
    const QImage moving = render(movingSettings(0.5F, 0.25F));
    ASSERT_EQ(harness_->renderer().lastRenderSize(), glm::ivec2(kWidth / 2, kHeight / 2));
    ASSERT_EQ(harness_->renderer().lastVssSize(), glm::ivec2(kWidth / 4, kHeight / 4));
    test::saveImage(moving, "moving-frame-", "half-vss-quarter");
    const QImage quarter = render(movingSettings(0.25F));
    const double ssim = 1.0 - vv::test::compareImages(moving, settled).difference;
    const double ssimQuarter = 1.0 - vv::test::compareImages(quarter, settled).difference;
    std::printf(
        "SSIM against the settled frame: vessels at 0.5 over a VSS at 0.25 %.4f, "
        "all at 0.25 %.4f\n",
        ssim, ssimQuarter);
    // 0.934 all at a quarter, 0.943 with the vessels at half size (the VSS
    // at the same size: where the iso-lines lie is the same).
    EXPECT_GE(ssim, 0.935);
    EXPECT_GT(ssim, ssimQuarter + 0.005);
}

TEST_F(MovingFrameTest, TheBudgetsStepBelowHalfSizeLooksLikeTheSettledFrame) {
    // The step dynamic resolution takes from half size when a frame is too
    // slow: the whole frame at 0.42 (the VSS at the render size), which
    // stays at SSIM >= 0.9 where a VSS below the render size does not on
    // the bundled demo (docs/benchmarks/render.md, "Moving frames, round 4").
    RefinementPolicy policy;
    policy.setFrameBudget(30.0);
    policy.frameMeasured(1e3);
    ASSERT_TRUE(policy.cameraMoved());
    const FrameSettings step = policy.frameSettings(displaySettings());
    const QImage settled = render(displaySettings());
    const QImage moving = render(step);
    const glm::ivec2 size = harness_->renderer().lastRenderSize();
    EXPECT_EQ(size, glm::ivec2(538, 302));  // 0.42 of 1280x720
    EXPECT_EQ(harness_->renderer().lastVssSize(), size);
    test::saveImage(moving, "moving-frame-", "step-below-half");
    const double ssim = 1.0 - vv::test::compareImages(moving, settled).difference;
    const QImage old = render(movingSettings(0.5F, 0.35F));
    std::printf("SSIM against the settled frame: the step below half size %.4f; 0.5 / 0.35 %.4f\n",
                ssim, 1.0 - vv::test::compareImages(old, settled).difference);
    EXPECT_GE(ssim, 0.9);
}

/// Mean of the largest channel difference (0..255) between `a` and `b` over
/// the window pixels next to a vessel's silhouette in `depth` (GL row order,
/// +Inf off the vessels, the window's size): those with a vessel and a
/// background pixel among their 3x3.
double silhouetteError(const QImage& a, const QImage& b, const Image<float>& depth) {
    double sum = 0.0;
    long n = 0;
    for (int y = 1; y + 1 < depth.height(); ++y) {
        for (int x = 1; x + 1 < depth.width(); ++x) {
            bool vessel = false;
            bool background = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    (std::isfinite(depth(x + dx, y + dy)) ? vessel : background) = true;
                }
            }
            if (!vessel || !background) {
                continue;
            }
            const int row = depth.height() - 1 - y;
            const QRgb p = a.pixel(x, row);
            const QRgb q = b.pixel(x, row);
            sum += std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                             std::abs(qBlue(p) - qBlue(q))});
            ++n;
        }
    }
    return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

TEST_F(MovingFrameTest, VesselEdgesOverAVssAtAQuarterAreDrawnAtHalfSize) {
    // Along the silhouettes a frame drawn at a quarter of the window's size
    // has 4-pixel stair steps and the VSS's colour bleeding over the vessel
    // edge (and the vessels' over the VSS); with only the VSS at a quarter
    // and the vessels at half size, the steps are 2 pixels and the VSS is
    // interpolated from its void pixels only.
    FrameSettings display = displaySettings();
    display.ao.enabled = false;  // only the sizes differ
    display.antialiasing = false;
    const QImage settled = render(display);
    const Image<float> depth = harness_->renderer().lastSolvedDepth();
    ASSERT_EQ(depth.width(), kWidth);
    const auto moving = [&](float scale, float vssScale) {
        FrameSettings s = movingSettings(scale, vssScale);
        return render(s);
    };
    const double quarter = silhouetteError(moving(0.25F, 0.25F), settled, depth);
    const QImage split = moving(0.5F, 0.25F);
    ASSERT_EQ(harness_->renderer().lastVssSize(), glm::ivec2(kWidth / 4, kHeight / 4));
    const double half = silhouetteError(split, settled, depth);
    std::printf(
        "mean colour error along the silhouettes: all at 0.25 %.2f, vessels at 0.5 "
        "over a VSS at 0.25 %.2f (of 255)\n",
        quarter, half);
    // 41 of 255 all at a quarter, 30 with the vessels at half size.
    EXPECT_LT(half, 0.8 * quarter);
}

/// `mesh` turned by `degrees` about the view axis (z) around `centre`.
scene::Mesh turned(scene::Mesh mesh, float degrees, glm::vec3 centre) {
    const float a = glm::radians(degrees);
    const glm::mat3 turn(std::cos(a), std::sin(a), 0.0F, -std::sin(a), std::cos(a), 0.0F, 0.0F,
                         0.0F, 1.0F);
    for (glm::vec3& p : mesh.positions) {
        p = centre + turn * (p - centre);
    }
    for (glm::vec3& n : mesh.normals) {
        n = turn * n;
    }
    return mesh;
}

/// Long straight silhouettes at slopes between 0.2 and 4 (tubes turned
/// 12, 27, 34 and 62, 76 degrees; seen along z).
scene::Scene slantedTubes() {
    scene::Scene scene;
    const float angles[] = {12.0F, 27.0F, -34.0F, 62.0F, -76.0F};
    const float offsets[] = {-9.0F, -4.5F, 0.0F, 4.5F, 9.0F};
    for (int i = 0; i < 5; ++i) {
        const glm::vec3 centre(offsets[i], 0.0F, 0.0F);
        scene.meshes.push_back(turned(vv::test::tube({.radius = 0.8F,
                                                      .start = centre - glm::vec3(9.0F, 0, 0),
                                                      .length = 18.0F,
                                                      .segments = 48,
                                                      .rings = 8}),
                                      angles[i], centre));
    }
    return scene;
}

/// Where an edge crosses a scan line (a column or a row of the window) in
/// a moving frame, against the settled frame's edge there.
struct EdgeCrossing {
    double offset = 0.0;  ///< window pixels, moving minus settled
    double width = 0.0;   ///< window pixels from 10 % to 90 % of the way across
};

/// A frame as seen along columns (`columns`) or rows: line `l`, place `i`.
struct ScanView {
    const QImage* image;
    bool columns;
    [[nodiscard]] int lines() const { return columns ? image->width() : image->height(); }
    [[nodiscard]] int length() const { return columns ? image->height() : image->width(); }
    [[nodiscard]] QRgb at(int l, int i) const {
        return columns ? image->pixel(l, i) : image->pixel(i, l);
    }
};

/// The fraction of the way from `background` to `vessel` of `c`.
double vesselFraction(QRgb c, glm::vec3 background, glm::vec3 vessel) {
    const glm::vec3 d = vessel - background;
    return glm::dot(test::toVec(c) - background, d) / glm::dot(d, d);
}

/// The edges of `settled` (flat vessels over a flat background, 1-pixel
/// steps) that cross the scan lines at more than about 53 degrees (their
/// crossing 4 lines either side lies within 3 pixels), with the same side
/// for 6 pixels before and after; each measured in `moving`.
void scanEdges(const ScanView& settled, const ScanView& moving, glm::vec3 background,
               glm::vec3 vessel, std::vector<EdgeCrossing>& out) {
    constexpr int kReach = 6;
    constexpr int kApart = 4;
    const int length = settled.length();
    const auto isVessel = [&](int l, int i) {
        return vesselFraction(settled.at(l, i), background, vessel) > 0.5;
    };
    // Whether line `l` has an edge of the same direction within 3 of i.
    const auto edgeNear = [&](int l, int i, bool from) {
        for (int k = std::max(i - 3, 0); k <= std::min(i + 3, length - 2); ++k) {
            if (isVessel(l, k) == from && isVessel(l, k + 1) != from) {
                return true;
            }
        }
        return false;
    };
    for (int l = kApart; l + kApart < settled.lines(); ++l) {
        for (int i = kReach; i + kReach + 1 < length; ++i) {
            const bool a = isVessel(l, i);
            if (a == isVessel(l, i + 1)) {
                continue;
            }
            bool clean = true;
            for (int k = i - kReach + 1; k <= i + kReach && clean; ++k) {
                clean = isVessel(l, k) == (k <= i ? a : !a);
            }
            if (!clean || !edgeNear(l - kApart, i, a) || !edgeNear(l + kApart, i, a)) {
                continue;
            }
            // The moving line's fraction of side `a` (1) against the other (0).
            const auto from = [&](int k) {
                const double f = vesselFraction(moving.at(l, k), background, vessel);
                return a ? f : 1.0 - f;
            };
            // Where it first falls below `level` (pixel centres at +0.5).
            const auto crossing = [&](double level) -> double {
                for (int k = i - kReach + 1; k < i + kReach; ++k) {
                    if (from(k) >= level && from(k + 1) < level) {
                        return k + 0.5 + (from(k) - level) / (from(k) - from(k + 1));
                    }
                }
                return std::numeric_limits<double>::quiet_NaN();
            };
            const double half = crossing(0.5);
            const double width = crossing(0.1) - crossing(0.9);
            if (std::isfinite(half) && std::isfinite(width)) {
                out.push_back({half - (i + 1.0), width});
            }
        }
    }
}

/// The edges of `settled` measured in `moving` along the columns (edges
/// flatter than about 37 degrees) and the rows (steeper than about 53).
std::vector<EdgeCrossing> edgeCrossings(const QImage& settled, const QImage& moving,
                                        glm::vec3 background, glm::vec3 vessel) {
    std::vector<EdgeCrossing> out;
    for (const bool columns : {true, false}) {
        scanEdges({&settled, columns}, {&moving, columns}, background, vessel, out);
    }
    return out;
}

double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[static_cast<std::size_t>(p * static_cast<double>(v.size() - 1))];
}

TEST_F(MovingFrameTest, VesselEdgesStaySharpWhileMoving) {
    // Flat vessels over a flat background (no light, VSS, AO, FXAA): the
    // settled frame's edges are 1-pixel steps at the window's size. A moving
    // frame at 0.42 (538x302 drawn into 1280x720) upscaled bilinearly
    // blurs every edge over a render pixel (2.4 window pixels).
    harness_->setScene(slantedTubes());
    style_.lighting = false;
    FrameSettings display;
    display.background = glm::vec3(0.1F, 0.2F, 0.3F);
    display.vss.enabled = false;
    display.ao.enabled = false;
    display.antialiasing = false;
    RefinementPolicy policy;
    policy.setInteractiveScale(0.42F);
    ASSERT_TRUE(policy.cameraMoved());
    const QImage settled = render(display);
    const QImage moving = render(policy.frameSettings(display));
    ASSERT_EQ(harness_->renderer().lastRenderSize(), glm::ivec2(538, 302));
    test::saveImage(moving, "moving-frame-", "slanted-tubes");
    test::saveImage(settled, "moving-frame-", "slanted-tubes-settled");
    // The flat colours as the settled frame drew them.
    const glm::vec3 background = test::toVec(settled.pixel(0, 0));
    glm::vec3 vessel = background;
    for (int x = 0; x < settled.width() && vessel == background; ++x) {
        vessel = test::toVec(settled.pixel(x, settled.height() / 2));
    }
    ASSERT_NE(vessel, background);
    const std::vector<EdgeCrossing> edges = edgeCrossings(settled, moving, background, vessel);
    ASSERT_GT(edges.size(), 2000U);
    std::vector<double> offsets;
    std::vector<double> widths;
    for (const EdgeCrossing& e : edges) {
        offsets.push_back(std::abs(e.offset));
        widths.push_back(e.width);
    }
    double mean = 0.0;
    for (const double o : offsets) {
        mean += o / static_cast<double>(offsets.size());
    }
    const double width = percentile(widths, 0.5);
    std::printf(
        "%zu edge crossings: |moving - settled| mean %.2f, 95th percentile %.2f px; "
        "10-90 %% width median %.2f, 95th percentile %.2f px\n",
        edges.size(), mean, percentile(offsets, 0.95), width, percentile(widths, 0.95));
    // Bilinear: widths 2.30 (median) and 3.88 (95th percentile), the edge
    // 0.52 (mean) and 1.21 (95th) off the settled one (whose own steps are
    // +-0.5). Drawn as the silhouette rebuilt from the render pixels'
    // steps: 1.52 / 1.60 wide (one pixel of anti-aliasing), 0.32 / 0.88 off.
    EXPECT_LT(width, 1.8);
    EXPECT_LT(percentile(widths, 0.95), 2.5);
    EXPECT_LT(mean, 0.42);
    EXPECT_LT(percentile(offsets, 0.95), 1.05);
}

TEST_F(MovingFrameTest, VesselEdgesOverTheVssLookLikeTheSettledFramesWhileMoving) {
    // The demo tree over its VSS at the budget's step below half size
    // (0.42), no AO or FXAA in either frame: along the silhouettes the
    // bilinear upscale mixed the VSS's and the vessel's render pixels
    // into blurred 2.4-pixel steps with dark notches (the VSS's colour at
    // the steps' corners).
    FrameSettings display = displaySettings();
    display.ao.enabled = false;
    display.antialiasing = false;
    const QImage settled = render(display);
    const Image<float> depth = harness_->renderer().lastSolvedDepth();
    ASSERT_EQ(depth.width(), kWidth);
    RefinementPolicy policy;
    policy.setInteractiveScale(0.42F);
    ASSERT_TRUE(policy.cameraMoved());
    const QImage moving = render(policy.frameSettings(display));
    ASSERT_EQ(harness_->renderer().lastRenderSize(), glm::ivec2(538, 302));
    test::saveImage(moving, "moving-frame-", "edges-over-vss");
    const double error = silhouetteError(moving, settled, depth);
    std::printf("mean colour error along the silhouettes at 0.42: %.2f of 255\n", error);
    // 32.3 upscaled bilinearly, 24.0 with the silhouettes rebuilt.
    EXPECT_LT(error, 28.0);
}

}  // namespace
}  // namespace vv::render
