// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/PacsWidgets.h"

#include <QCoreApplication>
#include <QDate>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QTableWidget>
#include <cmath>

#include "gui/DateText.h"
#include "gui/EngineTexts.h"

namespace vv::gui {

namespace {

constexpr double kMaxGb = 100000.0;

}  // namespace

QTableWidget* makeResultTable(QWidget* parent, const QString& objectName,
                              const QStringList& headers) {
    auto* table = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    table->setObjectName(objectName);
    table->setHorizontalHeaderLabels(headers);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->setSelectionMode(QAbstractItemView::SingleSelection);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->verticalHeader()->hide();
    table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table->horizontalHeader()->setStretchLastSection(true);
    return table;
}

void showAsProblem(QLabel* label, bool problem) {
    label->setStyleSheet(problem ? QStringLiteral("color: #b00020;") : QString());
}

void showProblemText(QLabel* label, const ProblemText& problem) {
    label->setText(problem.summary);
    label->setToolTip(problem.details.isEmpty()
                          ? QString()
                          : QCoreApplication::translate("vv::gui::PacsWidgets", "Details: %1")
                                .arg(problem.details));
    showAsProblem(label, true);
}

QLabel* makeErrorLabel(QWidget* parent, const QString& objectName) {
    auto* label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    showAsProblem(label, true);
    label->hide();
    return label;
}

QDialogButtonBox* makeOkCancel(QDialog* dialog) {
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, dialog);
    QObject::connect(buttons, &QDialogButtonBox::accepted, dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    return buttons;
}

QString studyDateText(const std::string& dicomDate) {
    const QDate date =
        QDate::fromString(QString::fromStdString(dicomDate), QStringLiteral("yyyyMMdd"));
    if (!date.isValid()) {
        return QString::fromStdString(dicomDate);
    }
    // Day and month in an order no reader can take the other way round (not
    // "3/4/2025"), and as the PDF report writes dates in the same language.
    return QLocale().toString(date, uiDateFormat());
}

QDoubleSpinBox* makeGigabyteBox(QWidget* parent, const QString& objectName, int decimals,
                                double minimumGb) {
    auto* box = new QDoubleSpinBox(parent);
    box->setObjectName(objectName);
    box->setRange(minimumGb, kMaxGb);
    box->setDecimals(decimals);
    box->setSuffix(QCoreApplication::translate("vv::gui::PacsWidgets", " GB"));
    return box;
}

QString quantityText(double value, const char* unit) {
    return QLocale().toString(value, 'g', 6) + QChar(0x00A0) + QLatin1String(unit);
}

std::uint64_t bytesOf(const QDoubleSpinBox* box) {
    return static_cast<std::uint64_t>(std::llround(box->value() * kBytesPerGb));
}

void setBytes(QDoubleSpinBox* box, std::uint64_t bytes) {
    box->setValue(static_cast<double>(bytes) / kBytesPerGb);
}

}  // namespace vv::gui
