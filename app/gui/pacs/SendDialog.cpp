// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/pacs/SendDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <cmath>
#include <utility>

#include "gui/EngineTexts.h"
#include "gui/ExportWorker.h"
#include "gui/ReportDialog.h"
#include "gui/ViewerWidget.h"
#include "gui/pacs/NetworkFailure.h"
#include "gui/pacs/PacsWidgets.h"

namespace vv::gui {
namespace {

constexpr int kWarningFirst = 0xB000;  ///< DIMSE warning statuses: 0xB000..0xBFFF
constexpr int kWarningLast = 0xBFFF;

QString qs(const std::string& s) {
    return QString::fromStdString(s);
}

/// "0xA700": the DIMSE status as the standard writes it (a code, not a number).
QString statusCode(std::uint16_t status) {
    return QStringLiteral("0x%1").arg(status, 4, 16, QLatin1Char('0'));
}

QString itemName(SendKind kind) {
    switch (kind) {
        case SendKind::SecondaryCapture:
            return SendDialog::tr("Report image (Secondary Capture)");
        case SendKind::EncapsulatedPdf:
            return SendDialog::tr("Report PDF (Encapsulated PDF)");
        case SendKind::MeasurementReport:
            return SendDialog::tr("Measurements (DICOM Structured Report)");
        case SendKind::Segmentation:
            break;
    }
    return SendDialog::tr("Segmentation (DICOM SEG)");
}

/// What the report is about, as the user knows it: the DICOM series by its
/// name (never its UID folder), the other files by their names.
QString dataName(const report::ReportSource& source) {
    if (source.syntheticDemo) {
        return SendDialog::tr("the synthetic demo tree");
    }
    QStringList names;
    if (!source.seriesName.empty()) {
        names << qs(source.seriesName);
    }
    for (const auto& file : source.files) {
        if (source.seriesName.empty() || file != source.dicomPath) {
            names << QFileInfo(QFile::decodeName(file.c_str())).fileName();
        }
    }
    return names.isEmpty() ? SendDialog::tr("the data on screen")
                           : names.join(QStringLiteral(", "));
}

}  // namespace

SendDialog::SendDialog(const ViewerWidget& viewer, report::ReportSource source,
                       PacsSettings settings, QWidget* parent)
    : QDialog(parent), viewer_(viewer), source_(std::move(source)), settings_(std::move(settings)) {
    setObjectName(QStringLiteral("sendDialog"));
    setWindowTitle(tr("Send to PACS"));
    data_ = new QLabel(this);
    data_->setObjectName(QStringLiteral("sendData"));
    data_->setWordWrap(true);
    data_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    findings_ = new QPlainTextEdit(this);
    findings_->setObjectName(QStringLiteral("sendFindings"));
    findings_->setPlaceholderText(tr("Findings, printed first in the report"));
    findings_->setTabChangesFocus(true);
    connect(findings_, &QPlainTextEdit::textChanged, this, [this] {
        newFindings_ = findings_->toPlainText();  // only a new report's are editable
        emit findingsEdited(newFindings_);
    });
    reportChoice_ = new QComboBox(this);
    reportChoice_->setObjectName(QStringLiteral("sendReportChoice"));
    reportChoice_->addItem(tr("A new report of the view, with the findings below"), QString());
    connect(reportChoice_, &QComboBox::currentIndexChanged, this, [this] {
        showFindings();
        updateButtons();
    });
    node_ = new QComboBox(this);
    node_->setObjectName(QStringLiteral("sendNode"));
    for (const PacsNode& node : settings_.nodes) {
        node_->addItem(tr("%1 (%2)").arg(qs(node.name), qs(pacs::describe(node.node))),
                       qs(node.name));
    }
    sc_ = new QCheckBox(tr("The view as an image (DICOM Secondary Capture)"), this);
    sc_->setObjectName(QStringLiteral("sendSecondaryCapture"));
    sc_->setChecked(true);
    pdf_ = new QCheckBox(tr("The PDF report (DICOM Encapsulated PDF)"), this);
    pdf_->setObjectName(QStringLiteral("sendPdf"));
    pdf_->setChecked(true);
    seg_ = new QCheckBox(tr("The segmentation (DICOM SEG)"), this);
    seg_->setObjectName(QStringLiteral("sendSegmentation"));
    seg_->setToolTip(tr("Only for data opened from DICOM and segmented"));
    sr_ = new QCheckBox(tr("The measurements (DICOM Structured Report)"), this);
    sr_->setObjectName(QStringLiteral("sendMeasurements"));
    sr_->setToolTip(tr("Find the centrelines first (Analysis panel)"));
    auto* what = new QVBoxLayout;
    what->addWidget(sc_);
    what->addWidget(pdf_);
    what->addWidget(seg_);
    what->addWidget(sr_);
    auto* form = new QFormLayout;
    form->addRow(tr("Data:"), data_);
    form->addRow(tr("&Report:"), reportChoice_);
    form->addRow(tr("&Findings:"), findings_);
    form->addRow(tr("PACS node:"), node_);
    form->addRow(tr("Send:"), what);

    progress_ = new QProgressBar(this);
    progress_->setObjectName(QStringLiteral("sendProgress"));
    progress_->setRange(0, 1000);
    progress_->setTextVisible(false);
    progress_->hide();
    stage_ = new QLabel(this);
    stage_->hide();
    results_ = new QTreeWidget(this);
    results_->setObjectName(QStringLiteral("sendResults"));
    results_->setColumnCount(2);
    results_->setHeaderLabels({tr("Instance"), tr("Answer of the node")});
    results_->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    results_->setRootIsDecorated(false);
    results_->setSelectionMode(QAbstractItemView::NoSelection);
    summary_ = new QLabel(this);
    summary_->setObjectName(QStringLiteral("sendSummary"));
    summary_->setWordWrap(true);
    summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    if (settings_.nodes.empty()) {
        summary_->setText(
            tr("No PACS node is set up yet: add one under DICOM > Preferences, then send."));
    }

    auto* buttons = new QDialogButtonBox(this);
    send_ = buttons->addButton(tr("&Send"), QDialogButtonBox::AcceptRole);
    send_->setObjectName(QStringLiteral("sendButton"));
    close_ = buttons->addButton(QDialogButtonBox::Close);
    connect(send_, &QPushButton::clicked, this, &SendDialog::send);
    connect(close_, &QPushButton::clicked, this, &SendDialog::reject);
    connect(sc_, &QCheckBox::toggled, this, &SendDialog::updateButtons);
    connect(pdf_, &QCheckBox::toggled, this, &SendDialog::updateButtons);
    connect(seg_, &QCheckBox::toggled, this, &SendDialog::updateButtons);
    connect(sr_, &QCheckBox::toggled, this, &SendDialog::updateButtons);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(progress_);
    layout->addWidget(stage_);
    layout->addWidget(results_, 1);
    layout->addWidget(summary_);
    layout->addWidget(buttons);
    resize(640, 520);
    data_->setText(dataName(source_));
    updateButtons();
}

SendDialog::~SendDialog() {
    delete worker_;  // cancels and waits for the step running
}

void SendDialog::setSliceSource(SliceSource source) {
    slice_ = std::move(source);
}

void SendDialog::setFindings(const QString& findings) {
    newFindings_ = findings;
    showFindings();
}

void SendDialog::showFindings() {
    const bool exported = !reportChoice_->currentData().toString().isEmpty();
    const QString& shown = exported ? exportedFindings_ : newFindings_;
    if (findings_->toPlainText() != shown) {
        const QSignalBlocker quiet(findings_);  // not an edit of the user's
        findings_->setPlainText(shown);
    }
}

void SendDialog::setExportedReport(const QString& pdf, const QString& findings) {
    exportedFindings_ = findings;
    while (reportChoice_->count() > 1) {
        reportChoice_->removeItem(1);
    }
    if (!pdf.isEmpty()) {
        reportChoice_->addItem(
            tr("The exported report %1, as it is").arg(QFileInfo(pdf).fileName()), pdf);
        reportChoice_->setItemData(1, QDir::toNativeSeparators(pdf), Qt::ToolTipRole);
        reportChoice_->setCurrentIndex(1);
    }
    showFindings();
    updateButtons();
}

void SendDialog::showScene(report::ReportSource source,
                           std::shared_ptr<const scene::LabelMap> labelMap, const QString& findings,
                           const QString& exportedPdf, const QString& exportedFindings) {
    const QString before = dataName(source_);
    const bool wasSending = worker_ != nullptr;
    abandonSend();
    source_ = std::move(source);
    data_->setText(dataName(source_));
    setFindings(findings);
    setExportedReport(exportedPdf, exportedFindings);
    results_->clear();
    finish(wasSending ? tr("Other data was opened: the send of %1 was stopped; nothing more "
                           "was sent.")
                            .arg(before)
                      : QString());
    setSegmentation(std::move(labelMap));
}

void SendDialog::abandonSend() {
    if (worker_ == nullptr) {
        return;
    }
    ExportWorker* old = std::exchange(worker_, nullptr);
    disconnect(old, nullptr, this, nullptr);  // its outcome is of the other data
    connect(old, &ExportWorker::finished, old, &QObject::deleteLater);
    old->cancel();
    progress_->hide();
    stage_->hide();
    updateButtons();
}

void SendDialog::setSegmentation(std::shared_ptr<const scene::LabelMap> labelMap) {
    labelMap_ = source_.dicomPath.empty() ? nullptr : std::move(labelMap);
    seg_->setChecked(labelMap_ != nullptr);
    updateButtons();
}

void SendDialog::setMeasurements(report::ReportMeasurementSection section,
                                 std::vector<dicom::SrGroup> groups) {
    measurements_ = std::move(section);
    measurementGroups_ = std::move(groups);
    sr_->setChecked(!measurementGroups_.empty());
    sr_->setToolTip(
        tr("The landmarks' sections, the lengths, the sizing table and the branches "
           "as a TID 1500 Measurement Report, read as data by a PACS"));
    updateButtons();
}

void SendDialog::setBlocked(const QString& reason) {
    blocked_ = reason;
    send_->setToolTip(reason);
    updateButtons();
}

void SendDialog::updateButtons() {
    const bool sending = worker_ != nullptr;
    const bool segmentation = labelMap_ != nullptr && seg_->isChecked();
    const bool measurements = !measurementGroups_.empty() && sr_->isChecked();
    send_->setEnabled(!sending && blocked_.isEmpty() && node_->count() > 0 &&
                      (sc_->isChecked() || pdf_->isChecked() || segmentation || measurements));
    node_->setEnabled(!sending);
    const bool exported = !reportChoice_->currentData().toString().isEmpty();
    reportChoice_->setEnabled(!sending);
    findings_->setReadOnly(sending || exported);
    findings_->setToolTip(exported ? tr("The exported report is sent with its own findings")
                                   : QString());
    sc_->setEnabled(!sending);
    pdf_->setEnabled(!sending);
    seg_->setEnabled(!sending && labelMap_ != nullptr);
    sr_->setEnabled(!sending && !measurementGroups_.empty());
    close_->setText(sending ? tr("Cancel") : tr("Close"));
}

void SendDialog::send() {
    const PacsNode* node = findNode(settings_, node_->currentData().toString().toStdString());
    if (worker_ != nullptr || node == nullptr || !viewer_.scene() || !blocked_.isEmpty()) {
        return;
    }
    folder_ = std::make_unique<QTemporaryDir>();
    if (!folder_->isValid()) {
        finish(ProblemText{tr("No temporary folder for the report could be made. Check the free "
                              "space and the permissions of the temporary folder."),
                           folder_->errorString()});
        return;
    }
    SendRequest request;
    report::ReportJobOptions& job = request.report;
    setReportView(viewer_, job);
    if (const auto slice = slice_ ? slice_() : std::nullopt) {
        job.slice = slice->first;
        job.sliceCaption = slice->second.toStdString();
    }
    job.findings = newFindings_.toStdString();
    job.existingPdf = QFile::encodeName(reportChoice_->currentData().toString()).toStdString();
    job.disclaimer = ReportDialog::disclaimer(QSettings()).toStdString();
    job.source = source_;
    request.secondaryCapture = sc_->isChecked();
    request.encapsulatedPdf = pdf_->isChecked();
    if (measurements_) {
        job.measurements = measurements_;  // a new report shows them too
        job.measurementGroups = measurementGroups_;
        request.measurementReport = sr_->isChecked();
    }
    if (labelMap_ != nullptr && seg_->isChecked()) {
        request.segmentation = labelMap_;
    }
    request.softwareVersion = VV_VERSION;
    request.me = settings_.me;
    request.node = node->node;
    request.folder = folder_->path().toStdString();

    const QString peer = qs(pacs::describe(node->node));
    auto outcome = std::make_shared<SendOutcome>();
    worker_ = new ExportWorker(
        tr("Sending the report to %1").arg(peer),
        [scene = viewer_.scene(), request, outcome](render::OffscreenRenderer& renderer,
                                                    const Progress& progress) {
            *outcome = runSendJob(renderer, *scene, request, progress);
            return QString();
        },
        this);
    connect(worker_, &ExportWorker::progressChanged, this,
            [this, peer](double fraction, const QString& stage) {
                progress_->setValue(static_cast<int>(std::lround(fraction * 1000.0)));
                stage_->setText(fraction < kReportShare ? stage : tr("Sending to %1…").arg(peer));
            });
    connect(worker_, &ExportWorker::succeeded, this,
            [this, outcome, peer, target = nodeText(qs(node->name), node->node)] {
                showOutcome(*outcome, peer, target);
            });
    connect(worker_, &ExportWorker::failed, this, [this] {
        const ProblemText& problem = worker_->problem();
        finish(ProblemText{tr("The report could not be made: %1").arg(problem.summary),
                           problem.details});
    });
    connect(worker_, &ExportWorker::cancelled, this,
            [this] { finish(tr("Cancelled: nothing more was sent.")); });
    connect(worker_, &ExportWorker::finished, this, [this] {
        worker_->deleteLater();
        worker_ = nullptr;
        progress_->hide();
        stage_->hide();
        updateButtons();
        emit sendFinished();
    });
    results_->clear();
    finish(QString());
    progress_->setValue(0);
    progress_->show();
    stage_->setText(tr("Making the report…"));
    stage_->show();
    worker_->start();
    updateButtons();
}

void SendDialog::cancelSend() {
    if (worker_ != nullptr) {
        worker_->cancel();
    }
}

void SendDialog::reject() {
    if (worker_ != nullptr) {
        cancelSend();  // Cancel while sending; the dialog stays to show the outcome
        return;
    }
    QDialog::reject();
}

void SendDialog::showOutcome(const SendOutcome& outcome, const QString& peer,
                             const QString& target) {
    results_->clear();
    std::size_t accepted = 0;
    for (std::size_t i = 0; i < outcome.items.size(); ++i) {
        auto* row = new QTreeWidgetItem(results_);
        row->setText(0, itemName(outcome.items[i].kind));
        QString answer = tr("Not sent");
        if (i < outcome.statuses.size()) {
            const pacs::SendStatus& status = outcome.statuses[i];
            accepted += status.accepted ? 1 : 0;
            answer = !status.accepted ? tr("Refused (status %1)").arg(statusCode(status.status))
                     : status.status >= kWarningFirst && status.status <= kWarningLast
                         ? tr("Accepted with a warning (status %1)").arg(statusCode(status.status))
                         : tr("Accepted");
        }
        row->setText(1, answer);
    }
    if (outcome.failure != SendFailure::None) {
        finish(failureText(outcome, target));
        return;
    }
    finish(tr("%L1 of %L2 accepted by %3")
               .arg(static_cast<qulonglong>(accepted))
               .arg(static_cast<qulonglong>(outcome.items.size()))
               .arg(peer));
}

ProblemText SendDialog::failureText(const SendOutcome& outcome, const QString& target) const {
    ProblemText problem;
    problem.details = qs(outcome.detail);
    switch (outcome.failure) {
        case SendFailure::Refused:
            problem.summary =
                tr("Nothing was sent: %1 refused the connection. Nobody listens at that host "
                   "and port, or a firewall blocks it.")
                    .arg(target);
            break;
        case SendFailure::Rejected:
            problem.summary =
                tr("Nothing was sent: %1 rejected the association. It may not know our AE "
                   "title %2, or the node's AE title is wrong.")
                    .arg(target, qs(settings_.me.aeTitle));
            break;
        case SendFailure::Timeout:
            problem.summary = tr("Nothing more was sent: %1 did not answer in time.").arg(target);
            break;
        case SendFailure::Tls:
            problem.summary = tr("Nothing was sent: the TLS connection to %1 failed. Check the "
                                 "certificates of both sides.")
                                  .arg(target);
            break;
        case SendFailure::PeerFailed:
            problem.summary =
                tr("The transfer to %1 failed: the PACS closed the connection or reported a "
                   "failure. The table says what was accepted before. Try again; if it keeps "
                   "happening, ask the PACS administrator.")
                    .arg(target);
            break;
        case SendFailure::None:
            break;
    }
    return problem;
}

void SendDialog::finish(const QString& summary) {
    summary_->setText(summary);
    summary_->setToolTip(QString());
    showAsProblem(summary_, false);
}

void SendDialog::finish(const ProblemText& problem) {
    showProblemText(summary_, problem);
}

}  // namespace vv::gui
