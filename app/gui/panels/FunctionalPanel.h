// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QWidget>
#include <optional>
#include <utility>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;
class QToolButton;

namespace vv::gui {

class ViewerWidget;

namespace panels {

class ArrayValuesWidget;
class HistogramWidget;

/// The "Functional parameters" panel: which point array colours the vessel
/// wall, through which colour map (viridis, cividis, inferno, blue-white-red;
/// continuous or N discrete bins), over which range (auto = the array's full
/// range, the 2nd-98th percentile, or typed in), with a histogram of the
/// array that marks the range, the no-data (NaN) colour and the legend's
/// title. Controls that do not apply (no scene, no arrays, no array chosen)
/// are disabled with a tooltip saying why.
class FunctionalPanel : public QWidget {
    Q_OBJECT

  public:
    enum class RangeMode { Auto, Percentile, Manual };
    /// The percentile range's bounds.
    static constexpr double kLowPercentile = 2.0;
    static constexpr double kHighPercentile = 98.0;

    explicit FunctionalPanel(ViewerWidget* viewer, QWidget* parent = nullptr);

    /// Refills the array list from the viewer's scene and selects the default
    /// array (wss when present).
    void sceneChanged();

    [[nodiscard]] QComboBox* arrayChooser() const noexcept { return array_; }
    [[nodiscard]] QComboBox* colorMapChooser() const noexcept { return map_; }
    [[nodiscard]] QComboBox* rangeModeChooser() const noexcept { return rangeMode_; }
    [[nodiscard]] HistogramWidget* histogram() const noexcept { return histogram_; }
    /// Continuous or categories, and the labels (ArrayValuesWidget).
    [[nodiscard]] ArrayValuesWidget* valuesChooser() const noexcept { return values_; }
    [[nodiscard]] RangeMode rangeMode() const noexcept;

    /// The p-th percentile (0..100, linear interpolation between order
    /// statistics) of the finite values; nullopt when there are none.
    [[nodiscard]] static std::optional<double> percentile(std::vector<float> values, double p);

  public slots:
    /// Shows the viewer's current style (without writing it back).
    void syncFromViewer();
    /// Sets the no-data colour (an invalid colour: the map's own); what the
    /// button's colour dialog calls.
    void setNoDataColor(const QColor& color);

  signals:
    void changed();

  private:
    void apply();
    void chooseNoDataColor();
    void arrayChosen();
    void updateApplicability();
    void updateNanColor();
    /// The chosen array's finite values over all meshes.
    [[nodiscard]] std::vector<float> arrayValues() const;

    ViewerWidget* viewer_;
    QComboBox* array_ = nullptr;
    QComboBox* map_ = nullptr;
    QSpinBox* bins_ = nullptr;
    QComboBox* rangeMode_ = nullptr;
    QDoubleSpinBox* min_ = nullptr;
    QDoubleSpinBox* max_ = nullptr;
    QToolButton* nanColor_ = nullptr;
    HistogramWidget* histogram_ = nullptr;
    QLineEdit* legendTitle_ = nullptr;
    ArrayValuesWidget* values_ = nullptr;
    /// The chosen array's percentile range (set when an array is chosen).
    std::optional<std::pair<float, float>> percentileRange_;
    bool syncing_ = false;
};

}  // namespace panels
}  // namespace vv::gui
