// SPDX-License-Identifier: GPL-3.0-or-later
// Laying the PDF report out top to bottom over pages: the cursor, page
// breaks, text, rules and label / value grids. Private to vv::report.
#pragma once

#include <QColor>
#include <QFont>
#include <QPageSize>
#include <QPainter>
#include <QPdfWriter>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <functional>
#include <utility>
#include <vector>

#include "vv/report/PdfReport.h"

namespace vv::report::pdf {

inline constexpr int kDpi = 300;
/// The page's margins (the footer lies in the content's last 9 mm).
inline constexpr double kMarginSideMm = 18.0;
inline constexpr double kMarginTopMm = 15.0;
inline constexpr double kMarginBottomMm = 15.0;

inline const QColor kInk(28, 32, 38);
inline const QColor kMuted(96, 104, 114);
inline const QColor kAccent(31, 78, 121);
inline const QColor kRule(190, 198, 206);
inline const QColor kZebra(242, 245, 248);
inline const QColor kWarning(150, 40, 30);

/// Millimetres in the report's pixels (300 dpi).
[[nodiscard]] constexpr double mm(double millimetres) {
    return millimetres / 25.4 * kDpi;
}

/// The report's font (DejaVu Sans) at `points`.
[[nodiscard]] QFont font(double points, bool bold = false, bool italic = false);

/// The cursor over the pages. Run twice: a dry run (draw = false) counts the
/// pages; the second run paints.
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
    /// The height of a page's content area.
    [[nodiscard]] double pageHeight() const noexcept { return content_.height(); }
    void advance(double dy) { y_ += dy; }

    /// Starts a new page unless `height` still fits on this one.
    void ensure(double height);
    void newPage();
    /// Called with the page's number when a page is complete (drawing run only).
    void onPageDone(std::function<void(int)> callback) { pageDone_ = std::move(callback); }
    void finish();

    /// Height of `text` in `f` wrapped to `width`.
    [[nodiscard]] double textHeight(const QString& text, const QFont& f, double w,
                                    int wrap = Qt::TextWordWrap) const;
    /// Width of the widest word of `text` in `f`: the least a box can be that
    /// wraps `text` without cutting a word.
    [[nodiscard]] double widestWord(const QString& text, const QFont& f) const;
    /// The height paragraph() takes for `text` in `f`.
    [[nodiscard]] double paragraphHeight(const QString& text, const QFont& f) const;
    /// Draws `text` at the cursor (wrapped; inset by what its glyphs reach
    /// left of their origin, as italic ones do) and advances by its height.
    void paragraph(const QString& text, const QFont& f, const QColor& colour,
                   double spaceAfter = 0.0);
    void text(const QRectF& box, const QString& text, const QFont& f, const QColor& colour,
              int flags);
    void rule(double at, const QColor& colour, double thicknessMm);
    void fill(const QRectF& box, const QColor& colour);
    /// The height heading() takes on a new page (without the space above it).
    [[nodiscard]] double headingHeight(const QString& title) const;
    /// A section heading kept on one page with `keep` of what follows (all
    /// of it when keep <= pageHeight() - headingHeight(title)).
    void heading(const QString& title, double keep);

  private:
    [[nodiscard]] double paragraphInset(const QString& text, const QFont& f) const;

    QPainter& painter_;
    QPdfWriter& writer_;
    QRectF content_;
    bool draw_;
    double y_;
    int page_ = 1;
    std::function<void(int)> pageDone_ = [](int) {};
};

/// The page of `paper`.
[[nodiscard]] QPageSize pageSize(PaperSize paper);

/// The report's page on `writer`: `paper`, portrait, the margins, 300 dpi.
void setUpPage(QPdfWriter& writer, PaperSize paper);

/// Paints a document onto `writer` (set up by setUpPage): `body` lays it out
/// through a Flow twice, a dry run counting the pages and the drawing run;
/// every page gets the footer: a rule, `footer` on the left, "Page n of N"
/// on the right. Throws IoError when the painter cannot start.
void paintPages(QPdfWriter& writer, const QString& footer, const std::function<void(Flow&)>& body);

/// Label / value pairs in `columns` columns (labels muted, values ink).
using Fields = std::vector<std::pair<QString, QString>>;

/// The height fieldGrid() takes.
[[nodiscard]] double fieldGridHeight(const Flow& flow, const Fields& fields, int columns);

/// Draws the grid at the cursor, on one page when it fits on one.
void fieldGrid(Flow& flow, const Fields& fields, int columns);

/// A table over pages: a header row (muted, repeated when the table goes on
/// to a new page), rows in zebra stripes (each as tall as its tallest cell), a rule and a note
/// below; on one page whenever it fits on one, its last row kept with the note. The first column is
/// left-aligned and takes what the others leave; every other column is right-aligned and as wide as
/// its header's longest word and its widest value need (no word is ever cut), at least its share of
/// 110 mm (24 mm at most).
class Table {
  public:
    /// `emptyMessage` is printed in place of the rows when there are none.
    Table(const Flow& flow, QStringList headers, std::vector<QStringList> rows, QString note,
          QString emptyMessage);

    /// The height of the whole table with its note.
    [[nodiscard]] double height() const;
    /// What a heading right above the table must keep with it (its `keep`):
    /// the whole table when draw() keeps it whole (it fits on a page), else
    /// the header and the first row — so the heading never stays behind on
    /// a page the table leaves.
    [[nodiscard]] double keepHeight() const;
    void draw(Flow& flow) const;

  private:
    void row(Flow& flow, const QStringList& cells, const QFont& f, double h,
             const QColor& colour) const;
    void header(Flow& flow) const;

    QStringList headers_;
    std::vector<QStringList> rows_;
    QString note_;
    QString empty_;
    std::vector<double> widths_;
    QFont headFont_ = font(8.0, true);
    QFont cellFont_ = font(9.0);
    QFont noteFont_ = font(7.5, false, true);
    double pad_ = mm(1.6);
    double headHeight_ = 0.0;
    double rowHeight_ = 0.0;          ///< of one line of cells
    std::vector<double> rowHeights_;  ///< each row's, its tallest cell's
    double noteHeight_ = 0.0;
    double pageHeight_ = 0.0;
};

}  // namespace vv::report::pdf
