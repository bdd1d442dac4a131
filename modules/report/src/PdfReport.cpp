// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/PdfReport.h"

#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QFont>
#include <QFontMetricsF>
#include <QPageLayout>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QTextLayout>
#include <QTimeZone>
#include <algorithm>
#include <cmath>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

#include "vv/Version.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/render/MeshStyle.h"
#include "vv/vss/Solver.h"

namespace vv::report {

namespace {

constexpr int kDpi = 300;
constexpr double kMarginSideMm = 18.0;
constexpr double kMarginTopMm = 15.0;
constexpr double kMarginBottomMm = 15.0;
/// The legends are laid out as on a view this many logical pixels wide.
constexpr double kLegendViewWidth = 1100.0;
const char* const kFontFamily = "DejaVu Sans";

const QColor kInk(28, 32, 38);
const QColor kMuted(96, 104, 114);
const QColor kAccent(31, 78, 121);
const QColor kRule(190, 198, 206);
const QColor kZebra(242, 245, 248);

double mm(double millimetres) {
    return millimetres / 25.4 * kDpi;
}

QString qs(const std::string& text) {
    return QString::fromStdString(text);
}

QPageSize pageSize(PaperSize paper) {
    return QPageSize(paper == PaperSize::A4 ? QPageSize::A4 : QPageSize::Letter);
}

double contentWidthMm(PaperSize paper) {
    return pageSize(paper).size(QPageSize::Millimeter).width() - 2.0 * kMarginSideMm;
}

/// Up to 3 significant digits, no exponent for ordinary magnitudes.
QString number(double value) {
    if (!std::isfinite(value)) {
        return QStringLiteral("\u2014");
    }
    const double a = std::abs(value);
    if (a == 0.0) {
        return QStringLiteral("0");
    }
    if (a >= 1e5 || a < 1e-3) {
        return QString::number(value, 'g', 3);
    }
    const int decimals = std::clamp(2 - static_cast<int>(std::floor(std::log10(a))), 0, 4);
    return QString::number(value, 'f', decimals);
}

/// A value as given (a threshold, p): up to 6 significant digits, no trailing zeros.
QString exact(double value) {
    return QString::number(value, 'g', 6);
}

QString percent(double fraction) {
    return QString::number(fraction * 100.0, 'f', 1) + " %";
}

QString withUnit(const QString& value, const std::string& unit) {
    return unit.empty() ? value : value + QChar(0x202F) + qs(unit);
}

QFont font(double points, bool bold = false, bool italic = false) {
    QFont f(QString::fromLatin1(kFontFamily));
    f.setPointSizeF(points);
    f.setBold(bold);
    f.setItalic(italic);
    f.setStyleHint(QFont::SansSerif);
    return f;
}

/// Lays the report out top to bottom over pages. Run twice: a dry run
/// (draw = false) counts the pages; the second run paints.
class Flow {
  public:
    Flow(QPainter& painter, QPdfWriter& writer, const QRectF& content, bool draw)
        : painter_(painter), writer_(writer), content_(content), draw_(draw), y_(content.top()) {}

    [[nodiscard]] bool drawing() const noexcept { return draw_; }
    [[nodiscard]] QPainter& painter() noexcept { return painter_; }
    [[nodiscard]] double left() const noexcept { return content_.left(); }
    [[nodiscard]] double width() const noexcept { return content_.width(); }
    [[nodiscard]] double y() const noexcept { return y_; }
    [[nodiscard]] int page() const noexcept { return page_; }
    void advance(double dy) { y_ += dy; }

    /// Starts a new page unless `height` still fits on this one.
    void ensure(double height) {
        if (y_ + height > content_.bottom() && y_ > content_.top()) {
            newPage();
        }
    }
    void newPage() {
        if (draw_) {
            pageDone_(page_);
            writer_.newPage();
        }
        ++page_;
        y_ = content_.top();
    }
    void onPageDone(std::function<void(int)> callback) { pageDone_ = std::move(callback); }
    void finish() {
        if (draw_) {
            pageDone_(page_);
        }
    }

    /// Height of `text` in `f` wrapped to `width`.
    [[nodiscard]] double textHeight(const QString& text, const QFont& f, double w,
                                    int wrap = Qt::TextWordWrap) const {
        const QFontMetricsF fm(f, &writer_);
        return fm.boundingRect(QRectF(0, 0, w, 1e6), wrap, text).height();
    }
    /// Draws `text` at the cursor (wrapped) and advances by its height.
    void paragraph(const QString& text, const QFont& f, const QColor& colour,
                   double spaceAfter = 0.0) {
        const double h = textHeight(text, f, width());
        ensure(h);
        if (draw_) {
            painter_.setFont(f);
            painter_.setPen(colour);
            painter_.drawText(QRectF(left(), y_, width(), h), Qt::TextWordWrap, text);
        }
        y_ += h + spaceAfter;
    }
    void text(const QRectF& box, const QString& text, const QFont& f, const QColor& colour,
              int flags) {
        if (draw_) {
            painter_.setFont(f);
            painter_.setPen(colour);
            painter_.drawText(box, flags, text);
        }
    }
    void rule(double at, const QColor& colour, double thicknessMm) {
        if (draw_) {
            painter_.setPen(QPen(colour, mm(thicknessMm)));
            painter_.drawLine(QPointF(left(), at), QPointF(left() + width(), at));
        }
    }
    void fill(const QRectF& box, const QColor& colour) {
        if (draw_) {
            painter_.fillRect(box, colour);
        }
    }

    /// A section heading kept together with `keep` of what follows.
    void heading(const QString& title, double keep) {
        const QFont f = font(11.0, true);
        const double h = textHeight(title, f, width());
        y_ += mm(5.0);
        ensure(h + mm(2.5) + keep);
        text(QRectF(left(), y_, width(), h), title, f, kAccent, Qt::AlignLeft | Qt::AlignBottom);
        y_ += h + mm(0.8);
        rule(y_, kRule, 0.25);
        y_ += mm(2.0);
    }

  private:
    QPainter& painter_;
    QPdfWriter& writer_;
    QRectF content_;
    bool draw_;
    double y_;
    int page_ = 1;
    std::function<void(int)> pageDone_ = [](int) {};
};

/// Label / value pairs in `columns` columns (labels muted, values ink).
/// Values wrap at word boundaries, or anywhere with `wrapAnywhere` (paths).
void fieldGrid(Flow& flow, const std::vector<std::pair<QString, QString>>& fields, int columns,
               bool wrapAnywhere = false) {
    const int wrap = wrapAnywhere ? Qt::TextWrapAnywhere : Qt::TextWordWrap;
    const QFont labelFont = font(8.0);
    const QFont valueFont = font(9.5);
    const double gap = mm(6.0);
    const double columnWidth = (flow.width() - gap * (columns - 1)) / columns;
    const double labelWidth = std::min(mm(40.0), columnWidth * 0.42);
    const double valueWidth = columnWidth - labelWidth;
    for (std::size_t row = 0; row * columns < fields.size(); ++row) {
        double h = 0.0;
        for (int c = 0; c < columns; ++c) {
            const std::size_t i = row * columns + c;
            if (i < fields.size()) {
                h = std::max({h, flow.textHeight(fields[i].second, valueFont, valueWidth, wrap),
                              flow.textHeight(fields[i].first, labelFont, labelWidth)});
            }
        }
        flow.ensure(h);
        for (int c = 0; c < columns; ++c) {
            const std::size_t i = row * columns + c;
            if (i >= fields.size()) {
                continue;
            }
            const double x = flow.left() + c * (columnWidth + gap);
            flow.text(QRectF(x, flow.y(), labelWidth, h), fields[i].first, labelFont, kMuted,
                      Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap);
            flow.text(QRectF(x + labelWidth, flow.y(), valueWidth, h), fields[i].second, valueFont,
                      kInk, Qt::AlignLeft | Qt::AlignVCenter | wrap);
        }
        flow.advance(h + mm(1.6));
    }
}

/// The view image across the content width, its legends painted over it as
/// on screen, and its caption.
void viewBlock(Flow& flow, const ReportView& view) {
    const double w = flow.width();
    const double h = w * view.image.height() / std::max(1, view.image.width());
    const QFont captionFont = font(8.0, false, true);
    const double captionHeight = flow.textHeight(qs(view.caption), captionFont, w);
    flow.ensure(h + mm(1.5) + captionHeight);
    const QRectF box(flow.left(), flow.y(), w, h);
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
        p.setPen(QPen(kRule, mm(0.2)));
        p.setBrush(Qt::NoBrush);
        p.drawRect(box);
    }
    flow.advance(h + mm(1.5));
    if (!view.caption.empty()) {
        flow.text(QRectF(flow.left(), flow.y(), w, captionHeight), qs(view.caption), captionFont,
                  kMuted, Qt::AlignLeft | Qt::TextWordWrap);
        flow.advance(captionHeight);
    }
}

void statsTable(Flow& flow, const ReportParameter& parameter) {
    QStringList headers = {QStringLiteral("Object"), QStringLiteral("Coverage"),
                           QStringLiteral("Min"), QStringLiteral("Mean"), QStringLiteral("Max")};
    if (parameter.thresholds.below) {
        headers << QStringLiteral("Area < ") +
                       withUnit(exact(*parameter.thresholds.below), parameter.unit);
    }
    if (parameter.thresholds.above) {
        headers << QStringLiteral("Area > ") +
                       withUnit(exact(*parameter.thresholds.above), parameter.unit);
    }
    const int columns = static_cast<int>(headers.size());
    // The object column takes what the numeric ones leave.
    const double numeric = mm(std::min(24.0, 110.0 / (columns - 1)));
    std::vector<double> widths(static_cast<std::size_t>(columns), numeric);
    widths[0] = flow.width() - numeric * (columns - 1);

    const QFont headFont = font(8.0, true);
    const QFont cellFont = font(9.0);
    const double pad = mm(1.6);
    double headHeight = 0.0;
    for (int c = 0; c < columns; ++c) {
        headHeight = std::max(
            headHeight,
            flow.textHeight(headers[c], headFont, widths[static_cast<std::size_t>(c)] - 2 * pad));
    }
    const double rowHeight = flow.textHeight(QStringLiteral("0"), cellFont, flow.width()) + 2 * pad;
    const auto row = [&](const QStringList& cells, const QFont& f, double h, const QColor& colour) {
        double x = flow.left();
        for (int c = 0; c < columns; ++c) {
            const double cw = widths[static_cast<std::size_t>(c)];
            const int align = (c == 0 ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter;
            flow.text(QRectF(x + pad, flow.y(), cw - 2 * pad, h), cells[c], f, colour,
                      align | Qt::TextWordWrap);
            x += cw;
        }
    };
    const auto header = [&] {
        flow.ensure(headHeight + 2 * pad + rowHeight);
        row(headers, headFont, headHeight + 2 * pad, kMuted);
        flow.advance(headHeight + 2 * pad);
        flow.rule(flow.y(), kInk, 0.3);
    };
    header();
    const QFont noteFont = font(7.5, false, true);
    const QString note =
        QStringLiteral("Values in ") +
        (parameter.unit.empty() ? QStringLiteral("the array's unit") : qs(parameter.unit)) +
        QStringLiteral(
            ". Coverage: share of the surface with finite values; the statistics are over "
            "that part. Mean and area shares are weighted by surface area, with values "
            "interpolated linearly within each triangle.");
    const double noteHeight = flow.textHeight(note, noteFont, flow.width()) + mm(1.5);
    int index = 0;
    for (const ParameterStats& s : parameter.stats) {
        const int before = flow.page();
        // The last row stays with the note below the table.
        const bool last = index + 1 == static_cast<int>(parameter.stats.size());
        flow.ensure(rowHeight + (last ? noteHeight : 0.0));
        if (flow.page() != before) {
            header();  // the table goes on: repeat its header
        }
        if (index % 2 == 1) {
            flow.fill(QRectF(flow.left(), flow.y(), flow.width(), rowHeight), kZebra);
        }
        QStringList cells = {qs(s.object.empty() ? std::string("(unnamed)") : s.object),
                             percent(s.coveredFraction), number(s.min), number(s.mean),
                             number(s.max)};
        if (parameter.thresholds.below) {
            cells << (s.fractionBelow ? percent(*s.fractionBelow) : QStringLiteral("\u2014"));
        }
        if (parameter.thresholds.above) {
            cells << (s.fractionAbove ? percent(*s.fractionAbove) : QStringLiteral("\u2014"));
        }
        row(cells, cellFont, rowHeight, kInk);
        flow.advance(rowHeight);
        ++index;
    }
    if (parameter.stats.empty()) {
        flow.paragraph(QStringLiteral("No object has finite values of this parameter."),
                       font(9.0, false, true), kMuted);
    }
    flow.rule(flow.y(), kRule, 0.25);
    flow.advance(mm(1.5));
    flow.paragraph(note, noteFont, kMuted);
}

QString solverText(const ReportSettings& s) {
    QString text = qs(std::string(vss::toString(s.vss.solver.kind)));
    if (s.vss.solver.kind == vss::SolverKind::Step) {
        text += QStringLiteral(", every %1th contour pixel").arg(s.vss.solver.step);
    }
    if (std::isnan(s.errorBound)) {
        text += QStringLiteral(" (no error bound)");
    } else if (s.errorBound == 0.0) {
        text += QStringLiteral(" (exact)");
    } else {
        text += QStringLiteral(" (max. error %1 of normalised depth)").arg(number(s.errorBound));
    }
    return text;
}

QString sexText(const ReportPatient& p) {
    if (!p.anonymise) {
        if (p.sex == "F") {
            return QStringLiteral("female");
        }
        if (p.sex == "M") {
            return QStringLiteral("male");
        }
        if (p.sex == "O") {
            return QStringLiteral("other");
        }
    }
    return qs(displayText(p, p.sex));
}

void paint(QPdfWriter& writer, const ReportContent& content) {
    QPainter painter;
    if (!painter.begin(&writer)) {
        throw IoError("cannot start the PDF painter");
    }
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    // Images as they are (Flate): JPEG would shift the colours of the view.
    painter.setRenderHint(QPainter::LosslessImageRendering);
    const QRect page = writer.pageLayout().paintRectPixels(kDpi);
    const QRectF contentRect(0.0, 0.0, page.width(), page.height() - mm(9.0));
    const QString created =
        QLocale::c().toString(content.created, QStringLiteral("yyyy-MM-dd HH:mm"));
    const QString zone = content.created.timeZoneAbbreviation();
    const QString software = QStringLiteral("VesselView ") + QString::fromLatin1(vv::kVersion);

    int pages = 1;
    for (const bool draw : {false, true}) {
        Flow flow(painter, writer, contentRect, draw);
        flow.onPageDone([&](int pageNumber) {
            const double top = page.height() - mm(6.0);
            painter.setPen(QPen(kRule, mm(0.25)));
            painter.drawLine(QPointF(0.0, top), QPointF(page.width(), top));
            QString left = software + QStringLiteral(" \u00b7 ") + qs(content.title) +
                           QStringLiteral(" \u00b7 ") + created + " " + zone;
            if (content.patient) {
                left += QStringLiteral(" \u00b7 ") +
                        qs(displayName(*content.patient, content.patient->name)) +
                        QStringLiteral(", ID ") +
                        qs(displayText(*content.patient, content.patient->id));
            }
            const QRectF box(0.0, top + mm(1.0), page.width(), mm(5.0));
            painter.setFont(font(7.0));
            painter.setPen(kMuted);
            painter.drawText(box, Qt::AlignLeft | Qt::AlignVCenter, left);
            painter.drawText(box, Qt::AlignRight | Qt::AlignVCenter,
                             QStringLiteral("Page %1 of %2").arg(pageNumber).arg(pages));
        });

        // Title block.
        const QFont titleFont = font(18.0, true);
        const double titleHeight =
            flow.textHeight(qs(content.title), titleFont, flow.width() * 0.65);
        const QFont metaFont = font(8.5);
        flow.text(QRectF(flow.left(), flow.y(), flow.width() * 0.65, titleHeight),
                  qs(content.title), titleFont, kInk,
                  Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap);
        const QString meta = software + QStringLiteral("\nCreated ") + created + " " + zone;
        flow.text(
            QRectF(flow.left() + flow.width() * 0.6, flow.y(), flow.width() * 0.4, titleHeight),
            meta, metaFont, kMuted, Qt::AlignRight | Qt::AlignVCenter);
        flow.advance(std::max(titleHeight, flow.textHeight(meta, metaFont, flow.width())) +
                     mm(2.0));
        flow.rule(flow.y(), kAccent, 0.6);
        flow.advance(mm(1.0));

        if (content.patient) {
            const ReportPatient& p = *content.patient;
            flow.heading(QStringLiteral("Patient and study"), mm(12.0));
            fieldGrid(
                flow,
                {{QStringLiteral("Patient name"), qs(displayName(p, p.name))},
                 {QStringLiteral("Patient ID"), qs(displayText(p, p.id))},
                 {QStringLiteral("Birth date"), qs(displayDate(p, p.birthDate))},
                 {QStringLiteral("Sex"), sexText(p)},
                 {QStringLiteral("Study date"), qs(displayDate(p, p.studyDate))},
                 {QStringLiteral("Accession number"), qs(displayText(p, p.accession))},
                 {QStringLiteral("Referring physician"), qs(displayName(p, p.referringPhysician))}},
                2);
        }

        if (!content.sources.empty()) {
            flow.heading(QStringLiteral("Data"), mm(8.0));
            std::vector<std::pair<QString, QString>> files;
            if (content.patient && content.patient->anonymise) {
                // Folder and file names of patient data often carry names or IDs.
                files.emplace_back(QStringLiteral("Source files"),
                                   QStringLiteral("%1 (names withheld: anonymised report)")
                                       .arg(content.sources.size()));
            } else {
                for (const auto& source : content.sources) {
                    const QFileInfo info(QFile::decodeName(source.c_str()));
                    files.emplace_back(
                        files.empty() ? QStringLiteral("Source files") : QString(),
                        info.fileName() + QStringLiteral("  \u2014  ") + info.absolutePath());
                }
            }
            fieldGrid(flow, files, 1, true);
        }

        const auto viewSection = [&](const QString& title, const ReportView& view) {
            const double h = flow.width() * view.image.height() / std::max(1, view.image.width());
            flow.heading(title, h);
            viewBlock(flow, view);
        };
        viewSection(QStringLiteral("View"), content.view);
        if (content.secondView) {
            viewSection(QStringLiteral("Second view"), *content.secondView);
        }

        if (content.parameter) {
            const ReportParameter& parameter = *content.parameter;
            QString title = QStringLiteral("Parameter statistics \u2014 ") + qs(parameter.name);
            if (!parameter.unit.empty()) {
                title += QStringLiteral(" (") + qs(parameter.unit) + QStringLiteral(")");
            }
            flow.heading(title, mm(20.0));
            QString scale = QStringLiteral("Colour map ") +
                            qs(std::string(colormaps::displayName(parameter.map))) +
                            (parameter.bins >= 2 ? QStringLiteral(" in %1 bins").arg(parameter.bins)
                                                 : QString()) +
                            QStringLiteral(" over ") + number(parameter.range.first) +
                            QStringLiteral(" \u2013 ") +
                            withUnit(number(parameter.range.second), parameter.unit) +
                            QStringLiteral("; values outside are shown in the end colours.");
            flow.paragraph(scale, font(8.5), kInk, mm(2.0));
            statsTable(flow, parameter);
        }

        const ReportSettings& s = content.settings;
        flow.heading(QStringLiteral("Rendering settings"), mm(20.0));
        std::vector<std::pair<QString, QString>> settings;
        if (s.vss.enabled) {
            settings.emplace_back(QStringLiteral("Void Space Surface"), QStringLiteral("on"));
            settings.emplace_back(QStringLiteral("Depth colour scale"),
                                  qs(std::string(colormaps::displayName(s.vss.scale))));
            settings.emplace_back(QStringLiteral("Interpolation power p"), exact(s.vss.solver.p));
            settings.emplace_back(QStringLiteral("Solver"), solverText(s));
            settings.emplace_back(QStringLiteral("Iso-lines"), s.vss.isoLines > 0
                                                                   ? QString::number(s.vss.isoLines)
                                                                   : QStringLiteral("none"));
        } else {
            settings.emplace_back(QStringLiteral("Void Space Surface"), QStringLiteral("off"));
        }
        settings.emplace_back(QStringLiteral("Vessel depth cue"),
                              qs(std::string(render::displayName(s.cue.cue))));
        settings.emplace_back(QStringLiteral("Ambient occlusion"),
                              s.ambientOcclusion ? QStringLiteral("on") : QStringLiteral("off"));
        settings.emplace_back(QStringLiteral("Anti-aliasing (FXAA)"),
                              s.antialiasing ? QStringLiteral("on") : QStringLiteral("off"));
        if (!s.view.empty()) {
            settings.emplace_back(QStringLiteral("Camera"), qs(s.view));
        }
        fieldGrid(flow, settings, 2);

        flow.heading(QStringLiteral("Findings"), mm(14.0));
        if (content.findings.empty()) {
            flow.paragraph(QStringLiteral("No findings entered."), font(9.5, false, true), kMuted);
        } else {
            flow.paragraph(qs(content.findings), font(10.0), kInk);
        }
        flow.finish();
        pages = flow.page();
    }
    painter.end();
}

}  // namespace

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
         {&content.view, content.secondView ? &*content.secondView : nullptr}) {
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
        writer.setResolution(kDpi);
        writer.setPageLayout(
            QPageLayout(pageSize(paper), QPageLayout::Portrait,
                        QMarginsF(kMarginSideMm, kMarginTopMm, kMarginSideMm, kMarginBottomMm),
                        QPageLayout::Millimeter));
        writer.setTitle(qs(content.title));
        writer.setCreator(QStringLiteral("VesselView ") + QString::fromLatin1(vv::kVersion));
        paint(writer, content);
    }
    buffer.close();
    return bytes;
}

void writePdfBytes(const std::filesystem::path& path, const QByteArray& pdf) {
    writeAtomically(path, [&](const std::filesystem::path& temporary) {
        QFile file(QFile::decodeName(temporary.c_str()));
        if (!file.open(QIODevice::WriteOnly) || file.write(pdf) != pdf.size() || !file.flush()) {
            throw IoError(path, "cannot write the PDF report: " + file.errorString().toStdString());
        }
        file.close();
    });
}

void writePdf(const std::filesystem::path& path, const ReportContent& content, PaperSize paper) {
    writePdfBytes(path, renderPdf(content, paper));
}

}  // namespace vv::report
