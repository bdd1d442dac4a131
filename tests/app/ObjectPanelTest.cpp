// SPDX-License-Identifier: GPL-3.0-or-later
// The Data panel's per-object controls (colour, opacity, array), the Display
// panel's light direction, and how sessions and QSettings keep them. Under
// Xvfb (QT_QPA_PLATFORM=xcb).
#include <QColorDialog>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QSpinBox>
#include <QToolButton>
#include <QTreeWidget>
#include <functional>
#include <string>

#include "GuiFixture.h"
#include "gui/Session.h"
#include "gui/ViewSettings.h"
#include "gui/panels/DataPanel.h"
#include "gui/panels/DisplayPanel.h"

namespace vv::test {
namespace {

class ObjectPanelTest : public GuiFixture {
  protected:
    /// The tube (with arrays) and a copy beside it without arrays.
    static std::shared_ptr<const scene::Scene> twoObjects() {
        auto scene = std::make_shared<scene::Scene>(*makeTubeScene());
        scene::Mesh copy = scene->meshes.front();
        copy.name = "copy";
        copy.pointArrays.clear();
        for (auto& p : copy.positions) {
            p.y += 8.0F;
        }
        scene->meshes.push_back(std::move(copy));
        return scene;
    }

    /// Shows `scene` and waits for its first frame and exact VSS.
    [[nodiscard]] bool show(std::shared_ptr<const scene::Scene> scene) {
        window_->setScene(std::move(scene), QStringLiteral("objects"));
        return waitForFrames() && waitForVss();
    }

    /// A new frame of the current view with its exact VSS; its image.
    QImage settledFrame() const {
        auto* viewer = window_->viewer();
        const quint64 frames = viewer->framesWithScene();
        EXPECT_TRUE(waitUntil([&] {
            const auto& s = viewer->vssStatus();
            return viewer->framesWithScene() > frames && s.shown && s.current && !s.pending &&
                   !s.preview;
        }));
        return viewer->grabFramebuffer();
    }

    static render::PassState passState(const gui::ViewerWidget& viewer, const std::string& name) {
        for (const auto& pass : viewer.lastPasses()) {
            if (pass.name == name) {
                return pass.state;
            }
        }
        ADD_FAILURE() << "no pass " << name;
        return render::PassState::Pending;
    }
};

TEST_F(ObjectPanelTest, DataPanelControlsChangeTheViewAndDisableWhereTheyDoNotApply) {
    auto* viewer = window_->viewer();
    ASSERT_TRUE(show(twoObjects()));
    auto* panel = window_->dataPanel();
    ASSERT_NE(panel->arrayChooser(0), nullptr);
    ASSERT_NE(panel->colorButton(1), nullptr);
    ASSERT_EQ(panel->opacityBox(2), nullptr);
    const QImage start = viewer->grabFramebuffer();

    // The copy has no arrays: its chooser is disabled and says why.
    EXPECT_TRUE(panel->arrayChooser(0)->isEnabled());
    EXPECT_FALSE(panel->arrayChooser(1)->isEnabled());
    EXPECT_FALSE(panel->arrayChooser(1)->toolTip().isEmpty());
    // The tube shows "wss": its colour does not apply, with a reason.
    EXPECT_EQ(viewer->style().arrayOf(0), "wss");
    EXPECT_FALSE(panel->colorButton(0)->isEnabled());
    EXPECT_FALSE(panel->colorButton(0)->toolTip().isEmpty());
    // Only the arrays the mesh has are offered (besides Scene array and None).
    QComboBox* array = panel->arrayChooser(0);
    ASSERT_EQ(array->count(), 4);
    EXPECT_EQ(array->findText(QStringLiteral("pressure")), 2);

    // Another array on the tube: new colours and a legend for it.
    array->setCurrentIndex(array->findText(QStringLiteral("pressure")));
    EXPECT_EQ(viewer->style().arrayOf(0), "pressure");
    EXPECT_EQ(viewer->style().arrayOf(1), "wss");
    const QImage pressure = settledFrame();
    EXPECT_GT(changedFraction(start, pressure), 0.005);
    ASSERT_TRUE(viewer->shownLegends().parameter.has_value());
    // The copy has no "wss": only the tube's array has a legend.
    EXPECT_EQ(viewer->shownLegends().parameter->name, "pressure");
    EXPECT_TRUE(viewer->shownLegends().moreParameters.empty());

    // None: the material colour, which the colour button now sets.
    array->setCurrentIndex(array->findData(gui::panels::DataPanel::NoArray));
    ASSERT_TRUE(panel->colorButton(0)->isEnabled());
    const QImage neutral = settledFrame();
    panel->colorButton(0)->click();
    auto* dialog = panel->findChild<QColorDialog*>(QStringLiteral("objectColorDialog"));
    ASSERT_NE(dialog, nullptr);
    dialog->setCurrentColor(QColor(20, 200, 40));
    dialog->accept();
    ASSERT_TRUE(viewer->style().object(0).color.has_value());
    EXPECT_NEAR(viewer->style().object(0).color->g, 200.0F / 255.0F, 1e-3F);
    const QImage green = settledFrame();
    EXPECT_GT(changedFraction(neutral, green), 0.005);

    // Opacity: the translucent pass runs, the view changes; 100 % culls it again.
    panel->opacityBox(0)->setValue(50);
    EXPECT_FLOAT_EQ(viewer->style().object(0).opacity, 0.5F);
    const QImage half = settledFrame();
    EXPECT_EQ(passState(*viewer, "translucent"), render::PassState::Executed);
    EXPECT_GT(changedFraction(green, half), 0.005);
    panel->opacityBox(0)->setValue(100);
    static_cast<void>(settledFrame());
    EXPECT_EQ(passState(*viewer, "translucent"), render::PassState::Culled);

    // For people to look at: the window with the Data panel's controls.
    window_->revealPanel(panel);
    QCoreApplication::processEvents();
    window_->grab().save(QString::fromStdString((panelTestDir() / "data-panel.png").string()));

    // A hidden object's controls are disabled, with the reason.
    panel->meshTree()->topLevelItem(0)->setCheckState(0, Qt::Unchecked);
    EXPECT_FALSE(panel->opacityBox(0)->isEnabled());
    EXPECT_FALSE(panel->arrayChooser(0)->isEnabled());
    EXPECT_FALSE(panel->opacityBox(0)->toolTip().isEmpty());

    // A new scene starts in the scene's style.
    window_->setScene(makeTubeScene(), QStringLiteral("tube"));
    EXPECT_TRUE(viewer->style().objects.empty());
    EXPECT_EQ(panel->opacityBox(0)->value(), 100);
}

TEST_F(ObjectPanelTest, LightDirectionChangesTheViewAndIsRemembered) {
    auto* viewer = window_->viewer();
    ASSERT_TRUE(show(makeTubeScene()));
    auto* display = window_->displayPanel();
    ASSERT_TRUE(display->lightAzimuthBox()->isEnabled());
    const QImage start = viewer->grabFramebuffer();
    display->lightAzimuthBox()->setValue(70.0);
    display->lightElevationBox()->setValue(-30.0);
    EXPECT_FLOAT_EQ(viewer->style().light.azimuth, 70.0F);
    EXPECT_FLOAT_EQ(viewer->style().light.elevation, -30.0F);
    const QImage moved = settledFrame();
    EXPECT_GT(changedFraction(start, moved), 0.01);

    // Remembered in QSettings.
    const QString file = QString::fromStdString((panelTestDir() / "light.ini").string());
    {
        QSettings settings(file, QSettings::IniFormat);
        gui::saveViewSettings(*viewer, settings);
    }
    display->lightResetButton()->click();
    EXPECT_EQ(viewer->style().light, render::LightAngles{});
    EXPECT_LT(changedFraction(start, settledFrame()), 0.002);
    {
        const QSettings settings(file, QSettings::IniFormat);
        gui::restoreViewSettings(*viewer, settings);
    }
    EXPECT_FLOAT_EQ(viewer->style().light.azimuth, 70.0F);
    EXPECT_FLOAT_EQ(viewer->style().light.elevation, -30.0F);
    gui::resetViewSettings(*viewer);
    EXPECT_EQ(viewer->style().light, render::LightAngles{});

    // Without data the light does not apply.
    window_->setScene(nullptr, QString());
    display->syncFromViewer();
    EXPECT_FALSE(display->lightAzimuthBox()->isEnabled());
    EXPECT_FALSE(display->lightAzimuthBox()->toolTip().isEmpty());
}

TEST(ObjectSession, LightAndObjectsRoundTripAndOldSessionsGetDefaults) {
    gui::Session s;
    s.files = {QStringLiteral("/data/a.vtp")};
    s.style.array = "wss";
    s.style.light = render::LightAngles{-120.5F, 33.0F};
    s.style.objects.resize(3);
    s.style.objects[0].color = glm::vec3(0.25F, 0.5F, 1.0F);
    s.style.objects[1].opacity = 0.4F;
    s.style.objects[1].array = "pressure";
    s.style.objects[2].array = "";
    s.style.hidden = {2};
    const fs::path path = panelTestDir() / "objects.vvs";
    gui::saveSession(path, s);
    const gui::Session back = gui::loadSession(path);
    EXPECT_EQ(back.style.light, s.style.light);
    EXPECT_EQ(back.style.objects, s.style.objects);
    EXPECT_EQ(back.style.hidden, s.style.hidden);

    // Edits the saved style object.
    const auto withStyle = [&](const std::function<void(QJsonObject&)>& edit) {
        QJsonObject root = QJsonDocument::fromJson(gui::sessionToJson(s, path)).object();
        QJsonObject view = root.value(QStringLiteral("view")).toObject();
        QJsonObject style = view.value(QStringLiteral("style")).toObject();
        edit(style);
        view.insert(QStringLiteral("style"), style);
        root.insert(QStringLiteral("view"), view);
        return QJsonDocument(root).toJson();
    };
    // A session from before: neither "light" nor "objects".
    const gui::Session old = gui::sessionFromJson(withStyle([](QJsonObject& style) {
                                                      style.remove(QStringLiteral("light"));
                                                      style.remove(QStringLiteral("objects"));
                                                  }),
                                                  path);
    EXPECT_EQ(old.style.light, render::LightAngles{});
    EXPECT_TRUE(old.style.objects.empty());
    EXPECT_TRUE(old.style.hidden.empty());

    // Bad values are refused with the field's name.
    const auto errorFor = [&](const QByteArray& json) -> std::string {
        try {
            static_cast<void>(gui::sessionFromJson(json, path));
        } catch (const FormatError& e) {
            return e.what();
        }
        return {};
    };
    const std::string opacity = errorFor(withStyle([](QJsonObject& style) {
        QJsonArray objects = style.value(QStringLiteral("objects")).toArray();
        QJsonObject second = objects[1].toObject();
        second.insert(QStringLiteral("opacity"), 1.4);
        objects[1] = second;
        style.insert(QStringLiteral("objects"), objects);
    }));
    EXPECT_NE(opacity.find("view.style.objects[1].opacity"), std::string::npos) << opacity;
    const std::string light = errorFor(withStyle([](QJsonObject& style) {
        style.insert(QStringLiteral("light"), QJsonArray{10.0, 95.0});
    }));
    EXPECT_NE(light.find("view.style.light"), std::string::npos) << light;
}

}  // namespace
}  // namespace vv::test
