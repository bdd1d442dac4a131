// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/panels/FunctionalPanel.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QSpinBox>
#include <QToolButton>
#include <algorithm>
#include <cmath>
#include <limits>

#include "common/SettingsSchema.h"
#include "gui/ViewerWidget.h"
#include "gui/panels/ArrayValuesWidget.h"
#include "gui/panels/HistogramWidget.h"
#include "gui/panels/PanelUtil.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/render/MeshStyle.h"

namespace vv::gui::panels {

std::optional<double> FunctionalPanel::percentile(std::vector<float> values, double p) {
    std::erase_if(values, [](float v) { return !std::isfinite(v); });
    if (values.empty()) {
        return std::nullopt;
    }
    // Selection instead of a full sort: linear time, also for millions of vertices.
    const double position =
        std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(values.size() - 1);
    const auto below = static_cast<std::size_t>(std::floor(position));
    const auto nth = values.begin() + static_cast<std::ptrdiff_t>(below);
    std::nth_element(values.begin(), nth, values.end());
    const double low = static_cast<double>(*nth);
    const double high = nth + 1 == values.end()
                            ? low
                            : static_cast<double>(*std::min_element(nth + 1, values.end()));
    const double f = position - static_cast<double>(below);
    return (1.0 - f) * low + f * high;
}

FunctionalPanel::FunctionalPanel(ViewerWidget* viewer, QWidget* parent)
    : QWidget(parent), viewer_(viewer) {
    setObjectName(QStringLiteral("functionalPanel"));
    auto* form = new QFormLayout(this);

    array_ = new QComboBox(this);
    array_->setObjectName(QStringLiteral("arrayChooser"));
    array_->addItem(tr("None"), QString());
    form->addRow(settingFormLabel("style.array"), array_);

    map_ = new QComboBox(this);
    map_->setObjectName(QStringLiteral("colorMapChooser"));
    for (const auto map : colormaps::allColorMaps()) {
        map_->addItem(engineName(colormaps::displayName(map)), static_cast<int>(map));
    }
    form->addRow(settingFormLabel("style.colorMap"), map_);
    bins_ = new QSpinBox(this);
    bins_->setObjectName(QStringLiteral("functionalBins"));
    // The setting's range, and one below its fewest bins standing for continuous (0).
    const app::Setting& bins = app::setting("style.bins");
    bins_->setRange(static_cast<int>(bins.min) - 1, static_cast<int>(bins.max));
    bins_->setSpecialValueText(tr("Continuous"));
    bins_->setSuffix(tr(" bins"));
    form->addRow(settingFormLabel("style.bins"), bins_);

    rangeMode_ = new QComboBox(this);
    rangeMode_->setObjectName(QStringLiteral("functionalRangeMode"));
    rangeMode_->addItem(tr("Auto (full range)"), static_cast<int>(RangeMode::Auto));
    rangeMode_->addItem(tr("Percentile 2–98"), static_cast<int>(RangeMode::Percentile));
    rangeMode_->addItem(tr("Manual"), static_cast<int>(RangeMode::Manual));
    form->addRow(tr("Range:"), rangeMode_);
    min_ = new QDoubleSpinBox(this);
    min_->setObjectName(QStringLiteral("functionalRangeMin"));
    max_ = new QDoubleSpinBox(this);
    max_->setObjectName(QStringLiteral("functionalRangeMax"));
    setUpForSetting(min_, "style.range[0]");
    setUpForSetting(max_, "style.range[1]");
    for (QDoubleSpinBox* box : {min_, max_}) {
        box->setKeyboardTracking(false);
        // At its minimum (no range: no array, or one without values) the
        // field shows a dash, never a number left from another array or file.
        box->setSpecialValueText(QStringLiteral("–"));
    }
    auto* rangeRow = new QHBoxLayout;
    rangeRow->addWidget(min_);
    rangeRow->addWidget(max_);
    form->addRow(tr("Min / max:"), rangeRow);

    histogram_ = new HistogramWidget(this);
    form->addRow(histogram_);

    nanColor_ = new QToolButton(this);
    nanColor_->setObjectName(QStringLiteral("functionalNanColor"));
    nanColor_->setAutoRaise(false);
    nanColor_->setMinimumWidth(48);
    form->addRow(settingFormLabel("style.noDataColor"), nanColor_);

    legendTitle_ = new QLineEdit(this);
    legendTitle_->setObjectName(QStringLiteral("functionalLegendTitle"));
    form->addRow(settingFormLabel("style.legendTitle"), legendTitle_);

    values_ = new ArrayValuesWidget(viewer_, this);
    form->addRow(settingFormLabel("style.values"), values_);
    connect(values_, &ArrayValuesWidget::changed, this, [this] {
        updateApplicability();
        emit changed();
    });

    makeNarrow(this);
    sceneChanged();

    connect(array_, &QComboBox::currentIndexChanged, this, [this] {
        if (!syncing_) {
            arrayChosen();
        }
    });
    auto applyLater = [this] {
        if (!syncing_) {
            apply();
        }
    };
    connect(map_, &QComboBox::currentIndexChanged, this, applyLater);
    connect(bins_, &QSpinBox::valueChanged, this, applyLater);
    connect(rangeMode_, &QComboBox::currentIndexChanged, this, applyLater);
    connect(min_, &QDoubleSpinBox::valueChanged, this, applyLater);
    connect(max_, &QDoubleSpinBox::valueChanged, this, applyLater);
    connect(nanColor_, &QToolButton::clicked, this, &FunctionalPanel::chooseNoDataColor);
    connect(legendTitle_, &QLineEdit::editingFinished, this, applyLater);
    // Dragging a range handle on the histogram types the range in.
    connect(histogram_, &HistogramWidget::rangeEdited, this, [this](double lo, double hi) {
        syncing_ = true;
        rangeMode_->setCurrentIndex(rangeMode_->findData(static_cast<int>(RangeMode::Manual)));
        min_->setValue(lo);
        max_->setValue(hi);
        syncing_ = false;
        apply();
    });
}

FunctionalPanel::RangeMode FunctionalPanel::rangeMode() const noexcept {
    return static_cast<RangeMode>(rangeMode_->currentData().toInt());
}

void FunctionalPanel::sceneChanged() {
    syncing_ = true;
    array_->clear();
    array_->addItem(tr("None"), QString());
    if (const auto& scene = viewer_->scene()) {
        for (const auto& name : render::pointArrayNames(*scene)) {
            array_->addItem(arrayLabel(*scene, name), QString::fromStdString(name));
        }
        const int index =
            array_->findData(QString::fromStdString(render::defaultArrayName(*scene)));
        array_->setCurrentIndex(std::max(index, 0));
    }
    fitToItems(array_);
    syncing_ = false;
    arrayChosen();
}

std::vector<float> FunctionalPanel::arrayValues() const {
    std::vector<float> values;
    const auto& scene = viewer_->scene();
    const std::string name = array_->currentData().toString().toStdString();
    if (!scene || name.empty()) {
        return values;
    }
    for (const auto& mesh : scene->meshes) {
        if (const scene::DataArray* array = mesh.pointArray(name)) {
            values.insert(values.end(), array->values.begin(), array->values.end());
        }
    }
    return values;
}

void FunctionalPanel::arrayChosen() {
    const std::vector<float> values = arrayValues();
    histogram_->setValues(values);
    percentileRange_.reset();
    const auto lo = percentile(values, kLowPercentile);
    const auto hi = percentile(values, kHighPercentile);
    if (lo && hi) {
        percentileRange_ = {static_cast<float>(*lo), static_cast<float>(*hi)};
    }
    // A typed range and a typed title belong to the array they were typed for.
    if (rangeMode() == RangeMode::Manual) {
        const QSignalBlocker blocker(rangeMode_);
        rangeMode_->setCurrentIndex(rangeMode_->findData(static_cast<int>(RangeMode::Auto)));
    }
    legendTitle_->clear();
    apply();
}

void FunctionalPanel::apply() {
    render::MeshStyle style = viewer_->style();
    style.array = array_->currentData().toString().toStdString();
    style.colorMap = static_cast<colormaps::ColorMap>(map_->currentData().toInt());
    style.bins = bins_->value() < 2 ? 0 : bins_->value();
    switch (rangeMode()) {
        case RangeMode::Auto:
            style.range.reset();
            break;
        case RangeMode::Percentile:
            style.range = percentileRange_;
            break;
        case RangeMode::Manual:
            style.range = std::pair{static_cast<float>(min_->value()),
                                    static_cast<float>(std::max(max_->value(), min_->value()))};
            break;
    }
    // The default title (name and unit) is no custom title.
    const QString title = legendTitle_->text().trimmed();
    const bool custom = !title.isEmpty() && !style.array.empty() && viewer_->scene() &&
                        title != arrayLabel(*viewer_->scene(), style.array);
    style.legendTitle = custom ? title.toStdString() : std::string();
    viewer_->setStyle(style);
    syncFromViewer();
    emit changed();
}

void FunctionalPanel::syncFromViewer() {
    syncing_ = true;
    const render::MeshStyle& style = viewer_->style();
    const int arrayIndex = array_->findData(QString::fromStdString(style.array));
    if (arrayIndex >= 0) {
        array_->setCurrentIndex(arrayIndex);
    }
    map_->setCurrentIndex(map_->findData(static_cast<int>(style.colorMap)));
    bins_->setValue(style.bins < 2 ? 1 : style.bins);
    if (style.range && rangeMode() == RangeMode::Auto) {
        rangeMode_->setCurrentIndex(rangeMode_->findData(static_cast<int>(RangeMode::Manual)));
    } else if (!style.range && rangeMode() != RangeMode::Auto) {
        rangeMode_->setCurrentIndex(rangeMode_->findData(static_cast<int>(RangeMode::Auto)));
    }
    // The range in use: the style's, else the array's full range.
    std::optional<std::pair<float, float>> shown = style.range;
    if (!shown && viewer_->scene() && !style.array.empty()) {
        shown = render::arrayRange(*viewer_->scene(), style.array);
    }
    if (shown) {
        min_->setValue(static_cast<double>(shown->first));
        max_->setValue(static_cast<double>(shown->second));
        histogram_->setRange(static_cast<double>(shown->first), static_cast<double>(shown->second));
    } else {
        min_->setValue(min_->minimum());
        max_->setValue(max_->minimum());
        histogram_->setRange(0.0, 0.0);
    }
    if (!style.legendTitle.empty()) {
        legendTitle_->setText(QString::fromStdString(style.legendTitle));
    } else if (!style.array.empty() && viewer_->scene()) {
        legendTitle_->setText(arrayLabel(*viewer_->scene(), style.array));
    } else {
        legendTitle_->clear();
    }
    syncing_ = false;
    values_->syncFromViewer();
    updateNanColor();
    updateApplicability();
}

void FunctionalPanel::setNoDataColor(const QColor& color) {
    render::MeshStyle style = viewer_->style();
    if (color.isValid()) {
        style.noDataColor = toVec(color);
    } else {
        style.noDataColor.reset();
    }
    viewer_->setStyle(style);
    syncFromViewer();
    emit changed();
}

void FunctionalPanel::chooseNoDataColor() {
    auto* dialog = new QColorDialog(nanColor_->palette().button().color(), this);
    dialog->setObjectName(QStringLiteral("noDataColorDialog"));
    dialog->setWindowTitle(tr("No-data colour"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    const auto map = static_cast<colormaps::ColorMap>(map_->currentData().toInt());
    dialog->setCurrentColor(
        toQColor(viewer_->style().noDataColor.value_or(colormaps::noDataColor(map))));
    connect(dialog, &QColorDialog::colorSelected, this, &FunctionalPanel::setNoDataColor);
    dialog->open();
}

void FunctionalPanel::updateNanColor() {
    const auto map = static_cast<colormaps::ColorMap>(map_->currentData().toInt());
    const QColor color =
        toQColor(viewer_->style().noDataColor.value_or(colormaps::noDataColor(map)));
    nanColor_->setStyleSheet(
        QStringLiteral("QToolButton { background-color: %1; }").arg(color.name()));
    nanColor_->setText(color.name());
}

void FunctionalPanel::updateApplicability() {
    const bool hasScene = viewer_->scene() != nullptr;
    const bool hasArrays = array_->count() > 1;
    const bool chosen = !array_->currentData().toString().isEmpty();
    const QString noScene = tr("No data loaded");
    const QString noArrays = tr("The loaded meshes have no point arrays");
    const QString noArray = tr("Choose an array to colour the vessels with");
    const QString whyNot = !hasScene ? noScene : (!hasArrays ? noArrays : noArray);
    setApplicable(array_, hasScene && hasArrays,
                  tr("Point array shown on the vessel wall through the colour map"),
                  hasScene ? noArrays : noScene);
    // Labels have their own palette: the colour map's controls do not apply.
    const bool mapped = chosen && values_ != nullptr && !values_->showsLabels();
    const QString labelsShown = tr("The array is shown as labels, each in its own colour");
    setApplicable(map_, mapped, tr("Colour map of the array's values"),
                  chosen ? labelsShown : whyNot);
    setApplicable(bins_, mapped, tr("Continuous colours, or the range cut into N equal bins"),
                  chosen ? labelsShown : whyNot);
    setApplicable(rangeMode_, mapped,
                  tr("Values mapped to the first and last colour: the full range, the 2nd to "
                     "98th percentile, or typed in"),
                  chosen ? labelsShown : whyNot);
    const bool manual = chosen && rangeMode() == RangeMode::Manual;
    for (QDoubleSpinBox* box : {min_, max_}) {
        setApplicable(box, manual, tr("Values at the first / last colour of the map"),
                      chosen ? tr("Choose the Manual range to type values") : whyNot);
    }
    setApplicable(histogram_, chosen,
                  tr("Distribution of the array; the lines mark the range (drag them to change "
                     "it)"),
                  whyNot);
    setApplicable(nanColor_, chosen,
                  tr("Colour of vertices without a value (NaN). By default each map has one "
                     "that never occurs in the map itself"),
                  whyNot);
    setApplicable(legendTitle_, chosen,
                  tr("Title of the parameter legend (default: the array's name and unit)"), whyNot);
}

}  // namespace vv::gui::panels
