// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/DataPanel.h"

#include <QColorDialog>
#include <QComboBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "gui/ViewerWidget.h"
#include "gui/panels/PanelUtil.h"
#include "vv/scene/QuantityTitle.h"

namespace vv::gui::panels {

namespace {

constexpr int kNameRole = Qt::UserRole + 1;

/// Shows `color` on `button` (a swatch; its name for screen readers).
void showColor(QToolButton* button, const QColor& color) {
    button->setAccessibleName(color.name());
    button->setStyleSheet(
        QStringLiteral("QToolButton { background-color: %1; }").arg(color.name()));
}

/// The chooser item that stands for `array` (nullopt = the scene's array).
int arrayIndex(const QComboBox* chooser, const std::optional<std::string>& array) {
    if (!array) {
        return chooser->findData(DataPanel::SceneArray);
    }
    if (array->empty()) {
        return chooser->findData(DataPanel::NoArray);
    }
    const int index = chooser->findData(QString::fromStdString(*array), kNameRole);
    return index >= 0 ? index : chooser->findData(DataPanel::SceneArray);
}

}  // namespace

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
    tree_->setHeaderLabels({tr("Object / array"), tr("Vertices"), tr("Triangles"), tr("Colour"),
                            settingLabel("objects[].opacity"), tr("Array")});
    // Shown in the order name, colour, opacity, array (the columns' logical
    // numbers stay), each as wide as it needs and the tree as wide as they
    // are: nothing scrolls sideways. The counts are below the tree (counts_),
    // an array's range in its row.
    for (const int column : {ColorColumn, OpacityColumn, ArrayColumn}) {
        tree_->header()->moveSection(tree_->header()->visualIndex(column), column - 2);
    }
    tree_->setColumnHidden(VerticesColumn, true);
    tree_->setColumnHidden(TrianglesColumn, true);
    tree_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    tree_->header()->setStretchLastSection(false);
    tree_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    tree_->setRootIsDecorated(true);
    layout->addWidget(tree_, 1);
    counts_ = new QLabel(this);
    counts_->setObjectName(QStringLiteral("dataCounts"));
    counts_->setWordWrap(true);
    layout->addWidget(counts_);
    series_ = new QPushButton(tr("DICOM Series…"), this);
    series_->setObjectName(QStringLiteral("dicomSeries"));
    connect(series_, &QPushButton::clicked, this, [this] { emit browseSeries(dicomSource_); });
    layout->addWidget(series_);
    setDicomSource({});
    sceneChanged({}, {});
    connect(tree_, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (!filling_ && column == NameColumn && item->parent() == nullptr) {
            applyVisibility();
        }
    });
}

void DataPanel::setDicomSource(const QString& dicomSource) {
    dicomSource_ = dicomSource;
    series_->setToolTip(
        dicomSource.isEmpty()
            ? tr("Choose a DICOM folder and browse its patients, studies and series")
            : tr("Browse the patients, studies and series of %1 and load another series")
                  .arg(QFileInfo(dicomSource).fileName()));
}

QToolButton* DataPanel::colorButton(int index) const {
    QTreeWidgetItem* item = tree_->topLevelItem(index);
    return item != nullptr ? qobject_cast<QToolButton*>(tree_->itemWidget(item, ColorColumn))
                           : nullptr;
}

QSpinBox* DataPanel::opacityBox(int index) const {
    QTreeWidgetItem* item = tree_->topLevelItem(index);
    return item != nullptr ? qobject_cast<QSpinBox*>(tree_->itemWidget(item, OpacityColumn))
                           : nullptr;
}

QComboBox* DataPanel::arrayChooser(int index) const {
    QTreeWidgetItem* item = tree_->topLevelItem(index);
    return item != nullptr ? qobject_cast<QComboBox*>(tree_->itemWidget(item, ArrayColumn))
                           : nullptr;
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
        updateApplicability();
        emit changed();
    }
}

template <typename Change>
void DataPanel::changeObject(int index, Change change) {
    if (filling_ || index < 0) {
        return;
    }
    render::MeshStyle style = viewer_->style();
    const auto at = static_cast<std::size_t>(index);
    if (style.objects.size() <= at) {
        style.objects.resize(at + 1);
    }
    change(style.objects[at]);
    if (style.objects == viewer_->style().objects) {
        return;
    }
    viewer_->setStyle(style);
    syncFromViewer();
    emit changed();
}

void DataPanel::chooseColor(int index) {
    const render::MeshStyle& style = viewer_->style();
    const glm::vec3 current =
        style.object(static_cast<std::size_t>(index)).color.value_or(style.vesselColor);
    auto* dialog = new QColorDialog(toQColor(current), this);
    dialog->setObjectName(QStringLiteral("objectColorDialog"));
    const auto& scene = viewer_->scene();
    const QString name =
        scene && static_cast<std::size_t>(index) < scene->meshes.size()
            ? QString::fromStdString(scene->meshes[static_cast<std::size_t>(index)].name)
            : QString();
    dialog->setWindowTitle(tr("Colour of %1").arg(name));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowModality(Qt::WindowModal);
    connect(dialog, &QColorDialog::colorSelected, this, [this, index](const QColor& color) {
        changeObject(index, [&](render::ObjectStyle& o) { o.color = toVec(color); });
    });
    dialog->open();
}

void DataPanel::addObjectControls(QTreeWidgetItem* item, int index) {
    const auto& mesh = viewer_->scene()->meshes[static_cast<std::size_t>(index)];
    auto* color = new QToolButton(tree_);
    color->setObjectName(QStringLiteral("objectColor%1").arg(index));
    color->setFixedWidth(32);
    connect(color, &QToolButton::clicked, this, [this, index] { chooseColor(index); });
    tree_->setItemWidget(item, ColorColumn, color);

    auto* opacity = new QSpinBox(tree_);
    opacity->setObjectName(QStringLiteral("objectOpacity%1").arg(index));
    setUpForSetting(opacity, "objects[].opacity");
    opacity->setKeyboardTracking(false);
    connect(opacity, &QSpinBox::valueChanged, this, [this, index](int shown) {
        changeObject(index, [&](render::ObjectStyle& o) {
            o.opacity = static_cast<float>(fromControl("objects[].opacity", shown));
        });
    });
    tree_->setItemWidget(item, OpacityColumn, opacity);

    auto* array = new QComboBox(tree_);
    array->setObjectName(QStringLiteral("objectArray%1").arg(index));
    array->addItem(tr("Scene array"), SceneArray);
    array->addItem(tr("None"), NoArray);
    for (const auto& pointArray : mesh.pointArrays) {
        array->addItem(QString::fromStdString(pointArray.name), NamedArray);
        array->setItemData(array->count() - 1, QString::fromStdString(pointArray.name), kNameRole);
    }
    fitToItems(array);
    connect(array, &QComboBox::currentIndexChanged, this, [this, index, array](int choice) {
        changeObject(index, [&](render::ObjectStyle& o) {
            switch (array->itemData(choice).toInt()) {
                case SceneArray:
                    o.array.reset();
                    break;
                case NoArray:
                    o.array = std::string();
                    break;
                default:
                    o.array = array->itemData(choice, kNameRole).toString().toStdString();
            }
        });
    });
    tree_->setItemWidget(item, ArrayColumn, array);
}

void DataPanel::sceneChanged(const QString& title, const QStringList& files) {
    filling_ = true;
    tree_->clear();
    // A new scene starts with every mesh shown, opaque, in the scene's style.
    if (!viewer_->style().hidden.empty() || !viewer_->style().objects.empty()) {
        render::MeshStyle style = viewer_->style();
        style.hidden.clear();
        style.objects.clear();
        viewer_->setStyle(style);
    }
    const auto& scene = viewer_->scene();
    if (!scene) {
        file_->setText(tr("No data loaded"));
        file_->setToolTip({});
        counts_->clear();
        filling_ = false;
        fitColumns();
        return;
    }
    QStringList names;
    for (const QString& f : files) {
        names << QFileInfo(f).fileName();
    }
    file_->setText(names.isEmpty() ? title : names.join(QStringLiteral(", ")));
    file_->setToolTip(files.join(QLatin1Char('\n')));
    const QLocale locale;
    QStringList counts;
    int index = 0;
    for (const auto& mesh : scene->meshes) {
        counts << tr("%1: %2 vertices, %3 triangles")
                      .arg(QString::fromStdString(mesh.name),
                           locale.toString(static_cast<qulonglong>(mesh.vertexCount())),
                           locale.toString(static_cast<qulonglong>(mesh.triangleCount())));
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
        addObjectControls(item, index++);
        for (const auto& array : mesh.pointArrays) {
            float lo = std::numeric_limits<float>::infinity();
            float hi = -lo;
            for (const float v : array.values) {
                if (std::isfinite(v)) {
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
            }
            const QString label =
                QString::fromStdString(scene::quantityTitle(array.name, array.unit));
            auto* child = new QTreeWidgetItem(item);
            child->setText(NameColumn, label);
            child->setText(VerticesColumn, lo <= hi
                                               ? tr("%1 – %2").arg(QLocale().toString(lo, 'g', 4),
                                                                   QLocale().toString(hi, 'g', 4))
                                               : tr("no data"));
            child->setToolTip(NameColumn, tr("Point array (range of its finite values)"));
            // The name and range across the row (the range column is hidden).
            child->setFirstColumnSpanned(true);
            child->setData(NameColumn, Qt::DisplayRole,
                           tr("%1: %2").arg(label, child->text(VerticesColumn)));
        }
        item->setExpanded(true);
    }
    counts_->setText(counts.join(QLatin1Char('\n')));
    filling_ = false;
    syncFromViewer();
    fitColumns();
}

void DataPanel::fitColumns() {
    int width = 0;
    for (int column = 0; column < ColumnCount; ++column) {
        if (!tree_->isColumnHidden(column)) {
            tree_->resizeColumnToContents(column);
            width += tree_->columnWidth(column);
        }
    }
    const int scrollBar = style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, tree_);
    tree_->setMinimumWidth(width + scrollBar + 2 * tree_->frameWidth());
}

void DataPanel::syncFromViewer() {
    const bool wasFilling = filling_;
    filling_ = true;
    const render::MeshStyle& style = viewer_->style();
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        const auto at = static_cast<std::size_t>(i);
        const bool hidden =
            std::find(style.hidden.begin(), style.hidden.end(), at) != style.hidden.end();
        tree_->topLevelItem(i)->setCheckState(NameColumn, hidden ? Qt::Unchecked : Qt::Checked);
        const render::ObjectStyle& o = style.object(at);
        if (QToolButton* color = colorButton(i)) {
            showColor(color, toQColor(o.color.value_or(style.vesselColor)));
        }
        if (QSpinBox* opacity = opacityBox(i)) {
            const QSignalBlocker block(opacity);
            opacity->setValue(static_cast<int>(
                std::lround(toControl("objects[].opacity", static_cast<double>(o.opacity)))));
        }
        if (QComboBox* array = arrayChooser(i)) {
            const QSignalBlocker block(array);
            array->setCurrentIndex(arrayIndex(array, o.array));
        }
    }
    filling_ = wasFilling;
    updateApplicability();
}

void DataPanel::updateApplicability() {
    const render::MeshStyle& style = viewer_->style();
    const auto& scene = viewer_->scene();
    for (int i = 0; i < tree_->topLevelItemCount(); ++i) {
        const auto at = static_cast<std::size_t>(i);
        const bool hidden =
            std::find(style.hidden.begin(), style.hidden.end(), at) != style.hidden.end();
        const QString whyHidden = tr("The object is hidden: tick it to show it");
        if (QToolButton* color = colorButton(i)) {
            const bool showsArray = !style.arrayOf(at).empty();
            setApplicable(color, !hidden && !showsArray,
                          tr("Material colour of this object when no array colours it"),
                          hidden ? whyHidden
                                 : tr("An array colours this object; choose the array None to "
                                      "use a material colour"));
        }
        if (QSpinBox* opacity = opacityBox(i)) {
            setApplicable(opacity, !hidden,
                          tr("Below 100 % the surface and the VSS behind it show through; "
                             "0 % hides the object"),
                          whyHidden);
        }
        if (QComboBox* array = arrayChooser(i)) {
            const bool hasArrays =
                scene && at < scene->meshes.size() && !scene->meshes[at].pointArrays.empty();
            setApplicable(array, !hidden && hasArrays,
                          tr("The array this object shows: the scene's (Functional panel), "
                             "none, or one of its own point arrays"),
                          hidden ? whyHidden : tr("This object has no point arrays"));
        }
    }
}

}  // namespace vv::gui::panels
