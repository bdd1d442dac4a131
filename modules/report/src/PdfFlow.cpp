// SPDX-License-Identifier: GPL-3.0-or-later
#include "PdfFlow.h"

#include <QFontMetricsF>
#include <QRegularExpression>
#include <algorithm>

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

void Flow::paragraph(const QString& text, const QFont& f, const QColor& colour, double spaceAfter) {
    const double h = textHeight(text, f, width());
    ensure(h);
    if (draw_) {
        painter_.setFont(f);
        painter_.setPen(colour);
        painter_.drawText(QRectF(left(), y_, width(), h), Qt::TextWordWrap, text);
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

}  // namespace vv::report::pdf
