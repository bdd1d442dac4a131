// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/ArrayValuesWidget.h"

#include <QComboBox>
#include <QListWidget>
#include <QPixmap>
#include <QVBoxLayout>
#include <algorithm>

#include "gui/ViewerWidget.h"
#include "gui/panels/PanelUtil.h"
#include "vv/colormaps/LabelPalette.h"
#include "vv/render/LegendPainter.h"
#include "vv/render/MeshStyle.h"

namespace vv::gui::panels {

ArrayValuesWidget::ArrayValuesWidget(ViewerWidget* viewer, QWidget* parent)
    : QWidget(parent), viewer_(viewer), mode_(new QComboBox(this)), labels_(new QListWidget(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    mode_->setObjectName(QStringLiteral("functionalValues"));
    mode_->addItem(tr("Automatic"), static_cast<int>(render::ArrayValues::Auto));
    mode_->addItem(tr("Continuous"), static_cast<int>(render::ArrayValues::Continuous));
    mode_->addItem(tr("Categories (labels)"), static_cast<int>(render::ArrayValues::Categories));
    layout->addWidget(mode_);
    labels_->setObjectName(QStringLiteral("functionalLabels"));
    labels_->setToolTip(tr("The labels of the array and their colours, as the legend shows them"));
    labels_->setSelectionMode(QAbstractItemView::NoSelection);
    labels_->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    layout->addWidget(labels_);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
    connect(mode_, &QComboBox::currentIndexChanged, this, [this] {
        if (!syncing_) {
            apply();
        }
    });
    syncFromViewer();
}

bool ArrayValuesWidget::showsLabels() const {
    return !labels_->isHidden();
}

void ArrayValuesWidget::apply() {
    render::MeshStyle style = viewer_->style();
    style.values = static_cast<render::ArrayValues>(mode_->currentData().toInt());
    viewer_->setStyle(style);
    syncFromViewer();
    emit changed();
}

void ArrayValuesWidget::syncFromViewer() {
    syncing_ = true;
    const render::MeshStyle& style = viewer_->style();
    mode_->setCurrentIndex(mode_->findData(static_cast<int>(style.values)));
    labels_->clear();
    const auto& scene = viewer_->scene();
    const auto labels = scene && !style.array.empty()
                            ? render::shownLabels(*scene, style, style.array)
                            : std::nullopt;
    if (labels) {
        const int side = fontMetrics().height() - 4;
        for (std::size_t i = 0; i < labels->size(); ++i) {
            QPixmap swatch(side, side);
            swatch.fill(toQColor(colormaps::labelColor(i)));
            labels_->addItem(new QListWidgetItem(QIcon(swatch), render::labelName((*labels)[i])));
        }
    }
    // As tall as its rows, at most 8 (then it scrolls).
    const int rows = std::clamp(labels_->count(), 1, 8);
    labels_->setFixedHeight(rows * std::max(labels_->sizeHintForRow(0), 1) +
                            2 * labels_->frameWidth() + 2);
    labels_->setVisible(labels.has_value());
    setApplicable(
        mode_, scene && !style.array.empty(),
        tr("Continuous: the values are measurements, shown through the colour map. Categories: "
           "the values are labels (segment, branch or group ids), one colour each. Automatic: "
           "categories for whole-numbered arrays with few distinct values"),
        tr("Choose an array to colour the vessels with"));
    syncing_ = false;
}

}  // namespace vv::gui::panels
