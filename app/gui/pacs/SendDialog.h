// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QImage>
#include <QString>
#include <memory>

#include "gui/pacs/PacsSettings.h"
#include "gui/pacs/SendJob.h"
#include "vv/report/ReportJob.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTemporaryDir;
class QTreeWidget;

namespace vv::gui {

class ExportWorker;
class ViewerWidget;

/// DICOM > Send to PACS…: sends the report of the view on screen to a
/// configured node. The user picks the node and what to send (the view as
/// DICOM Secondary Capture, the PDF report as DICOM Encapsulated PDF, and for
/// a DICOM scene with a segmentation the segmentation as DICOM SEG);
/// Send makes them in a temporary folder and C-STOREs them on an
/// ExportWorker (never on the GUI thread) with a progress bar, Cancel
/// stopping it. Afterwards a table says per instance whether the node
/// accepted it (with the DIMSE status when not), and a summary line says
/// "2 of 2 accepted by ORTHANC@host:port" (UI locale) or, when the network
/// failed, what failed (refused connection, rejected association, timeout,
/// TLS), translated. The dialog stays usable for another send.
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

    /// Adds the slice with its segmentation to the PDF (DICOM data).
    void setSlice(const QImage& image, const QString& caption);
    /// Offers `labelMap` (the segmentation of the DICOM series the source
    /// names) as DICOM SEG: segmentationBox() enabled and checked. Without a
    /// map or for a scene not from DICOM the box stays disabled.
    void setSegmentation(std::shared_ptr<const scene::LabelMap> labelMap);

    /// Item data: the node's name.
    [[nodiscard]] QComboBox* nodeChooser() const noexcept { return node_; }
    [[nodiscard]] QCheckBox* secondaryCaptureBox() const noexcept { return sc_; }
    [[nodiscard]] QCheckBox* pdfBox() const noexcept { return pdf_; }
    [[nodiscard]] QCheckBox* segmentationBox() const noexcept { return seg_; }
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

  private:
    void updateButtons();
    void showOutcome(const SendOutcome& outcome, const QString& peer);
    [[nodiscard]] QString failureText(const SendOutcome& outcome, const QString& peer) const;
    void finish(const QString& summary);

    const ViewerWidget& viewer_;
    report::ReportSource source_;
    PacsSettings settings_;
    QImage slice_;
    QString sliceCaption_;
    QComboBox* node_ = nullptr;
    QCheckBox* sc_ = nullptr;
    QCheckBox* pdf_ = nullptr;
    QCheckBox* seg_ = nullptr;
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
