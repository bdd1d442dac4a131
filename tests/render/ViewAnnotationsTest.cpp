// SPDX-License-Identifier: GPL-3.0-or-later
// The orientation marker and the scale bar (render::paintViewAnnotations):
// the letters name what the camera shows, the bar is as long on screen as
// its length at the focal plane projects to.
#include <gtest/gtest.h>

#include <QImage>
#include <QPainter>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "GlTestSupport.h"
#include "vv/render/Camera.h"
#include "vv/render/ViewAnnotations.h"
#include "vv/render/ViewPresets.h"

namespace vv::render {
namespace {

Camera anatomicalCamera(AnatomicalView view, int width = 800, int height = 600) {
    Camera camera;
    camera.setViewport(width, height);
    camera.setRotation(anatomicalRotation(view));
    camera.fit(Aabb{glm::vec3(-50.0F), glm::vec3(50.0F)});
    return camera;
}

/// Where world point `p` lands on screen (pixels, +y down), through the camera's matrices.
glm::dvec2 project(const Camera& camera, const glm::vec3& p) {
    const glm::vec4 clip = camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(p, 1.0F);
    return {(clip.x / clip.w + 1.0) * 0.5 * camera.viewportWidth(),
            (1.0 - clip.y / clip.w) * 0.5 * camera.viewportHeight()};
}

/// Pixels brighter than 200 in every channel.
bool bright(QRgb p) {
    return qRed(p) > 200 && qGreen(p) > 200 && qBlue(p) > 200;
}

/// The longest horizontal run of bright pixels inside `region`.
int longestBrightRun(const QImage& image, const QRect& region) {
    int best = 0;
    for (int y = region.top(); y <= region.bottom(); ++y) {
        int run = 0;
        for (int x = region.left(); x <= region.right(); ++x) {
            run = bright(image.pixel(x, y)) ? run + 1 : 0;
            best = std::max(best, run);
        }
    }
    return best;
}

/// Pixels with a channel above 200 (the marker's coloured axes, white text).
int colouredPixels(const QImage& image, const QRect& region) {
    int n = 0;
    for (int y = region.top(); y <= region.bottom(); ++y) {
        for (int x = region.left(); x <= region.right(); ++x) {
            const QRgb p = image.pixel(x, y);
            n += std::max({qRed(p), qGreen(p), qBlue(p)}) > 200 ? 1 : 0;
        }
    }
    return n;
}

int brightPixels(const QImage& image, const QRect& region) {
    int n = 0;
    for (int y = region.top(); y <= region.bottom(); ++y) {
        for (int x = region.left(); x <= region.right(); ++x) {
            n += bright(image.pixel(x, y)) ? 1 : 0;
        }
    }
    return n;
}

QImage painted(const Camera& camera, const ViewAnnotations& annotations) {
    QImage image(camera.viewportWidth(), camera.viewportHeight(), QImage::Format_RGB32);
    image.fill(QColor(60, 60, 60));
    QPainter painter(&image);
    paintViewAnnotations(painter, QRectF(image.rect()), camera, annotations);
    painter.end();
    return image;
}

TEST(ViewAnnotationsTest, PatientLettersFollowTheCamera) {
    // From the front, the patient's right is on the screen's left (radiological convention).
    const EdgeLabels anterior =
        edgeLabels(anatomicalCamera(AnatomicalView::Anterior), SceneFrame::PatientLps);
    EXPECT_EQ(anterior.left, QStringLiteral("R"));
    EXPECT_EQ(anterior.right, QStringLiteral("L"));
    EXPECT_EQ(anterior.top, QStringLiteral("S"));
    EXPECT_EQ(anterior.bottom, QStringLiteral("I"));
    const EdgeLabels posterior =
        edgeLabels(anatomicalCamera(AnatomicalView::Posterior), SceneFrame::PatientLps);
    EXPECT_EQ(posterior.left, QStringLiteral("L"));
    EXPECT_EQ(posterior.top, QStringLiteral("S"));
    // From the feet, like axial CT slices: anterior up, the patient's right on the left.
    const EdgeLabels inferior =
        edgeLabels(anatomicalCamera(AnatomicalView::Inferior), SceneFrame::PatientLps);
    EXPECT_EQ(inferior.left, QStringLiteral("R"));
    EXPECT_EQ(inferior.top, QStringLiteral("A"));
    // Turned 45 degrees about the vertical from the front: the left edge shows two letters
    Camera turned = anatomicalCamera(AnatomicalView::Anterior);
    turned.rotateView(glm::radians(45.0F), glm::vec3(0.0F, 1.0F, 0.0F));
    const glm::vec3 left = -turned.right();
    const EdgeLabels oblique = edgeLabels(turned, SceneFrame::PatientLps);
    EXPECT_EQ(oblique.left.size(), 2);
    EXPECT_EQ(oblique.left.contains(QLatin1Char('R')), left.x < 0.0F);
    EXPECT_EQ(oblique.left.contains(QLatin1Char('A')), left.y < 0.0F);
    EXPECT_EQ(oblique.left.contains(QLatin1Char('P')), left.y > 0.0F);
    // Without a patient frame: the axes by name.
    const EdgeLabels plain = edgeLabels(Camera{}, SceneFrame::Unknown);
    EXPECT_EQ(plain.left, QStringLiteral("-x"));
    EXPECT_EQ(plain.right, QStringLiteral("+x"));
    EXPECT_EQ(plain.top, QStringLiteral("+y"));
}

TEST(ViewAnnotationsTest, ScaleBarIsAsLongAsItsLengthProjectsAtTheFocalPlane) {
    vv::test::ensureGuiApplication();
    for (const float zoom : {1.0F, 3.7F}) {
        Camera camera = anatomicalCamera(AnatomicalView::Anterior);
        camera.zoom(zoom);
        const auto bar = scaleBarFor(camera, QSizeF(800.0, 600.0));
        ASSERT_TRUE(bar);
        // A round length: 1, 2 or 5 x 10^k mm, at most a quarter of the width.
        const double mantissa =
            bar->millimetres / std::pow(10.0, std::floor(std::log10(bar->millimetres)));
        EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
                    std::abs(mantissa - 5.0) < 1e-9)
            << bar->millimetres;
        // The bar's length on screen: the length laid along the screen's x at the
        // camera's target (the focal plane), projected with the camera.
        const glm::vec3 target = camera.target();
        const glm::dvec2 a = project(camera, target);
        const glm::dvec2 b =
            project(camera, target + camera.right() * static_cast<float>(bar->millimetres));
        const double expected = b.x - a.x;
        EXPECT_NEAR(bar->pixels, expected, 0.01 * expected);
        EXPECT_LE(expected, 0.25 * 800.0 + 1.0);
        EXPECT_GT(expected, 0.1 * 800.0);

        // What is painted: a bright bar that long in the top-right corner.
        const QImage image = painted(camera, {.orientationMarker = false, .scaleBar = true});
        const int run = longestBrightRun(image, QRect(400, 0, 400, 150));
        EXPECT_NEAR(run, expected, 1.5);
        const QImage none = painted(camera, {.orientationMarker = false, .scaleBar = false});
        EXPECT_EQ(brightPixels(none, none.rect()), 0);
    }
}

TEST(ViewAnnotationsTest, MarkerShowsPatientLettersOnlyWithAPatientFrame) {
    vv::test::ensureGuiApplication();
    const Camera camera = anatomicalCamera(AnatomicalView::Anterior);
    const QRect leftEdge(0, 260, 60, 80);
    const QRect marker(0, 0, 150, 150);
    const QImage patient = painted(
        camera, {.orientationMarker = true, .scaleBar = false, .frame = SceneFrame::PatientLps});
    EXPECT_GT(brightPixels(patient, leftEdge), 5);  // the "R" at the left edge
    EXPECT_GT(colouredPixels(patient, marker), 5);
    const QImage plain = painted(
        camera, {.orientationMarker = true, .scaleBar = false, .frame = SceneFrame::Unknown});
    EXPECT_EQ(brightPixels(plain, leftEdge), 0);  // no patient letters without a patient frame
    EXPECT_GT(colouredPixels(plain, marker), 5);  // but the axes' triad
}

TEST(ViewAnnotationsTest, MarkerLettersNeverCoverOneAnotherFromAnyDirection) {
    // Looking along (1, -1, 0), the x and y axes project onto one direction:
    // their letters were drawn on the same spot. Every direction of a sphere
    // of them, each with two rolls about the view axis.
    const QRectF area(0.0, 0.0, 800.0, 600.0);
    const double letter = 13.0;  // the annotations' font size for a view 600 px tall
    double closest = 1e9;
    glm::vec3 worst(0.0F);
    constexpr int kDirections = 400;
    for (int i = 0; i < kDirections; ++i) {
        // A Fibonacci sphere, and the diagonals that hit the worst case exactly.
        const double t = (i + 0.5) / kDirections;
        const double polar = std::acos(1.0 - 2.0 * t);
        const double azimuth = i * 2.399963229728653;
        glm::vec3 forward(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                          std::cos(polar));
        if (i < 12) {
            const std::array<glm::vec3, 12> diagonals{
                glm::vec3(1, -1, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1, -1), glm::vec3(0, 1, 1),
                glm::vec3(1, 0, -1), glm::vec3(1, 0, 1), glm::vec3(1, 1, 1),  glm::vec3(1, -1, 1),
                glm::vec3(0, 0, 1),  glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),  glm::vec3(-1, 1, 1)};
            forward = diagonals[static_cast<std::size_t>(i)];
        }
        forward = glm::normalize(forward);
        for (const float roll : {0.0F, 0.7F}) {
            Camera camera;
            camera.setViewport(800, 600);
            // View space: x right, y up, looking along -z; rolled about the view axis.
            const glm::vec3 helper =
                std::abs(forward.z) < 0.9F ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
            const glm::vec3 right0 = glm::normalize(glm::cross(forward, helper));
            const glm::vec3 up0 = glm::cross(right0, forward);
            const glm::vec3 right = std::cos(roll) * right0 + std::sin(roll) * up0;
            const glm::vec3 up = glm::cross(right, forward);
            camera.setRotation(glm::quat_cast(glm::mat3(right, up, -forward)));
            ASSERT_NEAR(glm::dot(camera.forward(), forward), 1.0F, 1e-3F)
                << "the test's rotation convention";
            const std::array<QPointF, 3> letters = markerLetterPositions(camera, area);
            for (std::size_t a = 0; a < 3; ++a) {
                for (std::size_t b = a + 1; b < 3; ++b) {
                    const double d = std::hypot(letters[a].x() - letters[b].x(),
                                                letters[a].y() - letters[b].y());
                    if (d < closest) {
                        closest = d;
                        worst = forward;
                    }
                }
            }
        }
    }
    EXPECT_GE(closest, kMarkerLetterGap * letter - 0.25)
        << "letters " << closest << " px apart looking along (" << worst.x << ", " << worst.y
        << ", " << worst.z << ")";
}

}  // namespace
}  // namespace vv::render
