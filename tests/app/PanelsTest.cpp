// SPDX-License-Identifier: GPL-3.0-or-later
// The side panels: every control changes the viewer's settings at once,
// controls that do not apply are disabled with a tooltip saying why, and the
// dock layout is restored from the settings.
#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMouseEvent>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QTreeWidget>
#include <QWheelEvent>
#include <algorithm>
#include <limits>
#include <numeric>

#include "GuiFixture.h"
#include "gui/panels/CollapsibleSection.h"
#include "gui/panels/DataPanel.h"
#include "gui/panels/DisplayPanel.h"
#include "gui/panels/FunctionalPanel.h"
#include "gui/panels/HistogramWidget.h"
#include "gui/panels/SidePanel.h"
#include "gui/panels/VssPanel.h"
#include "vv/render/LegendPainter.h"
#include "vv/vss/DepthNormalization.h"

namespace vv::test {
namespace {

using gui::panels::FunctionalPanel;
using gui::panels::VssPanel;

/// Every disabled control inside `root` has a tooltip (says why).
void expectDisabledControlsExplained(const QWidget* root, const char* where) {
    int disabled = 0;
    for (QWidget* w : root->findChildren<QWidget*>()) {
        const bool control = qobject_cast<QAbstractButton*>(w) != nullptr ||
                             qobject_cast<QComboBox*>(w) != nullptr ||
                             qobject_cast<QAbstractSpinBox*>(w) != nullptr ||
                             qobject_cast<QAbstractSlider*>(w) != nullptr ||
                             qobject_cast<QLineEdit*>(w) != nullptr;
        // Parts of other controls (line edits inside spin boxes, a combo box's
        // pop-up with its scroll bars) belong to their owner.
        if (!control || w->window() != root->window() ||
            qobject_cast<QAbstractSpinBox*>(w->parentWidget()) != nullptr ||
            qobject_cast<QComboBox*>(w->parentWidget()) != nullptr) {
            continue;
        }
        if (!w->isEnabled()) {
            ++disabled;
            EXPECT_FALSE(w->toolTip().isEmpty()) << where << ": " << w->objectName().toStdString()
                                                 << " is disabled without a reason";
        }
    }
    EXPECT_GT(disabled, 0) << where << ": nothing was disabled, so nothing was checked";
}

template <typename T>
T* child(const QObject* parent, const char* name) {
    T* found = parent->findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << name;
    return found;
}

class PanelsTest : public GuiFixture {};

TEST(FunctionalPanelPercentile, InterpolatesOrderStatisticsAndIgnoresNonFinite) {
    std::vector<float> values;
    for (int i = 100; i >= 0; --i) {
        values.push_back(static_cast<float>(i));
    }
    values.push_back(std::numeric_limits<float>::quiet_NaN());
    values.push_back(std::numeric_limits<float>::infinity());
    EXPECT_DOUBLE_EQ(*FunctionalPanel::percentile(values, 2.0), 2.0);
    EXPECT_DOUBLE_EQ(*FunctionalPanel::percentile(values, 98.0), 98.0);
    EXPECT_DOUBLE_EQ(*FunctionalPanel::percentile(values, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(*FunctionalPanel::percentile({1.0F, 2.0F}, 50.0), 1.5);
    // One outlier among many: the 98th percentile ignores it, the maximum would not.
    std::vector<float> outlier(99, 1.0F);
    outlier.push_back(1000.0F);
    EXPECT_DOUBLE_EQ(*FunctionalPanel::percentile(outlier, 98.0), 1.0);
    EXPECT_FALSE(FunctionalPanel::percentile({std::numeric_limits<float>::quiet_NaN()}, 50.0));
}

TEST_F(PanelsTest, PowerSliderIsLogarithmicFromAQuarterTo64) {
    EXPECT_DOUBLE_EQ(VssPanel::powerFromSlider(0), 0.25);
    EXPECT_DOUBLE_EQ(VssPanel::powerFromSlider(VssPanel::kSliderSteps), 64.0);
    EXPECT_NEAR(VssPanel::powerFromSlider(VssPanel::kSliderSteps / 2), 4.0, 1e-12);
    EXPECT_NEAR(VssPanel::powerFromSlider(VssPanel::kSliderSteps / 4), 1.0, 1e-12);
    EXPECT_EQ(VssPanel::sliderFromPower(2.0), 375);
    EXPECT_EQ(VssPanel::sliderFromPower(1000.0), VssPanel::kSliderSteps);
    EXPECT_EQ(VssPanel::sliderFromPower(0.01), 0);

    auto* panel = window_->vssPanel();
    auto* viewer = window_->viewer();
    panel->powerSlider()->setValue(VssPanel::kSliderSteps / 2);
    EXPECT_NEAR(viewer->vssSettings().solver.p, 4.0, 1e-9);
    EXPECT_NEAR(panel->powerBox()->value(), 4.0, 1e-9);
    panel->powerBox()->setValue(64.0);
    EXPECT_DOUBLE_EQ(viewer->vssSettings().solver.p, 64.0);
    EXPECT_EQ(panel->powerSlider()->value(), VssPanel::kSliderSteps);
    EXPECT_DOUBLE_EQ(panel->powerBox()->minimum(), 0.25);
    EXPECT_DOUBLE_EQ(panel->powerBox()->maximum(), 64.0);
}

TEST_F(PanelsTest, VssPanelControlsChangeTheViewer) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames());
    auto* panel = window_->vssPanel();
    auto* viewer = window_->viewer();

    auto* solver = panel->solverChooser();
    auto* tolerance = child<QDoubleSpinBox>(panel, "vssTolerance");
    auto* step = child<QSpinBox>(panel, "vssStep");
    EXPECT_TRUE(tolerance->isEnabled());  // fast by default
    EXPECT_FALSE(step->isEnabled());
    EXPECT_FALSE(step->toolTip().isEmpty());
    tolerance->setValue(2.0);
    EXPECT_NEAR(viewer->vssSettings().solver.tolerance, 2.0 / 255.0, 1e-12);
    EXPECT_TRUE(panel->statusLabel()->text().contains(QStringLiteral("2 / 255")))
        << panel->statusLabel()->text().toStdString();

    solver->setCurrentIndex(solver->findData(static_cast<int>(vss::SolverKind::Step)));
    EXPECT_EQ(viewer->vssSettings().solver.kind, vss::SolverKind::Step);
    EXPECT_TRUE(step->isEnabled());
    EXPECT_FALSE(tolerance->isEnabled());
    step->setValue(5);
    EXPECT_EQ(viewer->vssSettings().solver.step, 5);
    EXPECT_TRUE(panel->statusLabel()->text().contains(QStringLiteral("no error bound")));
    solver->setCurrentIndex(solver->findData(static_cast<int>(vss::SolverKind::Brute)));
    EXPECT_EQ(viewer->vssSettings().solver.kind, vss::SolverKind::Brute);
    EXPECT_TRUE(panel->statusLabel()->text().contains(QStringLiteral("exact")));

    panel->scaleChooser()->setCurrentIndex(
        panel->scaleChooser()->findData(static_cast<int>(colormaps::DepthScale::DarkMeansDeep)));
    EXPECT_EQ(viewer->vssSettings().scale, colormaps::DepthScale::DarkMeansDeep);

    auto* isoLines = child<QSpinBox>(panel, "vssIsoLines");
    auto* isoStrength = child<QSlider>(panel, "vssIsoStrength");
    isoLines->setValue(12);
    EXPECT_EQ(viewer->vssSettings().isoLines, 12);
    isoStrength->setValue(30);
    EXPECT_FLOAT_EQ(viewer->vssSettings().isoLineStrength, 0.30F);
    isoLines->setValue(0);
    EXPECT_FALSE(isoStrength->isEnabled());
    EXPECT_TRUE(isoStrength->toolTip().contains(QStringLiteral("iso-lines")));
    child<QSlider>(panel, "vssLighting")->setValue(40);
    EXPECT_FLOAT_EQ(viewer->vssSettings().lighting, 0.40F);

    auto* ao = child<QCheckBox>(panel, "aoEnabled");
    auto* radius = child<QDoubleSpinBox>(panel, "aoRadius");
    radius->setValue(7.5);
    EXPECT_FLOAT_EQ(viewer->aoSettings().radius, 7.5F);
    ao->setChecked(false);
    EXPECT_FALSE(viewer->aoSettings().enabled);
    EXPECT_FALSE(radius->isEnabled());

    // The solve time shows up next to the controls once the exact solve
    // arrived. The brute-force solver is chosen above: O(void x contour
    // pixels), ~15 s alone under the sanitizers, more beside other tests.
    ASSERT_TRUE(waitForVss(120000));
    ASSERT_TRUE(waitUntil([&] {
        return panel->statusLabel()->text().contains(QStringLiteral("solved in"));
    })) << panel->statusLabel()->text().toStdString();
    window_->grab().save(QString::fromStdString((panelTestDir() / "vss.png").string()));

    // Re-shading settings re-run only the shading: the VSS is not solved again.
    const quint64 frames = viewer->framesWithScene();
    const auto solves = viewer->view().frameRenderer().solveCounters().submitted;
    isoLines->setValue(4);
    ASSERT_TRUE(waitForFrames(frames + 1));
    EXPECT_EQ(viewer->view().frameRenderer().solveCounters().submitted, solves);
    for (const auto& pass : viewer->lastPasses()) {
        if (pass.name == "vss-solve") {
            EXPECT_EQ(pass.state, render::PassState::Cached);
        }
    }

    // Off: the panel's check box and the toolbar toggle agree, the rest is disabled.
    panel->enabledBox()->setChecked(false);
    EXPECT_FALSE(viewer->vssSettings().enabled);
    EXPECT_FALSE(window_->vssToggle()->isChecked());
    EXPECT_FALSE(panel->powerBox()->isEnabled());
    expectDisabledControlsExplained(panel, "VSS panel");
    window_->vssToggle()->setChecked(true);
    EXPECT_TRUE(panel->enabledBox()->isChecked());
    EXPECT_TRUE(panel->powerBox()->isEnabled());
}

TEST_F(PanelsTest, FixingTheDepthRangeStartsFromTheRangeOnScreen) {
    // The range on screen of one geometry throughout (no smooth copy
    // arriving in between to move it).
    window_->viewer()->setSmoothCoarseMeshes(false);
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames());
    auto* panel = window_->vssPanel();
    auto* viewer = window_->viewer();
    ASSERT_TRUE(waitUntil([&] { return viewer->vssStatus().shown; }));
    const double shownMin = viewer->vssStatus().dmin;
    const double shownMax = viewer->vssStatus().dmax;

    // Visible (default): near / far do not apply, and say why.
    EXPECT_EQ(viewer->vssSettings().range.mode, vss::RangeMode::Visible);
    EXPECT_FALSE(panel->rangeMinBox()->isEnabled());
    EXPECT_FALSE(panel->rangeMinBox()->toolTip().isEmpty());
    // ... and show the range on screen (they said 0.0 mm before), once the
    // window has taken the frame's status.
    EXPECT_TRUE(waitUntil([&] { return panel->rangeMaxBox()->value() > 0.0; }));
    EXPECT_NEAR(panel->rangeMinBox()->value(), shownMin, 0.05);
    EXPECT_NEAR(panel->rangeMaxBox()->value(), shownMax, 0.05);
    EXPECT_GT(panel->rangeMaxBox()->value(), panel->rangeMinBox()->value());

    auto* mode = panel->rangeChooser();
    mode->setCurrentIndex(mode->findData(static_cast<int>(vss::RangeMode::Fixed)));
    const render::VssSettings& fixed = viewer->vssSettings();
    EXPECT_EQ(fixed.range.mode, vss::RangeMode::Fixed);
    EXPECT_NEAR(fixed.range.dmin, shownMin, 0.05);  // the boxes show one decimal
    EXPECT_NEAR(fixed.range.dmax, shownMax, 0.05);
    EXPECT_TRUE(panel->rangeMaxBox()->isEnabled());

    // Far follows near: never an inverted range.
    panel->rangeMinBox()->setValue(shownMax + 10.0);
    EXPECT_GE(viewer->vssSettings().range.dmax, viewer->vssSettings().range.dmin);
    ASSERT_TRUE(waitForFrames());
    EXPECT_TRUE(viewer->renderError().isEmpty()) << viewer->renderError().toStdString();

    mode->setCurrentIndex(mode->findData(static_cast<int>(vss::RangeMode::Visible)));
    EXPECT_EQ(viewer->vssSettings().range.mode, vss::RangeMode::Visible);
}

/// One wording for a quantity in every place a person reads it: an array as
/// "wss (Pa)" (scene::quantityTitle) in the data panel, the legend title
/// field, the legend and the status bar; the depth as the depth legend's
/// title says it, in the legend and in the probe's tooltip.
TEST_F(PanelsTest, EveryPlaceNamesAQuantityInOneWording) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames());
    auto* viewer = window_->viewer();
    ASSERT_EQ(viewer->style().array, "wss");
    const QString wss = QStringLiteral("wss (Pa)");
    EXPECT_EQ(child<QLineEdit>(window_->functionalPanel(), "functionalLegendTitle")->text(), wss);
    const QTreeWidgetItem* mesh = window_->dataPanel()->meshTree()->topLevelItem(0);
    ASSERT_NE(mesh, nullptr);
    QStringList arrays;
    for (int i = 0; i < mesh->childCount(); ++i) {
        arrays << mesh->child(i)->text(0);
    }
    EXPECT_TRUE(arrays.filter(QStringLiteral("wss")).value(0).startsWith(wss))
        << arrays.join(QLatin1Char('|')).toStdString();
    EXPECT_TRUE(arrays.filter(QStringLiteral("pressure"))
                    .value(0)
                    .startsWith(QStringLiteral("pressure (mmHg)")));
    auto* range = window_->findChild<QLabel*>(QStringLiteral("arrayRangeLabel"));
    ASSERT_NE(range, nullptr);
    EXPECT_TRUE(range->text().startsWith(wss + QLatin1Char(':'))) << range->text().toStdString();
    // The legends over the view, turned on with the VSS showing its depth.
    viewer->setLegendsVisible(true);
    const quint64 frames = viewer->framesWithScene();
    ASSERT_TRUE(waitUntil(
        [&] {
            return viewer->framesWithScene() > frames && viewer->shownLegends().depth.has_value();
        },
        60000));
    const render::Legends legends = viewer->shownLegends();
    ASSERT_TRUE(legends.parameter.has_value());
    EXPECT_EQ(QString::fromStdString(render::parameterLegendTitle(*legends.parameter)), wss);
    const QString depthTitle = QString::fromStdString(render::depthLegendTitle(*legends.depth));
    EXPECT_EQ(depthTitle, render::depthQuantityName(render::DepthReference::FrontmostVessel) +
                              QStringLiteral(" (mm)"));
    // The probe names the depth as the legend does, its number in mm.
    std::optional<gui::ProbeResult> probe;
    for (int y = 1; y < 20 && !probe; ++y) {
        probe = viewer->probeAt(QPointF(0.5 * viewer->width(), y * viewer->height() / 20.0));
    }
    ASSERT_TRUE(probe.has_value());
    const QStringList lines = gui::ViewerWidget::probeText(*probe).split(QLatin1Char('\n'));
    EXPECT_TRUE(lines.back().startsWith(
        render::depthQuantityName(render::DepthReference::FrontmostVessel) + QStringLiteral(": ")))
        << lines.back().toStdString();
    EXPECT_TRUE(lines.back().endsWith(QStringLiteral(" mm"))) << lines.back().toStdString();
    for (const QString& line : lines) {
        EXPECT_FALSE(line.contains(QStringLiteral("nearest"))) << line.toStdString();
    }
}

TEST_F(PanelsTest, FunctionalPanelSetsTheNoDataColourAndTheLegendTitle) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames());
    auto* panel = window_->functionalPanel();
    auto* viewer = window_->viewer();
    ASSERT_FALSE(viewer->style().array.empty());  // wss by default
    auto* title = child<QLineEdit>(panel, "functionalLegendTitle");
    auto* nan = child<QToolButton>(panel, "functionalNanColor");
    EXPECT_TRUE(title->isEnabled());
    EXPECT_TRUE(nan->isEnabled());
    EXPECT_EQ(title->text(), QStringLiteral("wss (Pa)"));  // the default title
    EXPECT_TRUE(viewer->style().legendTitle.empty());

    title->setText(QStringLiteral("Wall shear stress (Pa)"));
    emit title->editingFinished();
    EXPECT_EQ(viewer->style().legendTitle, "Wall shear stress (Pa)");
    const quint64 frames = viewer->framesWithScene();
    ASSERT_TRUE(waitUntil([&] { return viewer->framesWithScene() > frames; }));
    ASSERT_TRUE(viewer->shownLegends().parameter.has_value());
    EXPECT_EQ(render::parameterLegendTitle(*viewer->shownLegends().parameter),
              "Wall shear stress (Pa)");

    panel->setNoDataColor(QColor(255, 0, 255));
    ASSERT_TRUE(viewer->style().noDataColor.has_value());
    EXPECT_FLOAT_EQ(viewer->style().noDataColor->g, 0.0F);
    EXPECT_EQ(nan->text(), QStringLiteral("#ff00ff"));
    panel->setNoDataColor(QColor());  // back to the map's own
    EXPECT_FALSE(viewer->style().noDataColor.has_value());

    // No array: neither applies, and the tooltips say why.
    auto* array = panel->arrayChooser();
    array->setCurrentIndex(array->findData(QString()));
    EXPECT_FALSE(title->isEnabled());
    EXPECT_FALSE(title->toolTip().isEmpty());
    EXPECT_TRUE(viewer->style().legendTitle.empty());  // a title belongs to its array
}

TEST_F(PanelsTest, FunctionalPanelChoosesArrayMapBinsAndRange) {
    auto* panel = window_->functionalPanel();
    auto* viewer = window_->viewer();
    // No data: nothing applies, and each control says so.
    EXPECT_FALSE(panel->arrayChooser()->isEnabled());
    EXPECT_TRUE(panel->arrayChooser()->toolTip().contains(QStringLiteral("No data")));
    expectDisabledControlsExplained(panel, "functional panel, no data");

    // A mesh without arrays.
    window_->setScene(makeTubeScene(false), QStringLiteral("bare"));
    EXPECT_FALSE(panel->arrayChooser()->isEnabled());
    EXPECT_TRUE(panel->arrayChooser()->toolTip().contains(QStringLiteral("no point arrays")));
    expectDisabledControlsExplained(panel, "functional panel, no arrays");

    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames());
    ASSERT_EQ(panel->arrayChooser()->count(), 3);  // None, pressure, wss
    EXPECT_EQ(viewer->style().array, "wss");
    EXPECT_TRUE(panel->arrayChooser()->isEnabled());
    // The histogram holds every value of wss: 31 rings of 32 vertices.
    const auto& counts = panel->histogram()->counts();
    EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), 0), 31 * 32);
    EXPECT_DOUBLE_EQ(panel->histogram()->minimum(), 0.0);
    EXPECT_DOUBLE_EQ(panel->histogram()->maximum(), 30.0);

    // The colour map changes the vessels in the rendered frame at once.
    const QImage viridis = viewer->grabFramebuffer();
    quint64 frames = viewer->framesWithScene();
    panel->colorMapChooser()->setCurrentIndex(
        panel->colorMapChooser()->findData(static_cast<int>(colormaps::ColorMap::Inferno)));
    EXPECT_EQ(viewer->style().colorMap, colormaps::ColorMap::Inferno);
    ASSERT_TRUE(waitForFrames(frames + 1));
    EXPECT_GT(changedFraction(viridis, viewer->grabFramebuffer()), 0.02);
    auto* bins = child<QSpinBox>(panel, "functionalBins");
    bins->setValue(6);
    EXPECT_EQ(viewer->style().bins, 6);
    bins->setValue(1);
    EXPECT_EQ(viewer->style().bins, 0);  // continuous

    // Percentile 2-98 of 0..30 (32 copies of each integer: the 2nd percentile is 0).
    auto* mode = panel->rangeModeChooser();
    auto* lo = child<QDoubleSpinBox>(panel, "functionalRangeMin");
    auto* hi = child<QDoubleSpinBox>(panel, "functionalRangeMax");
    EXPECT_FALSE(lo->isEnabled());
    EXPECT_FALSE(lo->toolTip().isEmpty());
    mode->setCurrentIndex(mode->findData(static_cast<int>(FunctionalPanel::RangeMode::Percentile)));
    ASSERT_TRUE(viewer->style().range.has_value());
    std::vector<float> values;
    for (int i = 0; i <= 30; ++i) {
        values.insert(values.end(), 32, static_cast<float>(i));
    }
    EXPECT_FLOAT_EQ(viewer->style().range->first,
                    static_cast<float>(*FunctionalPanel::percentile(values, 2.0)));
    EXPECT_FLOAT_EQ(viewer->style().range->second,
                    static_cast<float>(*FunctionalPanel::percentile(values, 98.0)));
    EXPECT_DOUBLE_EQ(panel->histogram()->rangeLow(),
                     static_cast<double>(viewer->style().range->first));

    mode->setCurrentIndex(mode->findData(static_cast<int>(FunctionalPanel::RangeMode::Manual)));
    EXPECT_TRUE(lo->isEnabled());
    lo->setValue(5.0);
    hi->setValue(20.0);
    ASSERT_TRUE(viewer->style().range.has_value());
    EXPECT_FLOAT_EQ(viewer->style().range->first, 5.0F);
    EXPECT_FLOAT_EQ(viewer->style().range->second, 20.0F);
    EXPECT_DOUBLE_EQ(panel->histogram()->rangeHigh(), 20.0);
    window_->revealPanel(panel);
    QCoreApplication::processEvents();
    window_->grab().save(QString::fromStdString((panelTestDir() / "functional.png").string()));

    // Dragging the upper handle on the histogram moves the range's end.
    auto* histogram = panel->histogram();
    ASSERT_GT(histogram->width(), 100);
    const QPointF from(histogram->xOfValue(20.0), histogram->height() / 2.0);
    const QPointF to(histogram->xOfValue(25.0), histogram->height() / 2.0);
    QMouseEvent press(QEvent::MouseButtonPress, from, histogram->mapToGlobal(from), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QMouseEvent move(QEvent::MouseMove, to, histogram->mapToGlobal(to), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QMouseEvent release(QEvent::MouseButtonRelease, to, histogram->mapToGlobal(to), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(histogram, &press);
    QCoreApplication::sendEvent(histogram, &move);
    QCoreApplication::sendEvent(histogram, &release);
    ASSERT_TRUE(viewer->style().range.has_value());
    EXPECT_FLOAT_EQ(viewer->style().range->first, 5.0F);
    EXPECT_NEAR(viewer->style().range->second, 25.0F, 0.2F);
    EXPECT_NEAR(hi->value(), 25.0, 0.2);
    EXPECT_EQ(panel->rangeMode(), FunctionalPanel::RangeMode::Manual);
    mode->setCurrentIndex(mode->findData(static_cast<int>(FunctionalPanel::RangeMode::Auto)));
    EXPECT_FALSE(viewer->style().range.has_value());

    panel->arrayChooser()->setCurrentIndex(
        panel->arrayChooser()->findData(QStringLiteral("pressure")));
    EXPECT_EQ(viewer->style().array, "pressure");
    EXPECT_DOUBLE_EQ(panel->histogram()->minimum(), 70.0);
    EXPECT_EQ(child<QLineEdit>(panel, "functionalLegendTitle")->text(),
              QStringLiteral("pressure (mmHg)"));

    panel->arrayChooser()->setCurrentIndex(0);  // None
    EXPECT_TRUE(viewer->style().array.empty());
    EXPECT_FALSE(panel->colorMapChooser()->isEnabled());
    EXPECT_TRUE(panel->colorMapChooser()->toolTip().contains(QStringLiteral("Choose an array")));
    expectDisabledControlsExplained(panel, "functional panel, no array chosen");
}

TEST_F(PanelsTest, DisplayPanelSetsCueBackgroundCameraLegendsAndOverlay) {
    auto* panel = window_->displayPanel();
    auto* viewer = window_->viewer();
    // Camera presets need data.
    auto* close = child<QToolButton>(panel, "viewClose");
    EXPECT_FALSE(close->isEnabled());
    expectDisabledControlsExplained(panel, "display panel, no data");

    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames());
    EXPECT_TRUE(close->isEnabled());

    auto* cue = panel->vesselCueChooser();
    const QImage noCue = viewer->grabFramebuffer();
    const quint64 frames = viewer->framesWithScene();
    cue->setCurrentIndex(cue->findData(static_cast<int>(render::VesselCue::Fog)));
    EXPECT_EQ(viewer->vesselCue().cue, render::VesselCue::Fog);
    ASSERT_TRUE(waitForFrames(frames + 1));
    EXPECT_GT(changedFraction(noCue, viewer->grabFramebuffer()), 0.01);
    auto* fog = child<QSlider>(panel, "fogStrength");
    auto* fresnel = child<QDoubleSpinBox>(panel, "fresnelExponent");
    EXPECT_TRUE(fog->isEnabled());
    EXPECT_FALSE(fresnel->isEnabled());
    EXPECT_TRUE(fresnel->toolTip().contains(QStringLiteral("Fresnel")));
    fog->setValue(30);
    EXPECT_FLOAT_EQ(viewer->vesselCue().fogStrength, 0.30F);
    cue->setCurrentIndex(cue->findData(static_cast<int>(render::VesselCue::Fresnel)));
    EXPECT_TRUE(fresnel->isEnabled());
    EXPECT_FALSE(fog->isEnabled());
    fresnel->setValue(2.5);
    EXPECT_FLOAT_EQ(viewer->vesselCue().fresnelExponent, 2.5F);
    cue->setCurrentIndex(cue->findData(static_cast<int>(render::VesselCue::Fog)));

    // The material colour applies only without an array.
    auto* vesselColor = panel->vesselColorButton();
    EXPECT_FALSE(vesselColor->isEnabled());  // wss colours the vessels
    EXPECT_TRUE(vesselColor->toolTip().contains(QStringLiteral("array")));
    window_->arrayChooser()->setCurrentIndex(0);
    EXPECT_TRUE(vesselColor->isEnabled());
    vesselColor->click();
    auto* dialog = window_->findChild<QColorDialog*>(QStringLiteral("vesselColorDialog"));
    ASSERT_NE(dialog, nullptr);
    dialog->setCurrentColor(QColor(51, 102, 204));
    dialog->accept();
    EXPECT_NEAR(viewer->style().vesselColor.b, 0.8F, 1e-3F);
    EXPECT_NEAR(viewer->style().vesselColor.r, 0.2F, 1e-3F);
    window_->arrayChooser()->setCurrentIndex(
        window_->arrayChooser()->findData(QStringLiteral("wss")));

    auto* background = panel->backgroundChooser();
    background->setCurrentIndex(background->findText(QStringLiteral("White")));
    EXPECT_EQ(viewer->background(), glm::vec3(1.0F));

    child<QToolButton>(panel, "viewFar")->click();
    const float far = viewer->camera().distance();
    close->click();
    EXPECT_LT(viewer->camera().distance(), far);
    const glm::quat before = viewer->camera().rotation();
    child<QToolButton>(panel, "viewSuperior")->click();
    EXPECT_GT(
        glm::length(glm::vec4(
            viewer->camera().rotation().x - before.x, viewer->camera().rotation().y - before.y,
            viewer->camera().rotation().z - before.z, viewer->camera().rotation().w - before.w)),
        0.1F);

    panel->legendsBox()->setChecked(false);
    EXPECT_FALSE(viewer->legendsVisible());
    window_->legendsToggle()->setChecked(true);
    EXPECT_TRUE(panel->legendsBox()->isChecked());

    panel->performanceBox()->setChecked(true);
    const quint64 framesNow = viewer->framesWithScene();
    viewer->update();
    ASSERT_TRUE(waitForFrames(framesNow + 1));
    ASSERT_TRUE(waitUntil([&] {
        return panel->performanceOverlay()->text().contains(QStringLiteral("geometry"));
    })) << panel->performanceOverlay()->text().toStdString();
    EXPECT_TRUE(panel->performanceOverlay()->isVisible());
    EXPECT_TRUE(panel->performanceOverlay()->text().contains(QStringLiteral("ms")));
    window_->revealPanel(panel);
    QCoreApplication::processEvents();
    window_->grab().save(QString::fromStdString((panelTestDir() / "display.png").string()));
}

TEST_F(PanelsTest, DataPanelListsMeshesAndArrays) {
    auto* panel = window_->dataPanel();
    EXPECT_EQ(panel->meshTree()->topLevelItemCount(), 0);
    window_->setScene(makeTubeScene(), QStringLiteral("tube scene"));
    ASSERT_EQ(panel->meshTree()->topLevelItemCount(), 1);
    const QTreeWidgetItem* mesh = panel->meshTree()->topLevelItem(0);
    EXPECT_EQ(mesh->text(0), QStringLiteral("tube"));
    EXPECT_EQ(mesh->text(1), QLocale().toString(31 * 32));
    ASSERT_EQ(mesh->childCount(), 2);
    EXPECT_TRUE(mesh->child(1)->text(0).startsWith(QStringLiteral("wss (Pa)")));
    EXPECT_TRUE(mesh->child(1)->text(1).contains(QStringLiteral("30")));
    EXPECT_EQ(panel->fileLabel()->text(), QStringLiteral("tube scene"));
    // Visibility: a check box per mesh, all shown.
    EXPECT_TRUE(mesh->flags().testFlag(Qt::ItemIsUserCheckable));
    EXPECT_TRUE(mesh->flags().testFlag(Qt::ItemIsEnabled));
    EXPECT_EQ(mesh->checkState(0), Qt::Checked);
}

TEST_F(PanelsTest, DataPanelHidesAndShowsSingleMeshes) {
    // The tube and a copy of it beside it.
    auto scene = std::make_shared<scene::Scene>(*makeTubeScene());
    scene::Mesh copy = scene->meshes.front();
    copy.name = "copy";
    for (auto& p : copy.positions) {
        p.y += 8.0F;
    }
    scene->meshes.push_back(std::move(copy));
    window_->setScene(scene, QStringLiteral("two tubes"));
    auto* viewer = window_->viewer();
    ASSERT_TRUE(waitForFrames());
    ASSERT_TRUE(waitUntil([&] {
        const auto& s = viewer->vssStatus();
        return s.shown && s.current && !s.pending;
    }));
    const QImage both = viewer->grabFramebuffer();
    auto* tree = window_->dataPanel()->meshTree();
    ASSERT_EQ(tree->topLevelItemCount(), 2);

    // A frame of the current view with its own (not a stale) VSS.
    const auto settled = [&] {
        const quint64 frames = viewer->framesWithScene();
        return waitUntil([&] {
            const auto& s = viewer->vssStatus();
            return viewer->framesWithScene() > frames && s.shown && s.current && !s.pending;
        });
    };
    tree->topLevelItem(1)->setCheckState(0, Qt::Unchecked);
    EXPECT_EQ(viewer->style().hidden, std::vector<std::size_t>{1});
    ASSERT_TRUE(settled());
    const QImage one = viewer->grabFramebuffer();
    EXPECT_GT(changedFraction(both, one), 0.01);  // the copy is gone (and the VSS changed)

    tree->topLevelItem(1)->setCheckState(0, Qt::Checked);
    EXPECT_TRUE(viewer->style().hidden.empty());
    ASSERT_TRUE(settled());
    EXPECT_LT(changedFraction(both, viewer->grabFramebuffer()), 0.01);

    // A new scene shows every mesh again.
    tree->topLevelItem(0)->setCheckState(0, Qt::Unchecked);
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    EXPECT_TRUE(viewer->style().hidden.empty());
}

TEST_F(PanelsTest, ScrollingTheSidePanelOverAComboBoxKeepsItsValue) {
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    ASSERT_TRUE(waitForFrames());
    window_->resize(1280, 500);  // short: the side panel scrolls
    QCoreApplication::processEvents();
    QComboBox* array = window_->functionalPanel()->arrayChooser();
    ASSERT_TRUE(array->isVisible());
    const QString before = array->currentText();
    auto* bar = window_->sidePanel()->verticalScrollBar();
    ASSERT_GT(bar->maximum(), bar->minimum());
    bar->setValue(bar->maximum());  // the wheel turns up: room to scroll
    ASSERT_FALSE(array->hasFocus());
    const QPointF at(array->width() / 2.0, array->height() / 2.0);
    QWheelEvent event(at, array->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(array, &event);
    EXPECT_EQ(array->currentText(), before) << "a wheel passing over changed the array";
    EXPECT_LT(bar->value(), bar->maximum()) << "the panel did not scroll";
}

TEST_F(PanelsTest, SidePanelSectionsAreRestoredAndCanBeReset) {
    // One side panel; the VSS and Functional sections open at first, the
    // solver's internals folded.
    // (The planning docks under the views stay hidden until centrelines are found.)
    int shownDocks = 0;
    for (const QDockWidget* dock : window_->findChildren<QDockWidget*>()) {
        shownDocks += dock->isVisible() ? 1 : 0;
    }
    ASSERT_EQ(shownDocks, 1);
    auto* side = window_->sidePanel();
    ASSERT_EQ(side->sections().size(), 6);
    auto* data = side->sectionOf(window_->dataPanel());
    ASSERT_NE(data, nullptr);
    EXPECT_TRUE(side->sectionOf(window_->vssPanel())->isExpanded());
    EXPECT_TRUE(side->sectionOf(window_->functionalPanel())->isExpanded());
    EXPECT_FALSE(data->isExpanded());
    EXPECT_FALSE(window_->vssPanel()->advancedSection()->isExpanded());
    EXPECT_FALSE(window_->vssPanel()->solverChooser()->isVisible());
    EXPECT_TRUE(window_->vssPanel()->scaleChooser()->isVisible());
    EXPECT_TRUE(window_->vssPanel()->powerBox()->isVisible());

    data->header()->click();  // open it
    EXPECT_TRUE(data->isExpanded());
    EXPECT_TRUE(window_->dataPanel()->isVisible());
    window_->close();  // remembered
    window_ = std::make_unique<gui::MainWindow>();
    window_->show();
    data = window_->sidePanel()->sectionOf(window_->dataPanel());
    EXPECT_TRUE(data->isExpanded());
    window_->resetLayout();
    EXPECT_FALSE(data->isExpanded());
    EXPECT_TRUE(window_->sidePanel()->sectionOf(window_->vssPanel())->isExpanded());
    window_->close();  // the next tests start from the default layout again
}

}  // namespace
}  // namespace vv::test
