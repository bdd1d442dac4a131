// SPDX-License-Identifier: GPL-3.0-or-later
// The probe (object, value, depth under the mouse) and the two-point
// measurement, on a tube of radius 2 along x (0..30) seen from +z: its front
// line (y = 0, z = 2) is the nearest visible vessel point everywhere.
#include <QAction>
#include <QCoreApplication>
#include <QHelpEvent>
#include <QImage>
#include <QKeySequence>
#include <QLabel>
#include <QLineF>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <optional>

#include "GuiFixture.h"
#include "gui/MeasureOverlay.h"

namespace vv::test {
namespace {

/// Sends a mouse event of `type` at `position` (logical widget coordinates).
void sendMouse(QWidget* widget, QEvent::Type type, const QPointF& position, Qt::MouseButton button,
               Qt::KeyboardModifiers modifiers) {
    const Qt::MouseButtons buttons =
        type == QEvent::MouseButtonPress ? Qt::MouseButtons(button) : Qt::MouseButtons();
    QMouseEvent event(type, position, widget->mapToGlobal(position), button, buttons, modifiers);
    QCoreApplication::sendEvent(widget, &event);
}

void click(QWidget* widget, const QPointF& position, Qt::KeyboardModifiers modifiers = {}) {
    sendMouse(widget, QEvent::MouseButtonPress, position, Qt::LeftButton, modifiers);
    sendMouse(widget, QEvent::MouseButtonRelease, position, Qt::LeftButton, modifiers);
}

class ProbeTest : public GuiFixture {
  protected:
    /// Shows the tube (VSS off: not needed here) and waits for a frame at full size.
    bool showTube() {
        window_->vssToggle()->setChecked(false);
        window_->setScene(makeTubeScene(), QStringLiteral("tube"));
        if (!waitForFrames(1)) {
            return false;
        }
        auto* viewer = window_->viewer();
        // A settled frame: rendered at the full size.
        return waitUntil([&] {
            const QSize device = viewer->size() * viewer->devicePixelRatioF();
            return !viewer->view().refinement().moving() && viewer->lastRenderSize() == device;
        });
    }

    /// The widget's centre row at fraction `fx` of its width.
    [[nodiscard]] QPointF onAxis(double fx) const {
        const auto* viewer = window_->viewer();
        return {fx * viewer->width(), 0.5 * viewer->height()};
    }
};

TEST_F(ProbeTest, ProbeGivesObjectValueUnitAndDepth) {
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    ASSERT_EQ(viewer->style().array, "wss");

    const auto centre = viewer->probeAt(onAxis(0.5));
    ASSERT_TRUE(centre.has_value()) << "no vessel at the centre of the view";
    EXPECT_EQ(centre->meshIndex, 0);
    EXPECT_EQ(centre->objectName, QStringLiteral("tube"));
    EXPECT_EQ(centre->arrayName, QStringLiteral("wss"));
    EXPECT_EQ(centre->unit, QStringLiteral("Pa"));
    // wss = ring index = x (the tube is 30 long with 30 rings).
    EXPECT_NEAR(centre->value, centre->worldPosition.x, 0.6F);
    EXPECT_NEAR(centre->worldPosition.x, 15.0F, 1.0F);
    EXPECT_NEAR(centre->worldPosition.y, 0.0F, 0.15F);
    EXPECT_NEAR(centre->worldPosition.z, 2.0F, 0.1F);
    EXPECT_NEAR(centre->depthBelowNearest, 0.0F, 0.1F);
    EXPECT_GT(centre->linearDepth, 0.0F);

    // Off-axis, towards the silhouette: deeper by 2 - z (a circle of radius 2).
    bool sawDeeper = false;
    for (int dy = 4; dy < viewer->height() / 2; dy += 4) {
        const auto p = viewer->probeAt(QPointF(0.5 * viewer->width(), 0.5 * viewer->height() - dy));
        if (!p) {
            break;
        }
        EXPECT_NEAR(p->depthBelowNearest, 2.0F - p->worldPosition.z, 0.12F) << "dy " << dy;
        EXPECT_NEAR(std::hypot(p->worldPosition.y, p->worldPosition.z), 2.0F, 0.1F);
        sawDeeper = sawDeeper || p->depthBelowNearest > 0.5F;
    }
    EXPECT_TRUE(sawDeeper) << "the probe never reached the tube's flank";

    // The background: nothing. Outside the widget: nothing.
    EXPECT_FALSE(viewer->probeAt(QPointF(0.5 * viewer->width(), 2.0)).has_value());
    EXPECT_FALSE(viewer->probeAt(QPointF(-5.0, -5.0)).has_value());

    const QString text = gui::ViewerWidget::probeText(*centre);
    EXPECT_TRUE(text.contains(QStringLiteral("tube"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral(" Pa"))) << text.toStdString();
    EXPECT_TRUE(text.contains(QStringLiteral("mm"))) << text.toStdString();
}

TEST_F(ProbeTest, NoArrayMeansNoValue) {
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    render::MeshStyle style = viewer->style();
    style.array.clear();
    viewer->setStyle(style);
    const quint64 before = viewer->framesWithScene();
    ASSERT_TRUE(waitForFrames(before + 1));
    const auto p = viewer->probeAt(onAxis(0.5));
    ASSERT_TRUE(p.has_value());
    EXPECT_TRUE(std::isnan(p->value));
    EXPECT_TRUE(p->arrayName.isEmpty());
    EXPECT_FALSE(gui::ViewerWidget::probeText(*p).contains(QStringLiteral("Pa")));
}

TEST_F(ProbeTest, HoverShowsTooltip) {
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    ASSERT_TRUE(viewer->hoverProbe());
    QToolTip::hideText();
    sendMouse(viewer, QEvent::MouseMove, onAxis(0.5), Qt::NoButton, {});
    EXPECT_TRUE(waitUntil(
        [] { return QToolTip::isVisible() && QToolTip::text().contains(QStringLiteral("tube")); },
        5000))
        << "tooltip: " << QToolTip::text().toStdString();
    QToolTip::hideText();

    // Qt's own tooltip event: over a vessel the probe, not the mouse help.
    const QPoint at = onAxis(0.5).toPoint();
    QHelpEvent help(QEvent::ToolTip, at, viewer->mapToGlobal(at));
    QCoreApplication::sendEvent(viewer, &help);
    EXPECT_TRUE(QToolTip::text().contains(QStringLiteral("tube")))
        << QToolTip::text().toStdString();
    QToolTip::hideText();
}

TEST_F(ProbeTest, TwoClickedPointsGiveDistanceAndDepthDifference) {
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    struct {
        int n = 0;
        [[nodiscard]] int count() const { return n; }
    } picked;
    QObject::connect(viewer, &gui::ViewerWidget::pointPicked, window_.get(),
                     [&picked] { ++picked.n; });

    // A plain click does not pick; Ctrl + click does.
    click(viewer, onAxis(0.3));
    EXPECT_EQ(picked.count(), 0);
    click(viewer, onAxis(0.3), Qt::ControlModifier);
    ASSERT_EQ(picked.count(), 1);
    ASSERT_EQ(window_->measurePoints().size(), 1);

    // In measure mode a plain click picks the second point.
    window_->measureToggle()->setChecked(true);
    click(viewer, onAxis(0.7));
    ASSERT_EQ(picked.count(), 2);
    ASSERT_EQ(window_->measurePoints().size(), 2);
    const auto& a = window_->measurePoints()[0];
    const auto& b = window_->measurePoints()[1];
    const gui::Measurement m = gui::measure(a, b, viewer->camera());
    // Both on the front line: the distance is their x difference, no depth difference.
    EXPECT_GT(b.worldPosition.x - a.worldPosition.x, 4.0F);
    EXPECT_NEAR(m.distance, b.worldPosition.x - a.worldPosition.x, 0.2F);
    EXPECT_NEAR(m.depthDifference, 0.0F, 0.1F);
    // The markers sit where the points were clicked (the probe's world
    // position projected back with the camera).
    const auto* overlay = window_->measureOverlay();
    EXPECT_TRUE(overlay->isVisible());
    ASSERT_EQ(overlay->points().size(), 2);
    const auto markA = overlay->project(a);
    const auto markB = overlay->project(b);
    ASSERT_TRUE(markA && markB);
    EXPECT_LT(QLineF(*markA, onAxis(0.3)).length(), 2.0);
    EXPECT_LT(QLineF(*markB, onAxis(0.7)).length(), 2.0);
    const QString label = window_->measureLabel()->text();
    EXPECT_TRUE(label.contains(QLocale().toString(static_cast<double>(m.distance), 'f', 1)))
        << label.toStdString();

    // A third click starts a new measurement; the background is no pick.
    click(viewer, QPointF(viewer->width() / 2.0, 2.0));
    EXPECT_EQ(picked.count(), 2);
    click(viewer, onAxis(0.5));
    EXPECT_EQ(window_->measurePoints().size(), 1);
    // Leaving measure mode keeps the measurement on screen; Esc clears it.
    window_->measureToggle()->setChecked(false);
    EXPECT_EQ(window_->measurePoints().size(), 1);
    EXPECT_TRUE(window_->measureOverlay()->isVisible());
    EXPECT_FALSE(window_->measureLabel()->text().isEmpty());
    auto* clear = window_->findChild<QAction*>(QStringLiteral("clearMeasurement"));
    ASSERT_NE(clear, nullptr);
    EXPECT_TRUE(clear->shortcuts().contains(QKeySequence(Qt::Key_Escape)));
    clear->trigger();
    EXPECT_TRUE(window_->measurePoints().isEmpty());
    EXPECT_FALSE(window_->measureOverlay()->isVisible());
    EXPECT_TRUE(window_->measureLabel()->text().isEmpty());
}

/// The number after `prefix` in `text` (UI-locale decimals), NaN when none.
double numberAfter(const QString& text, const QString& prefix) {
    const qsizetype at = text.indexOf(prefix);
    if (at < 0) {
        return std::nan("");
    }
    const QString rest = text.mid(at + prefix.size());
    const QString digits = rest.left(rest.indexOf(QLatin1Char(' ')));
    bool ok = false;
    const double value = QLocale().toDouble(digits, &ok);
    return ok ? value : std::nan("");
}

TEST_F(ProbeTest, MeasuredDepthDifferenceFollowsTheViewAndTheDistanceStays) {
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    click(viewer, onAxis(0.3), Qt::ControlModifier);
    click(viewer, onAxis(0.7), Qt::ControlModifier);
    ASSERT_EQ(window_->measurePoints().size(), 2);
    const glm::vec3 a = window_->measurePoints()[0].worldPosition;
    const glm::vec3 b = window_->measurePoints()[1].worldPosition;
    const QString distancePrefix = QStringLiteral("Distance 1–2: ");
    const double distance = numberAfter(window_->measureLabel()->text(), distancePrefix);
    EXPECT_NEAR(distance, glm::length(b - a), 0.051)
        << window_->measureLabel()->text().toStdString();

    // German numbers from here on: the label follows the UI locale.
    const QLocale before;
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    // Turn the view 40 degrees about its vertical axis: B (right of A) moves away.
    render::Camera camera = viewer->camera();
    camera.rotateView(glm::radians(40.0F), glm::vec3(0.0F, 1.0F, 0.0F));
    const quint64 frames = viewer->framesWithScene();
    viewer->setCamera(camera);
    ASSERT_TRUE(waitForFrames(frames + 1));
    QCoreApplication::processEvents();
    const QString label = window_->measureLabel()->text();
    QLocale::setDefault(before);
    // Depth difference along the new view direction, from the points and the camera's eye.
    const glm::vec3 viewDirection = glm::normalize(camera.target() - camera.eye());
    const double expected = glm::dot(b - a, viewDirection);
    ASSERT_GT(std::abs(expected), 3.0) << "the turn should put the points at other depths";
    const QString deeper =
        expected > 0 ? QStringLiteral("point 2 deeper by ") : QStringLiteral("point 1 deeper by ");
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    const double shownDepth = numberAfter(label, deeper);
    const double shownDistance = numberAfter(label, distancePrefix);
    QLocale::setDefault(before);
    EXPECT_NEAR(shownDepth, std::abs(expected), 0.051) << label.toStdString();
    EXPECT_TRUE(label.contains(QStringLiteral("depth difference in this view")))
        << label.toStdString();
    // The tooltip says what the depth difference is measured along.
    EXPECT_TRUE(window_->measureLabel()->toolTip().contains(
        QStringLiteral("along the current view direction")));
    EXPECT_NEAR(shownDistance, distance, 1e-9) << label.toStdString();
    EXPECT_TRUE(label.contains(QLatin1Char(','))) << "German decimals: " << label.toStdString();
}

/// `label` as the overlay marks a point at `at` (bold, white with a dark
/// halo) on a transparent image of `size`.
QImage markedLabel(const QString& label, const QFont& widgetFont, const QSize& size,
                   const QPointF& at) {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    QFont font = widgetFont;
    font.setBold(true);
    QPainterPath path;
    path.addText(at + QPointF(8.0, 16.0), font, label);
    painter.setPen(QPen(QColor(0, 0, 0, 200), 3.0));
    painter.drawPath(path);
    painter.fillPath(path, Qt::white);
    return image;
}

/// Pixels differing by more than 64 in alpha or grey inside `box`.
int differing(const QImage& a, const QImage& b, const QRect& box) {
    int n = 0;
    for (int y = box.top(); y <= box.bottom(); ++y) {
        for (int x = box.left(); x <= box.right(); ++x) {
            const QRgb p = a.pixel(x, y);
            const QRgb q = b.pixel(x, y);
            n += std::abs(qAlpha(p) - qAlpha(q)) > 64 || std::abs(qGray(p) - qGray(q)) > 64 ? 1 : 0;
        }
    }
    return n;
}

TEST_F(ProbeTest, MeasurePointsAreNumberedNotLettered) {
    // Letters would read as orientation labels (A = anterior) in DICOM views.
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    click(viewer, onAxis(0.3), Qt::ControlModifier);
    EXPECT_TRUE(window_->measureLabel()->text().startsWith(QStringLiteral("Measure: point 1 on")))
        << window_->measureLabel()->text().toStdString();
    click(viewer, onAxis(0.7), Qt::ControlModifier);
    ASSERT_EQ(window_->measurePoints().size(), 2);
    const QString label = window_->measureLabel()->text();
    EXPECT_TRUE(label.startsWith(QStringLiteral("Distance 1–2: "))) << label.toStdString();
    EXPECT_TRUE(window_->measureLabel()->toolTip().contains(QStringLiteral("points 1 and 2")));

    // The marks as drawn: beside each point its number, not a letter.
    auto* overlay = window_->measureOverlay();
    QImage drawn(overlay->size(), QImage::Format_ARGB32_Premultiplied);
    drawn.fill(Qt::transparent);
    overlay->render(&drawn, QPoint(), QRegion(), QWidget::DrawChildren);
    for (int i = 0; i < 2; ++i) {
        const auto at = overlay->project(window_->measurePoints()[i]);
        ASSERT_TRUE(at.has_value());
        // Right of the marker, below the line between the points.
        const QRect box = QRect(at->toPoint() + QPoint(7, 4), QSize(24, 18)) & drawn.rect();
        const auto miss = [&](const QString& text) {
            return differing(drawn, markedLabel(text, overlay->font(), drawn.size(), *at), box);
        };
        const QString number = QString::number(i + 1);
        const QString letter = i == 0 ? QStringLiteral("A") : QStringLiteral("B");
        EXPECT_LT(miss(number), miss(letter) / 4) << "point " << i + 1;
        EXPECT_LT(miss(number), 6) << "point " << i + 1;
    }
    drawn.save(QString::fromStdString((panelTestDir() / "measure-marks.png").string()));
}

TEST_F(ProbeTest, AMeasurementEndsWithItsScene) {
    ASSERT_TRUE(showTube());
    auto* viewer = window_->viewer();
    click(viewer, onAxis(0.3), Qt::ControlModifier);
    click(viewer, onAxis(0.7), Qt::ControlModifier);
    ASSERT_EQ(window_->measurePoints().size(), 2);
    // Other data: points on the old data mean nothing there.
    window_->setScene(makeTubeScene(false), QStringLiteral("other"));
    ASSERT_TRUE(waitForFrames(1));
    EXPECT_TRUE(window_->measurePoints().isEmpty());
    EXPECT_FALSE(window_->measureOverlay()->isVisible());
    EXPECT_TRUE(window_->measureLabel()->text().isEmpty())
        << window_->measureLabel()->text().toStdString();
}

TEST_F(ProbeTest, MeasureOfKnownPoints) {
    gui::ProbeResult a;
    gui::ProbeResult b;
    a.worldPosition = glm::vec3(1.0F, 2.0F, 3.0F);
    b.worldPosition = glm::vec3(4.0F, 6.0F, 0.5F);
    render::Camera camera;  // looks down -z: depth grows towards -z
    const gui::Measurement m = gui::measure(a, b, camera);
    EXPECT_FLOAT_EQ(m.distance, std::sqrt(9.0F + 16.0F + 6.25F));
    EXPECT_FLOAT_EQ(m.depthDifference, 2.5F);
    // Seen from the other side, B lies in front.
    camera.rotateView(glm::pi<float>(), glm::vec3(0.0F, 1.0F, 0.0F));
    EXPECT_NEAR(gui::measure(a, b, camera).depthDifference, -2.5F, 1e-5F);
    EXPECT_FLOAT_EQ(gui::measure(a, b, camera).distance, m.distance);
}

}  // namespace
}  // namespace vv::test
