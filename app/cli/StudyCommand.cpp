// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli study analyse`: the depth-judgement study's answers
// (results CSV files, vv/study/Results.h) analysed as the paper reports
// them (vv/study/Analysis.h): a summary on stdout, the tables as CSV.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/GuiApplication.h"
#include "cli/RenderOptions.h"
#include "common/SettingsSchema.h"
#include "vv/core/NumberText.h"
#include "vv/report/StudyReport.h"
#include "vv/segmentation/SceneSource.h"
#include "vv/study/Analysis.h"
#include "vv/study/Stimuli.h"

namespace vv::cli {

namespace {

constexpr const char* kStudyUsage =
    "usage: vesselview-cli study make SCENE... -o DIR [--conditions NAME,...]\n"
    "       [--condition NAME:SETTING=VALUE,...] [--pairs N] [--training-pairs N]\n"
    "       [--seed S] [--size WxH] [DICOM options as for render]\n"
    "  The stimuli of a depth-judgement study (the paper's \"Stimuli\"): per scene (a\n"
    "  mesh file or a DICOM series) its marker pairs, on visible vessel surface, their\n"
    "  depths at least 10 % of the view's depth range apart, clearly left and right,\n"
    "  balanced over screen distance, depth difference and whether the two border\n"
    "  the same void region; per pair and condition an image with the two markers.\n"
    "  -o, --output DIR     the study folder: stimuli/*.png and manifest.json\n"
    "                       (conditions, cameras, markers with their pixels and\n"
    "                       depths, the answer key, the criteria' values)\n"
    "  --conditions LIST    of the paper's VSS-CD, VSS-PCD, vessel-CD, vessel-PCD,\n"
    "                       baseline (default: all five; none for none)\n"
    "  --condition NAME:SETTING=VALUE,...\n"
    "                       adds a condition of its own (repeatable): a paper\n"
    "                       condition's settings (from=NAME, default baseline) with\n"
    "                       the display options of render, without their dashes\n"
    "                       (e.g. VSS-iso:from=VSS-CD,isolines=8 or\n"
    "                       fog:fog-strength=0.6 or lit:light=-30,20)\n"
    "  --pairs N            marker pairs per scene, default 5 (the paper's)\n"
    "  --training-pairs N   further pairs per scene for the training phase (never\n"
    "                       in the main block), default 1; 0 for none\n"
    "  --seed S             the same seed makes the same study, default 1\n"
    "  --size WxH           the images' size, default 1280x720\n"
    "\n"
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

/// The conditions named in `list` (comma-separated), of the paper's five.
std::vector<study::StimulusCondition> conditionsNamed(const std::string& list) {
    const std::vector<study::StimulusCondition> paper = study::paperConditions();
    std::vector<study::StimulusCondition> chosen;
    for (const std::string& name : splitList(list, "--conditions")) {
        const auto found = std::ranges::find_if(
            paper, [&](const study::StimulusCondition& c) { return c.name == name; });
        if (found == paper.end()) {
            throw UsageError("study make: --conditions: unknown condition '" + name +
                             "' (VSS-CD, VSS-PCD, vessel-CD, vessel-PCD, baseline)");
        }
        chosen.push_back(*found);
    }
    return chosen;
}

/// `--condition NAME:SETTING=VALUE,...`: a condition of its own, from the
/// settings of a paper condition (`from=NAME`, baseline when not given)
/// with the display settings named by the render command's options
/// (without their dashes: isolines=8, fog-strength=0.5, light=-30,20).
study::StimulusCondition customCondition(const std::string& text) {
    const std::string what = "study make: --condition '" + text + "':";
    const auto colon = text.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
        throw UsageError(what + " NAME:SETTING=VALUE,... expected (e.g. fog:fog-strength=0.6)");
    }
    // Pieces "key=value"; a piece without '=' continues the value before
    // it (a value with a comma: light=-30,20).
    std::vector<std::pair<std::string, std::string>> pieces;
    for (const std::string& piece : splitList(text.substr(colon + 1), "--condition")) {
        const auto equals = piece.find('=');
        if (equals == std::string::npos && !pieces.empty()) {
            pieces.back().second.append(",").append(piece);
        } else if (equals == std::string::npos || equals == 0) {
            throw UsageError(
                std::string(what).append(" '").append(piece).append("' is not SETTING=VALUE"));
        } else {
            pieces.emplace_back(piece.substr(0, equals), piece.substr(equals + 1));
        }
    }
    const std::vector<study::StimulusCondition> paper = study::paperConditions();
    study::StimulusCondition condition{text.substr(0, colon), paper.back().display,
                                       text.substr(colon + 1)};
    for (const auto& [key, value] : pieces) {
        if (key == "from") {
            condition.display = conditionsNamed(value).at(0).display;
        }
    }
    for (const auto& [key, value] : pieces) {
        const app::Setting* setting = app::settingForOption("--" + key);
        if (key == "from") {
            continue;
        }
        if (key == "light") {
            condition.display.style.light = parseLightAngles(value);
        } else if (setting == nullptr || setting->field.set == nullptr) {
            throw UsageError(std::string(what).append(" '").append(key).append(
                "' is no display setting (the display options of render, without their "
                "dashes: isolines, fog-strength, vss-lighting, ...)"));
        } else {
            try {
                setting->field.set(condition.display, app::parseSettingText(*setting, value));
            } catch (const InvalidArgumentError& e) {
                throw UsageError(
                    std::string(what).append(" ").append(key).append(" ").append(e.problem()));
            }
        }
    }
    return condition;
}

int studyMake(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    std::vector<std::filesystem::path> inputs;
    std::filesystem::path folder;
    std::vector<study::StimulusCondition> conditions = study::paperConditions();
    std::vector<study::StimulusCondition> added;
    study::StimulusOptions options;
    segmentation::SceneSourceOptions source;
    for (Arguments a("study make", args, 1); a.next();) {
        const std::string& name = a.name();
        if (name == "--help" || name == "-h") {
            out << kStudyUsage;
            return kOk;
        }
        if (name == "-o" || name == "--output") {
            folder = a.path();
        } else if (name == "--conditions") {
            const std::string list = a.value();
            conditions =
                list == "none" ? std::vector<study::StimulusCondition>{} : conditionsNamed(list);
        } else if (name == "--condition") {
            added.push_back(customCondition(a.value()));
        } else if (name == "--pairs") {
            const double pairs = parseNumber(a.value(), "--pairs");
            if (!(pairs >= 1.0 && pairs <= 1000.0) || pairs != std::floor(pairs)) {
                a.fail("--pairs must be a whole number from 1 to 1000");
            }
            options.pairsPerScene = static_cast<std::size_t>(pairs);
        } else if (name == "--training-pairs") {
            const double pairs = parseNumber(a.value(), "--training-pairs");
            if (!(pairs >= 0.0 && pairs <= 1000.0) || pairs != std::floor(pairs)) {
                a.fail("--training-pairs must be a whole number from 0 to 1000");
            }
            options.trainingPairsPerScene = static_cast<std::size_t>(pairs);
        } else if (name == "--seed") {
            const double seed = parseNumber(a.value(), "--seed");
            if (!(seed >= 0.0 && seed <= 9.0e15) || seed != std::floor(seed)) {
                a.fail("--seed must be a whole number >= 0");
            }
            options.seed = static_cast<std::uint64_t>(seed);
        } else if (name == "--size") {
            std::tie(options.width, options.height) = parseSize(a.value(), "--size", 64, 8192);
        } else if (segmentation::setSceneSourceOption(name, a.peekValue(), source)) {
            a.takeValue();
        } else if (a.isOption()) {
            a.fail("unknown option '" + name + "'");
        } else {
            inputs.emplace_back(a.current());
        }
    }
    if (inputs.empty()) {
        throw UsageError("study make needs one or more scenes (mesh files or DICOM series)");
    }
    conditions.insert(conditions.end(), added.begin(), added.end());
    if (conditions.empty()) {
        throw UsageError("study make needs at least one condition");
    }
    if (folder.empty()) {
        throw UsageError("study make needs the study folder: -o DIR");
    }
    std::vector<study::StimulusScene> scenes;
    std::set<std::string> names;
    for (const auto& input : inputs) {
        std::string name = input.stem().string();
        for (int n = 2; !names.insert(name).second; ++n) {
            name = input.stem().string() + "-" + std::to_string(n);
        }
        scenes.push_back({name, input.string(), segmentation::loadSceneSource(input, source)});
    }
    ensureGuiApplication();
    render::OffscreenRenderer renderer;
    study::StudyStimuli made;
    try {
        made = study::makeStimuli(renderer, scenes, conditions, options, folder);
    } catch (const IoError& e) {
        throw OutputError(e.what());
    }
    for (const std::string& note : made.notes) {
        err << "vesselview-cli: note: " << note << "\n";
    }
    const auto training = static_cast<std::size_t>(
        std::count_if(made.stimuli.begin(), made.stimuli.end(),
                      [](const study::Stimulus& s) { return s.block == study::Block::Training; }));
    out << made.stimuli.size() - training << " stimuli and " << training << " training stimuli ("
        << scenes.size() << " scene(s) x " << conditions.size()
        << " condition(s) x their pairs) in " << folder.string() << "\n";
    return kOk;
}

}  // namespace

int studyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (args.empty() || args.front() == "--help" || args.front() == "-h") {
        (args.empty() ? err : out) << kStudyUsage;
        return args.empty() ? kUsage : kOk;
    }
    if (args.front() == "make") {
        return studyMake(args, out, err);
    }
    if (args.front() != "analyse" && args.front() != "analyze") {
        throw UsageError("unknown study command '" + args.front() + "' (make, analyse)");
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
    const study::StudyAnalysis analysis = study::analyseResultsFiles(inputs, options);
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
