// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/study/StudyAnalysisDialog.h"

#include <QComboBox>
#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "gui/PathField.h"
#include "gui/study/StudyProblem.h"
#include "vv/core/Error.h"
#include "vv/report/StudyReport.h"
#include "vv/study/Results.h"

namespace vv::gui {
namespace {

std::filesystem::path pathOf(const QString& text) {
    return {text.trimmed().toStdString()};
}

}  // namespace

StudyAnalysisDialog::StudyAnalysisDialog(QWidget* parent)
    : QDialog(parent),
      files_(new QListWidget(this)),
      correction_(new QComboBox(this)),
      alpha_(new QDoubleSpinBox(this)),
      paper_(new QComboBox(this)),
      pdf_(new QLineEdit(this)),
      tables_(new QLineEdit(this)),
      analyseButton_(new QPushButton(tr("&Analyse"), this)),
      openPdf_(new QPushButton(tr("&Open the PDF"), this)),
      outcome_(new QTextBrowser(this)) {
    setWindowTitle(tr("Analyse Depth-Judgement Study"));
    auto* form = new QFormLayout(this);

    files_->setMinimumHeight(fontMetrics().height() * 5);
    // A long path shows its end (the file's name), the whole in its tooltip.
    files_->setTextElideMode(Qt::ElideLeft);
    files_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* fileButtons = new QVBoxLayout;
    auto* add = new QPushButton(tr("A&dd…"), this);
    auto* remove = new QPushButton(tr("Re&move"), this);
    fileButtons->addWidget(add);
    fileButtons->addWidget(remove);
    fileButtons->addStretch(1);
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(files_, 1);
    fileRow->addLayout(fileButtons);
    addBuddyRow(form, tr("Results &files:"), files_, fileRow);
    connect(add, &QPushButton::clicked, this, [this] {
        for (const QString& file : QFileDialog::getOpenFileNames(
                 this, tr("Results files of the study"), QString(), tr("Results (*.csv)"))) {
            addResultsFile(file);
        }
    });
    connect(remove, &QPushButton::clicked, this, [this] { delete files_->currentItem(); });

    correction_->addItem(tr("Bonferroni"), static_cast<int>(study::Correction::Bonferroni));
    correction_->addItem(tr("Holm"), static_cast<int>(study::Correction::Holm));
    form->addRow(tr("Post-hoc &correction:"), correction_);
    alpha_->setRange(0.001, 0.2);
    alpha_->setDecimals(3);
    alpha_->setSingleStep(0.01);
    alpha_->setValue(0.05);
    form->addRow(tr("Significance &level \u03b1:"), alpha_);
    paper_->addItem(tr("A4"), static_cast<int>(report::PaperSize::A4));
    paper_->addItem(tr("Letter"), static_cast<int>(report::PaperSize::Letter));
    // The paper the report dialog last used (ReportDialog's setting).
    paper_->setCurrentIndex(
        std::max(0, paper_->findData(QSettings().value(QStringLiteral("report/paper"), 0))));
    form->addRow(tr("&Paper:"), paper_);
    addBuddyRow(form, tr("PDF f&ile:"), pdf_,
                browseRow(pdf_, tr("The study's PDF"), tr("PDF (*.pdf)"), this));
    tables_->setPlaceholderText(tr("none"));
    showPath(tables_);
    auto* tablesRow = new QHBoxLayout;
    tablesRow->addWidget(tables_, 1);
    auto* browseTables = new QPushButton(tr("Browse…"), this);
    tablesRow->addWidget(browseTables);
    connect(browseTables, &QPushButton::clicked, this, [this] {
        const QString chosen =
            QFileDialog::getExistingDirectory(this, tr("Folder for the tables"), tables_->text());
        if (!chosen.isEmpty()) {
            tables_->setText(chosen);
        }
    });
    addBuddyRow(form, tr("&Tables (CSV) in:"), tables_, tablesRow);

    outcome_->setOpenLinks(false);
    outcome_->setMinimumHeight(fontMetrics().height() * 9);
    form->addRow(outcome_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(analyseButton_, QDialogButtonBox::ActionRole);
    buttons->addButton(openPdf_, QDialogButtonBox::ActionRole);
    openPdf_->setEnabled(false);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(analyseButton_, &QPushButton::clicked, this, [this] { static_cast<void>(analyse()); });
    connect(openPdf_, &QPushButton::clicked, this,
            [this] { QDesktopServices::openUrl(QUrl::fromLocalFile(pdf_->text().trimmed())); });
    connect(&watcher_, &QFutureWatcher<Outcome>::finished, this, &StudyAnalysisDialog::done);
    setMinimumWidth(fontMetrics().averageCharWidth() * 90);
}

void StudyAnalysisDialog::addResultsFile(const QString& file) {
    if (files_->findItems(file, Qt::MatchExactly).isEmpty()) {
        files_->addItem(file);
        files_->item(files_->count() - 1)->setToolTip(file);
    }
}

void StudyAnalysisDialog::setPdfPath(const QString& path) {
    pdf_->setText(path);
}

void StudyAnalysisDialog::setTablesFolder(const QString& folder) {
    tables_->setText(folder);
}

void StudyAnalysisDialog::setCorrection(study::Correction correction) {
    correction_->setCurrentIndex(correction_->findData(static_cast<int>(correction)));
}

QString StudyAnalysisDialog::outcome() const {
    return outcome_->toPlainText();
}

bool StudyAnalysisDialog::analyse() {
    if (watcher_.isRunning()) {
        return false;
    }
    std::vector<std::filesystem::path> inputs;
    inputs.reserve(static_cast<std::size_t>(files_->count()));
    for (int i = 0; i < files_->count(); ++i) {
        inputs.push_back(pathOf(files_->item(i)->text()));
    }
    const std::filesystem::path pdf = pathOf(pdf_->text());
    if (inputs.empty() || pdf.empty() || pdf.extension() != ".pdf") {
        outcome_->setPlainText(inputs.empty() ? tr("Add the study's results files.")
                                              : tr("Give the PDF a file name ending in .pdf."));
        return false;
    }
    study::AnalysisOptions options;
    options.alpha = alpha_->value();
    options.correction = static_cast<study::Correction>(correction_->currentData().toInt());
    const auto paper = static_cast<report::PaperSize>(paper_->currentData().toInt());
    const std::filesystem::path tables = pathOf(tables_->text());
    analyseButton_->setEnabled(false);
    openPdf_->setEnabled(false);
    outcome_->setPlainText(tr("Analysing…"));
    // Off the GUI thread: the files are read, the PDF drawn and written there.
    watcher_.setFuture(QtConcurrent::run([inputs, pdf, tables, options, paper]() -> Outcome {
        Outcome out;
        try {
            report::StudyReportContent content;
            for (const auto& input : inputs) {
                content.sources.push_back(input.filename().string());
            }
            out.analysis = study::analyseResultsFiles(inputs, options);
            report::writeStudyPdf(pdf, *out.analysis, content, paper);
            if (!tables.empty()) {
                std::error_code error;
                std::filesystem::create_directories(tables, error);
                if (error) {
                    throw IoError(tables, "cannot create the folder: " + error.message());
                }
                study::writeAnalysisTables(*out.analysis, tables);
            }
        } catch (const Error& e) {
            out.error = studyProblemText(e);
        }
        return out;
    }));
    return true;
}

void StudyAnalysisDialog::done() {
    const Outcome out = watcher_.result();
    analyseButton_->setEnabled(true);
    if (!out.error.isEmpty()) {
        outcome_->setPlainText(out.error);
        emit finished(false);
        return;
    }
    QStringList lines = report::studySummaryLines(*out.analysis);
    lines << tr("Written: %1").arg(pdf_->text().trimmed());
    outcome_->setPlainText(lines.join(QLatin1Char('\n')));
    openPdf_->setEnabled(true);
    emit finished(true);
}

}  // namespace vv::gui
