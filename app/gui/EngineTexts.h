// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <functional>

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

/// What went wrong, for a person: `error`'s problem (the modules' English
/// text, which names the cause precisely). In a translated UI it is led by a
/// sentence in the UI language saying what kind of problem it is (the file
/// cannot be read; is damaged or of an unsupported type; a value is out of
/// range; the graphics system failed), with the English detail in
/// parentheses. Never throws.
[[nodiscard]] QString problemText(const vv::Error& error);

}  // namespace vv::gui
