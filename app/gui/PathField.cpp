// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/PathField.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStyle>
#include <algorithm>

namespace vv::gui {

namespace {

/// The widest path shown in full, in average characters.
constexpr int kWidestPathCharacters = 70;
/// The narrowest field, in average characters.
constexpr int kNarrowestCharacters = 36;

void fitPath(QLineEdit* edit) {
    const QString& text = edit->text();
    const QFontMetrics& metrics = edit->fontMetrics();
    const int average = metrics.averageCharWidth();
    // QLineEdit's frame and inner margins.
    const int extra = 2 * edit->style()->pixelMetric(QStyle::PM_DefaultFrameWidth, nullptr, edit) +
                      8 + edit->textMargins().left() + edit->textMargins().right();
    edit->setMinimumWidth(std::clamp(metrics.horizontalAdvance(text) + extra,
                                     kNarrowestCharacters * average,
                                     kWidestPathCharacters * average));
    edit->setToolTip(text);
    if (!edit->hasFocus()) {
        edit->setCursorPosition(static_cast<int>(text.size()));  // the file name in view
    }
}

}  // namespace

void showPath(QLineEdit* edit) {
    fitPath(edit);
    QObject::connect(edit, &QLineEdit::textChanged, edit, [edit] { fitPath(edit); });
    QObject::connect(edit, &QLineEdit::editingFinished, edit, [edit] { fitPath(edit); });
}

QHBoxLayout* browseRow(QLineEdit* edit, const QString& title, const QString& filter,
                       QWidget* parent) {
    auto* browse =
        new QPushButton(QCoreApplication::translate("vv::gui::PathField", "Browse…"), parent);
    QObject::connect(browse, &QPushButton::clicked, parent, [edit, title, filter, parent] {
        const QString chosen = QFileDialog::getSaveFileName(
            parent, title, edit->text(), filter, nullptr, QFileDialog::DontConfirmOverwrite);
        if (!chosen.isEmpty()) {
            edit->setText(chosen);
        }
    });
    auto* row = new QHBoxLayout;
    row->addWidget(edit, 1);
    row->addWidget(browse);
    showPath(edit);
    return row;
}

void addBuddyRow(QFormLayout* form, const QString& text, QWidget* buddy, QLayout* field) {
    auto* label = new QLabel(text, buddy->parentWidget());
    label->setBuddy(buddy);
    form->addRow(label, field);
}

}  // namespace vv::gui
