// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <exception>

#include "gui/EngineTexts.h"

namespace vv::gui {

/// A problem of the study's files or answers for a person (ProblemText):
/// a study::StudyError as what it means for the study (a manifest or
/// results file that does not hold what the study needs, naming it; answers
/// that cannot be analysed as they are), anything else as describeProblem()
/// words it. The module's English text is the details. Never throws.
[[nodiscard]] ProblemText studyProblem(const std::exception& error);

/// The problem as the dialogs' text shows it: the summary, and the details
/// as a paragraph of their own (in another language than English marked as
/// the details, never inside a translated sentence).
[[nodiscard]] QString studyProblemText(const std::exception& error);

}  // namespace vv::gui
