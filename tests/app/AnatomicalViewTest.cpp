// SPDX-License-Identifier: GPL-3.0-or-later
// The 3-D view of a DICOM scene as a radiologist expects it, whatever way the
// series was scanned: `vesselview-cli render SERIES` opens in the anterior
// view (head up, the patient's left on the screen's right, like the coronal
// slice; a vessel running head to foot upright, not end-on), and the named
// anatomical views show the patient's sides where they belong (superior and
// inferior with anterior up). The phantom (tests/support/AnatomyPhantom.h)
// is written head first, feet first and oblique; the rendered pixels are
// checked, not camera vectors. Needs OpenGL: run under `xvfb-run -a`.
#include <gtest/gtest.h>

#include <QImage>
#include <filesystem>
#include <string>
#include <vector>

#include "AnatomyPhantom.h"
#include "CliRun.h"
#include "vv/render/Camera.h"
#include "vv/render/ViewAnnotations.h"
#include "vv/render/ViewPresets.h"
#include "vv/scene/Mesh.h"
#include "vv/slices/OrientationLetters.h"
#include "vv/slices/SlicePlane.h"

namespace vv::test {
namespace {

namespace fs = std::filesystem;

fs::path testDir() {
    return processTestDir("anatomical-views");
}

class AnatomicalViewTest : public ::testing::TestWithParam<PhantomGrid> {
  protected:
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(testDir(), ec);
    }

    /// The phantom on this test's grid rendered by the CLI with `extra`
    /// options (e.g. --view superior): what was drawn.
    static DrawnShape render(const PhantomGrid& grid, const std::vector<std::string>& extra) {
        const fs::path series = testDir() / grid.patientPosition / grid.name;
        if (!fs::exists(series)) {
            writePhantomSeries(series, grid);
        }
        const fs::path output =
            testDir() /
            (grid.name + (extra.empty() ? std::string("-default") : extra.back()) + ".png");
        std::vector<std::string> args{"render",
                                      series.string(),
                                      "-o",
                                      output.string(),
                                      "--size",
                                      "480x480",
                                      "--vss",
                                      "off",
                                      "--legends",
                                      "off",
                                      "--orientation-marker",
                                      "off",
                                      "--scale-bar",
                                      "off",
                                      "--background",
                                      "#000000"};
        args.insert(args.end(), extra.begin(), extra.end());
        const CliRunResult r = runCli(args);
        EXPECT_EQ(r.code, 0) << r.err;
        const QImage image(QString::fromStdString(output.string()));
        EXPECT_FALSE(image.isNull()) << output;
        return {image, qRgb(0, 0, 0)};
    }
};

TEST_P(AnatomicalViewTest, ADicomSeriesOpensInTheAnteriorView) {
    EXPECT_TRUE(showsAnteriorView(render(GetParam(), {})));
}

TEST_P(AnatomicalViewTest, NamedViewsShowThePatientsSidesWhereTheyBelong) {
    const PhantomGrid& grid = GetParam();
    EXPECT_TRUE(showsAnteriorView(render(grid, {"--view", "anterior"})));
    EXPECT_TRUE(showsAnteriorView(render(grid, {"--view", "far"})))
        << "far: the scene's home orientation, anterior for DICOM";
    EXPECT_TRUE(showsPosteriorView(render(grid, {"--view", "posterior"})));
    EXPECT_TRUE(showsAxialView(render(grid, {"--view", "superior"}), true));
    EXPECT_TRUE(showsAxialView(render(grid, {"--view", "inferior"}), false));
}

INSTANTIATE_TEST_SUITE_P(Grids, AnatomicalViewTest,
                         ::testing::Values(headFirstGrid(), feetFirstGrid(), obliqueGrid()),
                         [](const ::testing::TestParamInfo<PhantomGrid>& param) {
                             return param.index == 0   ? std::string("HeadFirst")
                                    : param.index == 1 ? std::string("FeetFirst")
                                                       : std::string("Oblique");
                         });

TEST(AnatomicalViewLettersTest, TheHomeViewsMarkerAgreesWithTheCoronalSlice) {
    // The anterior view looks as the coronal slice does: its edges name the
    // same patient sides (the marker's letters, render::edgeLabels).
    render::Camera camera;
    camera.setViewport(400, 400);
    camera.setRotation(render::homeRotation(scene::SceneFrame::PatientLps));
    const render::EdgeLabels edges = edgeLabels(camera, render::SceneFrame::PatientLps);
    slices::SlicePlane plane;
    plane.right = slices::sliceRight(slices::SliceOrientation::Coronal);
    plane.down = slices::sliceDown(slices::SliceOrientation::Coronal);
    const slices::EdgeLetters coronal = slices::edgeLetters(plane);
    EXPECT_EQ(edges.left.toStdString(), coronal.left);
    EXPECT_EQ(edges.right.toStdString(), coronal.right);
    EXPECT_EQ(edges.top.toStdString(), coronal.top);
    EXPECT_EQ(edges.bottom.toStdString(), coronal.bottom);
    // Meshes without a patient frame keep the former home view.
    EXPECT_FLOAT_EQ(render::homeRotation(scene::SceneFrame::Unknown).w, 1.0F);
}

}  // namespace
}  // namespace vv::test
