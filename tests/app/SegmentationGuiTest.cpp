// SPDX-License-Identifier: GPL-3.0-or-later
// The Segmentation panel: re-segmenting a loaded DICOM volume with a live
// preview on a worker, Apply / Cancel, a seed picked by clicking the view,
// and the ray-cast iso-surface display. Run under `xvfb-run -a` with
// QT_QPA_PLATFORM=xcb (OpenGL 4.1 needed).
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QMouseEvent>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>

#include "CtaSeriesFixture.h"
#include "GuiFixture.h"
#include "SyntheticCta.h"
#include "gui/MainWindow.h"
#include "gui/SegmentationTask.h"
#include "gui/SeriesDialog.h"
#include "gui/Session.h"
#include "gui/panels/CollapsibleSection.h"
#include "gui/panels/SegmentationPanel.h"
#include "gui/panels/SidePanel.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/render/ViewAnnotations.h"
#include "vv/render/ViewPresets.h"

namespace vv::test {
namespace {

using gui::panels::SegmentationPanel;

fs::path seriesDir() {
    return panelTestDir() / "segmentation-cta";
}

/// The number of vertices of `scene` whose world position satisfies `keep`.
template <typename Predicate>
std::size_t countVertices(const scene::Scene& scene, Predicate keep) {
    std::size_t n = 0;
    for (const auto& mesh : scene.meshes) {
        for (const glm::vec3& p : mesh.positions) {
            n += keep(glm::dvec3(p)) ? 1U : 0U;
        }
    }
    return n;
}

std::size_t vertexCount(const scene::Scene& scene) {
    return countVertices(scene, [](const glm::dvec3&) { return true; });
}

/// The fraction of the pixels of `image` off the background colour `srgb`.
double litFraction(const QImage& image, const glm::vec3& srgb) {
    const glm::ivec3 bg(glm::round(srgb * 255.0F));
    long lit = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            const int d = std::max(
                {std::abs(qRed(p) - bg.r), std::abs(qGreen(p) - bg.g), std::abs(qBlue(p) - bg.b)});
            lit += d > 12 ? 1 : 0;
        }
    }
    return static_cast<double>(lit) / (static_cast<double>(image.width()) * image.height());
}

std::size_t triangleCount(const scene::Scene& scene) {
    std::size_t n = 0;
    for (const auto& mesh : scene.meshes) {
        n += mesh.triangleCount();
    }
    return n;
}

/// A 64 x 64 x 48 synthetic CTA of a 3-generation tree with a bone block
/// beside it (~1000 HU, about 6 mm from the tree), written as a CT series.
class SegmentationGuiTest : public GuiFixture {
  protected:
    static void SetUpTestSuite() {
        GuiFixture::SetUpTestSuite();
        cta_ = writeTestCtaSeries(seriesDir());
    }
    static void TearDownTestSuite() {
        removeTestCtaSeries(seriesDir(), cta_);
        GuiFixture::TearDownTestSuite();
    }

    [[nodiscard]] SegmentationPanel* panel() const { return window_->segmentationPanel(); }

    /// Opens the series through File > Open Folder's path, lets `choose`
    /// adjust the series dialog, accepts it and waits for the vessels.
    void openSeries(const std::function<void(gui::SeriesDialog&)>& choose = {}) {
        QPointer<gui::SeriesDialog> dialog;
        const vv::test::ScopedConnection keep1(
            QObject::connect(window_.get(), &gui::MainWindow::seriesDialogShown, window_.get(),
                             [&dialog](gui::SeriesDialog* d) { dialog = d; }));
        window_->openDicom(QString::fromStdString(seriesDir().string()));
        ASSERT_TRUE(waitUntil([&] { return !dialog.isNull() || !window_->lastError().isEmpty(); }));
        ASSERT_FALSE(dialog.isNull()) << window_->lastError().toStdString();
        if (choose) {
            choose(*dialog);
        }
        dialog->accept();
        ASSERT_TRUE(waitUntil(
            [&] { return window_->volume() != nullptr || !window_->lastError().isEmpty(); },
            60000));
        ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
        ASSERT_NE(window_->viewer()->scene(), nullptr);
        ASSERT_TRUE(waitForFrames(1));
    }

    /// Waits for the next preview (after the debounce) and returns how long
    /// the GUI thread went without processing a 5 ms timer meanwhile.
    [[nodiscard]] qint64 waitForPreview(int previewsBefore) const {
        QElapsedTimer sinceTick;
        sinceTick.start();
        qint64 longestGap = 0;
        QTimer ticker;
        ticker.setInterval(5);
        QObject::connect(&ticker, &QTimer::timeout,
                         [&] { longestGap = std::max(longestGap, sinceTick.restart()); });
        ticker.start();
        EXPECT_TRUE(waitUntil(
            [&] { return panel()->previewsShown() > previewsBefore && !panel()->isPreviewing(); },
            30000))
            << "no preview: " << panel()->messageLabel()->text().toStdString();
        return longestGap;
    }

    /// Scans the viewer for a pixel whose probe lands where `want` holds.
    [[nodiscard]] std::optional<gui::ProbeResult> findPixel(
        const std::function<bool(const glm::dvec3&)>& want) const {
        gui::ViewerWidget* viewer = window_->viewer();
        constexpr int kStep = 6;
        for (int y = kStep; y < viewer->height(); y += kStep) {
            for (int x = kStep; x < viewer->width(); x += kStep) {
                auto hit = viewer->probeAt(QPointF(x, y));
                if (hit && want(glm::dvec3(hit->worldPosition))) {
                    return hit;
                }
            }
        }
        return std::nullopt;
    }

    /// A left click (press and release in place) on the viewer.
    void click(const QPointF& position) const {
        gui::ViewerWidget* viewer = window_->viewer();
        const QPointF global = viewer->mapToGlobal(position);
        QMouseEvent press(QEvent::MouseButtonPress, position, global, Qt::LeftButton,
                          Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(viewer, &press);
        QMouseEvent release(QEvent::MouseButtonRelease, position, global, Qt::LeftButton,
                            Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(viewer, &release);
    }

    [[nodiscard]] QString statusText() const {
        QStringList texts;
        for (const QLabel* label : window_->statusBar()->findChildren<QLabel*>()) {
            texts << label->text();
        }
        return texts.join(QLatin1Char('|'));
    }

    /// The largest voxel side, mm.
    [[nodiscard]] static double voxelSize() {
        const glm::dvec3 s = cta_->volume.spacing();
        return std::max({s.x, s.y, s.z});
    }

    static inline std::unique_ptr<SyntheticCta> cta_;
};

TEST_F(SegmentationGuiTest, PanelIsOnlyEnabledForScenesFromAVolume) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    EXPECT_FALSE(panel()->isEnabled());
    EXPECT_TRUE(panel()->toolTip().contains(QStringLiteral("Open Folder")))
        << panel()->toolTip().toStdString();
    EXPECT_EQ(window_->volume(), nullptr);

    openSeries();
    ASSERT_NE(window_->volume(), nullptr);
    EXPECT_EQ(window_->volume()->dims(), cta_->volume.dims());
    EXPECT_TRUE(panel()->isEnabled());
    // CT defaults from the load, and the modality default shown.
    EXPECT_DOUBLE_EQ(panel()->lowerBox()->value(), 200.0);
    EXPECT_DOUBLE_EQ(panel()->upperBox()->value(), 700.0);
    EXPECT_TRUE(panel()->boneRemovalBox()->isChecked());
    ASSERT_TRUE(waitUntil([&] { return panel()->defaultButton()->isEnabled(); }));
    EXPECT_TRUE(panel()->defaultLabel()->text().contains(QStringLiteral("700")));
    window_->revealPanel(panel());
    QCoreApplication::processEvents();
    window_->grab().save(
        QString::fromStdString((panelTestDir() / "segmentation-panel.png").string()));

    // A mesh scene again: disabled, the volume forgotten.
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    EXPECT_FALSE(panel()->isEnabled());
    EXPECT_EQ(window_->volume(), nullptr);
}

/// A DICOM scene is shaped by its segmentation: the section comes to the top
/// of the side panel, open. A mesh scene puts it back at the bottom, and its
/// disabled controls keep nothing of the last volume (no thresholds, no unit).
TEST_F(SegmentationGuiTest, ADicomSceneBringsTheSectionUpAndAMeshSceneClearsIt) {
    gui::panels::SidePanel* side = window_->sidePanel();
    gui::panels::CollapsibleSection* section = side->sectionOf(panel());
    ASSERT_NE(section, nullptr);
    const auto topmost = [side] {
        gui::panels::CollapsibleSection* top = nullptr;
        for (gui::panels::CollapsibleSection* s : side->sections()) {
            if (top == nullptr || s->y() < top->y()) {
                top = s;
            }
        }
        return top;
    };
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    QCoreApplication::processEvents();
    EXPECT_EQ(side->sections().back(), section);

    openSeries();
    QCoreApplication::processEvents();
    EXPECT_EQ(side->sections().front(), section);
    EXPECT_EQ(topmost(), section) << "not placed at the top of the panel";
    EXPECT_TRUE(section->isExpanded());
    EXPECT_TRUE(panel()->lowerBox()->text().contains(QStringLiteral("HU")));

    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    QCoreApplication::processEvents();
    EXPECT_EQ(side->sections().back(), section);
    EXPECT_NE(topmost(), section);
    EXPECT_FALSE(panel()->isEnabled());
    for (const QDoubleSpinBox* box :
         {panel()->lowerBox(), panel()->upperBox(), panel()->isoBox()}) {
        const QString shown = box->text();
        EXPECT_FALSE(shown.contains(QRegularExpression(QStringLiteral("[0-9]"))))
            << "the last volume's value stays: " << shown.toStdString();
        EXPECT_FALSE(shown.contains(QStringLiteral("HU"))) << shown.toStdString();
    }
    EXPECT_FALSE(panel()->boneRemovalBox()->isChecked());
    EXPECT_TRUE(panel()->defaultLabel()->text().isEmpty());
}

TEST_F(SegmentationGuiTest, ThresholdChangesPreviewOnAWorker) {
    openSeries();
    const auto loaded = window_->viewer()->scene();
    const Aabb treeBounds = loaded->bounds();
    // No bone removal and a range above the lumen: only the bone block is left.
    const int before = panel()->previewsShown();
    panel()->boneRemovalBox()->setChecked(false);
    panel()->upperBox()->setValue(3000.0);
    panel()->lowerBox()->setValue(800.0);
    EXPECT_TRUE(panel()->isPreviewing());
    EXPECT_EQ(window_->viewer()->scene(), loaded);  // debounced: not there yet
    // Started at once, it returns before the result: the work runs on a worker.
    panel()->startPreview();
    EXPECT_TRUE(panel()->isPreviewing());
    EXPECT_EQ(window_->viewer()->scene(), loaded);
    const qint64 gap = waitForPreview(before);
    ASSERT_NE(panel()->lastOutcome(), nullptr);
    const auto& block = *panel()->lastOutcome();
    // The GUI thread's longest stall (a frame of the new scene): a figure, not
    // a test (load on the machine sets it); what is tested is that the work
    // left the GUI thread, above.
    std::cout << "[ figures ] preview, step " << block.step << ": " << block.milliseconds
              << " ms on the worker; longest GUI stall " << gap << " ms\n";
    EXPECT_EQ(block.step, 2);
    const auto shown = window_->viewer()->scene();
    ASSERT_EQ(shown, block.scene);
    ASSERT_EQ(shown->meshes.size(), 1U);
    EXPECT_EQ(shown->meshes[0].name, "vessels (preview)");
    EXPECT_TRUE(statusText().contains(QStringLiteral("Preview"))) << statusText().toStdString();
    // Every vertex of the preview lies at the bone block (two coarse voxels of slack).
    const double margin = 2.0 * block.step * voxelSize();
    EXPECT_EQ(countVertices(*shown, [&](const glm::dvec3& p) { return !cta_->inBone(p, margin); }),
              0U);
    EXPECT_LT(glm::length(shown->bounds().size()), 0.6F * glm::length(treeBounds.size()));

    // Back to the CT default range and bone removal: the tree again, far larger than the block.
    ASSERT_TRUE(waitUntil([&] { return panel()->defaultButton()->isEnabled(); }));
    const int again = panel()->previewsShown();
    panel()->defaultButton()->click();
    panel()->boneRemovalBox()->setChecked(true);
    (void)waitForPreview(again);
    const auto tree = window_->viewer()->scene();
    EXPECT_DOUBLE_EQ(panel()->lowerBox()->value(), 200.0);
    EXPECT_GT(countVertices(*tree, [&](const glm::dvec3& p) { return !cta_->inBone(p, margin); }),
              vertexCount(*tree) / 2);
    EXPECT_GT(glm::length(tree->bounds().size()), 0.8F * glm::length(treeBounds.size()));
    EXPECT_NE(triangleCount(*tree), triangleCount(*shown));
}

TEST_F(SegmentationGuiTest, ApplyReplacesTheSceneAtFullResolutionKeepingTheCamera) {
    openSeries();
    window_->viewer()->setCamera(window_->viewer()->camera());  // fixed from here on
    const render::Camera camera = window_->viewer()->camera();
    const int before = panel()->previewsShown();
    panel()->lowerBox()->setValue(250.0);
    (void)waitForPreview(before);
    const std::size_t previewTriangles = triangleCount(*window_->viewer()->scene());

    bool applied = false;
    QObject::connect(panel(), &SegmentationPanel::applyFinished, window_.get(),
                     [&applied](bool ok) { applied = ok; });
    panel()->applyButton()->click();
    EXPECT_TRUE(panel()->isApplying());
    EXPECT_FALSE(panel()->applyButton()->isEnabled());
    EXPECT_TRUE(panel()->cancelButton()->isEnabled());
    ASSERT_TRUE(waitUntil([&] { return !panel()->isApplying(); }, 60000));
    ASSERT_TRUE(applied) << panel()->messageLabel()->text().toStdString();
    const auto scene = window_->viewer()->scene();
    ASSERT_EQ(scene->meshes.size(), 1U);
    EXPECT_EQ(scene->meshes[0].name, "vessels");
    EXPECT_EQ(panel()->lastOutcome()->step, 1);
    EXPECT_GT(triangleCount(*scene), previewTriangles);
    EXPECT_EQ(window_->viewer()->camera().target(), camera.target());
    EXPECT_FLOAT_EQ(window_->viewer()->camera().distance(), camera.distance());
    EXPECT_TRUE(waitForFrames(1));
}

TEST_F(SegmentationGuiTest, LivePreviewKeepsTheCameraTheUserMoved) {
    openSeries();
    ASSERT_TRUE(waitForFrames(1));
    // DICOM data is in the patient frame: the orientation marker names patient sides.
    EXPECT_EQ(window_->viewer()->viewAnnotations().frame, render::SceneFrame::PatientLps);
    // The user turns and zooms the view as a person would: a drag and a wheel notch.
    auto* viewer = window_->viewer();
    const QPointF from(viewer->width() * 0.4, viewer->height() * 0.5);
    const QPointF to(viewer->width() * 0.6, viewer->height() * 0.4);
    leftDrag(viewer, from, to);
    const render::Camera moved = viewer->camera();
    ASSERT_GT(std::abs(moved.rotation().w), 0.0F);
    ASSERT_LT(std::abs(moved.rotation().w), 0.9999F) << "the drag did not turn the view";

    const int before = panel()->previewsShown();
    panel()->lowerBox()->setValue(260.0);
    (void)waitForPreview(before);
    ASSERT_GT(panel()->previewsShown(), before);
    const quint64 frames = viewer->framesWithScene();
    ASSERT_TRUE(waitForFrames(frames + 1));
    const render::Camera after = viewer->camera();
    EXPECT_FLOAT_EQ(after.rotation().w, moved.rotation().w);
    EXPECT_FLOAT_EQ(after.rotation().x, moved.rotation().x);
    EXPECT_FLOAT_EQ(after.rotation().y, moved.rotation().y);
    EXPECT_FLOAT_EQ(after.rotation().z, moved.rotation().z);
    EXPECT_EQ(after.target(), moved.target());
    EXPECT_FLOAT_EQ(after.distance(), moved.distance());
}

TEST_F(SegmentationGuiTest, CancelledApplyKeepsTheScene) {
    openSeries();
    const auto loaded = window_->viewer()->scene();
    std::optional<bool> applied;
    QObject::connect(panel(), &SegmentationPanel::applyFinished, window_.get(),
                     [&applied](bool ok) { applied = ok; });
    panel()->apply();
    ASSERT_TRUE(panel()->isApplying());
    panel()->cancelButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !panel()->isApplying(); }, 60000));
    ASSERT_TRUE(applied.has_value());
    EXPECT_FALSE(*applied);
    EXPECT_EQ(window_->viewer()->scene(), loaded);
    EXPECT_TRUE(panel()->messageLabel()->text().contains(QStringLiteral("cancelled")));
    EXPECT_TRUE(panel()->applyButton()->isEnabled());
}

TEST_F(SegmentationGuiTest, ClickedSeedKeepsOnlyItsStructure) {
    // Tree and bone block both kept: no bone removal, a range up to 3000 HU.
    openSeries([](gui::SeriesDialog& dialog) {
        dialog.automaticThreshold()->setChecked(false);
        dialog.lowerThreshold()->setValue(200.0);
        dialog.upperThreshold()->setValue(3000.0);
        dialog.componentsBox()->setValue(2);
        dialog.boneRemoval()->setChecked(false);
    });
    const auto both = window_->viewer()->scene();
    const double voxel = voxelSize();
    ASSERT_GT(countVertices(*both, [&](const glm::dvec3& p) { return cta_->inBone(p, voxel); }),
              0U);
    const auto onBlock = findPixel([&](const glm::dvec3& p) { return cta_->inBone(p, voxel); });
    const auto onTree =
        findPixel([&](const glm::dvec3& p) { return !cta_->inBone(p, 3.0 * voxel); });
    ASSERT_TRUE(onBlock && onTree);

    // A click with Pick Seed on: the seed, its value, the seed mode, a preview of the block.
    panel()->pickSeedButton()->setChecked(true);
    const int before = panel()->previewsShown();
    click(onBlock->widgetPosition);
    ASSERT_TRUE(panel()->seed().has_value()) << panel()->messageLabel()->text().toStdString();
    EXPECT_FALSE(panel()->pickSeedButton()->isChecked());
    EXPECT_EQ(panel()->modeChooser()->currentIndex(),
              static_cast<int>(SegmentationPanel::Mode::Seed));
    EXPECT_FALSE(panel()->componentsBox()->isEnabled());
    const glm::ivec3 s = *panel()->seed();
    EXPECT_TRUE(panel()->seedLabel()->text().contains(QString::number(s.x)));
    EXPECT_GE(cta_->volume.value(s.x, s.y, s.z), 200.0F);
    (void)waitForPreview(before);
    const double coarseMargin = 2.0 * panel()->lastOutcome()->step * voxel;
    EXPECT_EQ(countVertices(*window_->viewer()->scene(),
                            [&](const glm::dvec3& p) { return !cta_->inBone(p, coarseMargin); }),
              0U);

    // Apply: the block at full resolution, nothing of the tree.
    panel()->apply();
    ASSERT_TRUE(waitUntil([&] { return !panel()->isApplying(); }, 60000));
    const auto block = window_->viewer()->scene();
    ASSERT_EQ(panel()->lastOutcome()->scene, block);
    EXPECT_EQ(panel()->lastOutcome()->componentsKept, 1U);
    EXPECT_EQ(countVertices(*block, [&](const glm::dvec3& p) { return !cta_->inBone(p, voxel); }),
              0U);

    // A seed on the tree (where it was clicked before): the tree alone.
    ASSERT_TRUE(panel()->pickSeed(onTree->worldPosition));
    panel()->apply();
    ASSERT_TRUE(waitUntil([&] { return !panel()->isApplying(); }, 60000));
    const auto tree = window_->viewer()->scene();
    ASSERT_EQ(panel()->lastOutcome()->scene, tree);
    EXPECT_EQ(countVertices(*tree, [&](const glm::dvec3& p) { return cta_->inBone(p, 0.0); }), 0U);
    EXPECT_GT(vertexCount(*tree), 0U);
}

TEST_F(SegmentationGuiTest, SeedInTheBackgroundExplainsAndKeepsTheScene) {
    openSeries();
    const auto loaded = window_->viewer()->scene();
    // Voxel (1, 1, 1): tissue, about 40 HU, far from the tree.
    const glm::vec3 tissue(cta_->volume.worldPosition({1.0, 1.0, 1.0}));
    ASSERT_LT(cta_->volume.value(1, 1, 1), 200.0F);
    EXPECT_FALSE(panel()->pickSeed(tissue));
    EXPECT_FALSE(panel()->seed().has_value());
    const QString message = panel()->messageLabel()->text();
    EXPECT_TRUE(message.contains(QStringLiteral("outside the threshold range")))
        << message.toStdString();
    EXPECT_TRUE(message.contains(QStringLiteral("no component there")));
    EXPECT_TRUE(message.contains(QStringLiteral("(1, 1, 1)")));
    EXPECT_EQ(panel()->modeChooser()->currentIndex(),
              static_cast<int>(SegmentationPanel::Mode::Largest));
    EXPECT_FALSE(panel()->isPreviewing());
    // Outside the volume altogether.
    EXPECT_FALSE(panel()->pickSeed(glm::vec3(cta_->volume.worldPosition({-20.0, 0.0, 0.0}))));
    EXPECT_TRUE(panel()->messageLabel()->text().contains(QStringLiteral("outside the volume")));
    QCoreApplication::processEvents();
    EXPECT_EQ(window_->viewer()->scene(), loaded);
}

TEST_F(SegmentationGuiTest, RaycastDisplayShowsTheVolumeWithVssAndSwitchesBack) {
    openSeries();
    gui::ViewerWidget* viewer = window_->viewer();
    const auto meshes = viewer->scene();
    ASSERT_TRUE(waitForVss());
    EXPECT_FALSE(panel()->isoBox()->isEnabled());

    auto* chooser = panel()->displayChooser();
    chooser->setCurrentIndex(
        chooser->findData(static_cast<int>(SegmentationPanel::Display::RaycastIsoSurface)));
    EXPECT_EQ(panel()->display(), SegmentationPanel::Display::RaycastIsoSurface);
    ASSERT_EQ(viewer->volume(), window_->volume());
    EXPECT_FLOAT_EQ(viewer->isoValue(), 200.0F);  // the lower threshold
    EXPECT_TRUE(panel()->isoBox()->isEnabled());
    EXPECT_FALSE(panel()->lowerBox()->isEnabled());
    EXPECT_FALSE(panel()->applyButton()->isEnabled());
    ASSERT_NE(viewer->scene(), nullptr);
    EXPECT_TRUE(viewer->scene()->meshes.empty());
    // Still the patient's frame: the marker names patient sides, the home
    // view is the anterior one.
    EXPECT_EQ(viewer->scene()->frame, scene::SceneFrame::PatientLps);
    EXPECT_EQ(viewer->viewAnnotations().frame, render::SceneFrame::PatientLps);
    EXPECT_NEAR(std::abs(glm::dot(viewer->camera().homeRotation(),
                                  render::anatomicalRotation(render::AnatomicalView::Anterior))),
                1.0F, 1e-5F);
    ASSERT_TRUE(waitForFrames(2));
    ASSERT_TRUE(waitForVss());
    const QImage image = viewer->grabFramebuffer();
    // Vessels and VSS cover a good part of the view: pixels off the background.
    EXPECT_GT(litFraction(image, viewer->background()), 0.05);
    EXPECT_TRUE(viewer->vssStatus().shown);
    image.save(QString::fromStdString((panelTestDir() / "segmentation-raycast.png").string()));

    // The probe on the ray-cast iso-surface: position and depth, no value.
    const auto hit = findPixel([](const glm::dvec3&) { return true; });
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->meshIndex, -1);
    EXPECT_TRUE(std::isnan(hit->value));
    EXPECT_GT(hit->linearDepth, 0.0F);
    EXPECT_TRUE(cta_->volume.worldBounds().min.x - 1.0F <= hit->worldPosition.x &&
                hit->worldPosition.x <= cta_->volume.worldBounds().max.x + 1.0F);
    // A seed picked on the iso-surface.
    EXPECT_TRUE(panel()->pickSeed(hit->worldPosition))
        << panel()->messageLabel()->text().toStdString();

    // A higher iso value ray casts a different surface.
    panel()->isoBox()->setValue(600.0);
    EXPECT_FLOAT_EQ(viewer->isoValue(), 600.0F);

    // Back to the surface mesh: the meshes as before, no volume.
    chooser->setCurrentIndex(
        chooser->findData(static_cast<int>(SegmentationPanel::Display::SurfaceMesh)));
    EXPECT_EQ(viewer->volume(), nullptr);
    EXPECT_EQ(viewer->scene(), meshes);
    EXPECT_TRUE(panel()->lowerBox()->isEnabled());
    ASSERT_TRUE(waitForFrames(2));
    // Drawn as before, not clipped away by the volume's clip planes.
    EXPECT_GT(litFraction(viewer->grabFramebuffer(), viewer->background()), 0.05);
}

TEST_F(SegmentationGuiTest, SessionReopensTheSeriesWithItsSegmentation) {
    openSeries();
    // A segmentation other than the default: threshold 300..700 HU, applied.
    panel()->lowerBox()->setValue(300.0);
    bool applied = false;
    QObject::connect(panel(), &SegmentationPanel::applyFinished, window_.get(),
                     [&applied](bool ok) { applied = ok; });
    panel()->applyButton()->click();
    ASSERT_TRUE(waitUntil([&] { return !panel()->isApplying(); }, 60000));
    ASSERT_TRUE(applied) << panel()->messageLabel()->text().toStdString();
    const std::size_t triangles = triangleCount(*window_->viewer()->scene());

    const fs::path file = panelTestDir() / "dicom-session.vvs";
    ASSERT_TRUE(window_->saveSessionTo(QString::fromStdString(file.string())));
    const gui::Session saved = gui::loadSession(file);
    ASSERT_TRUE(saved.dicom.has_value());
    EXPECT_FALSE(saved.dicom->seriesInstanceUid.empty());
    ASSERT_TRUE(saved.dicom->segmentation.range.has_value());
    EXPECT_FLOAT_EQ(saved.dicom->segmentation.range->lower, 300.0F);

    // A preview on screen is not the document's segmentation: saved again,
    // the session keeps the applied 300 HU and the status bar says so.
    const int previews = panel()->previewsShown();
    panel()->lowerBox()->setValue(250.0);
    (void)waitForPreview(previews);
    ASSERT_TRUE(window_->document()->showsPreview());
    ASSERT_TRUE(window_->saveSessionTo(QString::fromStdString(file.string())));
    const gui::Session withPreview = gui::loadSession(file);
    ASSERT_TRUE(withPreview.dicom.has_value());
    ASSERT_TRUE(withPreview.dicom->segmentation.range.has_value());
    EXPECT_FLOAT_EQ(withPreview.dicom->segmentation.range->lower, 300.0F);
    const auto* status = window_->statusBar()->findChild<QLabel*>(QStringLiteral("statusMessage"));
    ASSERT_NE(status, nullptr);
    EXPECT_TRUE(status->text().contains(QStringLiteral("not applied")))
        << status->text().toStdString();

    // Reopened: the same vessels, without the series chooser.
    window_->setScene(nullptr, QString());
    bool dialogShown = false;
    bool sessionApplied = false;
    QObject::connect(window_.get(), &gui::MainWindow::seriesDialogShown, window_.get(),
                     [&](gui::SeriesDialog*) { dialogShown = true; });
    QObject::connect(window_.get(), &gui::MainWindow::sessionApplied, window_.get(),
                     [&] { sessionApplied = true; });
    ASSERT_TRUE(window_->openSession(QString::fromStdString(file.string())));
    ASSERT_TRUE(
        waitUntil([&] { return sessionApplied || !window_->lastError().isEmpty(); }, 60000));
    ASSERT_TRUE(window_->lastError().isEmpty()) << window_->lastError().toStdString();
    EXPECT_FALSE(dialogShown);
    ASSERT_NE(window_->viewer()->scene(), nullptr);
    EXPECT_EQ(triangleCount(*window_->viewer()->scene()), triangles);
    EXPECT_NE(window_->volume(), nullptr);
    EXPECT_DOUBLE_EQ(panel()->lowerBox()->value(), 300.0);
}

TEST_F(SegmentationGuiTest, VolumeTooBigToRayCastFallsBackToTheSurface) {
    openSeries();
    gui::ViewerWidget* viewer = window_->viewer();
    const auto meshes = viewer->scene();
    // 40,000 slices: more than any GPU's 3-D texture side (llvmpipe: 2048).
    auto huge = std::make_shared<scene::Volume>(glm::ivec3(2, 2, 40000), scene::VoxelType::Int16);
    panel()->setVolume(huge);
    bool volumeFailed = false;
    bool renderFailed = false;
    QObject::connect(viewer, &gui::ViewerWidget::volumeFailed, viewer,
                     [&](const QString&) { volumeFailed = true; });
    QObject::connect(viewer, &gui::ViewerWidget::renderFailed, viewer,
                     [&](const QString&) { renderFailed = true; });
    auto* chooser = panel()->displayChooser();
    chooser->setCurrentIndex(
        chooser->findData(static_cast<int>(SegmentationPanel::Display::RaycastIsoSurface)));
    ASSERT_TRUE(waitUntil([&] { return volumeFailed || renderFailed; }, 30000));
    EXPECT_TRUE(volumeFailed);
    EXPECT_FALSE(renderFailed);
    // The panel is back on the surface, says why, and the viewer goes on drawing.
    EXPECT_TRUE(
        waitUntil([&] { return panel()->display() == SegmentationPanel::Display::SurfaceMesh; }));
    EXPECT_EQ(viewer->volume(), nullptr);
    EXPECT_EQ(viewer->scene(), meshes);
    EXPECT_NE(panel()->messageLabel()->text().indexOf(QStringLiteral("cannot be ray cast")), -1)
        << panel()->messageLabel()->text().toStdString();
    ASSERT_TRUE(waitForFrames(2));
    EXPECT_GT(litFraction(viewer->grabFramebuffer(), viewer->background()), 0.05);
    EXPECT_FALSE(renderFailed);
}

}  // namespace
}  // namespace vv::test
