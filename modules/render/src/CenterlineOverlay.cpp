// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/render/CenterlineOverlay.h"

#include <QCoreApplication>
#include <QFont>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <QPen>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "vv/colormaps/LabelPalette.h"
#include "vv/core/Error.h"

namespace vv::render {

namespace {

/// Line widths on a 1600 x 1200 view, pixels: the coloured core and its halo.
constexpr double kCoreWidth = 2.5;
constexpr double kHaloWidth = 4.5;
/// The branch numbers' pixel size on a 1600 x 1200 view.
constexpr double kNumberPixels = 15.0;

/// A point projected into the viewport: pixel coordinates (+y down) and its
/// linear view depth; `inFront` false behind the near plane.
struct Projected {
    QPointF pixel;
    double depth = 0.0;
    bool inFront = false;
};

class Projector {
  public:
    explicit Projector(const Camera& camera)
        : view_(camera.viewMatrix()),
          projection_(camera.projectionMatrix()),
          width_(camera.viewportWidth()),
          height_(camera.viewportHeight()),
          pixelPerDepth_(2.0 *
                         std::tan(glm::radians(static_cast<double>(camera.fieldOfView())) / 2.0) /
                         std::max(1, camera.viewportHeight())),
          near_(camera.nearPlane()) {}

    [[nodiscard]] Projected project(const glm::vec3& world) const {
        const glm::vec4 eye = view_ * glm::vec4(world, 1.0F);
        Projected p;
        p.depth = -static_cast<double>(eye.z);
        if (!(p.depth > static_cast<double>(near_))) {
            return p;
        }
        const glm::vec4 clip = projection_ * eye;
        const double x = (static_cast<double>(clip.x / clip.w) * 0.5 + 0.5) * width_;
        const double y = (0.5 - static_cast<double>(clip.y / clip.w) * 0.5) * height_;
        p.pixel = QPointF(x, y);
        p.inFront = std::isfinite(x) && std::isfinite(y);
        return p;
    }
    /// The size of one pixel at linear depth `depth`, scene units.
    [[nodiscard]] double pixelFootprint(double depth) const { return depth * pixelPerDepth_; }
    [[nodiscard]] int width() const noexcept { return width_; }
    [[nodiscard]] int height() const noexcept { return height_; }

  private:
    glm::mat4 view_;
    glm::mat4 projection_;
    int width_;
    int height_;
    double pixelPerDepth_;
    float near_;
};

void checkLine(const OverlayPolyline& line) {
    if (line.radiiMm.size() != line.points.size()) {
        throw InvalidArgumentError("centreline overlay: branch " + std::to_string(line.branch) +
                                   " has " + std::to_string(line.points.size()) + " points but " +
                                   std::to_string(line.radiiMm.size()) + " radii");
    }
}

void checkDepth(const Camera& camera, const Image<float>& depth) {
    if (depth.width() != camera.viewportWidth() || depth.height() != camera.viewportHeight()) {
        throw InvalidArgumentError(
            "centreline overlay: the depth image is " + std::to_string(depth.width()) + "x" +
            std::to_string(depth.height()) + ", the view " +
            std::to_string(camera.viewportWidth()) + "x" + std::to_string(camera.viewportHeight()));
    }
}

std::vector<bool> visible(const OverlayPolyline& line, const Projector& projector,
                          const Image<float>& depth, std::vector<Projected>& projected) {
    projected.clear();
    std::vector<bool> shown(line.points.size(), false);
    for (std::size_t i = 0; i < line.points.size(); ++i) {
        const Projected p = projector.project(line.points[i]);
        projected.push_back(p);
        if (!p.inFront) {
            continue;
        }
        const int x = static_cast<int>(std::floor(p.pixel.x()));
        const int y = static_cast<int>(std::floor(p.pixel.y()));
        if (x < 0 || y < 0 || x >= projector.width() || y >= projector.height()) {
            continue;
        }
        const double surface = depth(x, y);
        const double allowed = kSeenThroughRadii * std::max(0.0, double{line.radiiMm[i]}) +
                               projector.pixelFootprint(p.depth);
        // Background at its pixel (the line at a silhouette) shows it too.
        shown[i] = !std::isfinite(surface) || p.depth - surface <= allowed;
    }
    return shown;
}

QColor toQColor(const glm::vec3& c) {
    return QColor::fromRgbF(std::clamp(c.r, 0.0F, 1.0F), std::clamp(c.g, 0.0F, 1.0F),
                            std::clamp(c.b, 0.0F, 1.0F));
}

QColor valueColour(const CenterlineOverlay& overlay, float value) {
    const float span = overlay.max - overlay.min;
    const float t = span > 0.0F ? (value - overlay.min) / span : 0.5F;
    return toQColor(colormaps::sample(overlay.map, std::isnan(value) ? value : t));
}

/// A halo that sets `core` off: dark around light colours, light around
/// dark ones (a colour map's dark end on a dark vessel).
QColor haloFor(const QColor& core) {
    const double luminance = 0.2126 * core.redF() + 0.7152 * core.greenF() + 0.0722 * core.blueF();
    return luminance > 0.25 ? QColor(0, 0, 0, 170) : QColor(255, 255, 255, 190);
}

/// The branch's number beside the middle of its visible points.
void paintBranchNumber(QPainter& painter, const OverlayPolyline& line,
                       const std::vector<Projected>& projected, const std::vector<bool>& shown,
                       double scale) {
    std::vector<std::size_t> seen;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        if (shown[i]) {
            seen.push_back(i);
        }
    }
    if (seen.empty()) {
        return;
    }
    const QPointF at = projected[seen[seen.size() / 2]].pixel;
    QFont font = painter.font();
    font.setPixelSize(std::max(8, static_cast<int>(std::lround(kNumberPixels * scale))));
    font.setBold(true);
    const QString text = QLocale().toString(line.branch);
    QPainterPath path;
    const double gap = 4.0 * scale;
    path.addText(at + QPointF(gap, -gap), font, text);
    const QColor colour =
        toQColor(colormaps::labelColor(static_cast<std::size_t>(std::max(0, line.branch))));
    painter.setPen(QPen(haloFor(colour), 3.0 * scale, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
    painter.fillPath(path, colour);
}

}  // namespace

std::vector<bool> visiblePoints(const OverlayPolyline& line, const Camera& camera,
                                const Image<float>& depth) {
    checkLine(line);
    checkDepth(camera, depth);
    std::vector<Projected> projected;
    return visible(line, Projector(camera), depth, projected);
}

void paintCenterlines(QImage& image, const Camera& camera, const Image<float>& depth,
                      const CenterlineOverlay& overlay, double scale) {
    checkDepth(camera, depth);
    for (const auto& line : overlay.lines) {
        checkLine(line);
    }
    if (image.width() != camera.viewportWidth() || image.height() != camera.viewportHeight()) {
        throw InvalidArgumentError(
            "centreline overlay: the image is " + std::to_string(image.width()) + "x" +
            std::to_string(image.height()) + ", the view " +
            std::to_string(camera.viewportWidth()) + "x" + std::to_string(camera.viewportHeight()));
    }
    const Projector projector(camera);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    std::vector<Projected> projected;
    std::vector<std::vector<bool>> shown;
    std::vector<std::vector<Projected>> points;
    for (const auto& line : overlay.lines) {
        shown.push_back(visible(line, projector, depth, projected));
        points.push_back(projected);
    }
    // All halos first, then all cores: where lines cross, no halo cuts a core.
    for (const bool halo : {true, false}) {
        for (std::size_t l = 0; l < overlay.lines.size(); ++l) {
            const OverlayPolyline& line = overlay.lines[l];
            const QColor branchColour =
                toQColor(colormaps::labelColor(static_cast<std::size_t>(std::max(0, line.branch))));
            for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
                if (!shown[l][i] || !shown[l][i + 1]) {
                    continue;
                }
                QColor colour = overlay.colouring == CenterlineColouring::Branch
                                    ? branchColour
                                    : valueColour(overlay, line.radiiMm[i] + line.radiiMm[i + 1]);
                if (halo) {
                    colour = haloFor(colour);
                }
                painter.setPen(QPen(colour, (halo ? kHaloWidth : kCoreWidth) * scale, Qt::SolidLine,
                                    Qt::RoundCap, Qt::RoundJoin));
                painter.drawLine(points[l][i].pixel, points[l][i + 1].pixel);
            }
        }
    }
    if (overlay.colouring == CenterlineColouring::Branch) {
        for (std::size_t l = 0; l < overlay.lines.size(); ++l) {
            paintBranchNumber(painter, overlay.lines[l], points[l], shown[l], scale);
        }
    }
}

std::optional<ParameterLegend> centerlineLegend(const CenterlineOverlay& overlay) {
    if (overlay.colouring != CenterlineColouring::InscribedDiameter || overlay.lines.empty()) {
        return std::nullopt;
    }
    return ParameterLegend{.name = "centerlines",
                           .unit = std::string("mm"),
                           .min = overlay.min,
                           .max = overlay.max,
                           .map = overlay.map,
                           .bins = 0,
                           .title = centerlineLegendTitle(),
                           .labels = {}};
}

std::string centerlineLegendTitle() {
    return QCoreApplication::translate("vv::render::Legend", "Centreline: inscribed diameter")
               .toStdString() +
           " (mm)";
}

void addCenterlineLegend(Legends& legends, const CenterlineOverlay& overlay) {
    auto legend = centerlineLegend(overlay);
    if (!legend) {
        return;
    }
    if (!legends.parameter) {
        legends.parameter = std::move(*legend);
    } else {
        legends.moreParameters.push_back(std::move(*legend));
    }
}

}  // namespace vv::render
