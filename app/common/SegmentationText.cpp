// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SegmentationText.h"

#include <QCoreApplication>
#include <QLocale>
#include <string_view>

namespace vv::app {

namespace {

constexpr const char* kContext = "vv::app::SegmentationText";

QString tr(const char* text, int n = -1) {
    return QCoreApplication::translate(kContext, text, nullptr, n);
}

QString towards(segmentation::PatientDirection direction) {
    switch (direction) {
        case segmentation::PatientDirection::Superior:
            return tr("towards the head");
        case segmentation::PatientDirection::Inferior:
            return tr("towards the feet");
        case segmentation::PatientDirection::Left:
            return tr("to the patient's left");
        case segmentation::PatientDirection::Right:
            return tr("to the patient's right");
        case segmentation::PatientDirection::Anterior:
            return tr("anteriorly");
        case segmentation::PatientDirection::Posterior:
            return tr("posteriorly");
    }
    return {};
}

QString onOff(bool on) {
    return on ? tr("on") : tr("off");
}

}  // namespace

QString cutOffText(const std::vector<segmentation::CutOffVessel>& vessels) {
    if (vessels.empty()) {
        return {};
    }
    const segmentation::CutOffVessel& first = vessels.front();
    const QLocale locale;
    const auto mm = [&locale](double v) { return locale.toString(v, 'f', 0); };
    QString text = tr("The vessel may be cut off: a bright tube continues %1 mm %2 past the "
                      "segmentation's end at (%3, %4, %5) mm, where the signal may fade.")
                       .arg(mm(first.lengthMm),
                            towards(segmentation::dominantDirection(first.farEnd - first.end)),
                            mm(first.end.x), mm(first.end.y), mm(first.end.z));
    if (vessels.size() > 1) {
        text +=
            QStringLiteral(" ") + tr("%n more such end(s).", static_cast<int>(vessels.size() - 1));
    }
    return text;
}

QString thresholdRuleName(const segmentation::ThresholdRange& range) {
    // The rules' stable beginnings (segmentation::defaultThresholdRange() and the front ends).
    const std::string_view rule = range.rule;
    if (rule.starts_with("CT angiography default")) {
        return tr("CT angiography default");
    }
    if (rule.starts_with("histogram")) {
        return tr("from the histogram (Otsu)");
    }
    if (rule.starts_with("constant volume")) {
        return tr("the volume's only value");
    }
    if (rule.starts_with("chosen in the Segmentation panel")) {
        return tr("chosen in the Segmentation panel");
    }
    if (rule.starts_with("chosen in the series dialog")) {
        return tr("chosen in the series dialog");
    }
    if (rule.starts_with("saved in the session")) {
        return tr("saved in the session");
    }
    if (rule.starts_with("given on the command line")) {
        return tr("given on the command line");
    }
    return QString::fromStdString(range.rule);
}

report::ReportSegmentation reportSegmentation(const SegmentationProvenance& p) {
    report::ReportSegmentation section;
    const auto add = [&section](const QString& label, const QString& value) {
        section.settings.emplace_back(label.toStdString(), value.toStdString());
    };
    if (!p.segmentNames.empty()) {
        add(tr("Segments"), QString::fromStdString(segmentsText(p)));
        return section;
    }
    const QLocale locale;
    const auto value = [&locale](float v) {
        return locale.toString(static_cast<double>(v), 'g', 4);
    };
    const QString unit =
        p.unit.empty() ? QString() : QStringLiteral(" ") + QString::fromStdString(p.unit);
    add(tr("Threshold"),
        tr("%1 to %2%3 (%4)")
            .arg(value(p.range.lower), value(p.range.upper), unit, thresholdRuleName(p.range)));
    const bool ct = p.modality == "CT" || p.unit == "HU";
    if (!ct) {
        add(tr("Intensity correction"),
            p.intensityCorrected ? tr("on (MR signal fall-off divided out; gain %1 to %2)")
                                       .arg(locale.toString(p.gainLowest, 'f', 2),
                                            locale.toString(p.gainHighest, 'f', 2))
                                 : onOff(false));
    }
    const QString which =
        p.seed ? tr("the one under voxel (%1, %2, %3)").arg(p.seed->x).arg(p.seed->y).arg(p.seed->z)
               : tr("the %n largest", p.keepComponents);
    add(tr("Components"), tr("%1: kept %2 of %3")
                              .arg(which)
                              .arg(locale.toString(static_cast<qulonglong>(p.componentsKept)))
                              .arg(locale.toString(static_cast<qulonglong>(p.componentsFound))));
    add(tr("Bone removal"), onOff(p.boneRemoved));
    if (!p.cutOff.empty()) {
        section.warnings.push_back(cutOffText(p.cutOff).toStdString());
    }
    return section;
}

}  // namespace vv::app
