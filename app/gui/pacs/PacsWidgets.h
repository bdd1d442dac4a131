// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The widgets the DICOM network dialogs share: result tables, the line that
// shows a problem, OK / Cancel.

#include <QString>
#include <QStringList>
#include <string>

class QDialog;
class QDialogButtonBox;
class QLabel;
class QTableWidget;
class QWidget;

namespace vv::gui {

/// A read-only table chosen by whole rows (one at a time), without row
/// numbers; its columns fit their contents and the last takes the rest.
[[nodiscard]] QTableWidget* makeResultTable(QWidget* parent, const QString& objectName,
                                            const QStringList& headers);

/// Shows `label`'s text as a problem (red) or as plain information.
void showAsProblem(QLabel* label, bool problem);

/// A hidden, word-wrapped label for the message that refuses invalid input.
[[nodiscard]] QLabel* makeErrorLabel(QWidget* parent, const QString& objectName);

/// OK and Cancel, wired to `dialog`'s accept() and reject().
[[nodiscard]] QDialogButtonBox* makeOkCancel(QDialog* dialog);

/// A DICOM date (YYYYMMDD) as the UI locale writes dates (short format with
/// a four-digit year); the text itself when it is not a valid date.
[[nodiscard]] QString studyDateText(const std::string& dicomDate);

}  // namespace vv::gui
