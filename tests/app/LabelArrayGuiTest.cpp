// SPDX-License-Identifier: GPL-3.0-or-later
// A label array in the GUI: the Functional panel's "Values" chooser and label
// list, and the hover probe naming the segment. A tube of radius 2 along x
// (0..30) seen from +z, segment 1 on x < 15 and segment 2 ("Left iliac") beyond.
#include <QComboBox>
#include <QListWidget>

#include "GuiFixture.h"
#include "gui/panels/ArrayValuesWidget.h"
#include "gui/panels/FunctionalPanel.h"
#include "vv/colormaps/LabelPalette.h"

namespace vv::test {
namespace {

template <typename T>
T* child(const QObject* parent, const char* name) {
    T* found = parent->findChild<T*>(QString::fromLatin1(name));
    EXPECT_NE(found, nullptr) << "no child " << name;
    return found;
}

std::shared_ptr<const scene::Scene> segmentedTube() {
    auto scene = std::make_shared<scene::Scene>();
    scene::Mesh tube = vv::test::tube(
        {.radius = 2.0F, .start = glm::vec3(0.0F), .length = 30.0F, .segments = 32, .rings = 30});
    vv::test::addAxialArray(tube, "wss", "Pa", 0.0F, [](float x) { return x; });
    vv::test::addAxialArray(tube, "segment_id", "", 0.0F,
                            [](float x) { return x < 15.0F ? 1.0F : 2.0F; });
    tube.labelNames["segment_id"] = {{2, "Left iliac"}};
    scene->meshes.push_back(std::move(tube));
    return scene;
}

class LabelArrayGuiTest : public GuiFixture {
  protected:
    bool showSegments() {
        window_->vssToggle()->setChecked(false);
        window_->setScene(segmentedTube(), QStringLiteral("tube"));
        if (!waitForFrames(1)) {
            return false;
        }
        auto* panel = window_->functionalPanel();
        auto* array = child<QComboBox>(panel, "arrayChooser");
        array->setCurrentIndex(array->findData(QStringLiteral("segment_id")));
        auto* viewer = window_->viewer();
        const quint64 frames = viewer->framesWithScene();
        return waitUntil([&] {
            const QSize device = viewer->size() * viewer->devicePixelRatioF();
            return viewer->framesWithScene() > frames && !viewer->view().refinement().moving() &&
                   viewer->lastRenderSize() == device;
        });
    }
};

TEST_F(LabelArrayGuiTest, TheValuesChooserListsTheLabelsAndSwitchesToContinuous) {
    ASSERT_TRUE(showSegments());
    auto* viewer = window_->viewer();
    ASSERT_EQ(viewer->style().array, "segment_id");
    auto* panel = window_->functionalPanel();
    auto* mode = child<QComboBox>(panel, "functionalValues");
    auto* list = child<QListWidget>(panel, "functionalLabels");
    EXPECT_EQ(mode->currentData().toInt(), static_cast<int>(render::ArrayValues::Auto));
    ASSERT_FALSE(list->isHidden());
    ASSERT_EQ(list->count(), 2);
    EXPECT_EQ(list->item(0)->text(), QStringLiteral("Label 1"));
    EXPECT_EQ(list->item(1)->text(), QStringLiteral("Left iliac"));
    ASSERT_TRUE(viewer->shownLegends().parameter.has_value());
    EXPECT_EQ(viewer->shownLegends().parameter->labels.size(), 2U);

    // Labels have their own palette: the colour map does not apply.
    auto* map = child<QComboBox>(panel, "colorMapChooser");
    EXPECT_FALSE(map->isEnabled());
    mode->setCurrentIndex(mode->findData(static_cast<int>(render::ArrayValues::Continuous)));
    EXPECT_TRUE(map->isEnabled());
    EXPECT_EQ(viewer->style().values, render::ArrayValues::Continuous);
    EXPECT_TRUE(list->isHidden());
    const quint64 frames = viewer->framesWithScene();
    ASSERT_TRUE(waitUntil([&] { return viewer->framesWithScene() > frames; }));
    ASSERT_TRUE(viewer->shownLegends().parameter.has_value());
    EXPECT_TRUE(viewer->shownLegends().parameter->labels.empty());
}

// The colour-blind-safe switch changes colour maps and depth scales; labels
// keep their palette (Okabe-Ito, safe for every dichromacy: LabelPaletteTest).
TEST_F(LabelArrayGuiTest, ColourBlindSafeModeKeepsTheLabels) {
    ASSERT_TRUE(showSegments());
    auto* viewer = window_->viewer();
    window_->colorBlindSafeToggle()->setChecked(true);
    const quint64 frames = viewer->framesWithScene();
    ASSERT_TRUE(waitUntil([&] { return viewer->framesWithScene() > frames; }));
    ASSERT_TRUE(viewer->shownLegends().parameter.has_value());
    EXPECT_EQ(viewer->shownLegends().parameter->labels.size(), 2U);
    EXPECT_EQ(viewer->style().values, render::ArrayValues::Auto);
}

TEST_F(LabelArrayGuiTest, TheProbeNamesTheSegment) {
    ASSERT_TRUE(showSegments());
    auto* viewer = window_->viewer();
    const auto far = viewer->probeAt(QPointF(0.75 * viewer->width(), 0.5 * viewer->height()));
    ASSERT_TRUE(far.has_value());
    ASSERT_TRUE(far->labelName.has_value());
    EXPECT_EQ(gui::ViewerWidget::probeText(*far).split(QLatin1Char('\n')).value(1),
              QStringLiteral("segment_id 2 (Left iliac)"));
    const auto near = viewer->probeAt(QPointF(0.25 * viewer->width(), 0.5 * viewer->height()));
    ASSERT_TRUE(near.has_value());
    EXPECT_EQ(gui::ViewerWidget::probeText(*near).split(QLatin1Char('\n')).value(1),
              QStringLiteral("segment_id 1"));
}

}  // namespace
}  // namespace vv::test
