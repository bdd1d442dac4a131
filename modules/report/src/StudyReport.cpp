// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/StudyReport.h"

#include <QBuffer>
#include <QPdfWriter>
#include <algorithm>
#include <cmath>

#include "PdfFlow.h"
#include "ReportText.h"
#include "StudyCharts.h"
#include "vv/Version.h"

namespace vv::report {
namespace {

using pdf::Flow;
using pdf::font;
using pdf::mm;

constexpr double kChartHeightMm = 62.0;

QString pText(double p) {
    return p < 0.001 ? QStringLiteral("< ") + QLocale().toString(0.001, 'f', 3)
                     : QStringLiteral("= ") + QLocale().toString(p, 'f', 3);
}

/// A measure's value as read: a share as "92.5 %", a time as "1520 ms"
/// (no group separators, as every number of the reports), on one line
/// (a table cell never breaks it).
QString valueText(const study::MeasureResult& m, double v) {
    QString text = m.unit.empty() ? percent(v) : withUnit(integer(std::llround(v)), m.unit);
    return text.replace(QLatin1Char(' '), QChar(0x00a0));
}

/// "low – high", kept on one line (a table cell never wraps it).
QString rangeText(const study::MeasureResult& m, double low, double high) {
    return valueText(m, low) + QStringLiteral("\u00a0\u2013\u00a0") + valueText(m, high);
}

QString measureTitle(const study::MeasureResult& m) {
    return m.unit.empty() ? ReportText::tr("Accuracy") : ReportText::tr("Response time");
}

QStringList conditionNames(const study::StudyAnalysis& s) {
    QStringList names;
    for (const std::string& c : s.conditions) {
        names << qs(c);
    }
    return names;
}

void chart(Flow& flow, const study::StudyAnalysis& s, const study::MeasureResult& m) {
    const QRectF area(flow.left(), flow.y(), flow.width(), mm(kChartHeightMm));
    if (flow.drawing()) {
        QPainter& painter = flow.painter();
        if (m.unit.empty()) {
            std::vector<charts::Interval> values;
            for (const study::Summary& sum : m.perCondition) {
                values.push_back(
                    {std::max(0.0, sum.meanLow), sum.mean, std::min(1.0, sum.meanHigh)});
            }
            charts::Axis axis;
            axis.ticks = {0.0, 0.2, 0.4, 0.6, 0.8, 1.0};
            axis.label = [](double v) {  // whole per cent: the ticks are 20 % apart
                return integer(std::lround(100.0 * v)) + QStringLiteral("\u00a0%");
            };
            axis.title = ReportText::tr("Accuracy (mean, 95 % CI)");
            charts::errorBarChart(painter, area, conditionNames(s), values, axis, s.options.chance,
                                  ReportText::tr("chance level"));
        } else {
            std::vector<study::BoxStatistics> boxes;
            double high = 0.0;
            for (std::size_t c = 0; c < s.conditions.size(); ++c) {
                std::vector<double> column;
                for (const auto& row : m.table) {
                    column.push_back(row[c]);
                }
                boxes.push_back(study::boxStatistics(column));
                high = std::max(high, *std::ranges::max_element(column));
            }
            const charts::Axis axis = charts::axisFromZero(
                high, [](double v) { return integer(std::llround(v)); },
                ReportText::tr("Response time (ms)"));
            charts::boxPlotChart(painter, area, conditionNames(s), boxes, axis);
        }
    }
    flow.advance(mm(kChartHeightMm + 2.0));
}

pdf::Table conditionTable(const Flow& flow, const study::StudyAnalysis& s,
                          const study::MeasureResult& m) {
    const QStringList headers{ReportText::tr("Condition"), ReportText::tr("n"),
                              ReportText::tr("Mean"),      ReportText::tr("95 % CI"),
                              ReportText::tr("Median"),    ReportText::tr("Median CI"),
                              ReportText::tr("Rank sum")};
    std::vector<QStringList> rows;
    for (std::size_t c = 0; c < s.conditions.size(); ++c) {
        const study::Summary& sum = m.perCondition[c];
        rows.push_back({qs(s.conditions[c]), integer(static_cast<long long>(sum.count)),
                        valueText(m, sum.mean), rangeText(m, sum.meanLow, sum.meanHigh),
                        valueText(m, sum.median), rangeText(m, sum.medianLow, sum.medianHigh),
                        QLocale().toString(m.friedman.rankSums[c], 'f', 1)});
    }
    const QString note =
        ReportText::tr(
            "Per participant and condition: %1. Mean with its Student's t interval; "
            "median with the interval between two order statistics (it covers %2).")
            .arg(m.unit.empty() ? ReportText::tr("the share of correct answers")
                                : ReportText::tr("the median response time"),
                 m.perCondition.empty() ? QString() : percent(m.perCondition[0].medianConfidence));
    return {flow, headers, rows, note, QString()};
}

pdf::Table comparisonTable(const Flow& flow, const study::StudyAnalysis& s,
                           const study::MeasureResult& m) {
    const QStringList headers{ReportText::tr("Pair"), ReportText::tr("Rank-sum difference"),
                              ReportText::tr("Corrected p"), ReportText::tr("Significant")};
    std::vector<QStringList> rows;
    for (const study::PairComparison& pair : m.postHoc.pairs) {
        rows.push_back({qs(s.conditions[pair.first]) + QStringLiteral(" \u2013 ") +
                            qs(s.conditions[pair.second]),
                        QLocale().toString(pair.rankSumDifference, 'f', 1), pText(pair.adjustedP),
                        pair.significant ? ReportText::tr("yes") : ReportText::tr("no")});
    }
    const QString correction = m.postHoc.correction == study::Correction::Bonferroni
                                   ? ReportText::tr("Bonferroni")
                                   : ReportText::tr("Holm");
    const QString note =
        ReportText::tr(
            "Post-hoc comparisons of the conditions' rank sums (Siegel and Castellan), "
            "corrected by %1 at \u03b1 = %2; the critical difference of rank sums "
            "(Bonferroni) is %3.")
            .arg(correction, QLocale().toString(s.options.alpha, 'f', 2),
                 QLocale().toString(m.postHoc.criticalDifference, 'f', 2));
    return {flow, headers, rows, note, QString()};
}

QString friedmanText(const study::MeasureResult& m) {
    const study::FriedmanResult& f = m.friedman;
    return ReportText::tr("Friedman's test: \u03c7\u00b2(%1) = %2, p %3; Kendall's W = %4.")
        .arg(integer(f.degreesOfFreedom), QLocale().toString(f.chiSquared, 'f', 2), pText(f.pValue),
             QLocale().toString(f.kendallW, 'f', 2));
}

void measureSection(Flow& flow, const study::StudyAnalysis& s, const study::MeasureResult& m) {
    const QString friedman = friedmanText(m);
    flow.heading(measureTitle(m), mm(kChartHeightMm + 2.0) +
                                      flow.textHeight(friedman, font(9.5), flow.width()) + mm(2.0));
    chart(flow, s, m);
    flow.paragraph(friedman, font(9.5), pdf::kInk, mm(2.0));
    conditionTable(flow, s, m).draw(flow);
    flow.advance(mm(2.0));
    comparisonTable(flow, s, m).draw(flow);
}

pdf::Table participantTable(const Flow& flow, const study::StudyAnalysis& s) {
    const QStringList headers{ReportText::tr("Participant"), ReportText::tr("Answers"),
                              ReportText::tr("Correct"),     ReportText::tr("Median time"),
                              ReportText::tr("p (chance)"),  ReportText::tr("Included")};
    std::vector<QStringList> rows;
    for (const study::ParticipantResult& p : s.participants) {
        rows.push_back({qs(p.id), integer(static_cast<long long>(p.answers)), percent(p.accuracy),
                        withUnit(integer(std::llround(p.medianResponseMs)), "ms"),
                        QLocale().toString(p.chance.pValue, 'f', 3),
                        p.excluded ? ReportText::tr("no") : ReportText::tr("yes")});
    }
    return {flow, headers, rows, QString(), QString()};
}

QString exclusionText(const study::ParticipantResult& p) {
    if (!p.missingConditions.empty() && p.chance.aboveChance) {
        return ReportText::tr("%1: no answer in %2 condition(s), first %3")
            .arg(qs(p.id), integer(static_cast<long long>(p.missingConditions.size())),
                 qs(p.missingConditions.front()));
    }
    return ReportText::tr("%1: at chance level, %2 of %3 correct (p = %4)")
        .arg(qs(p.id), integer(static_cast<long long>(p.correct)),
             integer(static_cast<long long>(p.answers)),
             QLocale().toString(p.chance.pValue, 'f', 3));
}

void body(Flow& flow, const study::StudyAnalysis& s, const StudyReportContent& content,
          const QString& title, const QString& created) {
    flow.paragraph(title, font(16.0, true), pdf::kAccent, mm(1.0));
    flow.paragraph(created, font(8.5), pdf::kMuted, mm(4.0));

    pdf::Fields fields{
        {ReportText::tr("Participants"), integer(static_cast<long long>(s.participants.size()))},
        {ReportText::tr("Included"), integer(static_cast<long long>(s.included))},
        {ReportText::tr("Conditions"), conditionNames(s).join(QStringLiteral(", "))},
    };
    for (const std::string& source : content.sources) {
        fields.emplace_back(
            source == content.sources.front() ? ReportText::tr("Results files") : QString(),
            qs(source));
    }
    flow.heading(ReportText::tr("Participants"), pdf::fieldGridHeight(flow, fields, 1));
    pdf::fieldGrid(flow, fields, 1);
    flow.paragraph(
        ReportText::tr("A participant is excluded when their main-block answers are not above "
                       "chance (the one-sided exact binomial test against %1 gives p \u2265 %2), "
                       "or when they have no answer in some condition.")
            .arg(percent(s.options.chance), QLocale().toString(s.options.alpha, 'f', 2)),
        font(9.0), pdf::kInk, mm(1.0));
    for (const study::ParticipantResult& p : s.participants) {
        if (p.excluded) {
            flow.paragraph(ReportText::tr("Excluded \u2014 %1").arg(exclusionText(p)), font(9.0),
                           pdf::kWarning, mm(0.5));
        }
    }
    if (s.repeatedAnswers > 0) {
        flow.paragraph(ReportText::tr("%n answer(s) repeated a stimulus already answered (a "
                                      "resumed run): only the first counts.",
                                      nullptr, static_cast<int>(s.repeatedAnswers)),
                       font(9.0, false, true), pdf::kMuted, mm(0.5));
    }
    flow.advance(mm(2.0));
    measureSection(flow, s, s.accuracy);
    measureSection(flow, s, s.responseTime);
    const pdf::Table participants = participantTable(flow, s);
    flow.heading(ReportText::tr("Participants' answers (main block)"), participants.keepHeight());
    participants.draw(flow);
}

}  // namespace

QStringList studySummaryLines(const study::StudyAnalysis& s) {
    QStringList lines;
    lines << ReportText::tr("Participants") + QStringLiteral(": ") +
                 integer(static_cast<long long>(s.participants.size())) + QStringLiteral(", ") +
                 ReportText::tr("Included") + QStringLiteral(": ") +
                 integer(static_cast<long long>(s.included));
    for (const study::ParticipantResult& p : s.participants) {
        if (p.excluded) {
            lines << ReportText::tr("Excluded \u2014 %1").arg(exclusionText(p));
        }
    }
    for (const study::MeasureResult* m : {&s.accuracy, &s.responseTime}) {
        lines << measureTitle(*m) + QStringLiteral(": ") + friedmanText(*m);
        QStringList differing;
        for (const study::PairComparison& pair : m->postHoc.pairs) {
            if (pair.significant) {
                differing << qs(s.conditions[pair.first]) + QStringLiteral(" \u2013 ") +
                                 qs(s.conditions[pair.second]);
            }
        }
        lines << (differing.isEmpty()
                      ? ReportText::tr("No pair of conditions differs significantly.")
                      : ReportText::tr("Pairs that differ significantly: %1")
                            .arg(differing.join(QStringLiteral(", "))));
    }
    return lines;
}

QByteArray renderStudyPdf(const study::StudyAnalysis& analysis, const StudyReportContent& content,
                          PaperSize paper) {
    const QString title = ReportText::tr("Depth-judgement study");
    const QString created =
        formatDateTime(content.created) + QLatin1Char(' ') + content.created.timeZoneAbbreviation();
    const QString software = QStringLiteral("VesselView ") + QString::fromLatin1(vv::kVersion);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        pdf::setUpPage(writer, paper);
        writer.setTitle(title);
        writer.setCreator(software);
        pdf::paintPages(
            writer,
            software + QStringLiteral(" \u00b7 ") + title + QStringLiteral(" \u00b7 ") + created,
            [&](Flow& flow) { body(flow, analysis, content, title, created); });
    }
    buffer.close();
    return bytes;
}

void writeStudyPdf(const std::filesystem::path& path, const study::StudyAnalysis& analysis,
                   const StudyReportContent& content, PaperSize paper) {
    writePdfBytes(path, renderStudyPdf(analysis, content, paper));
}

}  // namespace vv::report
