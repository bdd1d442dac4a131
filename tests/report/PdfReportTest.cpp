// SPDX-License-Identifier: GPL-3.0-or-later
// The PDF report: content, paper sizes, what is left out, atomic writing.
// Reads the text back with pdftotext (poppler-utils, scripts/setup-deps).
#include <gtest/gtest.h>

#include <QPainter>
#include <QTimeZone>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "ReportTestUtil.h"
#include "vv/core/Error.h"
#include "vv/report/PdfReport.h"

namespace vv::report {
namespace {

namespace fs = std::filesystem;

class PdfReportTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { test::ensureGuiApplication(); }

    static ReportContent content(PaperSize paper) {
        ReportContent c;
        c.title = "Carotid study";
        c.sources = {"/data/case-17/vessels.vtp"};
        const int width = reportImageWidth(paper);
        c.view.image = test::testImage(width, width * 3 / 4);
        c.view.caption = "Far view";
        c.view.legends.depth =
            render::DepthLegend{colormaps::DepthScale::Chromadepth, 10.0, 52.0, "mm"};
        c.settings.errorBound = 0.5 / 255.0;
        c.settings.view = "far";
        c.findings = "Low wall shear stress at the distal bifurcation.";
        c.created = QDateTime(QDate(2026, 3, 4), QTime(9, 30), QTimeZone::utc());
        return c;
    }

    static void addParameter(ReportContent& c) {
        ReportParameter p;
        p.name = "wss";
        p.unit = "Pa";
        p.range = {0.25F, 3.5F};
        p.thresholds.below = 0.4;
        ParameterStats s;
        s.object = "left ICA";
        s.triangles = 100;
        s.area = 12.0;
        s.coveredFraction = 1.0;
        s.min = 0.125;
        s.mean = 1.5;
        s.max = 3.25;
        s.fractionBelow = 0.0625;
        p.stats = {s, s};
        p.stats[1].object = "right ICA";
        c.view.legends.parameter = render::ParameterLegend{
            "wss", "Pa", 0.25F, 3.5F, colormaps::ColorMap::Viridis, 0, {}, {}};
        c.parameter = p;
    }

    /// This process's folder of the PDFs text() writes.
    static const fs::path& dir() {
        static const fs::path folder = test::testDir("pdf-text");
        return folder;
    }

    /// The PDF's text (pdftotext -layout), written as dir()/name.pdf first.
    static std::string text(const QByteArray& pdf, const std::string& name) {
        const fs::path file = dir() / (name + ".pdf");
        {
            std::ofstream out(file, std::ios::binary);
            out.write(pdf.constData(), pdf.size());
        }
        std::string output;
        EXPECT_EQ(test::runTool("pdftotext -layout '" + file.string() + "' -", output), 0)
            << "pdftotext (poppler-utils) missing? run scripts/setup-deps: " << output;
        return output;
    }
};

TEST_F(PdfReportTest, A4ReportHoldsEverySection) {
    ReportContent c = content(PaperSize::A4);
    addParameter(c);
    ReportPatient patient;
    patient.name = "Doe^Jane";
    patient.id = "PID-0042";
    patient.birthDate = "19600215";
    patient.sex = "F";
    patient.studyDate = "20260301";
    patient.accession = "ACC-9";
    patient.referringPhysician = "Smith^John";
    c.patient = patient;
    const QByteArray pdf = renderPdf(c, PaperSize::A4);
    ASSERT_TRUE(pdf.startsWith("%PDF-"));
    EXPECT_TRUE(pdf.contains("/MediaBox [0 0 595.000000 842.000000]"));  // A4 in points
    const std::string t = text(pdf, "a4");
    for (const char* expected : {"Carotid study",
                                 "VesselView",
                                 "2026-03-04 09:30",
                                 "Patient and study",
                                 "Doe, Jane",
                                 "PID-0042",
                                 "1960-02-15",
                                 "ACC-9",
                                 "Smith, John",
                                 "vessels.vtp",
                                 "Parameter statistics",
                                 "left ICA",
                                 "right ICA",
                                 "0.125",
                                 "1.50",
                                 "3.25",
                                 "6.3 %",
                                 "Area <",
                                 "0.4",
                                 "over 0.25 \u2013 3.50",  // as the legend: one precision
                                 "Rendering settings",
                                 "Chromadepth",
                                 "Findings",
                                 "Low wall shear stress at the distal bifurcation.",
                                 "Page 1 of"}) {
        EXPECT_NE(t.find(expected), std::string::npos) << "missing '" << expected << "' in\n" << t;
    }
    // Source files by name only: no folder (home or build paths).
    EXPECT_EQ(t.find("/data/case-17"), std::string::npos) << t;
    // The default disclaimer under the title; the findings before the view.
    EXPECT_NE(t.find("Not for diagnostic use."), std::string::npos) << t;
    EXPECT_LT(t.find("Low wall shear stress"), t.find("Far view")) << t;
    EXPECT_LT(t.find("Not for diagnostic use."), t.find("Patient and study")) << t;
}

TEST_F(PdfReportTest, AnonymisedPatientShowsNoIdentifiers) {
    ReportContent c = content(PaperSize::A4);
    ReportPatient patient;
    patient.name = "Quillfeatherby^Zenobiaxa";
    patient.id = "PID-7Q4X-9KZ2";
    patient.anonymise = true;
    c.patient = patient;
    // Patient data folders are often named after the patient.
    c.sources = {"/data/Quillfeatherby_Zenobiaxa_PID-7Q4X-9KZ2/CTA/IM0001.dcm",
                 "/data/Quillfeatherby_Zenobiaxa_PID-7Q4X-9KZ2/CTA/IM0002.dcm"};
    const std::string t = text(renderPdf(c, PaperSize::A4), "anonymised");
    // Values that cannot occur by chance, searched in the decompressed text.
    for (const char* identifying : {"Quillfeatherby", "Zenobiaxa", "PID-7Q4X-9KZ2"}) {
        EXPECT_EQ(t.find(identifying), std::string::npos) << identifying << " in\n" << t;
    }
    EXPECT_EQ(t.find("IM0001"), std::string::npos) << t;
    EXPECT_NE(t.find("anonymised"), std::string::npos);
    EXPECT_NE(t.find("2 (names withheld"), std::string::npos) << t;

    c.patient->anonymise = false;  // not anonymised: the files are listed
    const std::string shown = text(renderPdf(c, PaperSize::A4), "identified");
    EXPECT_NE(shown.find("IM0001.dcm"), std::string::npos) << shown;
}

/// The footer line of the first page: the one with "Page 1 of".
std::string footerOf(const std::string& text) {
    const auto at = text.find("Page 1 of");
    if (at == std::string::npos) {
        return {};
    }
    const auto start = text.rfind('\n', at);
    return text.substr(start == std::string::npos ? 0 : start + 1, text.find('\n', at) - start);
}

TEST_F(PdfReportTest, FooterLeavesOutAPatientFieldNotGiven) {
    ReportContent c = content(PaperSize::A4);
    ReportPatient patient;
    patient.name = "Doe^Jane";
    c.patient = patient;
    std::string t = text(renderPdf(c, PaperSize::A4), "footer-name");
    std::string footer = footerOf(t);
    EXPECT_NE(footer.find("Carotid study \u00b7 2026-03-04 09:30 UTC \u00b7 Doe, Jane"),
              std::string::npos)
        << footer;
    EXPECT_EQ(footer.find("ID"), std::string::npos) << footer;
    // The patient block keeps its fields, the missing ID as "—".
    EXPECT_NE(t.find("Patient ID"), std::string::npos) << t;
    EXPECT_NE(t.find("\u2014"), std::string::npos) << t;

    c.patient->name.clear();
    c.patient->id = "PID-0042";
    footer = footerOf(text(renderPdf(c, PaperSize::A4), "footer-id"));
    EXPECT_NE(footer.find("UTC \u00b7 ID PID-0042"), std::string::npos) << footer;
    EXPECT_EQ(footer.find("\u2014"), std::string::npos) << footer;

    c.patient->id.clear();  // neither: no patient in the footer
    footer = footerOf(text(renderPdf(c, PaperSize::A4), "footer-none"));
    EXPECT_NE(footer.find("09:30 UTC"), std::string::npos) << footer;
    EXPECT_EQ(footer.find("\u2014"), std::string::npos) << footer;
    EXPECT_EQ(footer.find("UTC \u00b7"), std::string::npos) << footer;

    // Anonymised: both fields say so, even when empty.
    c.patient->anonymise = true;
    footer = footerOf(text(renderPdf(c, PaperSize::A4), "footer-anonymised"));
    EXPECT_NE(footer.find("anonymised, ID anonymised"), std::string::npos) << footer;
}

TEST_F(PdfReportTest, LetterWithoutPatientOrParameterLeavesThemOut) {
    const ReportContent c = content(PaperSize::Letter);
    const QByteArray pdf = renderPdf(c, PaperSize::Letter);
    EXPECT_TRUE(pdf.contains("/MediaBox [0 0 612.000000 792.000000]"));  // Letter in points
    const std::string t = text(pdf, "letter");
    EXPECT_EQ(t.find("Patient"), std::string::npos);
    EXPECT_EQ(t.find("Parameter statistics"), std::string::npos);
    EXPECT_NE(t.find("Rendering settings"), std::string::npos);
    EXPECT_NE(t.find("Depth behind the"), std::string::npos);  // the legend
}

TEST_F(PdfReportTest, TablesAreNeverSplitAcrossPages) {
    // Findings of growing length push the tables down over the page break:
    // whatever the length, each table's rows share one page.
    ReportContent c = content(PaperSize::A4);
    addParameter(c);
    ReportParameter& p = *c.parameter;
    p.stats.resize(6, p.stats.front());
    for (std::size_t i = 0; i < p.stats.size(); ++i) {
        p.stats[i].object = "segment-" + std::to_string(i + 1);
    }
    c.settings.vss.enabled = true;
    const std::vector<std::string> settings = {"Void Space Surface",    "Depth colour scale",
                                               "Interpolation power p", "Iso-lines",
                                               "Ambient occlusion",     "Camera"};
    int splitsTried = 0;
    for (int lines = 0; lines <= 60; lines += 4) {
        c.findings.clear();
        for (int i = 0; i < lines; ++i) {
            c.findings += "Finding line " + std::to_string(i + 1) + ".\n";
        }
        const std::string name = "tables-" + std::to_string(lines);
        (void)text(renderPdf(c, PaperSize::A4), name);  // writes dir()/name.pdf
        std::vector<std::string> pages;
        for (int page = 1; page <= 3; ++page) {
            std::string out;
            test::runTool("pdftotext -f " + std::to_string(page) + " -l " + std::to_string(page) +
                              " '" + (dir() / (name + ".pdf")).string() + "' -",
                          out);
            pages.push_back(out);
        }
        const auto pageOf = [&](const std::string& needle) {
            int found = 0;
            for (std::size_t i = 0; i < pages.size(); ++i) {
                if (pages[i].find(needle) != std::string::npos) {
                    found = static_cast<int>(i) + 1;
                }
            }
            return found;
        };
        SCOPED_TRACE("findings of " + std::to_string(lines) + " lines");
        const int table = pageOf("segment-1");
        ASSERT_GT(table, 0);
        for (const auto& s : p.stats) {
            EXPECT_EQ(pageOf(s.object), table) << s.object;
        }
        EXPECT_EQ(pageOf("Coverage: share"), table);  // the note stays with the table
        const int grid = pageOf(settings.front());
        for (const std::string& label : settings) {
            EXPECT_EQ(pageOf(label), grid) << label;
        }
        splitsTried += table > 1 ? 1 : 0;
    }
    EXPECT_GT(splitsTried, 0);  // some lengths moved the table to the next page
}

/// A slice as the report gets it: black around a grey disc, `width` x `height`.
QImage sliceImage(int width, int height) {
    QImage image(width, height, QImage::Format_RGB32);
    image.fill(Qt::black);
    QPainter painter(&image);
    painter.setBrush(QColor(160, 160, 160));
    painter.drawEllipse(QRectF(width * 0.25, height * 0.25, width * 0.5, height * 0.5));
    return image;
}

TEST_F(PdfReportTest, EveryPageKeepsItsMarginsAndTheSliceStaysWithItsHeading) {
    // Both papers; no slice, and slices of every shape (a tall one is taller
    // than a page at the content width); a portrait view too.
    const std::vector<std::pair<std::string, QSize>> slices = {
        {"none", {}}, {"tall", {2400, 3800}}, {"square", {2400, 2400}}, {"wide", {2400, 1200}}};
    const int dpi = 60;
    for (const PaperSize paper : {PaperSize::A4, PaperSize::Letter}) {
        for (const auto& [shape, size] : slices) {
            for (const bool portraitView : {false, true}) {
                const std::string name = std::string(paper == PaperSize::A4 ? "a4" : "letter") +
                                         "-" + shape + (portraitView ? "-portrait" : "");
                SCOPED_TRACE(name);
                ReportContent c = content(paper);
                addParameter(c);
                const int width = reportImageWidth(paper);
                if (portraitView) {
                    c.view.image = test::testImage(width, width * 16 / 9);
                }
                c.secondView = c.view;
                c.secondView->caption = "Anterior view";
                if (!size.isEmpty()) {
                    c.slice = ReportView{sliceImage(size.width(), size.height()),
                                         "Coronal slice at P 12.0 mm, window W 600 HU L 300 HU "
                                         "(CTA preset). Coloured fill and outline: the "
                                         "segmentation.",
                                         {}};
                }
                (void)text(renderPdf(c, paper), name);  // writes dir()/name.pdf
                const fs::path pdf = dir() / (name + ".pdf");
                const std::vector<QImage> pages = test::pdfPages(pdf, dir() / name, dpi);
                for (std::size_t i = 0; i < pages.size(); ++i) {
                    for (const std::string& problem : test::marginProblems(pages[i], dpi)) {
                        ADD_FAILURE() << "page " << i + 1 << ": " << problem;
                    }
                }
                if (size.isEmpty()) {
                    continue;
                }
                // The heading, the whole slice and its caption on one page.
                const auto words = test::pdfWords(pdf);
                const auto find = [&words](const std::string& word) {
                    return std::find_if(words.begin(), words.end(),
                                        [&](const test::PdfWord& w) { return w.text == word; });
                };
                const auto heading = find("Slice");
                const auto caption = find("Coronal");
                ASSERT_NE(heading, words.end());
                ASSERT_NE(caption, words.end());
                EXPECT_EQ(heading->page, caption->page);
                ASSERT_LE(static_cast<std::size_t>(heading->page), pages.size());
                // Between them the slice: its black fills most of that band.
                const QImage& page = pages[static_cast<std::size_t>(heading->page) - 1];
                const double scale = dpi / 72.0;
                const int top = static_cast<int>(heading->bottom * scale) + 2;
                const int bottom = static_cast<int>(caption->top * scale) - 2;
                EXPECT_GT(bottom - top, 40.0 / 25.4 * dpi) << "no room for the slice";
                int black = 0;
                for (int y = top; y < bottom; ++y) {
                    for (int x = 0; x < page.width(); ++x) {
                        black += qGray(page.pixel(x, y)) < 20 ? 1 : 0;
                    }
                }
                // The disc covers pi/16 of the slice; the rest of it is black.
                const double sliceShare = 1.0 - std::numbers::pi / 16.0;
                const double aspect = static_cast<double>(size.height()) / size.width();
                const double drawnHeight = bottom - top;
                const double drawnWidth =
                    std::min(drawnHeight / aspect, page.width() - 2.0 * 18.0 / 25.4 * dpi);
                EXPECT_GT(black, 0.85 * sliceShare * drawnWidth * drawnWidth * aspect)
                    << "the slice is cut";
            }
        }
    }
}

TEST_F(PdfReportTest, RefusesViewsBelowPrintResolution) {
    ReportContent c = content(PaperSize::A4);
    c.view.image = test::testImage(800, 600);
    EXPECT_THROW((void)renderPdf(c, PaperSize::A4), InvalidArgumentError);
    EXPECT_GE(reportImageWidth(PaperSize::A4), 2000);  // 174 mm at 300 dpi
    EXPECT_GT(reportImageWidth(PaperSize::Letter), reportImageWidth(PaperSize::A4));
    EXPECT_EQ(paperSizeFromName("Letter"), PaperSize::Letter);
    EXPECT_FALSE(paperSizeFromName("a5"));
}

TEST_F(PdfReportTest, FailedWriteLeavesNoFileAndKeepsTheOldOne) {
    const fs::path dir = test::testDir("pdf-atomic");
    // The parent is a regular file: nothing can be created.
    const fs::path blocker = dir / "not-a-folder";
    std::ofstream(blocker) << "x";
    EXPECT_THROW(writePdf(blocker / "r.pdf", content(PaperSize::A4), PaperSize::A4), IoError);
    // The target is a folder: the rename fails, the folder is untouched and
    // no temporary file remains.
    const fs::path occupied = dir / "occupied.pdf";
    fs::create_directories(occupied);
    std::ofstream(occupied / "keep") << "keep";
    EXPECT_THROW(writePdf(occupied, content(PaperSize::A4), PaperSize::A4), IoError);
    EXPECT_TRUE(fs::exists(occupied / "keep"));
    EXPECT_EQ(test::listing(dir), "not-a-folder occupied.pdf ");
    // An invalid report does not replace an existing one.
    const fs::path existing = dir / "existing.pdf";
    std::ofstream(existing) << "old";
    ReportContent bad = content(PaperSize::A4);
    bad.view.image = QImage();
    EXPECT_THROW(writePdf(existing, bad, PaperSize::A4), InvalidArgumentError);
    std::ifstream in(existing);
    std::stringstream old;
    old << in.rdbuf();
    EXPECT_EQ(old.str(), "old");
    // And a good one does.
    writePdf(existing, content(PaperSize::A4), PaperSize::A4);
    EXPECT_GT(fs::file_size(existing), 10000U);
}

}  // namespace
}  // namespace vv::report
