// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QComboBox;
class QListWidget;

namespace vv::gui {

class ViewerWidget;

namespace panels {

/// How the shown array's values are read (render::ArrayValues): a chooser
/// "Automatic / Continuous / Categories (labels)" and, while the array is
/// shown as labels, the list of its labels, each with its colour swatch and
/// its name (from the file, else "Label <value>"), as the legend shows them.
/// Part of the Functional panel.
class ArrayValuesWidget : public QWidget {
    Q_OBJECT

  public:
    explicit ArrayValuesWidget(ViewerWidget* viewer, QWidget* parent = nullptr);

    [[nodiscard]] QComboBox* modeChooser() const noexcept { return mode_; }
    [[nodiscard]] QListWidget* labelList() const noexcept { return labels_; }
    /// The shown array is drawn as labels (as of the last syncFromViewer()).
    [[nodiscard]] bool showsLabels() const;

  public slots:
    /// Shows the viewer's style and the labels of its array (without writing back).
    void syncFromViewer();

  signals:
    /// The user chose another mode (the viewer's style has it already).
    void changed();

  private:
    void apply();

    ViewerWidget* viewer_;
    QComboBox* mode_ = nullptr;
    QListWidget* labels_ = nullptr;
    bool syncing_ = false;
};

}  // namespace panels
}  // namespace vv::gui
