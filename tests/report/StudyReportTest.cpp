// SPDX-License-Identifier: GPL-3.0-or-later
// The study report as a reader sees it: the charts' marks where their
// values say (painted into an image, read back pixel by pixel), and the PDF
// in English and German: every page within its margins, the numbers of the
// analysis in the language's format, the paper's critical difference.
#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QImage>
#include <QLocale>
#include <QPainter>
#include <QTranslator>
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "PdfFlow.h"
#include "ReportTestUtil.h"
#include "SimulatedResults.h"
#include "StudyCharts.h"
#include "vv/report/StudyReport.h"
#include "vv/study/Analysis.h"

namespace vv::report {
namespace {

class StudyReportTest : public ::testing::Test {
  protected:
    static void SetUpTestSuite() { test::ensureGuiApplication(); }
    void TearDown() override { QLocale::setDefault(QLocale::c()); }
};

bool isAccent(QRgb pixel) {
    const QColor c(pixel);
    return std::abs(c.red() - pdf::kAccent.red()) < 40 &&
           std::abs(c.green() - pdf::kAccent.green()) < 40 &&
           std::abs(c.blue() - pdf::kAccent.blue()) < 40;
}

/// The rows of column `x` of `image` that are the marks' colour.
std::vector<int> accentRows(const QImage& image, int x) {
    std::vector<int> rows;
    for (int y = 0; y < image.height(); ++y) {
        if (isAccent(image.pixel(x, y))) {
            rows.push_back(y);
        }
    }
    return rows;
}

QImage canvas() {
    QImage image(2400, 760, QImage::Format_RGB32);
    image.fill(Qt::white);
    return image;
}

TEST_F(StudyReportTest, TheErrorBarsSitWhereTheirValuesSay) {
    QImage image = canvas();
    const QRectF area(0.0, 0.0, image.width(), image.height());
    const std::vector<charts::Interval> values{{0.6, 0.7, 0.8}, {0.85, 0.9, 0.95}, {0.3, 0.5, 0.7}};
    charts::Axis axis;
    axis.ticks = {0.0, 0.5, 1.0};
    axis.label = [](double v) { return QString::number(v); };
    axis.title = QStringLiteral("Accuracy");
    {
        QPainter painter(&image);
        painter.setRenderHint(QPainter::Antialiasing);
        charts::errorBarChart(painter, area, {"A", "B", "C"}, values, axis, 0.5, "chance");
    }
    const QRectF plot = charts::plotRect(area);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const int x = static_cast<int>(std::lround(charts::xOf(plot, i, values.size())));
        const std::vector<int> rows = accentRows(image, x);
        ASSERT_FALSE(rows.empty()) << i;
        // The bar runs from the high to the low end (the caps' strokes are
        // 0.4 mm: 5 px at 300 dpi).
        EXPECT_NEAR(rows.front(), charts::yOf(plot, axis, values[i].high), 4.0) << i;
        EXPECT_NEAR(rows.back(), charts::yOf(plot, axis, values[i].low), 4.0) << i;
        // The dot at the mean, wider than the bar.
        const int beside = x + static_cast<int>(pdf::mm(0.8));
        const int mean = static_cast<int>(std::lround(charts::yOf(plot, axis, values[i].centre)));
        EXPECT_TRUE(isAccent(image.pixel(beside, mean))) << i;
        EXPECT_FALSE(isAccent(image.pixel(beside, mean + static_cast<int>(pdf::mm(2.0))))) << i;
    }
}

TEST_F(StudyReportTest, TheBoxesSitWhereTheirQuartilesSay) {
    QImage image = canvas();
    const QRectF area(0.0, 0.0, image.width(), image.height());
    std::vector<study::BoxStatistics> boxes(2);
    boxes[0] = {.lowerQuartile = 1200.0,
                .median = 1500.0,
                .upperQuartile = 1700.0,
                .lowerWhisker = 1000.0,
                .upperWhisker = 2100.0,
                .outliers = {2600.0}};
    boxes[1] = {.lowerQuartile = 400.0,
                .median = 600.0,
                .upperQuartile = 900.0,
                .lowerWhisker = 300.0,
                .upperWhisker = 1200.0,
                .outliers = {}};
    const charts::Axis axis = charts::axisFromZero(
        2600.0, [](double v) { return QString::number(v); }, "ms");
    EXPECT_GE(axis.max, 2600.0);
    {
        QPainter painter(&image);
        charts::boxPlotChart(painter, area, {"A", "B"}, boxes, axis);
    }
    const QRectF plot = charts::plotRect(area);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        // Inside the box (7 mm either side), off the whiskers and their caps
        // (3.5 mm): the box's top and bottom and the median across it.
        const int x = static_cast<int>(std::lround(charts::xOf(plot, i, 2) + pdf::mm(5.0)));
        std::vector<int> rows = accentRows(image, x);
        std::vector<double> marks;  // the centres of runs of accent rows
        for (std::size_t r = 0; r < rows.size();) {
            std::size_t e = r;
            while (e + 1 < rows.size() && rows[e + 1] == rows[e] + 1) {
                ++e;
            }
            marks.push_back(0.5 * (rows[r] + rows[e]));
            r = e + 1;
        }
        ASSERT_EQ(marks.size(), 3U) << i;
        EXPECT_NEAR(marks[0], charts::yOf(plot, axis, boxes[i].upperQuartile), 3.0) << i;
        EXPECT_NEAR(marks[1], charts::yOf(plot, axis, boxes[i].median), 3.0) << i;
        EXPECT_NEAR(marks[2], charts::yOf(plot, axis, boxes[i].lowerQuartile), 3.0) << i;
    }
}

/// 20 simulated participants, 5 conditions (the paper's design), one
/// guessing participant more.
study::StudyAnalysis paperSizedStudy() {
    const std::vector<std::string> conditions{"VSS-CD", "VSS-PCD", "vessel-CD", "vessel-PCD",
                                              "baseline"};
    const std::vector<double> accuracy{0.92, 0.9, 0.91, 0.93, 0.7};
    std::mt19937 random(34);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::vector<study::Answer> answers;
    for (int p = 1; p <= 21; ++p) {
        int trial = 0;
        for (std::size_t c = 0; c < conditions.size(); ++c) {
            for (int i = 0; i < 30; ++i) {
                study::Answer a;
                a.participant = "P" + std::to_string(p);
                a.trial = ++trial;
                a.stimulus = conditions[c] + "/" + std::to_string(i);
                a.condition = conditions[c];
                a.correctAnswer = i % 2 == 0 ? study::Side::Left : study::Side::Right;
                const double chance = p == 21 ? 0.5 : accuracy[c];
                a.answer = uniform(random) < chance               ? a.correctAnswer
                           : a.correctAnswer == study::Side::Left ? study::Side::Right
                                                                  : study::Side::Left;
                a.responseMs = (c >= 2 && c <= 3 ? 2100.0 : 1500.0) * (0.8 + 0.4 * uniform(random));
                answers.push_back(a);
            }
        }
    }
    return study::analyseStudy(answers);
}

bool hasWord(const std::vector<test::PdfWord>& words, const std::string& text) {
    return std::ranges::any_of(words, [&](const test::PdfWord& w) {
        return test::withoutLigatures(w.text) == text;  // "Treffsicherheit" has an ff ligature
    });
}

TEST_F(StudyReportTest, ThePdfInBothLanguagesKeepsItsMarginsAndItsNumbers) {
    const study::StudyAnalysis analysis = paperSizedStudy();
    ASSERT_EQ(analysis.included, 20U);
    for (const char* language : {"en", "de"}) {
        QTranslator translator;
        if (std::string(language) == "de") {
            ASSERT_TRUE(
                translator.load(QStringLiteral("vesselview_de"), QStringLiteral(VV_QM_DIR)));
            QCoreApplication::installTranslator(&translator);
        }
        QLocale::setDefault(QLocale(QString::fromLatin1(language)));
        const auto dir = test::testDir(std::string("study-") + language);
        const auto pdf = dir / "study.pdf";
        StudyReportContent content;
        content.sources = {"results.csv"};
        writeStudyPdf(pdf, analysis, content, PaperSize::A4);
        const std::vector<test::PdfWord> words = test::pdfWords(pdf);
        const QLocale locale;
        // The paper's critical difference, 20 participants and 5 conditions.
        EXPECT_TRUE(hasWord(words, locale.toString(28.07, 'f', 2).toStdString() + ".")) << language;
        // Each condition's mean accuracy as the language writes it.
        for (const study::Summary& s : analysis.accuracy.perCondition) {
            EXPECT_TRUE(hasWord(words, locale.toString(100.0 * s.mean, 'f', 1).toStdString()))
                << language << " " << s.mean;
        }
        EXPECT_TRUE(hasWord(words, std::string(language) == "de" ? "Treffsicherheit" : "Accuracy"))
            << language;
        EXPECT_TRUE(hasWord(words, "P21")) << language;  // the excluded guesser, named
        // Each interval on one line of its cell: its two ends side by side
        // (a cell wrapped onto a second line runs over the next row).
        for (const study::Summary& s : analysis.accuracy.perCondition) {
            const std::string low = locale.toString(100.0 * s.meanLow, 'f', 1).toStdString();
            const std::string high = locale.toString(100.0 * s.meanHigh, 'f', 1).toStdString();
            bool sideBySide = false;
            for (const test::PdfWord& a : words) {
                for (const test::PdfWord& b : words) {
                    sideBySide =
                        sideBySide || (a.text == low && b.text == high && a.page == b.page &&
                                       std::abs(a.top - b.top) < 1.0 && b.left > a.left);
                }
            }
            EXPECT_TRUE(sideBySide) << language << ": " << low << " - " << high;
        }
        const std::vector<QImage> pages = test::pdfPages(pdf, dir, 100);
        ASSERT_GE(pages.size(), 2U);
        for (std::size_t i = 0; i < pages.size(); ++i) {
            for (const std::string& problem : test::marginProblems(pages[i], 100)) {
                ADD_FAILURE() << language << " page " << i + 1 << ": " << problem;
            }
        }
        QCoreApplication::removeTranslator(&translator);
    }
}

// A table kept whole (it fits on a page) takes its heading along: 13
// participants in 3 conditions put the participants' table on a new page,
// where its heading was left behind on the page before.
TEST_F(StudyReportTest, AHeadingStaysWithItsTable) {
    const auto dir = test::testDir("study-heading");
    study::test::writeSimulatedResults(dir / "results.csv", 1, 12, true);
    const study::StudyAnalysis analysis =
        study::analyseStudy(study::readResults(dir / "results.csv"));
    const auto pdf = dir / "study.pdf";
    writeStudyPdf(pdf, analysis, {}, PaperSize::A4);
    const std::vector<test::PdfWord> words = test::pdfWords(pdf);
    const auto heading =
        std::find_if(words.begin(), words.end(), [](const auto& w) { return w.text == "block)"; });
    const auto lastRow = std::find_if(words.rbegin(), words.rend(),
                                      [](const auto& w) { return w.text == "guesser"; });
    ASSERT_NE(heading, words.end());
    ASSERT_NE(lastRow, words.rend());
    EXPECT_EQ(heading->page, lastRow->page);
    EXPECT_GT(lastRow->top, heading->top);
}

}  // namespace
}  // namespace vv::report
