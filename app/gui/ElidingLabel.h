// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLabel>
#include <QString>

namespace vv::gui {

/// A one-line label that gives way: it asks for no width of its own, and
/// when its text is wider than the room it gets it ends in "…" and its
/// tooltip shows the whole text (a text is never cut off mid-letter). For
/// the status bar's general message, so that the permanent parts beside it
/// (the measurement, the VSS quality, the array's range) always show whole.
/// text() is the whole text. The dynamic property "vvElides" marks it for
/// ClippingCheck.
class ElidingLabel : public QLabel {
    Q_OBJECT

  public:
    explicit ElidingLabel(const QString& text = QString(), QWidget* parent = nullptr);

    /// The text as drawn at the current width ("…" at its end when elided).
    [[nodiscard]] QString shownText() const;
    [[nodiscard]] QSize minimumSizeHint() const override;

  protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;
};

}  // namespace vv::gui
