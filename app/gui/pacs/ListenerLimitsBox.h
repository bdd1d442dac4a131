// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGroupBox>

#include "vv/pacs/StorageScp.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace vv::gui {

/// The group "Listener limits" of DICOM > Preferences: the simultaneous
/// associations, the connections per address and in all, the association
/// request deadline (s), the largest instance and the largest association
/// (GB of 10^9 bytes, as the store's size limit), each with a tooltip saying
/// what it protects against; a line with the defaults (in the UI locale) and
/// Restore defaults. The ranges are ListenerLimits::validate()'s (the
/// largest instance from 0.01 GB) and follow each other, so that limits()
/// always fit together: connections in all from the simultaneous
/// associations up, per address up to in all, the largest association from
/// the largest instance up.
class ListenerLimitsBox : public QGroupBox {
    Q_OBJECT

  public:
    ListenerLimitsBox(const pacs::ListenerLimits& limits, QWidget* parent);

    /// The limits as entered (the sizes rounded to whole bytes).
    [[nodiscard]] pacs::ListenerLimits limits() const;
    /// Shows `limits` (each clamped to its range).
    void setLimits(const pacs::ListenerLimits& limits);

    [[nodiscard]] QSpinBox* associationsBox() const noexcept { return associations_; }
    [[nodiscard]] QSpinBox* perAddressBox() const noexcept { return perAddress_; }
    [[nodiscard]] QSpinBox* connectionsBox() const noexcept { return connections_; }
    [[nodiscard]] QSpinBox* requestSecondsBox() const noexcept { return requestSeconds_; }
    [[nodiscard]] QDoubleSpinBox* instanceBox() const noexcept { return instance_; }
    [[nodiscard]] QDoubleSpinBox* associationBox() const noexcept { return association_; }
    /// The line with the defaults.
    [[nodiscard]] QLabel* defaultsLabel() const noexcept { return defaults_; }
    [[nodiscard]] QPushButton* restoreButton() const noexcept { return restore_; }

  private:
    QSpinBox* associations_ = nullptr;
    QSpinBox* perAddress_ = nullptr;
    QSpinBox* connections_ = nullptr;
    QSpinBox* requestSeconds_ = nullptr;
    QDoubleSpinBox* instance_ = nullptr;
    QDoubleSpinBox* association_ = nullptr;
    QLabel* defaults_ = nullptr;
    QPushButton* restore_ = nullptr;
};

}  // namespace vv::gui
