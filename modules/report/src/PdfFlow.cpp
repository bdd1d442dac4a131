// SPDX-License-Identifier: GPL-3.0-or-later
#include "PdfFlow.h"

#include <QFontMetricsF>
#include <QPageLayout>
#include <QRegularExpression>
#include <algorithm>

#include "ReportText.h"
#include "vv/core/Error.h"

namespace vv::report::pdf {

namespace {

const char* const kFontFamily = "DejaVu Sans";

struct GridMetrics {
    QFont labelFont = font(8.0);
    QFont valueFont = font(9.5);
    double gap = mm(6.0);
    double columnWidth = 0.0;
    double labelWidth = 0.0;
    double valueWidth = 0.0;
};

GridMetrics gridMetrics(const Flow& flow, int columns) {
    GridMetrics m;
    m.columnWidth = (flow.width() - m.gap * (columns - 1)) / columns;
    m.labelWidth = std::min(mm(40.0), m.columnWidth * 0.42);
    m.valueWidth = m.columnWidth - m.labelWidth;
    return m;
}

double rowHeight(const Flow& flow, const GridMetrics& m, const Fields& fields, int columns,
                 std::size_t row) {
    double h = 0.0;
    for (int c = 0; c < columns; ++c) {
        const std::size_t i = row * columns + c;
        if (i < fields.size()) {
            h = std::max({h, flow.textHeight(fields[i].second, m.valueFont, m.valueWidth),
                          flow.textHeight(fields[i].first, m.labelFont, m.labelWidth)});
        }
    }
    return h;
}

constexpr double kRowGapMm = 1.6;

}  // namespace

QFont font(double points, bool bold, bool italic) {
    QFont f(QString::fromLatin1(kFontFamily));
    f.setPointSizeF(points);
    f.setBold(bold);
    f.setItalic(italic);
    f.setStyleHint(QFont::SansSerif);
    return f;
}

void Flow::ensure(double height) {
    if (y_ + height > content_.bottom() && y_ > content_.top()) {
        newPage();
    }
}

void Flow::newPage() {
    if (draw_) {
        pageDone_(page_);
        writer_.newPage();
    }
    ++page_;
    y_ = content_.top();
}

void Flow::finish() {
    if (draw_) {
        pageDone_(page_);
    }
}

double Flow::textHeight(const QString& text, const QFont& f, double w, int wrap) const {
    const QFontMetricsF fm(f, &writer_);
    return fm.boundingRect(QRectF(0, 0, w, 1e6), wrap, text).height();
}

double Flow::widestWord(const QString& text, const QFont& f) const {
    const QFontMetricsF fm(f, &writer_);
    double widest = 0.0;
    for (const QString& word :
         text.split(QRegularExpression(QStringLiteral("\\s")), Qt::SkipEmptyParts)) {
        widest = std::max(widest, fm.horizontalAdvance(word));
    }
    return widest;
}

double Flow::paragraphInset(const QString& text, const QFont& f) const {
    // A glyph that reaches left of its origin (an italic J) would cross the
    // margin at the start of a line: such a paragraph is inset by the most
    // any of its glyphs reaches.
    double inset = 0.0;
    if (f.italic()) {
        const QFontMetricsF fm(f, &writer_);
        for (const QChar c : text) {
            inset = std::max(inset, -fm.leftBearing(c));
        }
    }
    return inset;
}

double Flow::paragraphHeight(const QString& text, const QFont& f) const {
    return textHeight(text, f, width() - paragraphInset(text, f));
}

void Flow::paragraph(const QString& text, const QFont& f, const QColor& colour, double spaceAfter) {
    const double inset = paragraphInset(text, f);
    const double h = textHeight(text, f, width() - inset);
    ensure(h);
    if (draw_) {
        painter_.setFont(f);
        painter_.setPen(colour);
        painter_.drawText(QRectF(left() + inset, y_, width() - inset, h), Qt::TextWordWrap, text);
    }
    y_ += h + spaceAfter;
}

void Flow::text(const QRectF& box, const QString& text, const QFont& f, const QColor& colour,
                int flags) {
    if (draw_) {
        painter_.setFont(f);
        painter_.setPen(colour);
        painter_.drawText(box, flags, text);
    }
}

void Flow::rule(double at, const QColor& colour, double thicknessMm) {
    if (draw_) {
        // Flat ends: the rule ends at the content's edges, not half its width beyond.
        painter_.setPen(QPen(QBrush(colour), mm(thicknessMm), Qt::SolidLine, Qt::FlatCap));
        painter_.drawLine(QPointF(left(), at), QPointF(left() + width(), at));
    }
}

void Flow::fill(const QRectF& box, const QColor& colour) {
    if (draw_) {
        painter_.fillRect(box, colour);
    }
}

namespace {
QFont headingFont() {
    return font(11.0, true);
}
}  // namespace

double Flow::headingHeight(const QString& title) const {
    return textHeight(title, headingFont(), width()) + mm(2.8);
}

void Flow::heading(const QString& title, double keep) {
    const QFont f = headingFont();
    const double h = textHeight(title, f, width());
    y_ += mm(5.0);
    // Kept with what follows when that fits on a page at all.
    const double head = headingHeight(title);
    ensure(head + std::min(keep, pageHeight() - head));
    text(QRectF(left(), y_, width(), h), title, f, kAccent, Qt::AlignLeft | Qt::AlignBottom);
    y_ += h + mm(0.8);
    rule(y_, kRule, 0.25);
    y_ += mm(2.0);
}

double fieldGridHeight(const Flow& flow, const Fields& fields, int columns) {
    const GridMetrics m = gridMetrics(flow, columns);
    double total = 0.0;
    for (std::size_t row = 0; row * columns < fields.size(); ++row) {
        total += rowHeight(flow, m, fields, columns, row) + mm(kRowGapMm);
    }
    return total;
}

void fieldGrid(Flow& flow, const Fields& fields, int columns) {
    const GridMetrics m = gridMetrics(flow, columns);
    const double total = fieldGridHeight(flow, fields, columns);
    if (total <= flow.pageHeight()) {
        flow.ensure(total);  // never split a table that fits on a page
    }
    for (std::size_t row = 0; row * columns < fields.size(); ++row) {
        const double h = rowHeight(flow, m, fields, columns, row);
        flow.ensure(h);
        for (int c = 0; c < columns; ++c) {
            const std::size_t i = row * columns + c;
            if (i >= fields.size()) {
                continue;
            }
            const double x = flow.left() + c * (m.columnWidth + m.gap);
            flow.text(QRectF(x, flow.y(), m.labelWidth, h), fields[i].first, m.labelFont, kMuted,
                      Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap);
            flow.text(QRectF(x + m.labelWidth, flow.y(), m.valueWidth, h), fields[i].second,
                      m.valueFont, kInk, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap);
        }
        flow.advance(h + mm(kRowGapMm));
    }
}

Table::Table(const Flow& flow, QStringList headers, std::vector<QStringList> rows, QString note,
             QString emptyMessage)
    : headers_(std::move(headers)),
      rows_(std::move(rows)),
      note_(std::move(note)),
      empty_(std::move(emptyMessage)),
      pageHeight_(flow.pageHeight()) {
    const auto columns = static_cast<std::size_t>(headers_.size());
    const double numeric = mm(std::min(24.0, 110.0 / static_cast<double>(columns - 1)));
    widths_.assign(columns, numeric);
    double taken = 0.0;
    for (std::size_t c = 1; c < columns; ++c) {
        const auto column = static_cast<qsizetype>(c);
        double needed = flow.widestWord(headers_[column], headFont_);
        for (const QStringList& r : rows_) {
            needed = std::max(needed, flow.widestWord(r[column], cellFont_));
        }
        widths_[c] = std::max(numeric, needed + 2 * pad_ + mm(0.5));
        taken += widths_[c];
    }
    widths_[0] = flow.width() - taken;
    for (std::size_t c = 0; c < columns; ++c) {
        headHeight_ = std::max(headHeight_, flow.textHeight(headers_[static_cast<qsizetype>(c)],
                                                            headFont_, widths_[c] - 2 * pad_));
    }
    headHeight_ += 2 * pad_;
    rowHeight_ = flow.textHeight(QStringLiteral("0"), cellFont_, flow.width()) + 2 * pad_;
    // A row as tall as its tallest cell: a cell that wraps never runs over
    // the next row.
    for (const QStringList& r : rows_) {
        double tallest = rowHeight_;
        for (std::size_t c = 0; c < columns; ++c) {
            tallest = std::max(tallest, flow.textHeight(r[static_cast<qsizetype>(c)], cellFont_,
                                                        widths_[c] - 2 * pad_) +
                                            2 * pad_);
        }
        rowHeights_.push_back(tallest);
    }
    noteHeight_ = note_.isEmpty() ? 0.0 : flow.paragraphHeight(note_, noteFont_) + mm(1.5);
}

double Table::height() const {
    double rows = rows_.empty() ? rowHeight_ : 0.0;
    for (const double h : rowHeights_) {
        rows += h;
    }
    return headHeight_ + rows + mm(1.5) + noteHeight_;
}

double Table::keepHeight() const {
    if (height() <= pageHeight_) {
        return height();
    }
    return headHeight_ + (rowHeights_.empty() ? rowHeight_ : rowHeights_.front());
}

void Table::draw(Flow& flow) const {
    if (height() <= flow.pageHeight()) {
        flow.ensure(height());  // never split a table that fits on a page
    }
    header(flow);
    for (std::size_t index = 0; index < rows_.size(); ++index) {
        const int before = flow.page();
        // The last row stays with the note below the table.
        const bool last = index + 1 == rows_.size();
        const double h = rowHeights_[index];
        flow.ensure(h + (last ? noteHeight_ : 0.0));
        if (flow.page() != before) {
            header(flow);  // the table goes on: repeat its header
        }
        if (index % 2 == 1) {
            flow.fill(QRectF(flow.left(), flow.y(), flow.width(), h), kZebra);
        }
        row(flow, rows_[index], cellFont_, h, kInk);
        flow.advance(h);
    }
    if (rows_.empty()) {
        flow.paragraph(empty_, font(9.0, false, true), kMuted);
    }
    flow.rule(flow.y(), kRule, 0.25);
    flow.advance(mm(1.5));
    if (!note_.isEmpty()) {
        flow.paragraph(note_, noteFont_, kMuted);
    }
}

void Table::row(Flow& flow, const QStringList& cells, const QFont& f, double h,
                const QColor& colour) const {
    double x = flow.left();
    for (std::size_t c = 0; c < widths_.size(); ++c) {
        const double cw = widths_[c];
        const int align = (c == 0 ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter;
        flow.text(QRectF(x + pad_, flow.y(), cw - 2 * pad_, h), cells[static_cast<qsizetype>(c)], f,
                  colour, align | Qt::TextWordWrap);
        x += cw;
    }
}

void Table::header(Flow& flow) const {
    flow.ensure(headHeight_ + rowHeight_);
    row(flow, headers_, headFont_, headHeight_, kMuted);
    flow.advance(headHeight_);
    flow.rule(flow.y(), kInk, 0.3);
}

QPageSize pageSize(PaperSize paper) {
    return QPageSize(paper == PaperSize::A4 ? QPageSize::A4 : QPageSize::Letter);
}

void setUpPage(QPdfWriter& writer, PaperSize paper) {
    writer.setResolution(kDpi);
    writer.setPageLayout(
        QPageLayout(pageSize(paper), QPageLayout::Portrait,
                    QMarginsF(kMarginSideMm, kMarginTopMm, kMarginSideMm, kMarginBottomMm),
                    QPageLayout::Millimeter));
}

void paintPages(QPdfWriter& writer, const QString& footer, const std::function<void(Flow&)>& body) {
    QPainter painter;
    if (!painter.begin(&writer)) {
        throw IoError("cannot start the PDF painter");
    }
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    // Images as they are (Flate): JPEG would shift the colours of a view.
    painter.setRenderHint(QPainter::LosslessImageRendering);
    const QRect page = writer.pageLayout().paintRectPixels(kDpi);
    const QRectF content(0.0, 0.0, page.width(), page.height() - mm(9.0));
    int pages = 1;
    for (const bool draw : {false, true}) {
        Flow flow(painter, writer, content, draw);
        flow.onPageDone([&](int pageNumber) {
            const double top = page.height() - mm(6.0);
            painter.setPen(QPen(QBrush(kRule), mm(0.25), Qt::SolidLine, Qt::FlatCap));
            painter.drawLine(QPointF(0.0, top), QPointF(page.width(), top));
            const QRectF box(0.0, top + mm(1.0), page.width(), mm(5.0));
            painter.setFont(font(7.0));
            painter.setPen(kMuted);
            painter.drawText(box, Qt::AlignLeft | Qt::AlignVCenter, footer);
            painter.drawText(
                box, Qt::AlignRight | Qt::AlignVCenter,
                ReportText::tr("Page %1 of %2").arg(integer(pageNumber), integer(pages)));
        });
        body(flow);
        flow.finish();
        pages = flow.page();
    }
    painter.end();
}

}  // namespace vv::report::pdf
