// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli report --lang de|en` run as a user runs it (the installed
// layout of the build tree finds the translations): the German report has
// none of the report's English strings and no '.' decimal separator; the
// English one has no German. Also the patient options for meshes, the
// disclaimer, the order of the sections and the demo's provenance. OpenGL:
// run under `xvfb-run -a` (QT_QPA_PLATFORM=xcb); pdftotext (poppler-utils).
#include <gtest/gtest.h>
#include <unistd.h>

#include <QByteArray>
#include <QImage>
#include <QString>
#include <QTextDocumentFragment>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "CtaSeriesFixture.h"
#include "ReportTestUtil.h"
#include "TestMeshes.h"
#include "vv/meshio/MeshWriter.h"

namespace report_language_test {

namespace {

namespace fs = std::filesystem;
using vv::report::test::runTool;

fs::path freshDir(const std::string& name) {
    const fs::path dir =
        fs::path(VV_TEST_TMP) / "report-language" / (name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// The tube with "wss" (Pa) rising 0..10 along it, written to `dir`/tube.vtp.
fs::path writeTube(const fs::path& dir) {
    vv::scene::Mesh mesh = vv::test::tube(
        {.radius = 1.0F, .start = glm::vec3(0.0F), .length = 20.0F, .segments = 24, .rings = 20});
    vv::test::addAxialArray(mesh, "wss", "Pa", 0.0F, [](float x) { return 0.37F * x; });
    const fs::path file = dir / "tube.vtp";
    vv::meshio::writeVtp(mesh, file);
    return file;
}

/// Runs the CLI's report command on `input`; its exit code, output in `output`.
int runReport(const std::string& environment, const fs::path& input, const fs::path& pdf,
              const std::string& options, std::string& output) {
    return runTool(environment + " '" + std::string(VV_CLI_EXE) + "' report '" + input.string() +
                       "' -o '" + pdf.string() + "' " + options,
                   output);
}

using Word = vv::report::test::PdfWord;
using vv::report::test::pdfWords;

/// The report's text without the legends painted over the views (their
/// labels come from render::LegendPainter, not the report): the words
/// between each view's heading and its caption are left out. `views`: the
/// first word of each heading and of its caption, in the order of the pages.
std::string textOutsideTheViews(const std::vector<Word>& all,
                                const std::vector<std::pair<std::string, std::string>>& views) {
    struct Region {
        int page;
        double top;
        double bottom;
    };
    std::vector<Region> regions;
    std::size_t i = 0;
    for (const auto& [heading, caption] : views) {
        while (i < all.size() && all[i].text != heading) {
            ++i;
        }
        std::size_t j = i + 1;
        // The caption is below the image (not a word of the heading itself).
        while (j < all.size() && (all[j].text != caption ||
                                  (all[j].page == all[i].page && all[j].top <= all[i].bottom))) {
            ++j;
        }
        EXPECT_LT(j, all.size()) << heading << " / " << caption;
        if (j >= all.size()) {
            break;
        }
        regions.push_back({all[i].page, all[i].bottom, all[j].top});
        i = j + 1;
    }
    std::string text;
    for (const Word& w : all) {
        const bool inView = std::any_of(regions.begin(), regions.end(), [&w](const Region& r) {
            return w.page == r.page && w.top > r.top && w.bottom < r.bottom;
        });
        if (!inView) {
            text += w.text + " ";
        }
    }
    return text;
}

/// The report's strings: (English source, German translation) of the
/// context vv::report::ReportText in translations/vesselview_de.ts.
std::vector<std::pair<std::string, std::string>> reportStrings() {
    std::ifstream in(fs::path(VV_SOURCE_DIR) / "translations" / "vesselview_de.ts");
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string ts = buffer.str();
    const std::string name = "<name>vv::report::ReportText</name>";
    const auto start = ts.find(name);
    EXPECT_NE(start, std::string::npos) << "no report strings in vesselview_de.ts";
    const std::string context = ts.substr(start, ts.find("</context>", start) - start);
    std::vector<std::pair<std::string, std::string>> strings;
    const std::regex message(
        R"re(<source>([^<]*)</source>\s*(?:<extracomment>[^<]*</extracomment>\s*)?<translation>([^<]*)</translation>)re");
    const auto unescape = [](const std::string& s) {
        return QTextDocumentFragment::fromHtml(QString::fromStdString(s))
            .toPlainText()
            .toStdString();
    };
    for (auto it = std::sregex_iterator(context.begin(), context.end(), message);
         it != std::sregex_iterator(); ++it) {
        strings.emplace_back(unescape((*it)[1]), unescape((*it)[2]));
    }
    EXPECT_GT(strings.size(), 50U);
    return strings;
}

/// The pieces of `text` between its %1 placeholders, trimmed, with at least
/// three letters.
std::vector<std::string> fragments(const std::string& text) {
    std::vector<std::string> pieces;
    const std::regex placeholder("%[0-9]");
    for (auto it = std::sregex_token_iterator(text.begin(), text.end(), placeholder, -1);
         it != std::sregex_token_iterator(); ++it) {
        std::string piece = *it;
        const auto first = piece.find_first_not_of(" ,.():;<>\u2014");
        const auto last = piece.find_last_not_of(" ,.():;<>");
        if (first == std::string::npos) {
            continue;
        }
        piece = piece.substr(first, last - first + 1);
        if (std::count_if(piece.begin(), piece.end(),
                          [](unsigned char c) { return std::isalpha(c) != 0; }) >= 3) {
            pieces.push_back(piece);
        }
    }
    return pieces;
}

/// True when `piece` is in `text` as whole words (no letter right before or after).
bool containsWords(const std::string& text, const std::string& piece) {
    for (auto at = text.find(piece); at != std::string::npos; at = text.find(piece, at + 1)) {
        const auto letter = [&](std::size_t i) {
            return std::isalpha(static_cast<unsigned char>(text[i])) != 0 ||
                   static_cast<unsigned char>(text[i]) >= 0x80;
        };
        const bool before = at > 0 && letter(at - 1);
        const bool after = at + piece.size() < text.size() && letter(at + piece.size());
        if (!before && !after) {
            return true;
        }
    }
    return false;
}

/// The fragments of `strings`' first (or second) members that the other
/// language's strings do not hold too (e.g. "Min", "Void Space Surface").
std::vector<std::string> onlyIn(const std::vector<std::pair<std::string, std::string>>& strings,
                                bool english) {
    std::string other;
    for (const auto& [source, translation] : strings) {
        other += (english ? translation : source) + "\n";
    }
    std::vector<std::string> result;
    for (const auto& [source, translation] : strings) {
        if (source.find("yyyy") != std::string::npos) {
            continue;  // the date formats
        }
        for (const std::string& piece : fragments(english ? source : translation)) {
            if (!containsWords(other, piece)) {
                result.push_back(piece);
            }
        }
    }
    return result;
}

const std::string kPatient =
    "--patient-name 'Musterfrau^Erika' --patient-id P-4711 --birth-date 19640812 --sex F "
    "--study-date 20260301 --accession A-99 --referring-physician 'Huber^Hans'";

/// The text (outside the views' legends) of the tube's report in `language`:
/// both views, the statistics of 6 bins, the step solver, the patient.
std::string reportText(const std::string& language,
                       const std::vector<std::pair<std::string, std::string>>& views) {
    const fs::path dir = freshDir(language);
    const fs::path pdf = dir / "report.pdf";
    std::string output;
    EXPECT_EQ(runReport("", writeTube(dir), pdf,
                        "--lang " + language +
                            " --view far --second-view anterior --array wss --bins 6 "
                            "--solver step --note 'Stenose.' " +
                            kPatient,
                        output),
              0)
        << output;
    return textOutsideTheViews(pdfWords(pdf), views);
}

TEST(ReportLanguageTest, GermanReportHasNoEnglishAndNoDecimalPoint) {
    const std::string text = reportText("de", {{"Ansicht", "Fernansicht"}, {"Zweite", "Ansicht"}});
    const std::vector<std::string> englishOnly = onlyIn(reportStrings(), true);
    EXPECT_GT(englishOnly.size(), 60U);
    for (const std::string& english : englishOnly) {
        EXPECT_FALSE(containsWords(text, english)) << "English '" << english << "' in\n" << text;
    }
    // Numbers with the German decimal comma: no digit.digit left but the
    // version and the dates (dd.mm.yyyy).
    std::string numbers = std::regex_replace(text, std::regex(R"(VesselView \d+\.\d+\.\d+)"), "");
    numbers = std::regex_replace(numbers, std::regex(R"(\b\d{2}\.\d{2}\.\d{4}\b)"), "DATE");
    std::smatch decimal;
    EXPECT_FALSE(std::regex_search(numbers, decimal, std::regex(R"(\d\.\d)")))
        << "'" << decimal.str(0) << "' in\n"
        << text;
    EXPECT_NE(text.find(",0 %"), std::string::npos) << text;        // e.g. 100,0 %
    EXPECT_NE(text.find("12.08.1964"), std::string::npos) << text;  // the birth date
    EXPECT_NE(text.find("Nicht für diagnostische Zwecke."), std::string::npos) << text;
    // The parameter's colour map is the GUI's "Farbtabelle"; "Farbskala" is
    // the depth colour scale only ("Tiefen-Farbskala" in the settings).
    EXPECT_NE(text.find("Farbtabelle"), std::string::npos) << text;
    const auto count = [&text](const std::string& word) {
        std::size_t n = 0;
        for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
            ++n;
        }
        return n;
    };
    EXPECT_EQ(count("Farbskala"), count("Tiefen-Farbskala")) << text;
}

TEST(ReportLanguageTest, EnglishReportHasNoGerman) {
    const std::string text = reportText("en", {{"View", "Far"}, {"Second", "Anterior"}});
    for (const std::string& german : onlyIn(reportStrings(), false)) {
        EXPECT_FALSE(containsWords(text, german)) << "German '" << german << "' in\n" << text;
    }
    EXPECT_NE(text.find("1964-08-12"), std::string::npos) << text;
    EXPECT_NE(text.find("Not for diagnostic use."), std::string::npos) << text;
}

/// Page `page` of `pdf` as a grey image at `dpi`.
QImage pageImage(const fs::path& pdf, int page, int dpi) {
    const fs::path stem = pdf.parent_path() / (pdf.stem().string() + "-page");
    std::string output;
    EXPECT_EQ(runTool("pdftoppm -gray -png -singlefile -r " + std::to_string(dpi) + " -f " +
                          std::to_string(page) + " -l " + std::to_string(page) + " '" +
                          pdf.string() + "' '" + stem.string() + "'",
                      output),
              0)
        << output;
    return QImage(QString::fromStdString(stem.string() + ".png"));
}

/// Where the ink of `word` starts and ends on its page image (points):
/// a word cut at its cell's edge shows less than its box.
std::pair<double, double> inkSpan(const QImage& page, const Word& word, int dpi) {
    const double scale = dpi / 72.0;
    const int top = static_cast<int>(word.top * scale) + 1;
    const int bottom = static_cast<int>(word.bottom * scale) - 1;
    const int left = static_cast<int>((word.left - 3.0) * scale);
    const int right = static_cast<int>((word.right + 3.0) * scale);
    int first = right;
    int last = left;
    for (int x = std::max(left, 0); x < std::min(right, page.width()); ++x) {
        for (int y = std::max(top, 0); y < std::min(bottom, page.height()); ++y) {
            if (qGray(page.pixel(x, y)) < 170) {
                first = std::min(first, x);
                last = std::max(last, x);
            }
        }
    }
    return {first / scale, (last + 1) / scale};
}

/// The German statistics table shows its headers whole ("Abdeckung", not
/// "bdeckung"): in the page's pixels, every header word's ink fills its box
/// (a cut word loses its first letters to the cell's edge).
TEST(ReportLanguageTest, TheGermanStatisticsTableShowsEveryHeaderWhole) {
    const fs::path dir = freshDir("stats-de");
    const fs::path pdf = dir / "report.pdf";
    std::string output;
    ASSERT_EQ(runReport("", writeTube(dir), pdf, "--lang de --below 1 --above 3", output), 0)
        << output;
    const std::vector<Word> all = pdfWords(pdf);
    const auto object =
        std::find_if(all.begin(), all.end(), [](const Word& b) { return b.text == "Objekt"; });
    ASSERT_NE(object, all.end()) << "no statistics table";
    constexpr int kDpi = 200;
    const QImage page = pageImage(pdf, object->page, kDpi);
    ASSERT_FALSE(page.isNull());
    std::vector<std::string> headers;
    for (const Word& word : all) {
        const bool inHeader = word.page == object->page && word.left > object->right &&
                              word.top > object->top - 12.0 && word.bottom < object->bottom + 12.0;
        if (!inHeader || word.text.size() < 2) {
            continue;
        }
        headers.push_back(word.text);
        const auto [inkLeft, inkRight] = inkSpan(page, word, kDpi);
        EXPECT_LE(inkLeft, word.left + 1.5) << "'" << word.text << "' cut at its left";
        EXPECT_GE(inkRight, word.right - 1.5) << "'" << word.text << "' cut at its right";
    }
    for (const char* header : {"Abdeckung", "Min", "Mittelwert", "Max", "Fläche"}) {
        EXPECT_NE(std::find(headers.begin(), headers.end(), header), headers.end()) << header;
    }
}

/// The numbers under a legend's title word `title` (its first word) on page 1:
/// the labels of that legend, left to right.
std::vector<Word> legendLabels(const std::vector<Word>& all, const std::string& title) {
    const auto heading = std::find_if(
        all.begin(), all.end(), [&](const Word& b) { return b.page == 1 && b.text == title; });
    EXPECT_NE(heading, all.end()) << "no legend titled " << title;
    std::vector<Word> labels;
    if (heading == all.end()) {
        return labels;
    }
    const double line = heading->bottom - heading->top;
    static const std::regex number(R"(^[-−]?[0-9][0-9.,]*$)");
    for (const Word& b : all) {
        if (b.page == 1 && std::regex_match(b.text, number) && b.top > heading->bottom &&
            b.top < heading->bottom + 5.0 * line && b.left > heading->left - 2.0 &&
            b.right < heading->left + 200.0) {
            labels.push_back(b);
        }
    }
    std::sort(labels.begin(), labels.end(), [](const Word& a, const Word& b) {
        return a.top < b.top - 1.0 || (std::abs(a.top - b.top) <= 1.0 && a.left < b.left);
    });
    // The first row of numbers: the tick labels.
    std::vector<Word> row;
    for (const Word& b : labels) {
        if (row.empty() || std::abs(b.top - row.front().top) <= 1.0) {
            row.push_back(b);
        }
    }
    return row;
}

/// The legends in the PDF, in both languages: the depth legend titled in its
/// one wording, its ends shown, and no two tick labels closer than about two
/// digits (their text's height; the painter keeps 1.25 font sizes).
TEST(ReportLanguageTest, LegendLabelsInThePdfNeverCrowd) {
    for (const char* language : {"en", "de"}) {
        const fs::path dir = freshDir(std::string("legend-") + language);
        const fs::path pdf = dir / "report.pdf";
        std::string output;
        ASSERT_EQ(runReport("", writeTube(dir), pdf, std::string("--lang ") + language, output), 0)
            << output;
        const std::vector<Word> all = pdfWords(pdf);
        const bool german = std::string(language) == "de";
        std::string title;
        for (const Word& b : all) {
            if (b.page == 1) {
                title += b.text + " ";
            }
        }
        EXPECT_NE(title.find(german ? "Tiefe hinter dem vordersten Gefäß (mm)"
                                    : "Depth behind the frontmost vessel (mm)"),
                  std::string::npos)
            << title;
        for (const std::string& legend :
             {std::string(german ? "Tiefe" : "Depth"), std::string("wss")}) {
            const std::vector<Word> labels = legendLabels(all, legend);
            ASSERT_GE(labels.size(), 2U) << language << " " << legend;
            if (legend != "wss") {  // the depth from the frontmost vessel: 0 first
                EXPECT_TRUE(std::regex_match(labels.front().text, std::regex("0([.,]0+)?")))
                    << language << ": " << labels.front().text;
            }
            for (std::size_t i = 1; i < labels.size(); ++i) {
                const double height = labels[i].bottom - labels[i].top;
                EXPECT_GE(labels[i].left - labels[i - 1].right, 1.05 * height)
                    << language << " " << legend << ": '" << labels[i - 1].text << "' and '"
                    << labels[i].text << "' crowd";
            }
        }
    }
}

TEST(ReportLanguageTest, UnknownLanguageIsAUsageError) {
    const fs::path dir = freshDir("bad");
    const fs::path input = writeTube(dir);
    std::string output;
    EXPECT_EQ(runReport("", input, dir / "r.pdf", "--lang xx", output), 2) << output;
    EXPECT_NE(output.find("--lang must be one of en, de, got 'xx'"), std::string::npos) << output;
    EXPECT_FALSE(fs::exists(dir / "r.pdf"));
}

/// Where `words` start in `text` (npos when absent).
std::size_t position(const std::string& text, const std::string& words) {
    return text.find(words);
}

TEST(ReportLanguageTest, PatientForMeshesFindingsFirstNamesOnlyAndDisclaimer) {
    const fs::path dir = freshDir("sections");
    const fs::path input = writeTube(dir);
    const fs::path pdf = dir / "report.pdf";
    std::string output;
    ASSERT_EQ(runReport("", input, pdf,
                        "--view far --note 'Findings of the section test.' "
                        "--disclaimer 'Research use only, not validated.' " +
                            kPatient,
                        output),
              0)
        << output;
    std::string text;
    for (const Word& w : pdfWords(pdf)) {
        text += w.text + " ";
    }
    for (const char* expected :
         {"Musterfrau, Erika", "P-4711", "1964-08-12", "female", "2026-03-01", "A-99",
          "Huber, Hans", "Research use only, not validated.", "tube.vtp"}) {
        EXPECT_NE(text.find(expected), std::string::npos) << expected << " in\n" << text;
    }
    EXPECT_EQ(text.find("Not for diagnostic use."), std::string::npos) << text;
    // Findings right after the patient block, before the view and everything else.
    const std::size_t patient = position(text, "Patient and study");
    const std::size_t findings = position(text, "Findings of the section test.");
    const std::size_t view = position(text, "Far view");
    const std::size_t settings = position(text, "Rendering settings");
    ASSERT_NE(patient, std::string::npos) << text;
    ASSERT_NE(findings, std::string::npos) << text;
    EXPECT_LT(patient, findings);
    EXPECT_LT(findings, view);
    EXPECT_LT(findings, settings);
    // The file by name: no folder (build or home paths).
    EXPECT_EQ(text.find(dir.string()), std::string::npos) << text;
    EXPECT_EQ(text.find("report-language"), std::string::npos) << text;
    // Not the demo: no provenance line.
    EXPECT_EQ(text.find("Synthetic demo data"), std::string::npos) << text;

    // Bad patient values are usage errors.
    EXPECT_EQ(runReport("", input, dir / "bad.pdf", "--birth-date 1964-08-12", output), 2);
    EXPECT_NE(output.find("--birth-date must be a date as YYYYMMDD"), std::string::npos) << output;
    EXPECT_EQ(runReport("", input, dir / "bad.pdf", "--sex X", output), 2);
}

TEST(ReportLanguageTest, TheDemoIsNamedSyntheticData) {
    const fs::path dir = freshDir("demo");
    const fs::path input = writeTube(dir);
    const fs::path pdf = dir / "report.pdf";
    std::string output;
    // The bundled demo file as the app finds it (VV_DEMO_FILE, ResourcePaths.h).
    ASSERT_EQ(runReport("VV_DEMO_FILE='" + input.string() + "'", input, pdf, "", output), 0)
        << output;
    std::string text;
    for (const Word& w : pdfWords(pdf)) {
        text += w.text + " ";
    }
    EXPECT_NE(text.find("Synthetic demo data generated by VesselView: not patient data."),
              std::string::npos)
        << text;
}

TEST(ReportLanguageTest, TheSlicePageKeepsItsMarginsOnBothPapersInBothLanguages) {
    // `report DIR --slice`: the GUI's slice page from a DICOM series. Every
    // page of every report (with and without the slice) rasterised: nothing
    // crosses the margins or runs into the footer; the slice's heading,
    // image and caption on one page.
    const fs::path dir = freshDir("slice");
    auto cta = vv::test::writeTestCtaSeries(dir / "series");
    struct Case {
        std::string language;
        std::string paper;
        std::string slice;  ///< empty: no slice
        std::string heading;
        std::string plane;  ///< the caption's first word
    };
    const std::vector<Case> cases = {
        {"en", "a4", "coronal", "Slice", "Coronal"},
        {"de", "letter", "sagittal", "Schicht", "Sagittal"},
        {"de", "a4", "axial", "Schicht", "Axial"},
        {"en", "letter", "", "", ""},
        {"de", "a4", "", "", ""},
    };
    const int dpi = 60;
    for (const Case& c : cases) {
        const std::string name =
            c.language + "-" + c.paper + "-" + (c.slice.empty() ? "none" : c.slice);
        SCOPED_TRACE(name);
        const fs::path pdf = dir / (name + ".pdf");
        std::string output;
        ASSERT_EQ(runReport("", dir / "series", pdf,
                            "--lang " + c.language + " --paper " + c.paper +
                                " --second-view anterior --size 640x480 --triangles 20000" +
                                (c.slice.empty() ? std::string() : " --slice " + c.slice),
                            output),
                  0)
            << output;
        const std::vector<QImage> pages = vv::report::test::pdfPages(pdf, dir / name, dpi);
        for (std::size_t i = 0; i < pages.size(); ++i) {
            for (const std::string& problem : vv::report::test::marginProblems(pages[i], dpi)) {
                ADD_FAILURE() << "page " << i + 1 << ": " << problem;
            }
        }
        if (c.slice.empty()) {
            continue;
        }
        const std::vector<Word> all = pdfWords(pdf);
        const auto heading = std::find_if(all.begin(), all.end(),
                                          [&](const Word& w) { return w.text == c.heading; });
        ASSERT_NE(heading, all.end());
        // The caption: the plane's name below the heading.
        const auto caption = std::find_if(heading + 1, all.end(), [&](const Word& w) {
            // ("Sagittal," in German: "Sagittal, Schicht bei …")
            return w.text.rfind(c.plane, 0) == 0 &&
                   (w.page > heading->page || w.top > heading->bottom + 20);
        });
        ASSERT_NE(caption, all.end());
        EXPECT_EQ(caption->page, heading->page);
        // The caption names the window preset and the segmentation.
        std::string text;
        for (auto w = caption; w != all.end() && w->page == caption->page; ++w) {
            text += w->text + " ";
        }
        EXPECT_NE(text.find(c.language == "de" ? "Fenstervorgabe CTA" : "CTA preset"),
                  std::string::npos)
            << text;
        EXPECT_NE(text.find(c.language == "de" ? "Segmentierung" : "segmentation"),
                  std::string::npos)
            << text;
    }
    vv::test::removeTestCtaSeries(dir / "series", cta);
}

TEST(ReportLanguageTest, ASliceOfAMeshOrOutsideTheVolumeIsAUsageError) {
    const fs::path dir = freshDir("slice-errors");
    std::string output;
    EXPECT_EQ(runReport("", writeTube(dir), dir / "r.pdf", "--slice axial", output), 2);
    EXPECT_NE(output.find("--slice needs a DICOM image series"), std::string::npos) << output;
    EXPECT_FALSE(fs::exists(dir / "r.pdf"));
    EXPECT_EQ(runReport("", writeTube(dir), dir / "r.pdf", "--slice oblique", output), 2);
    EXPECT_NE(output.find("--slice must be axial, coronal or sagittal"), std::string::npos)
        << output;
    EXPECT_EQ(runReport("", writeTube(dir), dir / "r.pdf", "--slice axial@A12", output), 2);
    EXPECT_NE(output.find("lies along S/I"), std::string::npos) << output;
    auto cta = vv::test::writeTestCtaSeries(dir / "series");
    EXPECT_EQ(runReport("", dir / "series", dir / "r.pdf", "--slice axial@9000 --triangles 20000",
                        output),
              2);
    EXPECT_NE(output.find("lies outside the volume"), std::string::npos) << output;
    EXPECT_FALSE(fs::exists(dir / "r.pdf"));
    vv::test::removeTestCtaSeries(dir / "series", cta);
}

}  // namespace

}  // namespace report_language_test
