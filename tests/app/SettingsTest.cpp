// SPDX-License-Identifier: GPL-3.0-or-later
// Display settings remembered between sessions (QSettings), "Reset to
// Defaults", and the keyboard shortcut list in Help.
#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSettings>

#include "GuiFixture.h"
#include "gui/ViewSettings.h"

namespace vv::test {
namespace {

class SettingsTest : public GuiFixture {
  protected:
    void TearDown() override {
        GuiFixture::TearDown();
        QSettings().clear();  // the next test starts from the defaults
    }

    /// Closes the window (which saves its settings) and opens a new one.
    void reopen() {
        window_->close();
        window_ = std::make_unique<gui::MainWindow>();
        window_->show();
    }
};

TEST_F(SettingsTest, DisplaySettingsAreRememberedAndReset) {
    auto* viewer = window_->viewer();
    window_->vssPowerBox()->setValue(5.0);
    window_->colorBlindSafeToggle()->trigger();  // dark-means-deep, cividis
    render::VssSettings vss = viewer->vssSettings();
    vss.solver.kind = vss::SolverKind::Step;
    vss.solver.step = 4;
    vss.isoLines = 3;
    viewer->setVssSettings(vss);
    render::AoSettings ao = viewer->aoSettings();
    ao.enabled = false;
    ao.radius = 6.0F;
    viewer->setAoSettings(ao);
    render::MeshStyle style = viewer->style();
    style.bins = 5;
    style.vesselColor = glm::vec3(0.25F, 0.5F, 0.75F);
    viewer->setStyle(style);
    viewer->setVesselCue({render::VesselCue::Fog, 0.8F, 1.0F});
    viewer->setBackground(glm::vec3(1.0F));
    viewer->setLegendsVisible(false);

    reopen();
    viewer = window_->viewer();
    EXPECT_DOUBLE_EQ(viewer->vssSettings().solver.p, 5.0);
    EXPECT_EQ(viewer->vssSettings().scale, colormaps::DepthScale::DarkMeansDeep);
    EXPECT_EQ(viewer->vssSettings().solver.kind, vss::SolverKind::Step);
    EXPECT_EQ(viewer->vssSettings().solver.step, 4);
    EXPECT_EQ(viewer->vssSettings().isoLines, 3);
    EXPECT_FALSE(viewer->aoSettings().enabled);
    EXPECT_FLOAT_EQ(viewer->aoSettings().radius, 6.0F);
    EXPECT_EQ(viewer->style().colorMap, colormaps::ColorMap::Cividis);
    EXPECT_EQ(viewer->style().bins, 5);
    EXPECT_EQ(viewer->style().vesselColor, glm::vec3(0.25F, 0.5F, 0.75F));
    EXPECT_EQ(viewer->vesselCue().cue, render::VesselCue::Fog);
    EXPECT_EQ(viewer->background(), glm::vec3(1.0F));
    EXPECT_FALSE(viewer->legendsVisible());
    // The controls show the restored settings.
    EXPECT_DOUBLE_EQ(window_->vssPowerBox()->value(), 5.0);
    EXPECT_TRUE(window_->colorBlindSafeToggle()->isChecked());
    EXPECT_FALSE(window_->legendsToggle()->isChecked());

    window_->resetToDefaults();
    const render::VssSettings defaults;
    EXPECT_DOUBLE_EQ(viewer->vssSettings().solver.p, defaults.solver.p);
    EXPECT_EQ(viewer->vssSettings().scale, defaults.scale);
    EXPECT_EQ(viewer->vssSettings().solver.kind, defaults.solver.kind);
    EXPECT_TRUE(viewer->aoSettings().enabled);
    EXPECT_EQ(viewer->style().colorMap, render::MeshStyle{}.colorMap);
    EXPECT_EQ(viewer->style().bins, 0);
    EXPECT_EQ(viewer->style().vesselColor, render::MeshStyle{}.vesselColor);
    EXPECT_EQ(viewer->vesselCue().cue, render::VesselCue::None);
    EXPECT_EQ(viewer->background(), render::kDefaultBackground);
    EXPECT_TRUE(viewer->legendsVisible());
    EXPECT_FALSE(window_->colorBlindSafeToggle()->isChecked());
    EXPECT_DOUBLE_EQ(window_->vssPowerBox()->value(), defaults.solver.p);
}

TEST_F(SettingsTest, InvalidStoredValuesAreIgnored) {
    {
        QSettings settings;
        settings.setValue(QStringLiteral("view/depthScale"), QStringLiteral("rainbow"));
        settings.setValue(QStringLiteral("view/power"), 1000.0);
        settings.setValue(QStringLiteral("view/solver"), QStringLiteral("magic"));
        settings.setValue(QStringLiteral("view/bins"), 1);
        settings.setValue(QStringLiteral("view/vesselCue"), 99);
        settings.setValue(QStringLiteral("view/background"), QStringLiteral("not a colour"));
        settings.setValue(QStringLiteral("view/vesselColor"), QVariantList{0.5, 2.0, 0.5});
        settings.setValue(QStringLiteral("view/isoLines"), 7);
    }
    window_.reset();  // without closing, which would save its own settings
    window_ = std::make_unique<gui::MainWindow>();
    const render::VssSettings defaults;
    const auto* viewer = window_->viewer();
    EXPECT_EQ(viewer->vssSettings().scale, defaults.scale);
    EXPECT_DOUBLE_EQ(viewer->vssSettings().solver.p, defaults.solver.p);
    EXPECT_EQ(viewer->vssSettings().solver.kind, defaults.solver.kind);
    EXPECT_EQ(viewer->style().bins, 0);
    EXPECT_EQ(viewer->vesselCue().cue, render::VesselCue::None);
    EXPECT_EQ(viewer->background(), render::kDefaultBackground);
    EXPECT_EQ(viewer->style().vesselColor, render::MeshStyle{}.vesselColor);
    EXPECT_EQ(viewer->vssSettings().isoLines, 7);  // the valid one is taken
}

TEST_F(SettingsTest, ScreenshotModeIgnoresRememberedSettings) {
    window_->vssPowerBox()->setValue(7.0);
    reopen();
    EXPECT_DOUBLE_EQ(window_->viewer()->vssSettings().solver.p, 7.0);
    window_->setScreenshotTarget(
        QString::fromStdString((panelTestDir() / "never-written.png").string()));
    EXPECT_DOUBLE_EQ(window_->viewer()->vssSettings().solver.p, render::VssSettings{}.solver.p);
    window_->setScreenshotTarget({});
}

TEST_F(SettingsTest, HelpListsTheKeyboardShortcuts) {
    const QString summary = window_->shortcutSummary();
    const QString cvd =
        window_->colorBlindSafeToggle()->shortcut().toString(QKeySequence::NativeText);
    EXPECT_FALSE(cvd.isEmpty());
    EXPECT_TRUE(summary.contains(cvd.toHtmlEscaped())) << summary.toStdString();
    EXPECT_TRUE(summary.contains(QStringLiteral("Colour-blind safe"))) << summary.toStdString();
    EXPECT_TRUE(summary.contains(QStringLiteral("Reset Camera")));
    EXPECT_TRUE(summary.contains(QStringLiteral("wheel")));
    const QString about = window_->aboutText();
    EXPECT_TRUE(about.contains(QString::fromLatin1(qVersion()))) << about.toStdString();
}

}  // namespace
}  // namespace vv::test
