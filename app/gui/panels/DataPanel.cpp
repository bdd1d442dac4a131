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
}

void DataPanel::sceneChanged(const QString& title, const QStringList& files) {
    tree_->clear();
    const auto& scene = viewer_->scene();
    if (!scene) {
        file_->setText(tr("No data loaded"));
        file_->setToolTip({});
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
        // Visibility: shown, but not switchable yet.
        item->setFlags((item->flags() | Qt::ItemIsUserCheckable) & ~Qt::ItemIsEnabled);
        item->setCheckState(NameColumn, Qt::Checked);
        item->setToolTip(VerticesColumn,
                         tr("Every mesh of a scene is drawn; hiding single meshes is not "
                            "supported yet"));
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
}

}  // namespace vv::gui::panels
