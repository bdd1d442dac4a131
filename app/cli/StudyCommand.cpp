// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli study analyse`: the depth-judgement study's answers
// (results CSV files, vv/study/Results.h) analysed as the paper reports
// them (vv/study/Analysis.h): a summary on stdout, the tables as CSV.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "vv/core/NumberText.h"
#include "vv/report/StudyReport.h"
#include "vv/study/Analysis.h"

namespace vv::cli {

namespace {

constexpr const char* kStudyUsage =
    "usage: vesselview-cli study analyse RESULTS.csv... [-o STUDY.pdf] [--lang en|de]\n"
    "       [--paper a4|letter] [--tables DIR] [--alpha A] [--correction bonferroni|holm]\n"
    "  The answers of a depth-judgement study (one CSV row per answer, as the\n"
    "  study runner writes them; several files are read as one study) analysed\n"
    "  as the paper (Kreiser et al. 2018) reports it: per participant the\n"
    "  accuracy and the median response time in each condition (main block\n"
    "  only); participants at chance level (one-sided binomial test) or\n"
    "  without an answer in some condition excluded, with the reason; per\n"
    "  measure each condition's mean and median with 95 % intervals,\n"
    "  Friedman's test and the post-hoc comparisons of the conditions' rank\n"
    "  sums (critical difference with Bonferroni's correction; Holm's as the\n"
    "  option). A summary goes to stdout.\n"
    "  -o, --output FILE.pdf  the analysis as a PDF: the participants and the\n"
    "                       exclusions, per measure a chart (accuracy: mean and\n"
    "                       95 % interval per condition; response time: box\n"
    "                       plots), Friedman's test, the tables and the post-hoc\n"
    "                       comparisons; --lang its language, --paper its page\n"
    "  --tables DIR         conditions.csv, comparisons.csv, participants.csv\n"
    "                       (the folder is created)\n"
    "  --alpha A            significance level, default 0.05\n"
    "  --correction NAME    bonferroni (default) or holm\n"
    "  Exit code 3 for a results file that cannot be read or too few\n"
    "  participants or conditions left to analyse, with the reason.\n";

std::string pText(double p) {
    return p < 0.001 ? "< 0.001" : "= " + fixedText(p, 3);
}

void printMeasure(const study::StudyAnalysis& s, const study::MeasureResult& m, std::ostream& out) {
    const study::FriedmanResult& f = m.friedman;
    const bool proportion = m.unit.empty();
    const auto value = [&](double v) {
        return proportion ? fixedText(100.0 * v, 1) + " %" : fixedText(v, 0) + " " + m.unit;
    };
    out << "\n"
        << m.name << (m.unit.empty() ? "" : " [" + m.unit + "]") << ": Friedman chi^2("
        << f.degreesOfFreedom << ") = " << fixedText(f.chiSquared, 3) << ", p " << pText(f.pValue)
        << ", Kendall's W = " << fixedText(f.kendallW, 3) << "\n";
    for (std::size_t c = 0; c < s.conditions.size(); ++c) {
        const study::Summary& sum = m.perCondition[c];
        out << "  " << s.conditions[c] << ": mean " << value(sum.mean) << " [" << value(sum.meanLow)
            << ", " << value(sum.meanHigh) << "], median " << value(sum.median) << " ["
            << value(sum.medianLow) << ", " << value(sum.medianHigh) << "; "
            << fixedText(100.0 * sum.medianConfidence, 1) << " %], rank sum "
            << fixedText(f.rankSums[c], 1) << "\n";
    }
    out << "  post hoc (" << study::correctionName(m.postHoc.correction)
        << "; critical difference of rank sums " << fixedText(m.postHoc.criticalDifference, 2)
        << "):";
    bool any = false;
    for (const study::PairComparison& pair : m.postHoc.pairs) {
        if (pair.significant) {
            out << "\n    " << s.conditions[pair.first] << " vs " << s.conditions[pair.second]
                << ": difference " << fixedText(pair.rankSumDifference, 1) << ", corrected p "
                << pText(pair.adjustedP);
            any = true;
        }
    }
    out << (any ? "\n" : " no pair differs significantly\n");
}

void printSummary(const study::StudyAnalysis& s, std::ostream& out) {
    out << "Participants: " << s.participants.size() << ", included " << s.included << "\n";
    for (const study::ParticipantResult& p : s.participants) {
        if (p.excluded) {
            out << "  excluded " << p.id << ": " << p.exclusionReason << "\n";
        }
    }
    out << s.exclusionRule << "\n";
    for (const std::string& note : s.notes) {
        out << "Note: " << note << "\n";
    }
    printMeasure(s, s.accuracy, out);
    printMeasure(s, s.responseTime, out);
}

}  // namespace

int studyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (args.empty() || args.front() == "--help" || args.front() == "-h") {
        (args.empty() ? err : out) << kStudyUsage;
        return args.empty() ? kUsage : kOk;
    }
    if (args.front() != "analyse" && args.front() != "analyze") {
        throw UsageError("unknown study command '" + args.front() + "' (analyse)");
    }
    std::vector<std::filesystem::path> inputs;
    std::filesystem::path tables;
    std::filesystem::path pdfOutput;
    std::string language = "en";
    report::PaperSize paper = report::PaperSize::A4;
    study::AnalysisOptions options;
    for (Arguments a("study analyse", args, 1); a.next();) {
        const std::string& name = a.name();
        if (name == "--help" || name == "-h") {
            out << kStudyUsage;
            return kOk;
        }
        if (name == "--tables") {
            tables = a.path();
        } else if (name == "-o" || name == "--output") {
            pdfOutput = a.path();
            if (pdfOutput.extension() != ".pdf") {
                a.fail("the output must end in .pdf, not '" + pdfOutput.string() + "'");
            }
        } else if (name == "--lang") {
            language = a.value();
            checkLanguage("study analyse", language);
        } else if (name == "--paper") {
            const std::string& paperName = a.value();
            const auto chosen = report::paperSizeFromName(paperName);
            if (!chosen) {
                a.fail("--paper must be a4 or letter, not '" + paperName + "'");
            }
            paper = *chosen;
        } else if (name == "--alpha") {
            options.alpha = parseNumber(a.value(), "--alpha");
            if (!(options.alpha > 0.0 && options.alpha < 1.0)) {
                a.fail("--alpha must lie in (0, 1)");
            }
        } else if (name == "--correction") {
            const std::string& value = a.value();
            if (value != "bonferroni" && value != "holm") {
                a.fail("--correction must be bonferroni or holm, not '" + value + "'");
            }
            options.correction =
                value == "holm" ? study::Correction::Holm : study::Correction::Bonferroni;
        } else if (a.isOption()) {
            a.fail("unknown option '" + name + "'");
        } else {
            inputs.emplace_back(a.current());
        }
    }
    if (inputs.empty()) {
        throw UsageError("study analyse needs one or more results files");
    }
    std::vector<study::Answer> answers;
    for (const auto& input : inputs) {
        const std::vector<study::Answer> read = study::readResults(input);
        answers.insert(answers.end(), read.begin(), read.end());
    }
    const study::StudyAnalysis analysis = study::analyseStudy(answers, options);
    printSummary(analysis, out);
    if (!pdfOutput.empty()) {
        ensureGuiApplication();  // fonts
        useLanguage(language);
        report::StudyReportContent content;
        for (const auto& input : inputs) {
            content.sources.push_back(input.filename().string());
        }
        try {
            report::writeStudyPdf(pdfOutput, analysis, content, paper);
        } catch (const IoError& e) {
            throw OutputError(e.what());
        }
        err << "vesselview-cli: wrote " << pdfOutput.string() << "\n";
    }
    if (!tables.empty()) {
        std::error_code error;
        std::filesystem::create_directories(tables, error);
        if (error) {
            throw OutputError("cannot create " + tables.string() + ": " + error.message());
        }
        try {
            study::writeAnalysisTables(analysis, tables);
        } catch (const IoError& e) {
            throw OutputError(e.what());
        }
        err << "vesselview-cli: wrote the tables to " << tables.string() << "\n";
    }
    return kOk;
}

}  // namespace vv::cli
