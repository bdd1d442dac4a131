// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/analysis/MeasurementTables.h"

#include <QHeaderView>
#include <QLabel>
#include <QScrollBar>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

namespace vv::gui {

namespace {

QString qs(const std::string& text) {
    return QString::fromStdString(text);
}

}  // namespace

MeasurementTables::MeasurementTables(QWidget* parent)
    : QScrollArea(parent), content_(new QWidget), layout_(new QVBoxLayout(content_)) {
    setObjectName(QStringLiteral("measurementTables"));
    setWidgetResizable(true);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    layout_->addStretch(1);
    setWidget(content_);
}

void MeasurementTables::clear() {
    for (QObject* child : content_->children()) {
        if (child->isWidgetType()) {
            delete child;
        }
    }
    tables_.clear();
    setMinimumWidth(0);
}

void MeasurementTables::setSection(const report::ReportMeasurementSection& section) {
    clear();
    int widest = 0;
    int at = 0;
    for (const report::MeasurementTable& t : section.tables) {
        auto* title = new QLabel(qs(t.title), content_);
        QFont bold = title->font();
        bold.setBold(true);
        title->setFont(bold);
        title->setToolTip(qs(t.note));
        title->setWordWrap(true);
        auto* table = new QTableWidget(static_cast<int>(t.rows.size()),
                                       static_cast<int>(t.columns.size()), content_);
        table->setObjectName(QStringLiteral("measurementTable"));
        table->setProperty("title", qs(t.title));
        QStringList headers;
        for (const std::string& c : t.columns) {
            headers << qs(c);
        }
        table->setHorizontalHeaderLabels(headers);
        table->verticalHeader()->hide();
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
        table->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        table->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        table->setToolTip(qs(t.note));
        for (std::size_t r = 0; r < t.rows.size(); ++r) {
            const report::MeasurementRow& row = t.rows[r];
            table->setItem(static_cast<int>(r), 0, new QTableWidgetItem(qs(row.label)));
            for (std::size_t c = 0; c < row.cells.size(); ++c) {
                auto* item = new QTableWidgetItem(qs(report::measurementCellText(row.cells[c])));
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
                if (!row.cells[c].value && !row.cells[c].blankNote.empty()) {
                    item->setToolTip(qs(row.cells[c].blankNote));
                }
                table->setItem(static_cast<int>(r), static_cast<int>(c) + 1, item);
            }
        }
        table->resizeColumnsToContents();
        table->resizeRowsToContents();
        int width = 2 * table->frameWidth();
        for (int c = 0; c < table->columnCount(); ++c) {
            width += table->columnWidth(c);
        }
        table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
        table->setMinimumWidth(width);
        int height = table->horizontalHeader()->height() + 2 * table->frameWidth();
        for (int r = 0; r < table->rowCount(); ++r) {
            height += table->rowHeight(r);
        }
        table->setFixedHeight(height);
        widest = std::max(widest, width);
        layout_->insertWidget(at++, title);
        layout_->insertWidget(at++, table);
        tables_ << table;
    }
    const QMargins m = layout_->contentsMargins();
    setMinimumWidth(widest + m.left() + m.right() + verticalScrollBar()->sizeHint().width() +
                    2 * frameWidth());
}

QTableWidget* MeasurementTables::table(const QString& title) const {
    for (QTableWidget* t : tables_) {
        if (t->property("title").toString() == title) {
            return t;
        }
    }
    return nullptr;
}

}  // namespace vv::gui
