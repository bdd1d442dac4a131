// SPDX-License-Identifier: GPL-3.0-or-later
// What a person reads in the GUI, collected from the widgets (for the language
// tests): every visible label, button, group box title, tab, combo box item,
// header section, tree item, window title, tool tip, placeholder, spin box
// text / prefix / suffix and menu entry, each with where it was found.
#pragma once

#include <QAbstractButton>
#include <QAbstractItemModel>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QString>
#include <QTabBar>
#include <QTextDocumentFragment>
#include <QTreeWidget>
#include <QWidget>
#include <vector>

namespace vv::test {

/// One text a person can read, and where: "<class> '<objectName>' in '<owner>'".
struct VisibleText {
    QString where;
    QString text;
};

/// The texts of the GUI, each once per place.
class VisibleTexts {
  public:
    /// The texts of `root` and its visible descendants (`root` itself when visible).
    void collect(const QWidget* root) {
        if (!root->isVisible()) {
            return;
        }
        visit(root);
        for (const QWidget* child : root->findChildren<QWidget*>()) {
            if (child->isVisible()) {
                visit(child);
            }
        }
    }

    /// Every visible top-level widget (windows, dialogs, tool tips, menus).
    void collectTopLevels() {
        for (const QWidget* top : QApplication::topLevelWidgets()) {
            collect(top);
        }
    }

    /// The entries of `bar`'s menus, shown or not (text, tool tip, status tip).
    void collectMenus(const QMenuBar& bar) {
        for (const QAction* action : bar.actions()) {
            collectAction(action, QStringLiteral("menu"));
        }
    }

    /// A text the test shows on its own (e.g. a status message signalled).
    void add(const QString& where, const QString& text) {
        const QString trimmed = text.trimmed();
        if (trimmed.isEmpty()) {
            return;
        }
        for (const VisibleText& known : texts_) {
            if (known.where == where && known.text == trimmed) {
                return;
            }
        }
        texts_.push_back({where, trimmed});
    }

    [[nodiscard]] const std::vector<VisibleText>& texts() const noexcept { return texts_; }

  private:
    static QString describe(const QObject* object) {
        QString owner;
        for (const QObject* p = object->parent(); p != nullptr; p = p->parent()) {
            if (!p->objectName().isEmpty() && !p->objectName().startsWith(QLatin1String("qt_"))) {
                owner = p->objectName();
                break;
            }
        }
        return QStringLiteral("%1 '%2' in '%3'")
            .arg(QLatin1String(object->metaObject()->className()), object->objectName(), owner);
    }

    static QString plain(const QString& text) {
        return Qt::mightBeRichText(text) ? QTextDocumentFragment::fromHtml(text).toPlainText()
                                         : text;
    }

    void collectAction(const QAction* action, const QString& where) {
        const QString here = where + QStringLiteral(" > ") + QString(action->text()).remove('&');
        add(here, action->text());
        if (action->toolTip() != QString(action->text()).remove('&')) {
            add(here + QStringLiteral(" (tool tip)"), plain(action->toolTip()));
        }
        add(here + QStringLiteral(" (status tip)"), action->statusTip());
        if (action->menu() != nullptr) {
            for (const QAction* sub : action->menu()->actions()) {
                collectAction(sub, here);
            }
        }
    }

    void visit(const QWidget* w) {
        const QString where = describe(w);
        if (w->isWindow() || qobject_cast<const QDockWidget*>(w) != nullptr) {
            add(where + QStringLiteral(" (title)"), w->windowTitle());
        }
        add(where + QStringLiteral(" (tool tip)"), plain(w->toolTip()));
        if (const auto* label = qobject_cast<const QLabel*>(w)) {
            add(where, plain(label->text()));
        } else if (const auto* button = qobject_cast<const QAbstractButton*>(w)) {
            add(where, button->text());
        } else if (const auto* group = qobject_cast<const QGroupBox*>(w)) {
            add(where, group->title());
        } else if (const auto* tabs = qobject_cast<const QTabBar*>(w)) {
            for (int i = 0; i < tabs->count(); ++i) {
                add(where, tabs->tabText(i));
                add(where + QStringLiteral(" (tab tool tip)"), plain(tabs->tabToolTip(i)));
            }
        } else if (const auto* combo = qobject_cast<const QComboBox*>(w)) {
            for (int i = 0; i < combo->count(); ++i) {
                add(where, combo->itemText(i));
            }
        } else if (const auto* edit = qobject_cast<const QLineEdit*>(w)) {
            add(where + QStringLiteral(" (placeholder)"), edit->placeholderText());
        } else if (const auto* spin = qobject_cast<const QSpinBox*>(w)) {
            add(where, spin->text());
            add(where + QStringLiteral(" (prefix)"), spin->prefix());
            add(where + QStringLiteral(" (suffix)"), spin->suffix());
        } else if (const auto* dspin = qobject_cast<const QDoubleSpinBox*>(w)) {
            add(where, dspin->text());
            add(where + QStringLiteral(" (prefix)"), dspin->prefix());
            add(where + QStringLiteral(" (suffix)"), dspin->suffix());
        } else if (const auto* header = qobject_cast<const QHeaderView*>(w)) {
            if (const QAbstractItemModel* model = header->model()) {
                const int n = header->orientation() == Qt::Horizontal ? model->columnCount()
                                                                      : model->rowCount();
                for (int i = 0; i < n; ++i) {
                    if (!header->isSectionHidden(i)) {
                        add(where, model->headerData(i, header->orientation()).toString());
                    }
                }
            }
        } else if (const auto* tree = qobject_cast<const QTreeWidget*>(w)) {
            for (QTreeWidgetItemIterator it(const_cast<QTreeWidget*>(tree)); *it != nullptr; ++it) {
                for (int c = 0; c < tree->columnCount(); ++c) {
                    add(where + QStringLiteral(" (item)"), (*it)->text(c));
                    add(where + QStringLiteral(" (item tool tip)"), plain((*it)->toolTip(c)));
                }
            }
        } else if (const auto* bar = qobject_cast<const QStatusBar*>(w)) {
            add(where + QStringLiteral(" (message)"), bar->currentMessage());
        } else if (const auto* menu = qobject_cast<const QMenu*>(w)) {
            for (const QAction* action : menu->actions()) {
                add(where, action->text());
            }
        }
    }

    std::vector<VisibleText> texts_;
};

}  // namespace vv::test
