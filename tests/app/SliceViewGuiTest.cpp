// SPDX-License-Identifier: GPL-3.0-or-later
// The slice views: shown for a scene from a DICOM series only, the layout
// switch of View > Slices, scrolling through slices (slice, position and
// read-out follow), window / level by drag and by preset (the pixels follow
// the window), the segmentation overlay on the slices. Run under
// `xvfb-run -a` with QT_QPA_PLATFORM=xcb.
#include <gtest/gtest.h>

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QHelpEvent>
#include <QJsonDocument>
#include <QJsonObject>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QLineF>
#include <QLocale>
#include <QMenu>
#include <QMouseEvent>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>

#include "CtaSeriesFixture.h"
#include "GuiFixture.h"
#include "ReportTestUtil.h"
#include "SyntheticCta.h"
#include "common/SliceTexts.h"
#include "gui/ExportWorker.h"
#include "gui/MainWindow.h"
#include "gui/ReportDialog.h"
#include "gui/SeriesDialog.h"
#include "gui/SliceCursor.h"
#include "gui/SliceView.h"
#include "gui/SliceWorkspace.h"
#include "gui/panels/SegmentationPanel.h"
#include "vv/slices/Reslice.h"
#include "vv/slices/SliceOverlay.h"
#include "vv/slices/WindowLevel.h"

namespace vv::test {
namespace {

using gui::SliceLayout;
using gui::SliceView;
using slices::SliceOrientation;

fs::path seriesDir() {
    return panelTestDir() / "slices-cta";
}

class SliceViewGuiTest : public GuiFixture {
  protected:
    static void SetUpTestSuite() {
        GuiFixture::SetUpTestSuite();
        cta_ = writeTestCtaSeries(seriesDir());
    }
    static void TearDownTestSuite() {
        removeTestCtaSeries(seriesDir(), cta_);
        GuiFixture::TearDownTestSuite();
    }

    void SetUp() override {
        // Every test starts with the default layout (the layout is remembered).
        QSettings().remove(QLatin1String(gui::SliceWorkspace::kLayoutKey));
        GuiFixture::SetUp();
    }

    [[nodiscard]] gui::SliceWorkspace* workspace() const { return window_->sliceWorkspace(); }
    [[nodiscard]] SliceView* view(SliceOrientation o) const { return workspace()->sliceView(o); }

    void openSeries() {
        openDicomFolder(seriesDir());
        if (HasFatalFailure()) {
            return;
        }
        for (const auto o :
             {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
            view(o)->waitForSlice();
        }
        QCoreApplication::processEvents();
    }

    /// The View > Slices action whose text (without '&') is `text`.
    [[nodiscard]] QAction* menuAction(const QMenu* menu, const QString& text) const {
        for (QAction* a : menu->actions()) {
            if (a->text().remove(QLatin1Char('&')) == text) {
                return a;
            }
        }
        ADD_FAILURE() << "no action " << text.toStdString();
        return nullptr;
    }

    static void wheel(QWidget* widget, int notches) {
        const QPointF at(widget->width() / 2.0, widget->height() / 2.0);
        QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(widget, &event);
    }

    static inline std::unique_ptr<SyntheticCta> cta_;
};

/// Shows the slice of `view` with the most pixels in label 1's outline
/// colour; returns its index, -1 when no slice has any.
int showSliceWithMostOutline(SliceView* view) {
    const QRgb colour = 0xFF000000U | slices::overlayColor(1);
    int best = -1;
    int bestCount = 0;
    for (int k = 0; k < view->sliceCount(); ++k) {
        view->setSliceIndex(k);
        view->waitForSlice();
        const QImage& image = view->sliceImage();
        int n = 0;
        for (int y = 0; y < image.height(); ++y) {
            for (int x = 0; x < image.width(); ++x) {
                n += image.pixel(x, y) == colour ? 1 : 0;
            }
        }
        if (n > bestCount) {
            bestCount = n;
            best = k;
        }
    }
    if (best >= 0) {
        view->setSliceIndex(best);
        view->waitForSlice();
    }
    return best;
}

TEST_F(SliceViewGuiTest, MeshScenesShowNoSliceViews) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    QCoreApplication::processEvents();
    EXPECT_FALSE(workspace()->showsSlices());
    EXPECT_FALSE(workspace()->menu()->menuAction()->isVisible());
    EXPECT_TRUE(window_->viewer()->isVisible());

    openSeries();
    EXPECT_TRUE(workspace()->showsSlices());
    EXPECT_TRUE(workspace()->menu()->menuAction()->isVisible());
    for (const auto o :
         {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
        EXPECT_TRUE(view(o)->isVisible());
        EXPECT_FALSE(view(o)->sliceImage().isNull());
    }

    // A mesh scene again: the slice views go.
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    QCoreApplication::processEvents();
    EXPECT_FALSE(workspace()->showsSlices());
    EXPECT_FALSE(workspace()->menu()->menuAction()->isVisible());
}

TEST_F(SliceViewGuiTest, LayoutSwitch) {
    openSeries();
    QMenu* menu = workspace()->menu();
    const int fullWidth = workspace()->width();

    menuAction(menu, gui::SliceWorkspace::tr("3-D Only"))->trigger();
    QCoreApplication::processEvents();
    EXPECT_TRUE(window_->viewer()->isVisible());
    EXPECT_FALSE(workspace()->showsSlices());
    EXPECT_GT(window_->viewer()->width(), fullWidth * 9 / 10);

    menuAction(menu, gui::SliceWorkspace::tr("Large Coronal Slice"))->trigger();
    QCoreApplication::processEvents();
    EXPECT_FALSE(window_->viewer()->isVisible());
    EXPECT_TRUE(view(SliceOrientation::Coronal)->isVisible());
    EXPECT_FALSE(view(SliceOrientation::Axial)->isVisible());
    EXPECT_FALSE(view(SliceOrientation::Sagittal)->isVisible());
    EXPECT_GT(view(SliceOrientation::Coronal)->width(), fullWidth * 9 / 10);
    // What it shows: the slice, not an empty view.
    const QImage shown = view(SliceOrientation::Coronal)->grab().toImage();
    EXPECT_GT(changedFraction(shown, QImage(shown.size(), shown.format())), 0.2);

    menuAction(menu, gui::SliceWorkspace::tr("3-D and Three Slices"))->trigger();
    QCoreApplication::processEvents();
    EXPECT_TRUE(window_->viewer()->isVisible());
    for (const auto o :
         {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
        EXPECT_TRUE(view(o)->isVisible());
        EXPECT_LT(view(o)->width(), fullWidth * 6 / 10);
    }
    EXPECT_EQ(workspace()->sliceLayout(), SliceLayout::ThreeDAndSlices);

    // The choice is remembered: the next window starts with it.
    menuAction(menu, gui::SliceWorkspace::tr("Large Sagittal Slice"))->trigger();
    {
        const gui::MainWindow next;
        EXPECT_EQ(next.sliceWorkspace()->sliceLayout(), SliceLayout::SagittalLarge);
    }
    // Reset to Defaults brings the default back; an unknown stored name gives it too.
    window_->resetToDefaults();
    EXPECT_EQ(workspace()->sliceLayout(), SliceLayout::ThreeDAndSlices);
    QSettings().setValue(QLatin1String(gui::SliceWorkspace::kLayoutKey), QStringLiteral("huge"));
    {
        const gui::MainWindow next;
        EXPECT_EQ(next.sliceWorkspace()->sliceLayout(), SliceLayout::ThreeDAndSlices);
    }
}

TEST_F(SliceViewGuiTest, WheelScrollsSlicesAndTheReadoutFollows) {
    openSeries();
    SliceView* axial = view(SliceOrientation::Axial);
    const int before = axial->sliceIndex();
    const QImage imageBefore = axial->sliceImage();
    const QPointF centre(axial->width() / 2.0, axial->height() / 2.0);
    axial->hoverAt(centre);
    const QString readoutBefore = axial->readoutText();
    ASSERT_FALSE(readoutBefore.isEmpty());
    EXPECT_TRUE(readoutBefore.endsWith(QStringLiteral("HU"))) << readoutBefore.toStdString();

    wheel(axial, 3);
    axial->waitForSlice();
    EXPECT_EQ(axial->sliceIndex(), before + 3);
    EXPECT_EQ(axial->shownSliceIndex(), before + 3);
    EXPECT_GT(changedFraction(imageBefore, axial->sliceImage()), 0.01);
    // The position line and the read-out name the new slice's height.
    const double z = axial->slicePosition();
    EXPECT_NEAR(z - axial->stack()->position(before), 3.0 * axial->stack()->step, 1e-9);
    EXPECT_TRUE(axial->positionText().startsWith(app::slicePositionLabel(2, z)))
        << axial->positionText().toStdString();
    const QString readout = axial->readoutText();
    EXPECT_NE(readout, readoutBefore);
    EXPECT_TRUE(readout.contains(QLocale().toString(std::abs(z), 'f', 1))) << readout.toStdString();
    // The value is the voxel's under the point.
    const auto world = axial->worldAt(centre);
    ASSERT_TRUE(world);
    const auto sample = slices::voxelAt(*window_->volume(), *world);
    ASSERT_TRUE(sample);
    EXPECT_TRUE(readout.contains(app::voxelValueLabel(*sample))) << readout.toStdString();

    // In German the numbers take a decimal comma.
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    axial->hoverAt(centre + QPointF(1, 0));
    axial->hoverAt(centre);
    const QString german = axial->positionText();
    QLocale::setDefault(QLocale::c());
    EXPECT_TRUE(german.contains(QLatin1Char(','))) << german.toStdString();
}

TEST_F(SliceViewGuiTest, WindowDragAndPresetsChangeThePixels) {
    openSeries();
    SliceView* axial = view(SliceOrientation::Axial);
    SliceView* coronal = view(SliceOrientation::Coronal);
    const QImage before = axial->grab().toImage();
    const slices::Window start = axial->window();
    leftDrag(axial, QPointF(50, 50), QPointF(150, 90));
    QCoreApplication::processEvents();
    const slices::Window dragged = axial->window();
    EXPECT_GT(dragged.width, start.width);
    EXPECT_GT(dragged.center, start.center);
    EXPECT_DOUBLE_EQ(coronal->window().width, dragged.width);  // the views share the window
    EXPECT_GT(changedFraction(before, axial->grab().toImage()), 0.05);

    // Bone preset: every pixel without overlay is the window of its value.
    const auto& presets = workspace()->presets();
    std::size_t bone = presets.size();
    for (std::size_t n = 0; n < presets.size(); ++n) {
        if (presets[n].preset == slices::WindowPreset::Bone) {
            bone = n;
        }
    }
    ASSERT_LT(bone, presets.size());
    workspace()->applyPreset(bone);
    EXPECT_DOUBLE_EQ(axial->window().width, presets[bone].window.width);
    const auto plane = axial->stack()->planeAt(axial->sliceIndex());
    const auto values = slices::reslice(*window_->volume(), plane);
    const QImage& image = axial->sliceImage();
    ASSERT_EQ(image.width(), values.width());
    int checked = 0;
    for (int r = 0; r < values.height(); r += 3) {
        for (int c = 0; c < values.width(); c += 3) {
            const QRgb p = image.pixel(c, r);
            if (qRed(p) == qGreen(p) && qGreen(p) == qBlue(p)) {  // grey: no overlay
                ASSERT_EQ(qRed(p), slices::windowGray(values(c, r), presets[bone].window))
                    << c << "," << r;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 100);
}

TEST_F(SliceViewGuiTest, SegmentationOverlayOnTheSlices) {
    openSeries();
    ASSERT_NE(window_->document()->labelMap(), nullptr);
    SliceView* coronal = view(SliceOrientation::Coronal);
    // A coronal slice through the tree's root: its overlay pixels are in the
    // label colour where the label map has label 1.
    const QRgb colour = 0xFF000000U | slices::overlayColor(1);
    const int best = showSliceWithMostOutline(coronal);
    ASSERT_GE(best, 0) << "no outline pixel on any coronal slice";
    const auto labels =
        slices::resliceLabels(*window_->document()->labelMap(), coronal->stack()->planeAt(best));
    const QImage& image = coronal->sliceImage();
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            if (image.pixel(x, y) == colour) {
                ASSERT_EQ(labels(x, y), 1) << x << "," << y;
            }
        }
    }
    // Without the overlay the same slice is grey only.
    QAction* fill = menuAction(workspace()->menu(), gui::SliceWorkspace::tr("Segmentation Fill"));
    QAction* outline =
        menuAction(workspace()->menu(), gui::SliceWorkspace::tr("Segmentation Outline"));
    fill->setChecked(false);
    outline->setChecked(false);
    const QImage plain = coronal->sliceImage();
    for (int y = 0; y < plain.height(); ++y) {
        for (int x = 0; x < plain.width(); ++x) {
            const QRgb p = plain.pixel(x, y);
            ASSERT_TRUE(qRed(p) == qGreen(p) && qGreen(p) == qBlue(p)) << x << "," << y;
        }
    }
}

TEST_F(SliceViewGuiTest, OverlayFollowsTheSegmentationPreview) {
    openSeries();
    SliceView* axial = view(SliceOrientation::Axial);
    const auto loaded = window_->document()->labelMap();
    ASSERT_NE(loaded, nullptr);
    // The overlay's pixels over all axial slices, and how many of them lie on
    // bone (>= 700 HU).
    const auto overlayOnBone = [&] {
        int tinted = 0;
        int bone = 0;
        for (int k = 0; k < axial->sliceCount(); k += 3) {
            axial->setSliceIndex(k);
            axial->waitForSlice();
            const auto values =
                slices::reslice(*window_->volume(), axial->stack()->planeAt(axial->sliceIndex()));
            const QImage& image = axial->sliceImage();
            for (int r = 0; r < image.height(); ++r) {
                for (int c = 0; c < image.width(); ++c) {
                    const QRgb p = image.pixel(c, r);
                    if (!(qRed(p) == qGreen(p) && qGreen(p) == qBlue(p))) {
                        ++tinted;
                        bone += values(c, r) >= 700.0F ? 1 : 0;
                    }
                }
            }
        }
        return std::pair<int, int>(tinted, bone);
    };
    // Loaded with bone removal: the overlay is on the vessels.
    const auto [vesselTinted, vesselBone] = overlayOnBone();
    ASSERT_GT(vesselTinted, 50);
    EXPECT_LT(vesselBone, vesselTinted / 10);
    // Only the bone block (800..3000 HU, no bone removal): the overlay moves to it.
    auto* panel = window_->segmentationPanel();
    const int before = panel->previewsShown();
    panel->boneRemovalBox()->setChecked(false);
    panel->upperBox()->setValue(3000.0);
    panel->lowerBox()->setValue(800.0);
    panel->startPreview();
    ASSERT_TRUE(waitUntil([&] { return panel->previewsShown() > before && !panel->isPreviewing(); },
                          30000));
    const auto [tinted, bone] = overlayOnBone();
    ASSERT_GT(tinted, 50) << "no overlay on the bone block";
    // The preview's coarse grid blurs the edge by a coarse voxel.
    EXPECT_GT(bone, tinted * 3 / 4);
}

/// A left click (press and release in place) at `at` on `widget`.
void clickOn(QWidget* widget, const QPointF& at) {
    QMouseEvent press(QEvent::MouseButtonPress, at, widget->mapToGlobal(at), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(widget, &press);
    QMouseEvent release(QEvent::MouseButtonRelease, at, widget->mapToGlobal(at), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(widget, &release);
}

/// True when a pixel of `image` within one pixel of `at` is the cursor's green.
bool isCursorGreen(const QImage& image, const QPointF& at) {
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const QPoint q = at.toPoint() + QPoint(dx, dy);
            if (!image.rect().contains(q)) {
                continue;
            }
            const QRgb p = image.pixel(q);
            if (qGreen(p) > qRed(p) + 60 && qGreen(p) > qBlue(p) + 60) {
                return true;
            }
        }
    }
    return false;
}

TEST_F(SliceViewGuiTest, ClickOnASliceMovesTheOtherSlicesAndMarksThePoint) {
    openSeries();
    ASSERT_TRUE(waitForFrames(1));
    SliceView* axial = view(SliceOrientation::Axial);
    SliceView* coronal = view(SliceOrientation::Coronal);
    SliceView* sagittal = view(SliceOrientation::Sagittal);
    const QPointF at(axial->width() * 0.4, axial->height() * 0.6);
    const auto world = axial->worldAt(at);
    ASSERT_TRUE(world);
    const int axialBefore = axial->sliceIndex();
    clickOn(axial, at);
    for (SliceView* v : {axial, coronal, sagittal}) {
        v->waitForSlice();
    }
    ASSERT_TRUE(workspace()->cursor()->point());
    EXPECT_LT(glm::distance(*workspace()->cursor()->point(), *world), 1e-9);
    EXPECT_EQ(axial->sliceIndex(), axialBefore);
    EXPECT_EQ(coronal->sliceIndex(), coronal->stack()->nearestIndex(world->y));
    EXPECT_EQ(sagittal->sliceIndex(), sagittal->stack()->nearestIndex(world->x));
    // Each slice view draws the crosshair through the point.
    for (SliceView* v : {axial, coronal, sagittal}) {
        const auto p = v->widgetPointOf(*world);
        ASSERT_TRUE(p);
        const QImage shown = v->grab().toImage();
        EXPECT_TRUE(isCursorGreen(shown, *p + QPointF(20, 0))) << v->objectName().toStdString();
        EXPECT_TRUE(isCursorGreen(shown, *p + QPointF(0, -20))) << v->objectName().toStdString();
    }
    // And the 3-D view marks it where the camera projects it.
    QWidget* marker = workspace()->cursor()->marker();
    ASSERT_NE(marker, nullptr);
    EXPECT_TRUE(marker->isVisible());
    const auto onScreen = workspace()->cursor()->markerPosition();
    ASSERT_TRUE(onScreen);
    EXPECT_TRUE(window_->viewer()->rect().contains(onScreen->toPoint()));
    EXPECT_TRUE(isCursorGreen(marker->grab().toImage(), *onScreen + QPointF(7, 0)));
}

TEST_F(SliceViewGuiTest, ScrollingAViewMovesTheCrosshairOfTheOthersToItsLevel) {
    openSeries();
    ASSERT_TRUE(waitForFrames(1));
    SliceView* axial = view(SliceOrientation::Axial);
    SliceView* coronal = view(SliceOrientation::Coronal);
    SliceView* sagittal = view(SliceOrientation::Sagittal);
    const auto clicked = axial->worldAt(QPointF(axial->width() * 0.45, axial->height() * 0.5));
    ASSERT_TRUE(clicked);
    clickOn(axial, axial->widgetPointOf(*clicked).value());
    for (SliceView* v : {axial, coronal, sagittal}) {
        v->waitForSlice();
    }
    const auto markerBefore = workspace()->cursor()->markerPosition();
    // Scroll the axial view 8 slices: the cursor goes with its slice, and
    // the coronal and sagittal crosshairs show the level the axial view shows now.
    const int before = axial->sliceIndex();
    wheel(axial, 8);
    axial->waitForSlice();
    ASSERT_NE(axial->sliceIndex(), before);
    const glm::dvec3 level(clicked->x, clicked->y, axial->slicePosition());
    ASSERT_TRUE(workspace()->cursor()->point());
    EXPECT_LT(glm::distance(*workspace()->cursor()->point(), level), 1e-9);
    EXPECT_GT(std::abs(level.z - clicked->z), 4.0 * axial->stack()->step);
    for (SliceView* v : {coronal, sagittal}) {
        SCOPED_TRACE(v->objectName().toStdString());
        const QImage shown = v->grab().toImage();
        const auto now = v->widgetPointOf(level);
        const auto stale = v->widgetPointOf(*clicked);
        ASSERT_TRUE(now && stale);
        ASSERT_GT(std::abs(now->y() - stale->y()), 8.0);
        // The horizontal line at the new level, none at the clicked one.
        EXPECT_TRUE(isCursorGreen(shown, *now + QPointF(20, 0)));
        EXPECT_FALSE(isCursorGreen(shown, *stale + QPointF(20, 0)));
    }
    // The 3-D view's marker follows too.
    const auto markerAfter = workspace()->cursor()->markerPosition();
    ASSERT_TRUE(markerBefore && markerAfter);
    EXPECT_GT(QLineF(*markerBefore, *markerAfter).length(), 2.0);
    // The Up key in the coronal view moves the level along y in the others.
    QKeyEvent up(QEvent::KeyPress, Qt::Key_Up, Qt::NoModifier);
    QCoreApplication::sendEvent(coronal, &up);
    coronal->waitForSlice();
    EXPECT_DOUBLE_EQ(workspace()->cursor()->point()->y, coronal->slicePosition());
    EXPECT_DOUBLE_EQ(workspace()->cursor()->point()->z, axial->slicePosition());
}

TEST_F(SliceViewGuiTest, ClickOnAVesselIn3DMovesTheSlices) {
    openSeries();
    ASSERT_TRUE(waitForFrames(1));
    gui::ViewerWidget* viewer = window_->viewer();
    std::optional<gui::ProbeResult> hit;
    for (int y = 8; y < viewer->height() && !hit; y += 8) {
        for (int x = 8; x < viewer->width() && !hit; x += 8) {
            hit = viewer->probeAt(QPointF(x, y));
        }
    }
    ASSERT_TRUE(hit) << "no vessel under any probed pixel";
    clickOn(viewer, hit->widgetPosition);
    ASSERT_TRUE(workspace()->cursor()->point());
    const glm::dvec3 p = *workspace()->cursor()->point();
    EXPECT_LT(glm::distance(p, glm::dvec3(hit->worldPosition)), 1e-3);
    for (const auto o :
         {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
        SliceView* v = view(o);
        v->waitForSlice();
        EXPECT_EQ(v->sliceIndex(), v->stack()->nearestIndex(p[v->stack()->axis]));
        EXPECT_TRUE(v->crosshair());
    }
    // The point lies within the volume (it came from its surface).
    const auto sample = slices::voxelAt(*window_->volume(), p);
    ASSERT_TRUE(sample);
    // A mesh scene: clicks no longer set a cursor.
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    QCoreApplication::processEvents();
    EXPECT_FALSE(workspace()->cursor()->point());
    EXPECT_FALSE(workspace()->cursor()->marker()->isVisible());
}

TEST_F(SliceViewGuiTest, SeedIsPickedInASlice) {
    openSeries();
    SliceView* axial = view(SliceOrientation::Axial);
    const scene::Volume& volume = *window_->volume();
    // A widget point on bright lumen (300..700 HU) in some axial slice.
    std::optional<QPointF> onLumen;
    std::optional<slices::VoxelSample> lumen;
    for (int k = 0; k < axial->sliceCount() && !onLumen; k += 2) {
        axial->setSliceIndex(k);
        axial->waitForSlice();
        for (int y = 4; y < axial->height() && !onLumen; y += 3) {
            for (int x = 4; x < axial->width() && !onLumen; x += 3) {
                const auto world = axial->worldAt(QPointF(x, y));
                const auto sample = world ? slices::voxelAt(volume, *world) : std::nullopt;
                if (sample && sample->value >= 300.0F && sample->value <= 700.0F) {
                    onLumen = QPointF(x, y);
                    lumen = sample;
                }
            }
        }
    }
    ASSERT_TRUE(onLumen) << "no lumen in any axial slice";
    auto* panel = window_->segmentationPanel();
    panel->pickSeedButton()->setChecked(true);
    clickOn(axial, *onLumen);
    ASSERT_TRUE(panel->seed()) << panel->messageLabel()->text().toStdString();
    EXPECT_LE(glm::length(glm::vec3(*panel->seed() - lumen->voxel)), 2.0F * std::sqrt(3.0F));
    EXPECT_FALSE(panel->pickSeedButton()->isChecked());
    // Without Pick Seed a click only moves the cursor.
    const auto seed = panel->seed();
    clickOn(axial, *onLumen + QPointF(3, 0));
    EXPECT_EQ(panel->seed(), seed);
}

TEST_F(SliceViewGuiTest, ReportIncludesTheSliceWithItsOverlay) {
    openSeries();
    ASSERT_TRUE(waitForFrames(1));
    // The coronal slice through the tree's root, large.
    SliceView* coronal = view(SliceOrientation::Coronal);
    workspace()->setSliceLayout(SliceLayout::CoronalLarge);
    const QRgb colour = 0xFF000000U | slices::overlayColor(1);
    ASSERT_GE(showSliceWithMostOutline(coronal), 0);

    // File > Export Report offers the slice.
    const fs::path dir = panelTestDir() / "slice-report";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path pdf = dir / "report.pdf";
    const QString failure = exportReport(pdf, [](gui::ReportDialog& dialog) {
        ASSERT_NE(dialog.sliceBox(), nullptr);
        EXPECT_TRUE(dialog.sliceBox()->isChecked());
    });
    ASSERT_TRUE(failure.isEmpty()) << failure.toStdString();

    std::string text;
    ASSERT_EQ(report::test::runTool("pdftotext -layout '" + pdf.string() + "' -", text), 0);
    EXPECT_NE(text.find("Slice with segmentation"), std::string::npos) << text;
    // (Spaces as pdftotext writes them: no-break spaces become plain ones.)
    QString expected = app::orientationName(SliceOrientation::Coronal) +
                       QStringLiteral(" slice at ") +
                       app::slicePositionLabel(1, coronal->slicePosition());
    const std::string caption = expected.replace(QChar(0x00A0), QLatin1Char(' ')).toStdString();
    text = QString::fromStdString(text).replace(QChar(0x00A0), QLatin1Char(' ')).toStdString();
    EXPECT_NE(text.find(caption), std::string::npos) << caption << "\n" << text;
    // The slice is an image of its own in the PDF, with the overlay's colour on it.
    ASSERT_EQ(report::test::runTool(
                  "pdfimages -png '" + pdf.string() + "' '" + (dir / "image").string() + "'", text),
              0)
        << text;
    int images = 0;
    int overlayPixels = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".png") {
            continue;
        }
        ++images;
        const QImage image(QString::fromStdString(entry.path().string()));
        for (int y = 0; y < image.height(); y += 2) {
            for (int x = 0; x < image.width(); x += 2) {
                const QRgb p = image.pixel(x, y);
                overlayPixels += std::abs(qRed(p) - qRed(colour)) < 12 &&
                                         std::abs(qGreen(p) - qGreen(colour)) < 12 &&
                                         std::abs(qBlue(p) - qBlue(colour)) < 12
                                     ? 1
                                     : 0;
            }
        }
    }
    EXPECT_GE(images, 2);  // the view and the slice
    EXPECT_GT(overlayPixels, 50);
    // The caption says the window's preset and what the colours are.
    std::string words;
    for (const report::test::PdfWord& w : report::test::pdfWords(pdf)) {
        words += w.text + " ";
    }
    words = report::test::withoutLigatures(words);  // "ﬁll" -> "fill"
    EXPECT_NE(words.find("(CTA preset). Coloured fill and outline: the segmentation."),
              std::string::npos)
        << words;
    // Every page within its margins, nothing over the footer.
    const int dpi = 60;
    const std::vector<QImage> pages = report::test::pdfPages(pdf, dir / "pages", dpi);
    for (std::size_t i = 0; i < pages.size(); ++i) {
        for (const std::string& problem : report::test::marginProblems(pages[i], dpi)) {
            ADD_FAILURE() << "page " << i + 1 << ": " << problem;
        }
    }
}

TEST_F(SliceViewGuiTest, MouseHelpOnlyOffTheImage) {
    openSeries();
    SliceView* coronal = view(SliceOrientation::Coronal);  // wider than high: margins above / below
    const auto showHelpAt = [&](const QPoint& at) {
        QToolTip::hideText();
        QHelpEvent help(QEvent::ToolTip, at, coronal->mapToGlobal(at));
        QCoreApplication::sendEvent(coronal, &help);
        return waitUntil([] { return QToolTip::isVisible(); }, 1000) ? QToolTip::text() : QString();
    };
    const QString onImage = showHelpAt(QPoint(coronal->width() / 2, coronal->height() / 2));
    EXPECT_TRUE(onImage.isEmpty()) << onImage.toStdString();
    const auto world = coronal->worldAt(QPointF(coronal->width() / 2.0, 2.0));
    ASSERT_TRUE(world);
    ASSERT_FALSE(slices::voxelAt(*window_->volume(), *world)) << "the top edge is on the image";
    const QString offImage = showHelpAt(QPoint(coronal->width() / 2, 2));
    EXPECT_TRUE(offImage.contains(QStringLiteral("Wheel"))) << offImage.toStdString();
    QToolTip::hideText();
}

/// A CT just above the size resliced at once: 256 x 256 x 130 voxels, the
/// value of slice k = 10 k HU.
std::shared_ptr<scene::Volume> bigCtVolume() {
    auto big = std::make_shared<scene::Volume>(glm::ivec3(256, 256, 130), scene::VoxelType::Int16);
    big->setModality("CT");
    for (std::size_t n = 0; n < big->voxelCount(); ++n) {
        big->setValueAt(n, static_cast<float>(n / (256U * 256U) * 10U));
    }
    return big;
}

TEST_F(SliceViewGuiTest, BigVolumesAreReslicedOnAWorker) {
    // Just above the size resliced at once: a new slice is not there when
    // setSliceIndex returns (the GUI thread goes on), and arrives later.
    const auto big = bigCtVolume();
    ASSERT_GT(big->voxelCount(), SliceView::kSynchronousVoxels);
    SliceView view(SliceOrientation::Axial);
    view.resize(300, 300);
    view.setWindow({0.0, 4000.0});
    view.setVolume(big);
    view.waitForSlice();
    EXPECT_EQ(view.shownSliceIndex(), 65);
    view.setSliceIndex(100);
    EXPECT_EQ(view.sliceIndex(), 100);
    EXPECT_EQ(view.shownSliceIndex(), 65);  // still the old slice
    view.waitForSlice();
    EXPECT_EQ(view.shownSliceIndex(), 100);
    EXPECT_EQ(qRed(view.sliceImage().pixel(128, 128)), slices::windowGray(1000.0F, {0.0, 4000.0}));

    // In the window, its presets (a pass over every voxel) come from a worker too.
    workspace()->setVolume(big, nullptr);
    EXPECT_TRUE(workspace()->presets().empty());
    ASSERT_TRUE(waitUntil([&] { return !workspace()->presets().empty(); }, 30000));
    EXPECT_EQ(workspace()->presets().front().preset, slices::WindowPreset::Cta);
    EXPECT_DOUBLE_EQ(workspace()->presets().back().window.width, 1290.0);  // 0 .. 1290 HU
}

/// The slice views' state as a person sees it: each view's position line
/// and slice image, the axial view as drawn (no hover read-out).
struct ShownSlices {
    std::array<QString, 3> positions;
    std::array<QImage, 3> images;
    QImage axialShown;
};

TEST_F(SliceViewGuiTest, ASavedSessionReopensWithTheSameSlices) {
    openSeries();
    SliceView* axial = view(SliceOrientation::Axial);
    std::array<SliceView*, 3> views{axial, view(SliceOrientation::Coronal),
                                    view(SliceOrientation::Sagittal)};
    // Slice views unlike a new volume's: one large axial slice, the bone
    // window, the outline only, a cursor, moved slices, the axial view zoomed
    // and panned.
    workspace()->setSliceLayout(SliceLayout::AxialLarge);
    const auto& presets = workspace()->presets();
    const auto bone = std::find_if(presets.begin(), presets.end(), [](const auto& p) {
        return p.preset == slices::WindowPreset::Bone;
    });
    ASSERT_NE(bone, presets.end());
    const slices::WindowPreset firstPreset = presets.front().preset;  // a new volume's
    workspace()->applyPreset(static_cast<std::size_t>(bone - presets.begin()));
    menuAction(workspace()->menu(), gui::SliceWorkspace::tr("Segmentation Fill"))->trigger();
    QCoreApplication::processEvents();
    const auto cursor = axial->worldAt(QPointF(axial->width() * 0.45, axial->height() * 0.55));
    ASSERT_TRUE(cursor);
    workspace()->cursor()->setPoint(*cursor);
    axial->setSliceIndex(axial->sliceIndex() - 5);
    views[1]->setSliceIndex(views[1]->sliceCount() / 4);
    views[2]->setSliceIndex(views[2]->sliceCount() * 3 / 4);
    axial->setZoom(2.5);
    axial->setPan({6.0, -4.0});
    // The cursor followed the planes scrolled to.
    ASSERT_TRUE(workspace()->cursor()->point());
    const glm::dvec3 followed = *workspace()->cursor()->point();
    EXPECT_LT(
        glm::distance(followed, glm::dvec3(views[2]->slicePosition(), views[1]->slicePosition(),
                                           axial->slicePosition())),
        1e-9);
    const auto shown = [&] {
        ShownSlices s;
        for (std::size_t n = 0; n < views.size(); ++n) {
            views[n]->waitForSlice();
            s.positions.at(n) = views[n]->positionText();
            s.images.at(n) = views[n]->sliceImage();
        }
        QEvent leave(QEvent::Leave);  // no hover read-out
        QCoreApplication::sendEvent(axial, &leave);
        s.axialShown = axial->grab().toImage();
        return s;
    };
    const ShownSlices before = shown();
    const slices::Window window = workspace()->window();
    const auto tip = axial->widgetPointOf(followed);
    ASSERT_TRUE(tip);
    const QString path = QString::fromStdString((panelTestDir() / "slices.vvs").string());
    ASSERT_TRUE(window_->saveSessionTo(path));

    // A fresh window (3-D and three slices, both overlay styles), then the session.
    workspace()->setSliceLayout(SliceLayout::ThreeDAndSlices);
    ASSERT_TRUE(openSessionInNewWindow(path)) << "the session was never applied";
    ASSERT_NE(window_->volume(), nullptr);
    QCoreApplication::processEvents();
    EXPECT_EQ(workspace()->sliceLayout(), SliceLayout::AxialLarge);
    EXPECT_TRUE(view(SliceOrientation::Axial)->isVisible());
    EXPECT_FALSE(view(SliceOrientation::Coronal)->isVisible());
    EXPECT_DOUBLE_EQ(workspace()->window().width, window.width);
    EXPECT_DOUBLE_EQ(workspace()->window().center, window.center);
    EXPECT_EQ(workspace()->chosenPreset(), std::optional(slices::WindowPreset::Bone));
    EXPECT_FALSE(
        menuAction(workspace()->menu(), gui::SliceWorkspace::tr("Segmentation Fill"))->isChecked());
    EXPECT_TRUE(menuAction(workspace()->menu(), gui::SliceWorkspace::tr("Segmentation Outline"))
                    ->isChecked());
    ASSERT_TRUE(workspace()->cursor()->point());
    EXPECT_LT(glm::distance(*workspace()->cursor()->point(), followed), 1e-9);
    axial = view(SliceOrientation::Axial);
    const std::array<SliceView*, 3> reopened{axial, view(SliceOrientation::Coronal),
                                             view(SliceOrientation::Sagittal)};
    for (std::size_t n = 0; n < views.size(); ++n) {
        views.at(n) = reopened.at(n);  // what shown() reads
    }
    const ShownSlices after = shown();
    for (std::size_t n = 0; n < views.size(); ++n) {
        EXPECT_EQ(after.positions.at(n), before.positions.at(n)) << n;
        ASSERT_EQ(after.images.at(n).size(), before.images.at(n).size()) << n;
        EXPECT_EQ(changedFraction(after.images.at(n), before.images.at(n)), 0.0) << n;
    }
    // Zoom and pan: the cursor at the same place in the view, the same picture.
    EXPECT_DOUBLE_EQ(axial->zoom(), 2.5);
    const auto tipAfter = axial->widgetPointOf(followed);
    ASSERT_TRUE(tipAfter);
    EXPECT_NEAR(tipAfter->x(), tip->x(), 1e-6);
    EXPECT_NEAR(tipAfter->y(), tip->y(), 1e-6);
    ASSERT_EQ(after.axialShown.size(), before.axialShown.size());
    const double changed = changedFraction(after.axialShown, before.axialShown);
    EXPECT_LT(changed, 0.001);
    if (changed >= 0.001) {
        before.axialShown.save(QString::fromStdString((panelTestDir() / "before.png").string()));
        after.axialShown.save(QString::fromStdString((panelTestDir() / "after.png").string()));
    }

    // The same session written before slice views were kept: a new volume's views.
    QFile file(path);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
    ASSERT_TRUE(root.contains(QStringLiteral("slices")));
    root.remove(QStringLiteral("slices"));
    const QString old = QString::fromStdString((panelTestDir() / "slices-old.vvs").string());
    QFile out(old);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
    out.write(QJsonDocument(root).toJson());
    out.close();
    workspace()->setSliceLayout(SliceLayout::ThreeDAndSlices);  // the remembered layout
    ASSERT_TRUE(openSessionInNewWindow(old)) << "the session was never applied";
    ASSERT_NE(window_->volume(), nullptr);
    EXPECT_EQ(workspace()->sliceLayout(), SliceLayout::ThreeDAndSlices);
    EXPECT_FALSE(workspace()->cursor()->point().has_value());
    EXPECT_EQ(workspace()->chosenPreset(), std::optional(firstPreset));
    for (const auto o :
         {SliceOrientation::Axial, SliceOrientation::Coronal, SliceOrientation::Sagittal}) {
        SliceView* v = view(o);
        EXPECT_EQ(v->sliceIndex(), v->sliceCount() / 2);
        EXPECT_DOUBLE_EQ(v->zoom(), 1.0);
        EXPECT_EQ(v->pan(), glm::dvec2(0.0));
    }
    EXPECT_TRUE(
        menuAction(workspace()->menu(), gui::SliceWorkspace::tr("Segmentation Fill"))->isChecked());
}

TEST_F(SliceViewGuiTest, ASessionWindowIsNotReplacedByPresetsFromTheWorker) {
    // A big volume's presets are found on a worker; a session applied before
    // they arrive keeps its window and checks its preset when they do.
    const auto big = bigCtVolume();
    ASSERT_GT(big->voxelCount(), SliceView::kSynchronousVoxels);
    workspace()->setVolume(big, nullptr);
    ASSERT_TRUE(workspace()->presets().empty());
    auto state = workspace()->sessionState();
    ASSERT_TRUE(state);
    SliceView* axial = view(SliceOrientation::Axial);
    const slices::Window soft{40.0, 400.0};
    state->window = soft;
    state->preset = slices::WindowPreset::SoftTissue;
    state->views.at(0).position = axial->stack()->position(5);  // 50 HU
    workspace()->applySessionState(*state);
    EXPECT_EQ(workspace()->sessionState()->preset, slices::WindowPreset::SoftTissue);
    ASSERT_TRUE(waitUntil([&] { return !workspace()->presets().empty(); }, 30000));
    QCoreApplication::processEvents();
    EXPECT_DOUBLE_EQ(workspace()->window().center, soft.center);
    EXPECT_DOUBLE_EQ(workspace()->window().width, soft.width);
    EXPECT_EQ(workspace()->chosenPreset(), std::optional(slices::WindowPreset::SoftTissue));
    axial->waitForSlice();
    EXPECT_EQ(axial->shownSliceIndex(), 5);
    EXPECT_EQ(qRed(axial->sliceImage().pixel(128, 128)), slices::windowGray(50.0F, soft));
}

}  // namespace
}  // namespace vv::test
