// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QScrollArea>
#include <QString>

namespace vv::gui::panels {

class CollapsibleSection;

/// The main window's one side panel: its parts as CollapsibleSections one
/// under the other, scrolling vertically only. It is never narrower than its
/// widest part needs (opened or folded), so nothing in it is cut off and no
/// horizontal scroll bar is ever needed. A mouse wheel over a combo box,
/// spin box or slider that has no keyboard focus scrolls the panel instead of
/// changing the control's value.
class SidePanel : public QScrollArea {
    Q_OBJECT

  public:
    explicit SidePanel(QWidget* parent = nullptr);

    /// Appends `panel` under a header `title` (see CollapsibleSection; the
    /// section's key is the panel's objectName) and returns the section.
    CollapsibleSection* addSection(const QString& title, QWidget* panel, bool expandedByDefault);
    [[nodiscard]] const QList<CollapsibleSection*>& sections() const noexcept { return sections_; }
    /// The section holding `panel`; nullptr when none does.
    [[nodiscard]] CollapsibleSection* sectionOf(const QWidget* panel) const;
    /// Opens the section holding `panel` and scrolls it into view.
    void reveal(const QWidget* panel);
    /// Moves `section` (one of sections()) to place `index` among the
    /// sections (clamped: 0 = the top, sections().size() - 1 = the bottom).
    void moveSection(CollapsibleSection* section, int index);

    [[nodiscard]] QSize minimumSizeHint() const override;
    [[nodiscard]] QSize sizeHint() const override;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    QWidget* content_;
    QList<CollapsibleSection*> sections_;
};

}  // namespace vv::gui::panels
