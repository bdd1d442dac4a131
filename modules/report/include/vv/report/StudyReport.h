// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QStringList>
#include <filesystem>
#include <string>
#include <vector>

#include "vv/report/PdfReport.h"
#include "vv/study/Analysis.h"

namespace vv::report {

/// What the study report shows besides the analysis.
struct StudyReportContent {
    std::vector<std::string> sources;  ///< the results files, by name
    QDateTime created = QDateTime::currentDateTime();
};

/// The depth-judgement study's analysis as a PDF (the page, margins,
/// fonts and footer of the vessel report): the participants and the
/// exclusion rule with each exclusion; per measure an error-bar chart of
/// the accuracy (mean and 95 % interval, chance level marked) or box plots
/// of the response times, Friedman's test, the per-condition table and the
/// post-hoc comparisons with the critical difference; the participants'
/// table. In the installed translation (the default QLocale's numbers).
[[nodiscard]] QByteArray renderStudyPdf(const study::StudyAnalysis& analysis,
                                        const StudyReportContent& content, PaperSize paper);

/// The analysis in a few lines, worded as the PDF words it (the installed
/// translation, the default QLocale's numbers): the participants and how
/// many are included, each exclusion with its reason, and per measure
/// Friedman's test and the pairs of conditions that differ significantly.
[[nodiscard]] QStringList studySummaryLines(const study::StudyAnalysis& analysis);

/// renderStudyPdf() written atomically to `path`. Throws IoError.
void writeStudyPdf(const std::filesystem::path& path, const study::StudyAnalysis& analysis,
                   const StudyReportContent& content, PaperSize paper);

}  // namespace vv::report
