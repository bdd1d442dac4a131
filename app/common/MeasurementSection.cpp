// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/MeasurementSection.h"

#include <QCoreApplication>
#include <QLocale>
#include <QString>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "common/SliceReport.h"
#include "vv/core/Error.h"
#include "vv/slices/CurvedReformation.h"
#include "vv/slices/Reslice.h"

namespace vv::app {

/// The section's texts, translated in this context.
class MeasurementText {
    Q_DECLARE_TR_FUNCTIONS(vv::app::MeasurementText)
};

namespace {

using planning::Blank;
using planning::LandmarkKind;
using report::MeasurementCell;
using report::MeasurementRow;
using report::MeasurementTable;

std::string str(const QString& text) {
    return text.toStdString();
}

const char* const kMm = "mm";
const char* const kMm2 = "mm\u00b2";
const char* const kDegree = "\u00b0";

MeasurementCell mm(std::optional<double> value, std::string blank = {}) {
    return {value, 1, kMm, std::move(blank)};
}

/// Equivalent, minimum and maximum diameter of a section, or three blanks.
std::vector<MeasurementCell> diameters(const std::optional<planning::SectionSizes>& s,
                                       const std::string& blank) {
    if (!s) {
        return {mm(std::nullopt, blank), mm(std::nullopt), mm(std::nullopt)};
    }
    return {mm(s->equivalentDiameterMm), mm(s->minDiameterMm), mm(s->maxDiameterMm)};
}

std::string definitions() {
    return str(QCoreApplication::translate(
        "vv::app::MeasurementText",
        "\u00d8: diameter. Equivalent \u00d8: 2\u221a(area/\u03c0) of the lumen section "
        "perpendicular to the centreline; minimum and maximum \u00d8: its smallest and largest "
        "caliper (Feret) width. Lengths along the centreline unless marked straight."));
}

/// A landmark's name as the report shows it: a preset's in the UI language
/// unless the user renamed it.
std::string shownName(const std::string& name, LandmarkKind kind) {
    return kind != LandmarkKind::Free && name == planning::landmarkEnglishName(kind)
               ? landmarkName(kind)
               : name;
}

/// shownName of the landmark called `name` in the file.
std::string shownName(const ReportMeasurements& m, const std::string& name) {
    for (const MeasuredLandmark& l : m.landmarks) {
        if (l.name == name) {
            return shownName(l.name, l.kind);
        }
    }
    return name;
}

MeasurementTable landmarkTable(const ReportMeasurements& m) {
    MeasurementTable t;
    t.title = str(MeasurementText::tr("Landmarks"));
    t.columns = {str(MeasurementText::tr("Landmark")),
                 str(MeasurementText::tr("Equivalent \u00d8")),
                 str(MeasurementText::tr("Minimum \u00d8")),
                 str(MeasurementText::tr("Maximum \u00d8")), str(MeasurementText::tr("Area"))};
    bool junction = false;
    for (const MeasuredLandmark& l : m.landmarks) {
        MeasurementRow row;
        row.label = shownName(l.name, l.kind);
        if (l.section && l.section->atAJunction) {
            row.label += " *";
            junction = true;
        }
        row.cells = diameters(
            l.section, str(MeasurementText::tr("the section there has no closed lumen contour")));
        row.cells.push_back(l.section ? MeasurementCell{l.section->areaMm2, 0, kMm2, {}}
                                      : MeasurementCell{std::nullopt, 0, kMm2, {}});
        t.rows.push_back(std::move(row));
    }
    t.note = definitions();
    if (junction) {
        t.note += " " + str(MeasurementText::tr(
                            "* Where lumens merge: the section holds part of the other lumen."));
    }
    return t;
}

MeasurementTable lengthTable(const ReportMeasurements& m) {
    MeasurementTable t;
    t.title = str(MeasurementText::tr("Lengths between landmarks"));
    t.columns = {str(MeasurementText::tr("From \u2013 to")),
                 str(MeasurementText::tr("Along the centreline")),
                 str(MeasurementText::tr("Straight"))};
    for (const MeasuredLength& length : m.lengths) {
        t.rows.push_back({shownName(m, length.from) + " \u2013 " + shownName(m, length.to),
                          {mm(length.alongMm), mm(length.straightMm)}});
    }
    return t;
}

MeasurementTable aorticDiameterTable(const planning::AorticSizing& s) {
    MeasurementTable t;
    t.title = str(MeasurementText::tr("Aortic sizing: diameters"));
    t.columns = {str(MeasurementText::tr("Place")), str(MeasurementText::tr("Equivalent \u00d8")),
                 str(MeasurementText::tr("Minimum \u00d8")),
                 str(MeasurementText::tr("Maximum \u00d8"))};
    const auto add = [&t](const QString& label,
                          const planning::SizingValue<planning::SectionSizes>& v) {
        t.rows.push_back({str(label), diameters(v.value, blankNote(v.blank))});
    };
    add(MeasurementText::tr("Neck at the lowest renal artery"), s.neckDiameters[0]);
    for (std::size_t i = 1; i < s.neckDiameters.size(); ++i) {
        add(MeasurementText::tr("Neck %1 mm below the lowest renal artery")
                .arg(QLocale().toString(planning::AorticSizing::kNeckDepthsMm[i], 'f', 0)),
            s.neckDiameters[i]);
    }
    add(MeasurementText::tr("Largest aneurysm diameter"), s.largestAneurysm);
    add(MeasurementText::tr("Smallest left iliac (access)"), s.smallestIliac[0]);
    add(MeasurementText::tr("Smallest right iliac (access)"), s.smallestIliac[1]);
    t.note = str(MeasurementText::tr(
        "Below: along the centreline from the tree's source towards the aortic "
        "bifurcation. Smallest iliac: the section of smallest minimum diameter from "
        "the aortic bifurcation to the internal iliac origin."));
    return t;
}

MeasurementTable aorticLengthTable(const planning::AorticSizing& s) {
    MeasurementTable t;
    t.title = str(MeasurementText::tr("Aortic sizing: lengths and angles"));
    t.columns = {str(MeasurementText::tr("Measure")), str(MeasurementText::tr("Value"))};
    const auto length = [&t](const QString& label, const planning::SizingValue<double>& v) {
        t.rows.push_back({str(label), {mm(v.value, blankNote(v.blank))}});
    };
    const auto angle = [&t](const QString& label, const planning::SizingValue<double>& v) {
        t.rows.push_back({str(label), {{v.value, 0, kDegree, blankNote(v.blank)}}});
    };
    length(MeasurementText::tr("Neck length (lowest renal artery to start of the aneurysm)"),
           s.neckLengthMm);
    angle(MeasurementText::tr("Angle \u03b1 (suprarenal aorta to neck)"), s.suprarenalToNeckDeg);
    angle(MeasurementText::tr("Angle \u03b2 (neck to aneurysm)"), s.neckToAneurysmDeg);
    length(MeasurementText::tr("Lowest renal artery to aortic bifurcation"),
           s.renalToBifurcationMm);
    length(MeasurementText::tr("Lowest renal artery to left internal iliac origin"),
           s.renalToInternalIliacMm[0]);
    length(MeasurementText::tr("Lowest renal artery to right internal iliac origin"),
           s.renalToInternalIliacMm[1]);
    length(MeasurementText::tr("Aortic bifurcation to left internal iliac origin"),
           s.bifurcationToInternalIliacMm[0]);
    length(MeasurementText::tr("Aortic bifurcation to right internal iliac origin"),
           s.bifurcationToInternalIliacMm[1]);
    t.note = str(MeasurementText::tr(
        "Angles between the principal axes of the centreline: the suprarenal aorta "
        "over 15 mm above the lowest renal artery, the neck, and the aneurysm from "
        "its start to the aortic bifurcation."));
    return t;
}

MeasurementTable branchTable(const ReportMeasurements& m) {
    MeasurementTable t;
    t.title = str(MeasurementText::tr("Branches"));
    t.columns = {str(MeasurementText::tr("Branch")), str(MeasurementText::tr("Length")),
                 str(MeasurementText::tr("Narrowest")), str(MeasurementText::tr("Widest")),
                 str(MeasurementText::tr("Stenosis (diameter)"))};
    for (const MeasuredBranch& b : m.branches) {
        const auto equivalent = [](const std::optional<planning::SectionSizes>& s) {
            return mm(s ? std::optional<double>(s->equivalentDiameterMm) : std::nullopt);
        };
        t.rows.push_back({b.name.empty() ? str(MeasurementText::tr("Branch %1").arg(b.id)) : b.name,
                          {mm(b.lengthMm),
                           equivalent(b.narrowest),
                           equivalent(b.widest),
                           {b.stenosisDiameterPercent, 0, "%",
                            str(MeasurementText::tr("not graded: too few sections measure "
                                                    "the branch, or it has no healthy "
                                                    "reference"))}}});
    }
    t.note = str(MeasurementText::tr(
        "Narrowest and widest: equivalent diameters outside the branch's ends and "
        "junctions; stenosis at the narrowest point against the reference diameter."));
    return t;
}

/// The profile along the file's path, its landmarks and stenoses marked.
report::ProfileFigure profileFigure(const ReportMeasurements& m, const MeasuredProfile& profile) {
    report::ProfileFigure f;
    f.title = str(QCoreApplication::translate("vv::app::MeasurementText",
                                              "Diameter profile along the path (%1 long)")
                      .arg(QString::fromStdString(
                          report::measurementCellText({profile.lengthMm, 1, "mm", {}}))));
    f.note = str(
        QCoreApplication::translate(
            "vv::app::MeasurementText",
            "Solid: equivalent diameter; dashed: minimum and maximum caliper diameter. Gaps: no "
            "section measures the vessel there (an end, a junction). Marked: narrowings of %1 or "
            "more in diameter.")
            .arg(QString::fromStdString(
                report::measurementCellText({kMarkedStenosisPercent, 0, "%", {}}))));
    f.lengthMm = profile.lengthMm;
    f.xTitle = str(
        QCoreApplication::translate("vv::app::MeasurementText", "Distance along the path (mm)"));
    f.yTitle = str(QCoreApplication::translate("vv::app::MeasurementText", "Diameter (mm)"));
    f.series = {{str(QCoreApplication::translate("vv::app::MeasurementText", "Equivalent")), {}},
                {str(QCoreApplication::translate("vv::app::MeasurementText", "Minimum")), {}},
                {str(QCoreApplication::translate("vv::app::MeasurementText", "Maximum")), {}}};
    const double gap = std::numeric_limits<double>::quiet_NaN();
    for (const MeasuredProfile::Point& p : profile.points) {
        f.pathMm.push_back(p.pathMm);
        f.series[0].values.push_back(p.equivalentMm.value_or(gap));
        f.series[1].values.push_back(p.minMm.value_or(gap));
        f.series[2].values.push_back(p.maxMm.value_or(gap));
    }
    for (const MeasuredLandmark& l : m.landmarks) {
        if (l.pathMm) {
            f.landmarks.push_back({*l.pathMm, shownName(l.name, l.kind)});
        }
    }
    for (const MeasuredBranch& b : m.branches) {
        if (b.stenosisPathMm && b.stenosisDiameterPercent &&
            *b.stenosisDiameterPercent >= kMarkedStenosisPercent) {
            f.stenoses.push_back(
                {*b.stenosisPathMm,
                 report::measurementCellText({*b.stenosisDiameterPercent, 0, "%", {}})});
        }
    }
    return f;
}

/// The cross-section at each landmark that has its contour in the file.
std::vector<report::SectionFigure> sectionFigures(const ReportMeasurements& m) {
    std::vector<report::SectionFigure> figures;
    for (const MeasuredLandmark& l : m.landmarks) {
        if (!l.section || l.contour.size() < 3) {
            continue;
        }
        report::SectionFigure f;
        f.title = shownName(l.name, l.kind);
        const planning::SectionSizes& s = *l.section;
        f.caption =
            str(MeasurementText::tr("Minimum %1, maximum %2, equivalent %3")
                    .arg(QString::fromStdString(report::measurementCellText(mm(s.minDiameterMm))),
                         QString::fromStdString(report::measurementCellText(mm(s.maxDiameterMm))),
                         QString::fromStdString(
                             report::measurementCellText(mm(s.equivalentDiameterMm)))));
        f.contour = l.contour;
        f.minCaliper = l.minCaliper;
        f.maxCaliper = l.maxCaliper;
        f.fieldMm = sectionFieldMm(s.maxDiameterMm);
        figures.push_back(std::move(f));
    }
    return figures;
}

}  // namespace

std::string landmarkName(LandmarkKind kind) {
    switch (kind) {
        case LandmarkKind::Free:
            return {};
        case LandmarkKind::LowestRenalArtery:
            return str(
                QCoreApplication::translate("vv::app::MeasurementText", "Lowest renal artery"));
        case LandmarkKind::AneurysmStart:
            return str(
                QCoreApplication::translate("vv::app::MeasurementText", "Start of the aneurysm"));
        case LandmarkKind::LargestAneurysmDiameter:
            return str(QCoreApplication::translate("vv::app::MeasurementText",
                                                   "Largest aneurysm diameter"));
        case LandmarkKind::AorticBifurcation:
            return str(
                QCoreApplication::translate("vv::app::MeasurementText", "Aortic bifurcation"));
        case LandmarkKind::LeftInternalIliacOrigin:
            return str(QCoreApplication::translate("vv::app::MeasurementText",
                                                   "Left internal iliac origin"));
        case LandmarkKind::RightInternalIliacOrigin:
            return str(QCoreApplication::translate("vv::app::MeasurementText",
                                                   "Right internal iliac origin"));
    }
    return {};
}

std::string blankNote(const Blank& b) {
    const QString landmark = QString::fromStdString(landmarkName(b.landmark));
    const QString other = QString::fromStdString(landmarkName(b.other));
    const QString length = QLocale().toString(b.mm, 'f', 0);
    switch (b.reason) {
        case Blank::Reason::None:
            return {};
        case Blank::Reason::LandmarkMissing:
            return str(QCoreApplication::translate("vv::app::MeasurementText",
                                                   "no landmark \u201c%1\u201d is placed")
                           .arg(landmark));
        case Blank::Reason::NoAorticPath:
            return str(QCoreApplication::translate(
                "vv::app::MeasurementText", "no landmark below the neck sets the aortic path"));
        case Blank::Reason::NotOnAorticPath:
            return str(
                QCoreApplication::translate(
                    "vv::app::MeasurementText",
                    "\u201c%1\u201d is not on the centreline from the source to \u201c%2\u201d")
                    .arg(landmark, other));
        case Blank::Reason::PathEndsTooSoon:
            return str(QCoreApplication::translate(
                           "vv::app::MeasurementText",
                           "the aortic path ends less than %1 mm below the lowest renal artery")
                           .arg(length));
        case Blank::Reason::NoContour:
            return str(QCoreApplication::translate(
                "vv::app::MeasurementText", "the section there has no closed lumen contour"));
        case Blank::Reason::AneurysmNotBelowRenal:
            return str(QCoreApplication::translate(
                "vv::app::MeasurementText",
                "the start of the aneurysm is not below the lowest renal artery"));
        case Blank::Reason::NeckTooShort:
            return str(QCoreApplication::translate("vv::app::MeasurementText",
                                                   "the neck is shorter than %1 mm")
                           .arg(length));
        case Blank::Reason::TooLittleAboveRenal:
            return str(QCoreApplication::translate(
                           "vv::app::MeasurementText",
                           "less than %1 mm of centreline above the lowest renal artery")
                           .arg(length));
        case Blank::Reason::AneurysmTooShort:
            return str(QCoreApplication::translate("vv::app::MeasurementText",
                                                   "the aneurysm is shorter than %1 mm")
                           .arg(length));
        case Blank::Reason::NoVesselSection:
            return str(QCoreApplication::translate(
                           "vv::app::MeasurementText",
                           "no section between \u201c%1\u201d and \u201c%2\u201d measures the "
                           "vessel itself")
                           .arg(landmark, other));
    }
    return {};
}

report::ReportMeasurementSection measurementSection(const ReportMeasurements& m) {
    report::ReportMeasurementSection section;
    const auto add = [&section](MeasurementTable t) {
        if (!t.rows.empty()) {
            section.tables.push_back(std::move(t));
        }
    };
    if (m.sizing) {
        add(aorticDiameterTable(*m.sizing));
        add(aorticLengthTable(*m.sizing));
    }
    add(landmarkTable(m));
    add(lengthTable(m));
    add(branchTable(m));
    if (m.profile && m.profile->points.size() >= 2) {
        section.profile = profileFigure(m, *m.profile);
    }
    section.sections = sectionFigures(m);
    return section;
}

double sectionFieldMm(double maxDiameterMm) noexcept {
    return std::max(20.0, 2.5 * maxDiameterMm);
}

ReformationGrid reformationGrid(const scene::Volume& volume, double widestMm) {
    const glm::dvec3 spacing = volume.spacing();
    return {std::max(10.0, 1.5 * widestMm),
            std::clamp(std::min({spacing.x, spacing.y, spacing.z}), 0.25, 1.0)};
}

void addVolumePictures(report::ReportMeasurementSection& section, const ReportMeasurements& m,
                       const scene::Volume& volume, const slices::Window& window, double degrees) {
    /// Pixels along a section picture's side.
    constexpr int kSectionPixels = 160;
    const ImageView<const std::uint8_t> noLabels;
    const auto grey = [&](const Image<float>& values) {
        return sliceImage(values.view(), noLabels, window, slices::OverlayStyle{});
    };
    if (m.profile && m.profile->points.size() >= 2) {
        std::vector<glm::dvec3> points;
        double widest = 0.0;
        for (const MeasuredProfile::Point& p : m.profile->points) {
            if (!p.position) {
                points.clear();
                break;  // a file without positions
            }
            points.push_back(*p.position);
            widest = std::max(widest, p.maxMm.value_or(0.0));
        }
        if (points.size() >= 2) {
            const ReformationGrid grid = reformationGrid(volume, widest);
            try {
                report::ReformationFigure figure;
                figure.image = grey(slices::curvedReformation(volume, points, grid.halfWidthMm,
                                                              grid.rowSpacingMm, degrees));
                figure.lengthMm = m.profile->lengthMm;
                figure.halfWidthMm = grid.halfWidthMm;
                for (const MeasuredLandmark& l : m.landmarks) {
                    if (l.pathMm) {
                        figure.landmarks.push_back({*l.pathMm, shownName(l.name, l.kind)});
                    }
                }
                figure.caption =
                    str(QCoreApplication::translate(
                            "vv::app::MeasurementText",
                            "Curved reformation along the path (stretched: the path straight, "
                            "distances true along it), turned %1° about the path; window width %2, "
                            "level %3.")
                            .arg(QLocale().toString(std::lround(degrees)))
                            .arg(QLocale().toString(window.width, 'f', 0))
                            .arg(QLocale().toString(window.center, 'f', 0)));
                section.reformation = std::move(figure);
            } catch (const InvalidArgumentError&) {
                // a path the volume cannot follow: no reformation
            }
        }
    }
    // The section figures follow the landmarks with a contour, in order.
    std::size_t next = 0;
    for (const MeasuredLandmark& l : m.landmarks) {
        if (!l.section || l.contour.size() < 3) {
            continue;
        }
        if (next >= section.sections.size()) {
            break;
        }
        report::SectionFigure& figure = section.sections[next++];
        if (!l.plane) {
            continue;
        }
        try {
            figure.image = grey(slices::reslice(
                volume, slices::sectionPlane(l.plane->centre, l.plane->u, l.plane->v,
                                             figure.fieldMm, kSectionPixels)));
        } catch (const InvalidArgumentError&) {
            figure.image = QImage();  // the contour alone
        }
    }
}

}  // namespace vv::app
