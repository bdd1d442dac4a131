// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QFormLayout;
class QHBoxLayout;
class QLayout;
class QLineEdit;
class QWidget;

namespace vv::gui {

/// Makes `edit` show the file path it holds: wide enough for the whole path
/// (up to about 70 characters), and for a longer path the end of it (the
/// file name) in view with the whole path in its tooltip. Follows every
/// change of the text.
void showPath(QLineEdit* edit);

/// `edit` (showPath()) with a "Browse…" button beside it that opens a save
/// dialog titled `title` for `filter` over `parent` and puts the chosen path
/// into `edit`. The dialog does not ask before replacing a file: the export
/// dialogs ask when they write (ExportDialog::accept()).
[[nodiscard]] QHBoxLayout* browseRow(QLineEdit* edit, const QString& title, const QString& filter,
                                     QWidget* parent);

/// A form row whose label `text` ("&File:") names `buddy` (its mnemonic
/// focuses it; no '&' is shown) and whose field is `field` (a row holding
/// `buddy`). QFormLayout::addRow(QString, QLayout*) leaves the label without
/// a buddy, which shows the '&'.
void addBuddyRow(QFormLayout* form, const QString& text, QWidget* buddy, QLayout* field);

}  // namespace vv::gui
