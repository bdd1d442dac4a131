// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SegmentationText.h"

#include <QCoreApplication>
#include <QLocale>
#include <string_view>

namespace vv::app {

namespace {

QString towards(segmentation::PatientDirection direction) {
    switch (direction) {
        case segmentation::PatientDirection::Superior:
            return QCoreApplication::translate("vv::app::SegmentationText", "towards the head");
        case segmentation::PatientDirection::Inferior:
            return QCoreApplication::translate("vv::app::SegmentationText", "towards the feet");
        case segmentation::PatientDirection::Left:
            return QCoreApplication::translate("vv::app::SegmentationText",
                                               "to the patient's left");
        case segmentation::PatientDirection::Right:
            return QCoreApplication::translate("vv::app::SegmentationText",
                                               "to the patient's right");
        case segmentation::PatientDirection::Anterior:
            return QCoreApplication::translate("vv::app::SegmentationText", "anteriorly");
        case segmentation::PatientDirection::Posterior:
            return QCoreApplication::translate("vv::app::SegmentationText", "posteriorly");
    }
    return {};
}

QString onOff(bool on) {
    return on ? QCoreApplication::translate("vv::app::SegmentationText", "on")
              : QCoreApplication::translate("vv::app::SegmentationText", "off");
}

}  // namespace

QString cutOffText(const std::vector<segmentation::CutOffVessel>& vessels) {
    if (vessels.empty()) {
        return {};
    }
    const segmentation::CutOffVessel& first = vessels.front();
    const QLocale locale;
    const auto mm = [&locale](double v) { return locale.toString(v, 'f', 0); };
    QString text = QCoreApplication::translate(
                       "vv::app::SegmentationText",
                       "The vessel may be cut off: a bright tube continues %1 mm %2 past the "
                       "segmentation's end at (%3, %4, %5) mm, where the signal may fade.")
                       .arg(mm(first.lengthMm),
                            towards(segmentation::dominantDirection(first.farEnd - first.end)),
                            mm(first.end.x), mm(first.end.y), mm(first.end.z));
    if (vessels.size() > 1) {
        const int more = static_cast<int>(vessels.size() - 1);
        text += QStringLiteral(" ");
        text += QCoreApplication::translate("vv::app::SegmentationText", "%n more such end(s).",
                                            nullptr, more);
    }
    return text;
}

QString thresholdRuleName(const segmentation::ThresholdRange& range) {
    // The rules' stable beginnings (segmentation::defaultThresholdRange() and the front ends).
    const std::string_view rule = range.rule;
    if (rule.starts_with("CT angiography default")) {
        return QCoreApplication::translate("vv::app::SegmentationText", "CT angiography default");
    }
    if (rule.starts_with("histogram")) {
        return QCoreApplication::translate("vv::app::SegmentationText",
                                           "from the histogram (Otsu)");
    }
    if (rule.starts_with("constant volume")) {
        return QCoreApplication::translate("vv::app::SegmentationText", "the volume's only value");
    }
    if (rule.starts_with("chosen in the Segmentation panel")) {
        return QCoreApplication::translate("vv::app::SegmentationText",
                                           "chosen in the Segmentation panel");
    }
    if (rule.starts_with("chosen in the series dialog")) {
        return QCoreApplication::translate("vv::app::SegmentationText",
                                           "chosen in the series dialog");
    }
    if (rule.starts_with("saved in the session")) {
        return QCoreApplication::translate("vv::app::SegmentationText", "saved in the session");
    }
    if (rule.starts_with("--threshold")) {
        return QCoreApplication::translate("vv::app::SegmentationText", "given with --threshold");
    }
    return QString::fromStdString(range.rule);
}

report::ReportSegmentation reportSegmentation(const SegmentationProvenance& p) {
    report::ReportSegmentation section;
    const auto add = [&section](const QString& label, const QString& value) {
        section.settings.emplace_back(label.toStdString(), value.toStdString());
    };
    if (!p.segmentNames.empty()) {
        add(QCoreApplication::translate("vv::app::SegmentationText", "Segments"),
            QString::fromStdString(segmentsText(p)));
        return section;
    }
    const QLocale locale;
    const auto value = [&locale](float v) {
        return locale.toString(static_cast<double>(v), 'g', 4);
    };
    const QString unit =
        p.unit.empty() ? QString() : QStringLiteral(" ") + QString::fromStdString(p.unit);
    add(QCoreApplication::translate("vv::app::SegmentationText", "Threshold"),
        QCoreApplication::translate("vv::app::SegmentationText", "%1 to %2%3 (%4)")
            .arg(value(p.range.lower), value(p.range.upper), unit, thresholdRuleName(p.range)));
    const bool ct = p.modality == "CT" || p.unit == "HU";
    if (!ct) {
        add(QCoreApplication::translate("vv::app::SegmentationText", "Intensity correction"),
            p.intensityCorrected
                ? QCoreApplication::translate("vv::app::SegmentationText",
                                              "on (MR signal fall-off divided out; gain %1 to %2)")
                      .arg(locale.toString(p.gainLowest, 'f', 2),
                           locale.toString(p.gainHighest, 'f', 2))
                : onOff(false));
    }
    const QString which =
        p.seed ? QCoreApplication::translate("vv::app::SegmentationText",
                                             "the one under voxel (%1, %2, %3)")
                     .arg(p.seed->x)
                     .arg(p.seed->y)
                     .arg(p.seed->z)
               : QCoreApplication::translate("vv::app::SegmentationText", "the %n largest", nullptr,
                                             p.keepComponents);
    add(QCoreApplication::translate("vv::app::SegmentationText", "Components"),
        QCoreApplication::translate("vv::app::SegmentationText", "%1: kept %2 of %3")
            .arg(which)
            .arg(locale.toString(static_cast<qulonglong>(p.componentsKept)))
            .arg(locale.toString(static_cast<qulonglong>(p.componentsFound))));
    add(QCoreApplication::translate("vv::app::SegmentationText", "Bone removal"),
        onOff(p.boneRemoved));
    if (!p.cutOff.empty()) {
        section.warnings.push_back(cutOffText(p.cutOff).toStdString());
    }
    return section;
}

}  // namespace vv::app
