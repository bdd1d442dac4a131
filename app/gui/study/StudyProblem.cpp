// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/study/StudyProblem.h"

#include <QCoreApplication>
#include <QDir>

#include "vv/study/Results.h"

namespace vv::gui {
namespace {

constexpr const char* kContext = "vv::gui::StudyProblem";

}  // namespace

ProblemText studyProblem(const std::exception& error) {
    const auto* study = dynamic_cast<const study::StudyError*>(&error);
    if (study == nullptr) {
        return describeProblem(error, FileAccess::Reading);
    }
    ProblemText text;
    text.details = QString::fromStdString(study->what());
    const char* answers = QT_TRANSLATE_NOOP("vv::gui::StudyProblem",
                                            "The study's answers cannot be analysed as they are.");
    const char* file =
        QT_TRANSLATE_NOOP("vv::gui::StudyProblem", "%1 does not hold what the study needs.");
    text.summary =
        study->file().empty()
            ? QCoreApplication::translate(kContext, answers)
            : QCoreApplication::translate(kContext, file)
                  .arg(QDir::toNativeSeparators(QString::fromStdString(study->file().string())));
    return text;
}

QString studyProblemText(const std::exception& error) {
    const ProblemText problem = studyProblem(error);
    if (problem.details.isEmpty()) {
        return problem.summary;
    }
    const char* details = QT_TRANSLATE_NOOP("vv::gui::StudyProblem", "Details (in English): %1");
    return problem.summary + QStringLiteral("\n\n") +
           (englishUi() ? problem.details
                        : QCoreApplication::translate(kContext, details).arg(problem.details));
}

}  // namespace vv::gui
