// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QWidget>

class QToolButton;

namespace vv::gui::panels {

/// A titled part of a panel that folds: a flat header button (arrow right =
/// folded, down = open; the whole title always shown) over its content.
/// Whether it is open is remembered in QSettings ("sections/<key>") and
/// restored when it is built again. Its objectName is `key` + "Section", its
/// header's `key` + "SectionHeader".
///
/// Its minimum width is the content's even while folded, so that opening it
/// never makes the surrounding panel wider (and never needs a horizontal
/// scroll bar).
class CollapsibleSection : public QWidget {
    Q_OBJECT

  public:
    /// Takes ownership of `content`. `expandedByDefault` applies when nothing
    /// is remembered for `key` (and after resetToDefault()).
    CollapsibleSection(const QString& title, QWidget* content, const QString& key,
                       bool expandedByDefault, QWidget* parent = nullptr);

    [[nodiscard]] QToolButton* header() const noexcept { return header_; }
    [[nodiscard]] QWidget* content() const noexcept { return content_; }
    [[nodiscard]] bool isExpanded() const noexcept { return expanded_; }
    [[nodiscard]] const QString& key() const noexcept { return key_; }

    /// Opens or folds the section and remembers it.
    void setExpanded(bool expanded);
    /// Open or folded as when nothing was remembered; forgets the remembered state.
    void resetToDefault();

    [[nodiscard]] QSize minimumSizeHint() const override;

  signals:
    void expandedChanged(bool expanded);

  private:
    void applyExpanded(bool expanded);

    QToolButton* header_;
    QWidget* content_;
    QString key_;
    bool expandedByDefault_;
    bool expanded_ = false;
};

}  // namespace vv::gui::panels
