// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QImage>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "gui/pacs/PacsSettings.h"
#include "gui/pacs/SendJob.h"
#include "vv/report/ReportJob.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTemporaryDir;
class QTreeWidget;

namespace vv::gui {

class ExportWorker;
struct ProblemText;
class ViewerWidget;

/// DICOM > Send to PACS…: sends the report of the view on screen to a
/// configured node. It names the data on screen (a DICOM series by its
/// description, never its UID folder) and lets the user review and edit the
/// report's findings (dataLabel(), findingsEdit()). The user picks the node and what to send (the
/// view as DICOM Secondary Capture, the PDF report as DICOM Encapsulated PDF, and for a DICOM scene
/// with a segmentation the segmentation as DICOM SEG); Send makes them in a temporary folder and
/// C-STOREs them on an ExportWorker (never on the GUI thread) with a progress bar, Cancel stopping
/// it. Afterwards a table says per instance whether the node accepted it (with the DIMSE status
/// when not), and a summary line says "2 of 2 accepted by ORTHANC@host:port" (UI locale) or, when
/// the network failed, what failed (refused connection, rejected association, timeout, TLS),
/// translated. The dialog stays usable for another send. When other data is shown (showScene()), it
/// forgets the last send's results, stops a send in progress and offers the new data.
class SendDialog : public QDialog {
    Q_OBJECT

  public:
    /// `source` names the data on screen (DICOM data: the report joins its study).
    SendDialog(const ViewerWidget& viewer, report::ReportSource source, PacsSettings settings,
               QWidget* parent = nullptr);
    ~SendDialog() override;
    SendDialog(const SendDialog&) = delete;
    SendDialog& operator=(const SendDialog&) = delete;
    SendDialog(SendDialog&&) = delete;
    SendDialog& operator=(SendDialog&&) = delete;

    /// The slice with its segmentation for the PDF (DICOM data): asked for
    /// when Send makes the report (the slice shown then); nullopt = none.
    using SliceSource = std::function<std::optional<std::pair<QImage, QString>>()>;
    void setSliceSource(SliceSource source);
    /// The findings printed in the report (editable in findingsEdit()).
    void setFindings(const QString& findings);
    /// The PDF report exported last for the data (File > Export Report) and
    /// its findings: reportChooser() offers to send it as it is (and chooses
    /// it; findingsEdit() then shows its findings, read-only); an empty
    /// `pdf` = none, only a new report.
    void setExportedReport(const QString& pdf, const QString& findings);
    /// Other data is on screen: `source` (with its segmentation `labelMap`,
    /// may be null, and its `findings`) replaces what the dialog offered. The
    /// last send's results are cleared; a send in progress is stopped and
    /// its outcome dropped (the summary says so).
    void showScene(report::ReportSource source, std::shared_ptr<const scene::LabelMap> labelMap,
                   const QString& findings, const QString& exportedPdf,
                   const QString& exportedFindings);
    /// Offers `labelMap` (the segmentation of the DICOM series the source
    /// names) as DICOM SEG: segmentationBox() enabled and checked. Without a
    /// map or for a scene not from DICOM the box stays disabled.
    void setSegmentation(std::shared_ptr<const scene::LabelMap> labelMap);
    /// While `reason` is not empty nothing can be sent and the Send button's
    /// tooltip says why (a segmentation preview on screen that was not applied).
    void setBlocked(const QString& reason);

    /// "Data: <series name or file names>": what the report is about.
    [[nodiscard]] QLabel* dataLabel() const noexcept { return data_; }
    /// The report's findings (free text, printed first); read-only while
    /// the exported report is chosen (its findings are in it).
    [[nodiscard]] QPlainTextEdit* findingsEdit() const noexcept { return findings_; }
    /// Which report: item 0 a new one of the view (data empty), item 1 the
    /// exported one (data: its path) when there is one.
    [[nodiscard]] QComboBox* reportChooser() const noexcept { return reportChoice_; }
    /// Item data: the node's name.
    [[nodiscard]] QComboBox* nodeChooser() const noexcept { return node_; }
    [[nodiscard]] QCheckBox* secondaryCaptureBox() const noexcept { return sc_; }
    [[nodiscard]] QCheckBox* pdfBox() const noexcept { return pdf_; }
    [[nodiscard]] QCheckBox* segmentationBox() const noexcept { return seg_; }
    /// The planning measurements as a DICOM SR (enabled by setMeasurements()).
    [[nodiscard]] QCheckBox* measurementsBox() const noexcept { return sr_; }
    /// The planning measurements of the scene (the Analysis panel's): the
    /// new report's Measurements section and the SR's groups; checks the
    /// measurements box. Without them the box is off and says why.
    void setMeasurements(report::ReportMeasurementSection section,
                         std::vector<dicom::SrGroup> groups);
    [[nodiscard]] QPushButton* sendButton() const noexcept { return send_; }
    [[nodiscard]] QProgressBar* progressBar() const noexcept { return progress_; }
    /// One top-level row per instance: what it is, and the node's answer.
    [[nodiscard]] QTreeWidget* resultTable() const noexcept { return results_; }
    /// The outcome of the last send (or why Send is not possible).
    [[nodiscard]] QLabel* summaryLabel() const noexcept { return summary_; }
    [[nodiscard]] bool isSending() const noexcept { return worker_ != nullptr; }

    /// Starts sending (what Send does); nothing when sending or nothing to send.
    void send();
    /// Cancels a send in progress (what Cancel does while sending).
    void cancelSend();

    void reject() override;

  signals:
    /// A send ended (accepted, refused, failed or cancelled); summaryLabel() says how.
    void sendFinished();
    /// The user edited the findings (to keep them for the data's next report).
    void findingsEdited(const QString& findings);

  private:
    void updateButtons();
    /// The findings of the report chosen in reportChooser().
    void showFindings();
    /// `peer`: the node's AE@host:port; `target`: nodeText() (its name too).
    void showOutcome(const SendOutcome& outcome, const QString& peer, const QString& target);
    /// What failed, naming `target`, in the UI language; the detail apart.
    [[nodiscard]] ProblemText failureText(const SendOutcome& outcome, const QString& target) const;
    /// Shows `summary` as plain information.
    void finish(const QString& summary);
    /// Shows `problem` as a problem (its details as the tooltip).
    void finish(const ProblemText& problem);
    /// Stops the send in progress and drops its outcome.
    void abandonSend();

    const ViewerWidget& viewer_;
    report::ReportSource source_;
    PacsSettings settings_;
    SliceSource slice_;
    QLabel* data_ = nullptr;
    QPlainTextEdit* findings_ = nullptr;
    QComboBox* reportChoice_ = nullptr;
    QString newFindings_;       ///< the findings of a new report
    QString exportedFindings_;  ///< the findings in the exported report
    QString blocked_;           ///< setBlocked()
    QComboBox* node_ = nullptr;
    QCheckBox* sc_ = nullptr;
    QCheckBox* pdf_ = nullptr;
    QCheckBox* seg_ = nullptr;
    QCheckBox* sr_ = nullptr;
    std::optional<report::ReportMeasurementSection> measurements_;
    std::vector<dicom::SrGroup> measurementGroups_;
    std::shared_ptr<const scene::LabelMap> labelMap_;
    QPushButton* send_ = nullptr;
    QPushButton* close_ = nullptr;
    QProgressBar* progress_ = nullptr;
    QLabel* stage_ = nullptr;
    QTreeWidget* results_ = nullptr;
    QLabel* summary_ = nullptr;
    std::unique_ptr<QTemporaryDir> folder_;  ///< the outputs of the last send
    ExportWorker* worker_ = nullptr;         ///< the send in progress (a child)
};

}  // namespace vv::gui
