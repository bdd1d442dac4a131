// SPDX-License-Identifier: GPL-3.0-or-later
// The colour-blind-safe mode: one switch (View menu, toolbar, Ctrl+Shift+B)
// that sets dark-means-deep on the VSS, cividis on the vessels and no
// red/green cue; the legends follow; and a rendered frame of the demo tree in
// that mode holds no red/green confusion pair, while the default chromadepth
// frame does.
//
// A red/green confusion pair (vv::colormaps::findRedGreenConfusions) is two
// of the frame's dominant colours (8-bit pixels binned on a 16^3 grid, bins
// with at least 0.2 % of the pixels, each bin's mean colour) that differ by
// CIEDE2000 >= 10 for normal vision but by < 3 as seen by a protanope or a
// deuteranope (Machado et al. 2009, severity 1): colours that tell things
// apart only through the red-green channel those viewers lack.
#include <QAction>
#include <QComboBox>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QShortcutEvent>
#include <QToolBar>
#include <vector>

#include "GuiFixture.h"
#include "gui/DisplayPreset.h"
#include "gui/panels/VssPanel.h"
#include "vv/colormaps/ColorVision.h"
#include "vv/meshio/MeshLoader.h"

namespace vv::test {
namespace {

using colormaps::ColorMap;
using colormaps::DepthScale;
using render::VesselCue;

TEST(DisplayPreset, ColorBlindSafeSetsDarkMeansDeepCividisAndNoColourCue) {
    gui::DisplayState state;
    state.vss.solver.p = 5.0;
    state.vss.scale = DepthScale::Chromadepth;
    state.style.array = "wss";
    state.style.colorMap = ColorMap::BlueWhiteRed;
    state.style.bins = 7;
    state.cue.cue = VesselCue::Fresnel;
    EXPECT_FALSE(gui::isColorBlindSafe(state));
    const gui::DisplayState safe = gui::colorBlindSafe(state);
    EXPECT_TRUE(gui::isColorBlindSafe(safe));
    EXPECT_EQ(safe.vss.scale, DepthScale::DarkMeansDeep);
    EXPECT_EQ(safe.style.colorMap, ColorMap::Cividis);
    EXPECT_EQ(safe.cue.cue, VesselCue::None);
    EXPECT_EQ(safe.vss.solver.p, 5.0);
    EXPECT_EQ(safe.style.array, "wss");
    EXPECT_EQ(safe.style.bins, 7);

    // Viridis counts as safe too (the user may pick it in the mode); fog is kept.
    state.style.colorMap = ColorMap::Viridis;
    state.cue.cue = VesselCue::Fog;
    EXPECT_EQ(gui::colorBlindSafe(state).style.colorMap, ColorMap::Cividis);
    EXPECT_EQ(gui::colorBlindSafe(state).cue.cue, VesselCue::Fog);
    state.vss.scale = DepthScale::DarkMeansDeep;
    EXPECT_TRUE(gui::isColorBlindSafe(state));
    for (const VesselCue cue :
         {VesselCue::Chromadepth, VesselCue::PseudoChromadepth, VesselCue::Fresnel}) {
        state.cue.cue = cue;
        state.vss.scale = DepthScale::DarkMeansDeep;
        EXPECT_FALSE(gui::isColorBlindSafe(state)) << static_cast<int>(cue);
    }
}

/// The frame's red/green confusion pairs (see the top of this file).
std::vector<colormaps::ConfusionPair> confusions(const QImage& frame) {
    const QImage rgb = frame.convertToFormat(QImage::Format_RGB888);
    std::vector<glm::u8vec3> pixels;
    pixels.reserve(static_cast<std::size_t>(rgb.width()) * static_cast<std::size_t>(rgb.height()));
    for (int y = 0; y < rgb.height(); ++y) {
        const uchar* line = rgb.constScanLine(y);
        for (int x = 0; x < rgb.width(); ++x) {
            pixels.emplace_back(line[3 * x], line[3 * x + 1], line[3 * x + 2]);
        }
    }
    std::vector<glm::dvec3> colors;
    for (const auto& entry : colormaps::dominantColors(pixels, 16, 0.002)) {
        colors.push_back(entry.srgb);
    }
    return colormaps::findRedGreenConfusions(colors, {10.0, 3.0});
}

class ColorBlindSafeTest : public GuiFixture {};

TEST_F(ColorBlindSafeTest, OneSwitchInMenuAndToolbarWithShortcut) {
    QAction* toggle = window_->colorBlindSafeToggle();
    ASSERT_NE(toggle, nullptr);
    EXPECT_EQ(toggle->shortcut(), QKeySequence(QStringLiteral("Ctrl+Shift+B")));
    EXPECT_TRUE(toggle->isCheckable());
    bool inMenu = false;
    for (QAction* menu : window_->menuBar()->actions()) {
        if (menu->menu() != nullptr && menu->menu()->actions().contains(toggle)) {
            inMenu = true;
        }
    }
    EXPECT_TRUE(inMenu);
    bool inToolBar = false;
    for (QToolBar* bar : window_->findChildren<QToolBar*>()) {
        inToolBar = inToolBar || bar->actions().contains(toggle);
    }
    EXPECT_TRUE(inToolBar);

    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    auto* viewer = window_->viewer();
    render::VesselCueSettings fresnel = viewer->vesselCue();
    fresnel.cue = VesselCue::Fresnel;
    viewer->setVesselCue(fresnel);
    ASSERT_TRUE(waitForFrames());
    EXPECT_FALSE(toggle->isChecked());  // chromadepth by default

    toggle->trigger();
    EXPECT_TRUE(toggle->isChecked());
    EXPECT_EQ(viewer->vssSettings().scale, DepthScale::DarkMeansDeep);
    EXPECT_EQ(viewer->style().colorMap, ColorMap::Cividis);
    EXPECT_EQ(viewer->vesselCue().cue, VesselCue::None);
    // The panels show it.
    EXPECT_EQ(window_->depthScaleChooser()->currentData().toInt(),
              static_cast<int>(DepthScale::DarkMeansDeep));
    EXPECT_EQ(window_->colorMapChooser()->currentData().toInt(),
              static_cast<int>(ColorMap::Cividis));
    EXPECT_EQ(window_->vesselCueChooser()->currentData().toInt(),
              static_cast<int>(VesselCue::None));
    // The legends follow: the depth legend in dark-means-deep, the parameter one in cividis.
    ASSERT_TRUE(waitForVss());
    ASSERT_TRUE(waitUntil([&] {
        const auto& legends = viewer->shownLegends();
        return legends.depth && legends.depth->scale == DepthScale::DarkMeansDeep &&
               legends.parameter && legends.parameter->map == ColorMap::Cividis;
    })) << "the legends did not follow";

    // Off restores the colours from before.
    toggle->trigger();
    EXPECT_FALSE(toggle->isChecked());
    EXPECT_EQ(viewer->vssSettings().scale, DepthScale::Chromadepth);
    EXPECT_EQ(viewer->style().colorMap, ColorMap::Viridis);
    EXPECT_EQ(viewer->vesselCue().cue, VesselCue::Fresnel);

    // The keyboard shortcut switches it on, too.
    QShortcutEvent shortcut(toggle->shortcut(), 0);
    QCoreApplication::sendEvent(toggle, &shortcut);
    EXPECT_TRUE(toggle->isChecked());
    EXPECT_EQ(viewer->vssSettings().scale, DepthScale::DarkMeansDeep);

    // Choosing an unsafe scale in the panel leaves the mode.
    window_->depthScaleChooser()->setCurrentIndex(
        window_->depthScaleChooser()->findData(static_cast<int>(DepthScale::PseudoChromadepth)));
    EXPECT_FALSE(toggle->isChecked());
    EXPECT_EQ(viewer->vssSettings().scale, DepthScale::PseudoChromadepth);
    // Picking dark-means-deep by hand (cividis still on) is the safe mode again.
    window_->depthScaleChooser()->setCurrentIndex(
        window_->depthScaleChooser()->findData(static_cast<int>(DepthScale::DarkMeansDeep)));
    EXPECT_TRUE(toggle->isChecked());
}

TEST_F(ColorBlindSafeTest, DemoFrameHasNoRedGreenConfusionPairs) {
    window_->setScene(std::make_shared<const scene::Scene>(
                          meshio::loadScene({std::filesystem::path(VV_DEMO_VTP)})),
                      QStringLiteral("demo"));
    auto* viewer = window_->viewer();
    ASSERT_TRUE(waitForFrames());
    ASSERT_TRUE(waitForVss());
    ASSERT_EQ(viewer->style().array, "wss");
    // Default: chromadepth on the VSS, viridis on the vessels.
    const QImage chromadepth = viewer->grabFramebuffer();
    chromadepth.save(QString::fromStdString((panelTestDir() / "cvd-default.png").string()));
    const auto unsafe = confusions(chromadepth);
    EXPECT_FALSE(unsafe.empty()) << "the check must be able to fail";

    window_->colorBlindSafeToggle()->trigger();
    const quint64 frames = viewer->framesWithScene();
    ASSERT_TRUE(waitForFrames(frames + 1));
    ASSERT_TRUE(waitForVss());
    // The view with its legends (the overlay is a child widget of the viewer).
    const QImage safe = viewer->grab().toImage();
    safe.save(QString::fromStdString((panelTestDir() / "cvd-safe.png").string()));
    const auto pairs = confusions(safe);
    for (const auto& p : pairs) {
        ADD_FAILURE() << "confusion (" << colormaps::name(p.vision) << "): " << p.first.r << ","
                      << p.first.g << "," << p.first.b << " vs " << p.second.r << "," << p.second.g
                      << "," << p.second.b << " dE00 " << p.normalDelta << " -> "
                      << p.simulatedDelta;
    }
    std::printf("red/green confusion pairs: default %zu, colour-blind safe %zu\n", unsafe.size(),
                pairs.size());

    // Without an array the vessels show their neutral material: still safe.
    window_->arrayChooser()->setCurrentIndex(0);
    ASSERT_TRUE(viewer->style().array.empty());
    EXPECT_TRUE(window_->colorBlindSafeToggle()->isChecked());
    const quint64 before = viewer->framesWithScene();
    ASSERT_TRUE(waitForFrames(before + 1));
    const QImage neutral = viewer->grab().toImage();
    neutral.save(QString::fromStdString((panelTestDir() / "cvd-safe-neutral.png").string()));
    EXPECT_TRUE(confusions(neutral).empty()) << confusions(neutral).size() << " pairs";
}

}  // namespace
}  // namespace vv::test
