// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/DataPanel.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

#include "gui/ViewerWidget.h"

namespace vv::gui::panels {

DataPanel::DataPanel(ViewerWidget* viewer, QWidget* parent) : QWidget(parent), viewer_(viewer) {
    setObjectName(QStringLiteral("dataPanel"));
    auto* layout = new QVBoxLayout(this);
    file_ = new QLabel(this);
    file_->setObjectName(QStringLiteral("dataFile"));
    file_->setWordWrap(true);
    file_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(file_);
    tree_ = new QTreeWidget(this);
    tree_->setObjectName(QStringLiteral("dataMeshes"));
    tree_->setColumnCount(ColumnCount);
    tree_->setHeaderLabels({tr("Object / array"), tr("Vertices"), tr("Triangles")});
    tree_->header()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    tree_->setRootIsDecorated(true);
    layout->addWidget(tree_, 1);
    sceneChanged({}, {});
    connect(tree_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (!filling_ && column == NameColumn && item->parent() == nullptr) {
            applyVisibility();
        }
    });
}

void DataPanel::applyVisibility() {
    render::MeshStyle style = viewer_->style();
    style.hidden.clear();
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        if (tree_->topLevelItem(i)->checkState(NameColumn) != Qt::Checked) {
            style.hidden.push_back(static_cast<std::size_t>(i));
        }
    }
    if (style.hidden != viewer_->style().hidden) {
        viewer_->setStyle(style);
        emit changed();
    }
}

void DataPanel::sceneChanged(const QString& title, const QStringList& files) {
    filling_ = true;
    tree_->clear();
    if (!viewer_->style().hidden.empty()) {  // a new scene starts with every mesh shown
        render::MeshStyle style = viewer_->style();
        style.hidden.clear();
        viewer_->setStyle(style);
    }
    const auto& scene = viewer_->scene();
    if (!scene) {
        file_->setText(tr("No data loaded"));
        file_->setToolTip({});
        filling_ = false;
        return;
    }
    QStringList names;
    for (const QString& f : files) {
        names << QFileInfo(f).fileName();
    }
    file_->setText(names.isEmpty() ? title : names.join(QStringLiteral(", ")));
    file_->setToolTip(files.join(QLatin1Char('\n')));
    const QLocale locale;
    for (const auto& mesh : scene->meshes) {
        auto* item = new QTreeWidgetItem(tree_);
        item->setText(NameColumn, QString::fromStdString(mesh.name));
        item->setText(VerticesColumn, locale.toString(static_cast<qulonglong>(mesh.vertexCount())));
        item->setText(TrianglesColumn,
                      locale.toString(static_cast<qulonglong>(mesh.triangleCount())));
        item->setToolTip(NameColumn, mesh.source.empty()
                                         ? tr("Generated")
                                         : QString::fromStdString(mesh.source.string()));
        // Visibility: the check box shows or hides the mesh.
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        item->setCheckState(NameColumn, Qt::Checked);
        for (const auto& array : mesh.pointArrays) {
            float lo = std::numeric_limits<float>::infinity();
            float hi = -lo;
            for (const float v : array.values) {
                if (std::isfinite(v)) {
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
            }
            QString label = QString::fromStdString(array.name);
            if (!array.unit.empty()) {
                label += QStringLiteral(" [%1]").arg(QString::fromStdString(array.unit));
            }
            auto* child = new QTreeWidgetItem(item);
            child->setText(NameColumn, label);
            child->setText(VerticesColumn, lo <= hi ? tr("%1 – %2")
                                                          .arg(static_cast<double>(lo), 0, 'g', 4)
                                                          .arg(static_cast<double>(hi), 0, 'g', 4)
                                                    : tr("no data"));
            child->setToolTip(NameColumn, tr("Point array (range of its finite values)"));
        }
        item->setExpanded(true);
    }
    filling_ = false;
}

}  // namespace vv::gui::panels
