// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The widgets the DICOM network dialogs share: result tables, the line that
// shows a problem, OK / Cancel, sizes in GB.

#include <QString>
#include <QStringList>
#include <cstdint>
#include <string>

class QDialog;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLabel;
class QTableWidget;
class QWidget;

namespace vv::gui {

struct ProblemText;

/// A read-only table chosen by whole rows (one at a time), without row
/// numbers; its columns fit their contents and the last takes the rest.
[[nodiscard]] QTableWidget* makeResultTable(QWidget* parent, const QString& objectName,
                                            const QStringList& headers);

/// Shows `label`'s text as a problem (red) or as plain information.
void showAsProblem(QLabel* label, bool problem);

/// Shows `problem` on `label` as a problem: its summary (UI language) as the
/// text, its English details as the tooltip ("Details: …"; none when empty).
void showProblemText(QLabel* label, const ProblemText& problem);

/// A hidden, word-wrapped label for the message that refuses invalid input.
[[nodiscard]] QLabel* makeErrorLabel(QWidget* parent, const QString& objectName);

/// OK and Cancel, wired to `dialog`'s accept() and reject().
[[nodiscard]] QDialogButtonBox* makeOkCancel(QDialog* dialog);

/// `value` in the UI locale (up to 6 significant digits) and its `unit`
/// ("5 s", "4 GB"), joined by a no-break space: never split over two lines.
[[nodiscard]] QString quantityText(double value, const char* unit);

/// Bytes in a GB of the UI, as the CLI's NGB counts them.
inline constexpr double kBytesPerGb = 1e9;

/// A spin box of a size in GB (kBytesPerGb), in
/// the UI locale, with `decimals` decimals, from `minimumGb` to 100,000 GB.
[[nodiscard]] QDoubleSpinBox* makeGigabyteBox(QWidget* parent, const QString& objectName,
                                              int decimals, double minimumGb);
/// The value of a makeGigabyteBox() in bytes.
[[nodiscard]] std::uint64_t bytesOf(const QDoubleSpinBox* box);
/// Shows `bytes` in a makeGigabyteBox() (rounded to its decimals).
void setBytes(QDoubleSpinBox* box, std::uint64_t bytes);

/// A DICOM date (YYYYMMDD) as the UI language writes dates unambiguously,
/// the same as the PDF report: 2025-03-07 in English, 07.03.2025 in German;
/// the text itself when it is not a valid date.
[[nodiscard]] QString studyDateText(const std::string& dicomDate);

}  // namespace vv::gui
