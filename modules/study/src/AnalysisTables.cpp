// SPDX-License-Identifier: GPL-3.0-or-later
#include <sstream>

#include "vv/core/AtomicFile.h"
#include "vv/core/CsvField.h"
#include "vv/core/NumberText.h"
#include "vv/study/Analysis.h"

namespace vv::study {
namespace {

std::string number(double value) {
    return significantText(value, 6);
}

std::string unitSuffix(const MeasureResult& m) {
    return m.unit.empty() ? std::string() : " [" + m.unit + "]";
}

std::string conditionsTable(const StudyAnalysis& study) {
    std::ostringstream t;
    t << "measure,condition,n,mean,mean_ci95_low,mean_ci95_high,sd,median,median_ci_low,"
         "median_ci_high,median_ci_coverage,rank_sum\n";
    for (const MeasureResult* m : {&study.accuracy, &study.responseTime}) {
        for (std::size_t c = 0; c < study.conditions.size(); ++c) {
            const Summary& s = m->perCondition[c];
            t << csvField(m->name + unitSuffix(*m)) << ',' << csvField(study.conditions[c]) << ','
              << s.count << ',' << number(s.mean) << ',' << number(s.meanLow) << ','
              << number(s.meanHigh) << ',' << number(s.standardDeviation) << ',' << number(s.median)
              << ',' << number(s.medianLow) << ',' << number(s.medianHigh) << ','
              << number(s.medianConfidence) << ',' << number(m->friedman.rankSums[c]) << '\n';
        }
    }
    return t.str();
}

std::string comparisonsTable(const StudyAnalysis& study) {
    std::ostringstream t;
    t << "measure,test,first,second,statistic,df,p,adjusted_p,critical_difference,significant,"
         "correction\n";
    for (const MeasureResult* m : {&study.accuracy, &study.responseTime}) {
        const FriedmanResult& f = m->friedman;
        t << csvField(m->name) << ",Friedman,,," << number(f.chiSquared) << ','
          << f.degreesOfFreedom << ',' << number(f.pValue) << ",,,"
          << (f.pValue < study.options.alpha ? "yes" : "no") << ",\n";
        t << csvField(m->name) << ",Kendall's W,,," << number(f.kendallW) << ",,,,,,\n";
        for (const PairComparison& pair : m->postHoc.pairs) {
            t << csvField(m->name) << ",rank-sum difference,"
              << csvField(study.conditions[pair.first]) << ','
              << csvField(study.conditions[pair.second]) << ',' << number(pair.rankSumDifference)
              << ",," << number(pair.pValue) << ',' << number(pair.adjustedP) << ','
              << number(m->postHoc.criticalDifference) << ',' << (pair.significant ? "yes" : "no")
              << ',' << correctionName(m->postHoc.correction) << '\n';
        }
    }
    return t.str();
}

std::string participantsTable(const StudyAnalysis& study) {
    std::ostringstream t;
    t << "participant,answers,correct,accuracy,median_response [ms],chance_p,excluded,reason\n";
    for (const ParticipantResult& p : study.participants) {
        t << csvField(p.id) << ',' << p.answers << ',' << p.correct << ',' << number(p.accuracy)
          << ',' << number(p.medianResponseMs) << ',' << number(p.chance.pValue) << ','
          << (p.excluded ? "yes" : "no") << ',' << csvField(p.exclusionReason) << '\n';
    }
    return t.str();
}

}  // namespace

void writeAnalysisTables(const StudyAnalysis& study, const std::filesystem::path& folder) {
    writeFileAtomically(folder / "conditions.csv", conditionsTable(study));
    writeFileAtomically(folder / "comparisons.csv", comparisonsTable(study));
    writeFileAtomically(folder / "participants.csv", participantsTable(study));
}

}  // namespace vv::study
