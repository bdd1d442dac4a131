// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <exception>
#include <functional>

class QWidget;

namespace vv {
class Error;
}
namespace vv::segmentation {
struct ThresholdRange;
}

namespace vv::gui {

/// The engine modules' English texts that the GUI shows (the modules hold no
/// Qt: their texts are stable English keys), in the UI language.
///
/// Progress stages (meshio, dicom, demo, segmentation, report): the table in
/// EngineTexts.cpp lists every stage the GUI can show; a stage that names a
/// file ("Reading aorta.vtp") keeps the file name.

/// `stage` in the UI language: its translation when the stage is known, else
/// `stage` unchanged. Never throws.
[[nodiscard]] QString translatedStage(const QString& stage);

/// Whether `stage` is in the table (an exact stage or "<verb> <file name>").
[[nodiscard]] bool isKnownStage(const QString& stage);

/// Why segmentation::defaultThresholdRange() chose `range` (its `rule`), in
/// the UI language, the values written by `value` (e.g. "200 HU"); a rule the
/// GUI does not know comes back unchanged. Never throws.
[[nodiscard]] QString thresholdRuleText(const segmentation::ThresholdRange& range,
                                        const std::function<QString(double)>& value);

/// A problem as a person reads it: `summary` in the UI language says what
/// kind of problem it is and names the file; `details` is the module's own
/// text (English: the modules hold no Qt), which names the cause precisely.
/// A message box shows `summary` as its text and `details` in its Details
/// part (showProblem()); never one English sentence inside a German one.
struct ProblemText {
    QString summary;
    QString details;  ///< may be empty
    /// One line for a status bar or a log: the summary, and the details in
    /// an English UI (where they are in the UI's language).
    [[nodiscard]] QString line() const;
};

/// True when the UI speaks English (no translation installed answers for
/// it): the modules' English details are then readable as they are.
[[nodiscard]] bool englishUi();

/// What the caller was doing with the file when it failed (an IoError says
/// "could not be read" or "could not be written").
enum class FileAccess { Reading, Writing };

/// `error` for a person (see ProblemText): the kind of a vv::Error (the file
/// cannot be read / written; is damaged, empty or of an unsupported type; a
/// value is out of range; the graphics system failed), naming error.file()
/// when it has one; any other exception is an unexpected error. Never throws.
[[nodiscard]] ProblemText describeProblem(const std::exception& error, FileAccess access);

/// A message box (window-modal, not blocking, deleted when closed) with
/// `problem`: its summary as the text, the details as the informative text
/// in an English UI and behind "Show Details…" in any other language.
void showProblem(QWidget* parent, const QString& objectName, const QString& title,
                 const ProblemText& problem);

}  // namespace vv::gui
