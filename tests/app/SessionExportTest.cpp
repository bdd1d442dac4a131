// SPDX-License-Identifier: GPL-3.0-or-later
// The GUI and the command line render a session alike: a view set up in the
// GUI (two files, one object translucent, a colour map, p, iso-lines, a cue,
// a light, a turned camera) is saved as a session and exported with File >
// Export Image; `vesselview-cli render --session` at the same size gives the
// same pixels. Needs a display: xvfb-run -a, QT_QPA_PLATFORM=xcb.
#include <QCheckBox>
#include <QImage>
#include <QLineEdit>
#include <QSpinBox>
#include <memory>
#include <sstream>
#include <string>

#include "GuiFixture.h"
#include "cli/Cli.h"
#include "gui/ExportImageDialog.h"
#include "gui/ExportWorker.h"
#include "vv/meshio/MeshWriter.h"

namespace vv::test {
namespace {

class SessionExportTest : public GuiFixture {
  protected:
    /// File > Export Image of the current view at width x height, with legends.
    QImage exportImage(const fs::path& file, int width, int height) {
        gui::ExportImageDialog dialog(*window_->viewer(), window_.get());
        dialog.fileEdit()->setText(QString::fromStdString(file.string()));
        dialog.keepAspectBox()->setChecked(false);
        dialog.widthBox()->setValue(width);
        dialog.heightBox()->setValue(height);
        dialog.legendsBox()->setChecked(window_->viewer()->legendsVisible());
        auto finished = std::make_shared<bool>(false);
        auto succeeded = std::make_shared<bool>(false);
        QObject::connect(&dialog, &gui::ExportImageDialog::exportStarted,
                         [finished, succeeded](gui::ExportWorker* worker) {
                             QObject::connect(worker, &gui::ExportWorker::succeeded,
                                              [succeeded] { *succeeded = true; });
                             QObject::connect(worker, &gui::ExportWorker::finished,
                                              [finished] { *finished = true; });
                         });
        dialog.accept();
        EXPECT_TRUE(waitUntil([&] { return *finished; }, 120000)) << "the export never ended";
        EXPECT_TRUE(*succeeded);
        return QImage(QString::fromStdString(file.string()));
    }
};

TEST_F(SessionExportTest, TheCommandLineRendersWhatTheGuiExports) {
    const fs::path dir = panelTestDir() / "session-export";
    fs::create_directories(dir);
    const fs::path tube = dir / "tube.vtp";
    meshio::writeVtp(makeTubeScene()->meshes.front(), tube);
    window_->openFiles({QStringLiteral(VV_DEMO_VTP), QString::fromStdString(tube.string())});
    auto* viewer = window_->viewer();
    ASSERT_TRUE(waitUntil(
        [&] { return viewer->scene() != nullptr && viewer->scene()->meshes.size() == 2; }, 60000));
    ASSERT_TRUE(waitForFrames(1));

    // A view unlike the defaults, as a user would leave it.
    render::Camera camera = viewer->camera();
    camera.rotateView(0.7F, glm::vec3(0.3F, 1.0F, 0.0F));
    camera.zoom(1.3F);
    camera.pan(glm::vec2(25.0F, -10.0F));
    viewer->setCamera(camera);
    render::VssSettings vss = viewer->vssSettings();
    vss.scale = colormaps::DepthScale::PseudoChromadepth;
    vss.solver.p = 4.0;
    vss.isoLines = 6;
    vss.isoLineStrength = 0.7F;
    viewer->setVssSettings(vss);
    render::AoSettings ao = viewer->aoSettings();
    ao.radius = 5.0F;
    viewer->setAoSettings(ao);
    render::MeshStyle style = viewer->style();
    style.colorMap = colormaps::ColorMap::Inferno;
    style.bins = 7;
    style.light = {35.0F, -15.0F};
    style.objects.resize(2);
    style.objects[1].opacity = 0.5F;
    style.objects[1].array = "pressure";
    style.objects[0].color = glm::vec3(0.2F, 0.6F, 0.9F);
    viewer->setStyle(style);
    viewer->setVesselCue({render::VesselCue::Fog, 0.5F, 1.0F});
    viewer->setBackground(glm::vec3(0.05F, 0.1F, 0.2F));
    ASSERT_TRUE(waitForVss());

    const fs::path session = dir / "view.vvs";
    ASSERT_TRUE(window_->saveSessionTo(QString::fromStdString(session.string())));
    const QImage fromGui = exportImage(dir / "gui.png", 480, 360);
    ASSERT_EQ(fromGui.size(), QSize(480, 360));

    const fs::path cliFile = dir / "cli.png";
    std::ostringstream out;
    std::ostringstream err;
    const int code = cli::run(
        {"render", "--session", session.string(), "-o", cliFile.string(), "--size", "480x360"}, out,
        err);
    ASSERT_EQ(code, cli::kOk) << err.str();
    const QImage fromCli(QString::fromStdString(cliFile.string()));
    ASSERT_EQ(fromCli.size(), fromGui.size());

    // Identical: the same scene, settings and camera through the same renderer.
    EXPECT_TRUE(fromGui.convertToFormat(QImage::Format_RGB32) ==
                fromCli.convertToFormat(QImage::Format_RGB32))
        << changedFraction(fromGui, fromCli) * 100.0
        << " % of the pixels differ by more than 8; see " << (dir / "gui.png") << " and "
        << cliFile;
    // And the view is the one set up above, not the defaults: a default
    // render of the same files differs.
    const fs::path plainFile = dir / "plain.png";
    ASSERT_EQ(
        cli::run({"render", VV_DEMO_VTP, "-o", plainFile.string(), "--size", "480x360"}, out, err),
        cli::kOk)
        << err.str();
    EXPECT_GT(changedFraction(QImage(QString::fromStdString(plainFile.string())), fromCli), 0.1);
}

}  // namespace
}  // namespace vv::test
