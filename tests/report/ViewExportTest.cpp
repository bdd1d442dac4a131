// SPDX-License-Identifier: GPL-3.0-or-later
// The view export through a real OpenGL 4.1 context: run under
// `xvfb-run -a` with QT_QPA_PLATFORM=xcb (scripts/test does).
#include <gtest/gtest.h>

#include <QImage>
#include <QString>
#include <filesystem>
#include <fstream>
#include <memory>

#include "ReportTestUtil.h"
#include "vv/core/Error.h"
#include "vv/report/ViewExport.h"

namespace vv::report {
namespace {

namespace fs = std::filesystem;

class ViewExportTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        test::ensureGuiApplication();
        scene_.meshes.push_back(test::makeTube("tube"));
    }

    static std::unique_ptr<render::OffscreenRenderer> renderer() {
        try {
            return std::make_unique<render::OffscreenRenderer>();
        } catch (const Error& e) {
            ADD_FAILURE() << "no OpenGL (run under xvfb-run -a, QT_QPA_PLATFORM=xcb): " << e.what();
            return nullptr;
        }
    }

    static ViewExportOptions options(int width, int height) {
        ViewExportOptions o;
        o.render.width = width;
        o.render.height = height;
        o.render.display.style.array = "wss";
        o.render.display.vss.enabled = false;  // background stays background
        o.render.display.ao.enabled = false;
        return o;
    }

    static scene::Scene scene_;
};

scene::Scene ViewExportTest::scene_;

TEST_F(ViewExportTest, TransparentBackgroundKeepsTheVesselOpaque) {
    auto r = renderer();
    ASSERT_TRUE(r);
    ViewExportOptions o = options(320, 240);
    o.legends = false;
    o.transparentBackground = true;
    const RenderedView view = renderView(*r, scene_, o);
    ASSERT_EQ(view.image.size(), QSize(320, 240));
    EXPECT_TRUE(view.image.hasAlphaChannel());
    EXPECT_EQ(qAlpha(view.image.pixel(2, 2)), 0);        // background corner
    EXPECT_EQ(qAlpha(view.image.pixel(160, 120)), 255);  // the tube's middle
    EXPECT_TRUE(view.legends.parameter.has_value());     // wss is shown
    EXPECT_FALSE(view.legends.depth.has_value());        // no VSS
    // Opaque export of the same view: the same vessel colour.
    o.transparentBackground = false;
    const RenderedView opaque = renderView(*r, scene_, o);
    EXPECT_FALSE(opaque.image.hasAlphaChannel());
    const QRgb a = view.image.pixel(160, 120);
    const QRgb b = opaque.image.pixel(160, 120);
    EXPECT_NEAR(qRed(a), qRed(b), 2);
    EXPECT_NEAR(qGreen(a), qGreen(b), 2);
    EXPECT_NEAR(qBlue(a), qBlue(b), 2);
}

TEST_F(ViewExportTest, LegendsScaleWithTheImage) {
    auto r = renderer();
    ASSERT_TRUE(r);
    ViewExportOptions o = options(3200, 2400);
    o.legends = false;
    const QImage plain = renderView(*r, scene_, o).image;
    o.legends = true;
    const QImage legends = renderView(*r, scene_, o).image;
    // The parameter legend is bottom right; at twice the reference size its
    // box is twice as large, so a pixel 400 px in from the corner is covered.
    const QPoint inside(3200 - 300, 2400 - 60);
    EXPECT_NE(plain.pixel(inside), legends.pixel(inside));
    EXPECT_EQ(plain.pixel(10, 10), legends.pixel(10, 10));
}

TEST_F(ViewExportTest, SizeLimits) {
    auto r = renderer();
    ASSERT_TRUE(r);
    EXPECT_GE(maxRenderSide(), 4096);
    EXPECT_EQ(r->maxRenderSide(), maxRenderSide());  // what renderView() uses
    EXPECT_THROW((void)renderView(*r, scene_, options(7681, 100)), InvalidArgumentError);
    EXPECT_THROW((void)renderView(*r, scene_, options(7680, 4321)), InvalidArgumentError);
    EXPECT_THROW((void)renderView(*r, scene_, options(0, 100)), InvalidArgumentError);
}

TEST_F(ViewExportTest, PngWritesAtomically) {
    const fs::path dir = test::testDir("png");
    QImage image(8, 4, QImage::Format_ARGB32);
    image.fill(qRgba(10, 200, 30, 128));
    const fs::path file = dir / "view.png";
    writePng(file, image);
    const QImage back(QString::fromStdString(file.string()));
    ASSERT_FALSE(back.isNull());
    EXPECT_EQ(back.size(), image.size());
    EXPECT_EQ(qAlpha(back.pixel(3, 2)), 128);
    // Failures: the parent is a regular file; the target is a folder.
    std::ofstream(dir / "file") << "x";
    EXPECT_THROW(writePng(dir / "file" / "view.png", image), IoError);
    fs::create_directories(dir / "folder.png");
    EXPECT_THROW(writePng(dir / "folder.png", image), IoError);
    EXPECT_THROW(writePng(dir / "none.png", QImage()), InvalidArgumentError);
    EXPECT_EQ(test::listing(dir), "file folder.png view.png ");
}

}  // namespace
}  // namespace vv::report
