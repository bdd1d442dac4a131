// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QScrollArea>

#include "vv/report/PdfReport.h"

class QTableWidget;
class QVBoxLayout;

namespace vv::gui {

/// The planning measurements as the report prints them (issue 35): each
/// table of a report::ReportMeasurementSection under its title, one table
/// widget each (its own columns: a long label in one table does not widen
/// another's numbers), values as the report writes them (the UI locale, the
/// unit), a blank one as a dash with why in its tooltip, the table's note in
/// the title's tooltip. Scrolls vertically; never horizontally: its minimum
/// width is what its widest table needs.
class MeasurementTables : public QScrollArea {
    Q_OBJECT

  public:
    explicit MeasurementTables(QWidget* parent = nullptr);

    /// Shows `section`'s tables (its figures are the report's).
    void setSection(const report::ReportMeasurementSection& section);
    void clear();

    /// The table titled `title` (as shown); nullptr if none.
    [[nodiscard]] QTableWidget* table(const QString& title) const;
    [[nodiscard]] const QList<QTableWidget*>& tables() const noexcept { return tables_; }

  private:
    QWidget* content_;
    QVBoxLayout* layout_;
    QList<QTableWidget*> tables_;
};

}  // namespace vv::gui
