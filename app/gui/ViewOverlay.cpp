// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ViewOverlay.h"

#include <QPainter>
#include <utility>

namespace vv::gui {

ViewOverlay::ViewOverlay(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("viewOverlay"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
    setFocusPolicy(Qt::NoFocus);
}

void ViewOverlay::setFrame(render::Legends legends, const render::Camera& camera,
                           const render::ViewAnnotations& annotations) {
    const bool wasBlank = legends_.empty() && !annotating();
    legends_ = std::move(legends);
    legends_.interactive = true;  // over the live view: hovering names a label
    camera_ = camera;
    annotations_ = annotations;
    if (!(wasBlank && legends_.empty() && !annotating())) {
        update();  // the camera moves the marker and the scale bar with every frame
    }
}

void ViewOverlay::paintEvent(QPaintEvent* event) {
    Q_UNUSED(event);
    if (legends_.empty() && !annotating()) {
        return;
    }
    QPainter painter(this);
    if (!legends_.empty()) {
        render::paintLegends(painter, QRectF(rect()), legends_);
    }
    if (annotating()) {
        render::paintViewAnnotations(painter, QRectF(rect()), camera_, annotations_);
    }
}

}  // namespace vv::gui
