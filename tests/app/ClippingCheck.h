// SPDX-License-Identifier: GPL-3.0-or-later
// Finds text a person cannot read in full: every visible label, button, combo
// box, tab, group box title, header section, table column and line edit (its
// placeholder too) under a widget whose text needs more room than it has, an
// '&' shown literally, a horizontal scroll bar, and widgets that stick out of a
// scroll area's view. Status bars and message boxes are widgets like any
// other; a gui::ElidingLabel (property "vvElides") is never cut: it ends in
// "…" and shows the rest in its tooltip.
#pragma once

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QComboBox>
#include <QFileInfo>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QTabBar>
#include <QTextDocument>
#include <QWidget>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vv::test {

/// Every problem as one line each, for a failure message.
inline std::string listed(const std::vector<std::string>& problems) {
    std::string text;
    for (const std::string& problem : problems) {
        text += "\n  " + problem;
    }
    return text;
}

/// "QLabel 'vssStatus' (parent 'vssPanel')" for failure messages.
inline QString describeWidget(const QWidget* widget) {
    QString name = widget->objectName();
    const QWidget* named = widget->parentWidget();
    while (name.isEmpty() && named != nullptr) {
        name = QStringLiteral("in ") + named->objectName();
        named = named->objectName().isEmpty() ? named->parentWidget() : nullptr;
    }
    return QStringLiteral("%1 '%2'").arg(QString::fromLatin1(widget->metaObject()->className()),
                                         name);
}

/// The text as shown: one '&' before a letter marks a mnemonic, "&&" is '&'.
inline QString withoutMnemonic(QString text) {
    text.replace(QRegularExpression(QStringLiteral("&(?!&)")), QString());
    return text.replace(QStringLiteral("&&"), QStringLiteral("&"));
}

/// The widest line of `text` in `metrics`.
inline int textWidth(const QFontMetrics& metrics, const QString& text) {
    int widest = 0;
    for (const QString& line : text.split(QLatin1Char('\n'))) {
        widest = std::max(widest, metrics.horizontalAdvance(line));
    }
    return widest;
}

/// True when `text` looks like a file path (a folder and a file name).
inline bool looksLikePath(const QString& text) {
    return text.contains(QLatin1Char('/')) && !QFileInfo(text).fileName().isEmpty();
}

class ClippingCheck {
  public:
    /// Every problem found under `root` (root included), one line each.
    [[nodiscard]] static std::vector<std::string> problems(const QWidget* root) {
        ClippingCheck check;
        QList<const QWidget*> widgets{root};
        for (const QWidget* child : root->findChildren<QWidget*>()) {
            widgets << child;
        }
        for (const QWidget* widget : widgets) {
            if (widget->isVisible() && (widget == root || !widget->isWindow())) {
                check.inspect(widget);
            }
        }
        return check.problems_;
    }

  private:
    void fail(const QWidget* widget, const QString& what) {
        problems_.push_back((describeWidget(widget) + QStringLiteral(": ") + what).toStdString());
    }

    void inspect(const QWidget* widget) {
        if (const auto* label = qobject_cast<const QLabel*>(widget)) {
            inspectLabel(label);
        } else if (const auto* button = qobject_cast<const QAbstractButton*>(widget)) {
            if (!button->text().isEmpty() && button->sizeHint().width() > button->width()) {
                fail(button, QStringLiteral("\"%1\" needs %2 px, has %3")
                                 .arg(button->text())
                                 .arg(button->sizeHint().width())
                                 .arg(button->width()));
            }
        } else if (const auto* combo = qobject_cast<const QComboBox*>(widget)) {
            inspectCombo(combo);
        } else if (const auto* tabs = qobject_cast<const QTabBar*>(widget)) {
            inspectTabs(tabs);
        } else if (const auto* group = qobject_cast<const QGroupBox*>(widget)) {
            const int needed =
                textWidth(group->fontMetrics(), withoutMnemonic(group->title())) + 16;
            if (needed > group->width()) {
                fail(group, QStringLiteral("title \"%1\" needs %2 px, has %3")
                                .arg(group->title())
                                .arg(needed)
                                .arg(group->width()));
            }
        } else if (const auto* header = qobject_cast<const QHeaderView*>(widget)) {
            inspectHeader(header);
        } else if (const auto* edit = qobject_cast<const QLineEdit*>(widget)) {
            inspectLineEdit(edit);
        } else if (const auto* bar = qobject_cast<const QScrollBar*>(widget)) {
            if (bar->orientation() == Qt::Horizontal) {
                fail(bar, QStringLiteral("a horizontal scroll bar is shown"));
            }
        }
        if (const auto* view = qobject_cast<const QAbstractItemView*>(widget)) {
            inspectColumns(view);
        }
        inspectInsideScrollArea(widget);
    }

    void inspectLabel(const QLabel* label) {
        const QString text = label->text();
        if (text.isEmpty()) {
            return;
        }
        if (label->property("vvElides").toBool()) {
            return;  // gui::ElidingLabel: ends in "…" when narrow, whole in its tooltip
        }
        const bool rich = label->textFormat() == Qt::RichText ||
                          (label->textFormat() == Qt::AutoText && Qt::mightBeRichText(text));
        if (!rich && label->buddy() == nullptr &&
            text.contains(QRegularExpression(QStringLiteral("&(?!&)\\w")))) {
            fail(label, QStringLiteral("shows a literal '&': \"%1\"").arg(text));
        }
        const QRect room = label->contentsRect();
        if (label->wordWrap()) {
            const int height = label->heightForWidth(label->width());
            if (height > label->height() + 1) {
                fail(label, QStringLiteral("\"%1\" needs %2 px of height, has %3")
                                .arg(text)
                                .arg(height)
                                .arg(label->height()));
            }
            return;
        }
        int needed = 0;
        if (rich) {
            QTextDocument document;
            document.setDefaultFont(label->font());
            document.setDocumentMargin(0);
            document.setHtml(text);
            needed = static_cast<int>(std::ceil(document.idealWidth()));
        } else {
            needed = textWidth(label->fontMetrics(),
                               label->buddy() != nullptr ? withoutMnemonic(text) : text);
        }
        needed += 2 * label->margin();
        if (needed > room.width()) {
            fail(label, QStringLiteral("\"%1\" needs %2 px, has %3")
                            .arg(text)
                            .arg(needed)
                            .arg(room.width()));
        }
    }

    void inspectCombo(const QComboBox* combo) {
        if (combo->isEditable()) {
            return;  // its line edit is checked on its own
        }
        QStyleOptionComboBox option;
        option.initFrom(combo);
        option.editable = false;
        option.frame = combo->hasFrame();
        // The style draws the text 1 px in from each side of the edit field.
        const QRect field =
            combo->style()
                ->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, combo)
                .adjusted(1, 0, -1, 0);
        for (int i = 0; i < combo->count(); ++i) {
            int needed = combo->fontMetrics().horizontalAdvance(combo->itemText(i));
            if (!combo->itemIcon(i).isNull()) {
                needed += combo->iconSize().width() + 4;
            }
            if (needed > field.width()) {
                fail(combo, QStringLiteral("item \"%1\" needs %2 px, has %3")
                                .arg(combo->itemText(i))
                                .arg(needed)
                                .arg(field.width()));
            }
        }
    }

    void inspectTabs(const QTabBar* tabs) {
        const int padding =
            2 * tabs->style()->pixelMetric(QStyle::PM_TabBarTabHSpace, nullptr, tabs) / 2;
        for (int i = 0; i < tabs->count(); ++i) {
            const QString shown = withoutMnemonic(tabs->tabText(i));
            const int needed = tabs->fontMetrics().horizontalAdvance(shown) + padding;
            if (needed > tabs->tabRect(i).width()) {
                fail(tabs, QStringLiteral("tab \"%1\" needs %2 px, has %3")
                               .arg(tabs->tabText(i))
                               .arg(needed)
                               .arg(tabs->tabRect(i).width()));
            }
        }
    }

    void inspectHeader(const QHeaderView* header) {
        const QAbstractItemModel* model = header->model();
        if (model == nullptr || header->orientation() != Qt::Horizontal) {
            return;
        }
        const int margin =
            2 * header->style()->pixelMetric(QStyle::PM_HeaderMargin, nullptr, header);
        for (int section = 0; section < header->count(); ++section) {
            if (header->isSectionHidden(section)) {
                continue;
            }
            const QString text =
                model->headerData(section, Qt::Horizontal, Qt::DisplayRole).toString();
            const int needed = header->fontMetrics().horizontalAdvance(text) + margin;
            if (needed > header->sectionSize(section)) {
                fail(header, QStringLiteral("column \"%1\" needs %2 px, has %3")
                                 .arg(text)
                                 .arg(needed)
                                 .arg(header->sectionSize(section)));
            }
            const int right =
                header->sectionViewportPosition(section) + header->sectionSize(section);
            if (right > header->viewport()->width() + 1) {
                fail(header, QStringLiteral("column \"%1\" ends at %2 px, outside the %3 px shown")
                                 .arg(text)
                                 .arg(right)
                                 .arg(header->viewport()->width()));
            }
        }
    }

    void inspectColumns(const QAbstractItemView* view) {
        const QAbstractItemModel* model = view->model();
        if (model == nullptr) {
            return;
        }
        // The column header (a table also has a row header, whose sections are rows).
        const QHeaderView* header = nullptr;
        for (const QHeaderView* candidate : view->findChildren<const QHeaderView*>()) {
            if (candidate->orientation() == Qt::Horizontal && candidate->parentWidget() == view) {
                header = candidate;
            }
        }
        for (int column = 0; column < model->columnCount(); ++column) {
            if (header == nullptr || header->isSectionHidden(column)) {
                continue;
            }
            const int needed = view->sizeHintForColumn(column);
            const int has = header->sectionSize(column);
            if (needed > has) {
                fail(view, QStringLiteral("column \"%1\": its cells need %2 px, have %3")
                               .arg(model->headerData(column, Qt::Horizontal).toString())
                               .arg(needed)
                               .arg(has));
            }
        }
    }

    void inspectLineEdit(const QLineEdit* edit) {
        // An empty field shows its placeholder: it must fit as well.
        const QString text = edit->text().isEmpty() ? edit->placeholderText() : edit->text();
        if (text.isEmpty() || edit->echoMode() != QLineEdit::Normal) {
            return;
        }
        const QMargins margins = edit->textMargins();
        const int frame = edit->hasFrame() ? edit->style()->pixelMetric(
                                                 QStyle::PM_DefaultFrameWidth, nullptr, edit)
                                           : 0;
        const int room = edit->contentsRect().width() - margins.left() - margins.right() -
                         2 * frame - 4;  // QLineEdit's own 2 px each side
        const QFontMetrics& metrics = edit->fontMetrics();
        if (metrics.horizontalAdvance(text) <= room) {
            return;
        }
        const auto* spin = qobject_cast<const QAbstractSpinBox*>(edit->parentWidget());
        if (spin == nullptr && looksLikePath(text)) {
            // A long path: the file name in view, the whole path in the tooltip.
            const QString name = QFileInfo(text).fileName();
            if (edit->toolTip() == text && edit->cursorPosition() == text.size() &&
                metrics.horizontalAdvance(name) <= room) {
                return;
            }
        }
        fail(spin != nullptr ? static_cast<const QWidget*>(spin) : edit,
             QStringLiteral("\"%1\" needs %2 px, has %3")
                 .arg(text)
                 .arg(metrics.horizontalAdvance(text))
                 .arg(room));
    }

    /// A widget inside a scroll area must not stick out to the right of its view.
    void inspectInsideScrollArea(const QWidget* widget) {
        for (const QWidget* up = widget->parentWidget(); up != nullptr; up = up->parentWidget()) {
            const auto* area = qobject_cast<const QScrollArea*>(up);
            if (area == nullptr || area->widget() == nullptr ||
                !area->widget()->isAncestorOf(widget)) {
                continue;
            }
            const QWidget* view = area->viewport();
            const int right = widget->mapTo(view, QPoint(widget->width(), 0)).x();
            if (right > view->width() + 1) {
                fail(widget, QStringLiteral("ends at %1 px, outside the %2 px of its scroll area")
                                 .arg(right)
                                 .arg(view->width()));
            }
            return;
        }
    }

    std::vector<std::string> problems_;
};

}  // namespace vv::test
