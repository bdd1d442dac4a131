// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/PdfReport.h"

#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QFont>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

#include "MeasurementFigures.h"
#include "PdfFlow.h"
#include "ReportText.h"
#include "vv/Version.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/render/MeshStyle.h"
#include "vv/scene/QuantityTitle.h"
#include "vv/vss/Solver.h"

namespace vv::report {

namespace {

using pdf::Flow;
using pdf::font;
using pdf::kDpi;
using pdf::mm;

/// The legends are laid out as on a view this many logical pixels wide.
constexpr double kLegendViewWidth = 1100.0;

double contentWidthMm(PaperSize paper) {
    return pdf::pageSize(paper).size(QPageSize::Millimeter).width() - 2.0 * pdf::kMarginSideMm;
}

QString onOff(bool on) {
    return on ? ReportText::tr("on") : ReportText::tr("off");
}

constexpr double kCaptionGapMm = 1.5;

QFont captionFont() {
    return font(8.0, false, true);
}

/// The size of a view's image on the page: the content width at the image's
/// aspect, or smaller (same aspect) when that would not fit on one page under
/// `title` with its caption: a tall image (a portrait view, a coronal slice)
/// is scaled to the page's frame, never cut by the page's end or the footer.
QSizeF imageSize(const Flow& flow, const QString& title, const ReportView& view) {
    const double aspect =
        static_cast<double>(view.image.height()) / std::max(1, view.image.width());
    const double captionHeight =
        view.caption.empty() ? 0.0 : flow.textHeight(qs(view.caption), captionFont(), flow.width());
    const double frame =
        flow.pageHeight() - flow.headingHeight(title) - mm(kCaptionGapMm) - captionHeight;
    const double h = std::min(flow.width() * aspect, std::max(frame, mm(10.0)));
    return {h / aspect, h};
}

/// The height viewBlock() takes for an image of `size`.
double blockHeight(const Flow& flow, const ReportView& view, const QSizeF& size) {
    const double captionHeight =
        view.caption.empty() ? 0.0 : flow.textHeight(qs(view.caption), captionFont(), flow.width());
    return size.height() + mm(kCaptionGapMm) + captionHeight;
}

/// The view image at `size`, centred across the content width, its legends
/// painted over it as on screen, and its caption.
void viewBlock(Flow& flow, const ReportView& view, const QSizeF& size) {
    const double w = size.width();
    const double h = size.height();
    const QFont f = captionFont();
    const double captionHeight = flow.textHeight(qs(view.caption), f, flow.width());
    flow.ensure(blockHeight(flow, view, size));
    const QRectF box(flow.left() + (flow.width() - w) / 2.0, flow.y(), w, h);
    if (flow.drawing()) {
        QPainter& p = flow.painter();
        p.save();
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.setRenderHint(QPainter::Antialiasing);
        p.drawImage(box, view.image);
        // Legends in the coordinates of a kLegendViewWidth-wide view.
        const double scale = w / kLegendViewWidth;
        p.translate(box.topLeft());
        p.scale(scale, scale);
        render::paintLegends(p, QRectF(0.0, 0.0, kLegendViewWidth, h / scale), view.legends);
        p.restore();
        // The frame inside the image's box: nothing beyond the content's edges.
        const double pen = mm(0.2);
        p.setPen(QPen(QBrush(pdf::kRule), pen, Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin));
        p.setBrush(Qt::NoBrush);
        p.drawRect(box.adjusted(pen / 2, pen / 2, -pen / 2, -pen / 2));
    }
    flow.advance(h + mm(kCaptionGapMm));
    if (!view.caption.empty()) {
        flow.text(QRectF(flow.left(), flow.y(), flow.width(), captionHeight), qs(view.caption), f,
                  pdf::kMuted, Qt::AlignLeft | Qt::TextWordWrap);
        flow.advance(captionHeight);
    }
}

/// The parameter statistics' table: one row per object, with the note on
/// what coverage and the weighting mean.
pdf::Table statsTable(const Flow& flow, const ReportParameter& parameter) {
    QStringList headers = {ReportText::tr("Object"), ReportText::tr("Coverage"),
                           ReportText::tr("Min"), ReportText::tr("Mean"), ReportText::tr("Max")};
    if (parameter.thresholds.below) {
        headers << ReportText::tr("Area < %1")
                       .arg(withUnit(exact(*parameter.thresholds.below), parameter.unit));
    }
    if (parameter.thresholds.above) {
        headers << ReportText::tr("Area > %1")
                       .arg(withUnit(exact(*parameter.thresholds.above), parameter.unit));
    }
    std::vector<QStringList> rows;
    for (const ParameterStats& s : parameter.stats) {
        QStringList cells = {s.object.empty() ? ReportText::tr("(unnamed)") : qs(s.object),
                             percent(s.coveredFraction), number(s.min), number(s.mean),
                             number(s.max)};
        if (parameter.thresholds.below) {
            cells << (s.fractionBelow ? percent(*s.fractionBelow) : QStringLiteral("\u2014"));
        }
        if (parameter.thresholds.above) {
            cells << (s.fractionAbove ? percent(*s.fractionAbove) : QStringLiteral("\u2014"));
        }
        rows.push_back(cells);
    }
    const QString note =
        (parameter.unit.empty() ? ReportText::tr("Values in the array's unit.")
                                : ReportText::tr("Values in %1.").arg(qs(parameter.unit))) +
        QLatin1Char(' ') +
        ReportText::tr(
            "Coverage: share of the surface with finite values; the statistics are over "
            "that part. Mean and area shares are weighted by surface area, with values "
            "interpolated linearly within each triangle.");
    return {flow, headers, rows, note,
            ReportText::tr("No object has finite values of this parameter.")};
}

/// A measurement table: its rows, a dash for each blank value and, in its
/// note, the definitions and why each blank value is blank.
pdf::Table measurementTable(const Flow& flow, const MeasurementTable& t) {
    QStringList headers;
    for (const std::string& column : t.columns) {
        headers << qs(column);
    }
    std::vector<QStringList> rows;
    QStringList blanks;
    for (const MeasurementRow& row : t.rows) {
        QStringList cells{qs(row.label)};
        for (const MeasurementCell& cell : row.cells) {
            cells << qs(measurementCellText(cell));
            if (!cell.value && !cell.blankNote.empty() &&
                !blanks.contains(qs(row.label) + QStringLiteral(": ") + qs(cell.blankNote))) {
                blanks << qs(row.label) + QStringLiteral(": ") + qs(cell.blankNote);
            }
        }
        rows.push_back(cells);
    }
    QString note = qs(t.note);
    if (!blanks.isEmpty()) {
        note += (note.isEmpty() ? QString() : QStringLiteral(" ")) +
                ReportText::tr("Blank (\u2014): %1.").arg(blanks.join(QStringLiteral("; ")));
    }
    return {flow, headers, rows, note, ReportText::tr("Nothing measured.")};
}

void measurementSection(Flow& flow, const ReportMeasurementSection& section) {
    bool first = true;
    for (const MeasurementTable& t : section.tables) {
        const pdf::Table table = measurementTable(flow, t);
        const double titleHeight = flow.paragraphHeight(qs(t.title), font(9.5, true));
        const double keep = titleHeight + mm(1.5) + table.keepHeight();
        if (first) {
            flow.heading(ReportText::tr("Measurements"), keep);
            first = false;
        } else {
            flow.ensure(keep + mm(3.0));
            flow.advance(mm(3.0));
        }
        flow.paragraph(qs(t.title), font(9.5, true), pdf::kInk, mm(1.5));
        table.draw(flow);
    }
    if (first && (section.profile || section.reformation || !section.sections.empty())) {
        flow.heading(ReportText::tr("Measurements"), mm(70.0));
    }
    if (section.profile) {
        figures::profileFigure(flow, *section.profile);
    }
    if (section.reformation) {
        figures::reformationFigure(flow, *section.reformation);
    }
    figures::sectionFigures(flow, section.sections);
}

QString solverName(vss::SolverKind kind) {
    switch (kind) {
        case vss::SolverKind::Reference:
            return ReportText::tr("reference");
        case vss::SolverKind::Brute:
            return ReportText::tr("brute force");
        case vss::SolverKind::Step:
            return ReportText::tr("step");
        case vss::SolverKind::Fast:
            return ReportText::tr("fast");
    }
    return qs(std::string(vss::toString(kind)));
}

QString solverText(const ReportSettings& s) {
    QString text = solverName(s.vss.solver.kind);
    if (s.vss.solver.kind == vss::SolverKind::Step) {
        text += ReportText::tr(", every %1th contour pixel").arg(integer(s.vss.solver.step));
    }
    if (std::isnan(s.errorBound)) {
        text += ReportText::tr(" (no error bound)");
    } else if (s.errorBound == 0.0) {
        text += ReportText::tr(" (exact)");
    } else {
        text += ReportText::tr(" (max. error %1 of normalised depth)").arg(number(s.errorBound));
    }
    return text;
}

QString sexText(const ReportPatient& p) {
    if (!p.anonymise) {
        if (p.sex == "F") {
            return ReportText::tr("female");
        }
        if (p.sex == "M") {
            return ReportText::tr("male");
        }
        if (p.sex == "O") {
            return ReportText::tr("other");
        }
    }
    return qs(displayText(p, p.sex));
}

pdf::Fields patientFields(const ReportPatient& p) {
    return {{ReportText::tr("Patient name"), qs(displayName(p, p.name))},
            {ReportText::tr("Patient ID"), qs(displayText(p, p.id))},
            {ReportText::tr("Birth date"), qs(displayDate(p, p.birthDate))},
            {ReportText::tr("Sex"), sexText(p)},
            {ReportText::tr("Study date"), qs(displayDate(p, p.studyDate))},
            {ReportText::tr("Accession number"), qs(displayText(p, p.accession))},
            {ReportText::tr("Referring physician"), qs(displayName(p, p.referringPhysician))}};
}

/// The patient in the page footer: name and ID, leaving out what was not
/// given (the patient block shows it as "—"; a running footer does not need
/// "ID —"); empty when neither was given. Anonymised: both as "anonymised".
QString footerPatient(const ReportPatient& p) {
    const QString notGiven = QStringLiteral("\u2014");  // displayText() for an empty value
    const QString name = qs(displayName(p, p.name));
    const QString id = qs(displayText(p, p.id));
    if (id == notGiven) {
        return name == notGiven ? QString() : name;
    }
    return name == notGiven ? ReportText::tr("ID %1").arg(id)
                            : ReportText::tr("%1, ID %2").arg(name, id);
}

QString syntheticDemoText() {
    return ReportText::tr("Synthetic demo data generated by VesselView: not patient data.");
}

/// The data section: the DICOM series by its name and the files by name
/// (only their count when anonymised), and where the data came from.
pdf::Fields dataFields(const ReportContent& content) {
    pdf::Fields files;
    if (content.patient && content.patient->anonymise) {
        // File names of patient data often carry names or IDs.
        const auto count = content.sources.size() + (content.series.empty() ? 0 : 1);
        files.emplace_back(ReportText::tr("Source files"),
                           ReportText::tr("%1 (names withheld: anonymised report)")
                               .arg(integer(static_cast<long long>(count))));
    } else {
        if (!content.series.empty()) {
            files.emplace_back(ReportText::tr("DICOM series"), qs(content.series));
        }
        for (const auto& source : content.sources) {
            files.emplace_back(
                source == content.sources.front() ? ReportText::tr("Source files") : QString(),
                QFileInfo(QFile::decodeName(source.c_str())).fileName());
        }
    }
    if (content.syntheticDemo) {
        files.emplace_back(
            ReportText::tr("Provenance"),
            ReportText::tr("Synthetic demo data generated by VesselView: not patient data."));
    }
    return files;
}

/// How the series was segmented: its warnings first (a vessel that may be
/// cut off), in the warning colour, then its settings; on one page with the heading.
void segmentationSection(Flow& flow, const ReportSegmentation& segmentation) {
    pdf::Fields fields;
    for (const auto& [label, value] : segmentation.settings) {
        fields.emplace_back(qs(label), qs(value));
    }
    const QFont warningFont = font(9.0, true);
    const double gap = mm(1.5);
    double height = pdf::fieldGridHeight(flow, fields, 1);
    for (const std::string& warning : segmentation.warnings) {
        height += flow.textHeight(qs(warning), warningFont, flow.width()) + gap;
    }
    flow.heading(ReportText::tr("Segmentation"), height);
    for (const std::string& warning : segmentation.warnings) {
        flow.paragraph(qs(warning), warningFont, pdf::kWarning, gap);
    }
    pdf::fieldGrid(flow, fields, 1);
}

pdf::Fields settingsFields(const ReportSettings& s) {
    pdf::Fields settings;
    if (s.vss.enabled) {
        settings.emplace_back(ReportText::tr("Void Space Surface"), onOff(true));
        settings.emplace_back(ReportText::tr("Depth colour scale"),
                              engineName(colormaps::displayName(s.vss.scale)));
        settings.emplace_back(ReportText::tr("Interpolation power p"), exact(s.vss.solver.p));
        settings.emplace_back(ReportText::tr("Solver"), solverText(s));
        settings.emplace_back(ReportText::tr("Iso-lines"), s.vss.isoLines > 0
                                                               ? integer(s.vss.isoLines)
                                                               : ReportText::tr("none"));
    } else {
        settings.emplace_back(ReportText::tr("Void Space Surface"), onOff(false));
    }
    settings.emplace_back(ReportText::tr("Vessel depth cue"),
                          engineName(render::displayName(s.cue.cue)));
    settings.emplace_back(ReportText::tr("Ambient occlusion"), onOff(s.ambientOcclusion));
    settings.emplace_back(ReportText::tr("Anti-aliasing (FXAA)"), onOff(s.antialiasing));
    if (s.smoothedWallMm) {
        settings.emplace_back(ReportText::tr("Coarse facets"),
                              ReportText::tr("smoothed up close (the wall moved by at most %1)")
                                  .arg(withUnit(number(*s.smoothedWallMm), "mm")));
    }
    if (!s.view.empty()) {
        settings.emplace_back(ReportText::tr("Camera"), qs(s.view));
    }
    return settings;
}

QString scaleText(const ReportParameter& parameter) {
    const QString map = engineName(colormaps::displayName(parameter.map));
    const auto [lowText, highText] = rangeNumbers(parameter.range.first, parameter.range.second);
    const QString& low = lowText;
    const QString high = withUnit(highText, parameter.unit);
    const QString scale =
        parameter.bins >= 2
            ? ReportText::tr("Colour map %1 in %2 bins over %3 \u2013 %4.")
                  .arg(map, integer(parameter.bins), low, high)
            : ReportText::tr("Colour map %1 over %2 \u2013 %3.").arg(map, low, high);
    return scale + QLatin1Char(' ') +
           ReportText::tr("Values outside are shown in the end colours.");
}

QString titleOf(const ReportContent& content) {
    return content.title.empty() ? qs(defaultReportTitle()) : qs(content.title);
}

/// The title block: title, software and date, the disclaimer.
void titleBlock(Flow& flow, const ReportContent& content, const QString& software,
                const QString& created) {
    const QString title = titleOf(content);
    const QFont titleFont = font(18.0, true);
    const double titleHeight = flow.textHeight(title, titleFont, flow.width() * 0.65);
    const QFont metaFont = font(8.5);
    flow.text(QRectF(flow.left(), flow.y(), flow.width() * 0.65, titleHeight), title, titleFont,
              pdf::kInk, Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap);
    const QString meta = software + QLatin1Char('\n') + ReportText::tr("Created %1").arg(created);
    flow.text(QRectF(flow.left() + flow.width() * 0.6, flow.y(), flow.width() * 0.4, titleHeight),
              meta, metaFont, pdf::kMuted, Qt::AlignRight | Qt::AlignVCenter);
    flow.advance(std::max(titleHeight, flow.textHeight(meta, metaFont, flow.width())) + mm(2.0));
    flow.rule(flow.y(), pdf::kAccent, 0.6);
    flow.advance(mm(1.5));
    if (!content.disclaimer.empty()) {
        flow.paragraph(qs(content.disclaimer), font(9.0, true), pdf::kWarning, mm(0.5));
    }
    if (content.syntheticDemo) {
        flow.paragraph(syntheticDemoText(), font(9.0, true), pdf::kWarning, mm(0.5));
    }
}

void paint(QPdfWriter& writer, const ReportContent& content) {
    const QString created =
        formatDateTime(content.created) + QLatin1Char(' ') + content.created.timeZoneAbbreviation();
    const QString software = QStringLiteral("VesselView ") + QString::fromLatin1(vv::kVersion);
    QString footer = software + QStringLiteral(" \u00b7 ") + titleOf(content) +
                     QStringLiteral(" \u00b7 ") + created;
    if (const QString patient = content.patient ? footerPatient(*content.patient) : QString();
        !patient.isEmpty()) {
        footer += QStringLiteral(" \u00b7 ") + patient;
    }
    pdf::paintPages(writer, footer, [&](Flow& flow) {
        titleBlock(flow, content, software, created);

        if (content.patient) {
            const pdf::Fields fields = patientFields(*content.patient);
            flow.heading(ReportText::tr("Patient and study"),
                         pdf::fieldGridHeight(flow, fields, 2));
            pdf::fieldGrid(flow, fields, 2);
        }

        // What the reader signs comes first.
        flow.heading(ReportText::tr("Findings"), mm(14.0));
        if (content.findings.empty()) {
            flow.paragraph(ReportText::tr("No findings entered."), font(9.5, false, true),
                           pdf::kMuted);
        } else {
            flow.paragraph(qs(content.findings), font(10.0), pdf::kInk);
        }

        // Heading, image and caption on one page.
        const auto viewSection = [&](const QString& title, const ReportView& view) {
            const QSizeF size = imageSize(flow, title, view);
            flow.heading(title, blockHeight(flow, view, size));
            viewBlock(flow, view, size);
        };
        viewSection(ReportText::tr("View"), content.view);
        if (content.secondView) {
            viewSection(ReportText::tr("Second view"), *content.secondView);
        }
        if (content.slice) {
            viewSection(ReportText::tr("Slice with segmentation"), *content.slice);
        }

        if (content.parameter) {
            const ReportParameter& parameter = *content.parameter;
            const QString name = qs(scene::quantityTitle(parameter.name, parameter.unit));
            const QString scale = scaleText(parameter);
            const pdf::Table table = statsTable(flow, parameter);
            flow.heading(
                ReportText::tr("Parameter statistics \u2014 %1").arg(name),
                flow.textHeight(scale, font(8.5), flow.width()) + mm(2.0) + table.height());
            flow.paragraph(scale, font(8.5), pdf::kInk, mm(2.0));
            table.draw(flow);
        }

        if (content.measurements && !content.measurements->tables.empty()) {
            measurementSection(flow, *content.measurements);
        }

        const pdf::Fields data = dataFields(content);
        if (!data.empty()) {
            flow.heading(ReportText::tr("Data"), pdf::fieldGridHeight(flow, data, 1));
            pdf::fieldGrid(flow, data, 1);
        }

        if (content.segmentation) {
            segmentationSection(flow, *content.segmentation);
        }

        const pdf::Fields settings = settingsFields(content.settings);
        flow.heading(ReportText::tr("Rendering settings"), pdf::fieldGridHeight(flow, settings, 2));
        pdf::fieldGrid(flow, settings, 2);
    });
}

}  // namespace

std::string measurementCellText(const MeasurementCell& cell) {
    if (!cell.value) {
        return "\u2014";
    }
    return withUnit(fixed(*cell.value, cell.decimals), cell.unit).toStdString();
}

std::string defaultReportTitle() {
    return QCoreApplication::translate("vv::report::ReportText", "Vessel tree report")
        .toStdString();
}

namespace {
const char* const kDefaultDisclaimer =
    QT_TRANSLATE_NOOP("vv::report::ReportText", "Not for diagnostic use.");
}  // namespace

std::string defaultDisclaimer() {
    return QCoreApplication::translate("vv::report::ReportText", kDefaultDisclaimer).toStdString();
}

bool isDefaultDisclaimer(std::string_view text) {
    return text == kDefaultDisclaimer || text == defaultDisclaimer();
}

std::optional<PaperSize> paperSizeFromName(std::string_view name) noexcept {
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (lower == "a4") {
        return PaperSize::A4;
    }
    if (lower == "letter") {
        return PaperSize::Letter;
    }
    return std::nullopt;
}

int reportImageWidth(PaperSize paper) noexcept {
    return static_cast<int>(std::ceil(mm(contentWidthMm(paper))));
}

QByteArray renderPdf(const ReportContent& content, PaperSize paper) {
    const int minimum = reportImageWidth(paper);
    for (const ReportView* view :
         {&content.view, content.secondView ? &*content.secondView : nullptr,
          content.slice ? &*content.slice : nullptr}) {
        if (view != nullptr && (view->image.isNull() || view->image.width() < minimum)) {
            throw InvalidArgumentError("report: a view must be at least " +
                                       std::to_string(minimum) +
                                       " pixels wide (300 dpi across the page), got " +
                                       std::to_string(view->image.width()));
        }
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    {
        QPdfWriter writer(&buffer);
        pdf::setUpPage(writer, paper);
        writer.setTitle(titleOf(content));
        writer.setCreator(QStringLiteral("VesselView ") + QString::fromLatin1(vv::kVersion));
        paint(writer, content);
    }
    buffer.close();
    return bytes;
}

void writePdfBytes(const std::filesystem::path& path, const QByteArray& pdf) {
    writeFileAtomically(path,
                        std::string_view(pdf.constData(), static_cast<std::size_t>(pdf.size())));
}

void writePdf(const std::filesystem::path& path, const ReportContent& content, PaperSize paper) {
    writePdfBytes(path, renderPdf(content, paper));
}

}  // namespace vv::report
