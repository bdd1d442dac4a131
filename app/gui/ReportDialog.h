// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "gui/ExportWorker.h"
#include "vv/report/ReportJob.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QSettings;
class QLineEdit;
class QPlainTextEdit;

namespace vv::gui {

class ViewerWidget;

/// Sets what a report shows of `viewer` (Export Report, Send to PACS): the
/// view as on screen (currentViewOptions() at the view's size: its depth
/// range pinned to the screen's), its caption and description, the legends
/// switch, and the second view's depth range: the one the user chose, not
/// the first view's pinned one (every legend describes its own image).
void setReportView(const ViewerWidget& viewer, report::ReportJobOptions& job);

/// File > Export Report…: the PDF report of the current view (its camera and
/// display settings, exactly what is on screen) with the options of
/// `vesselview-cli report`: paper (A4 / Letter), findings (free text), a
/// second view (a camera preset), the statistics thresholds (area below /
/// above a value; only with a parameter shown), the patient and study of
/// mesh data (DICOM data brings its own), anonymise (for DICOM data or an
/// entered patient), the disclaimer line, and optional DICOM Secondary
/// Capture, DICOM Encapsulated PDF and PNG outputs. It proposes report.pdf in
/// the last export folder (report-2.pdf, … when taken). accept() checks the
/// fields (a message box says what is wrong), asks before it replaces any
/// existing output (naming each), remembers the folder, paper,
/// anonymise choice and disclaimer (QSettings), and runs
/// report::runReportJob() on an ExportWorker with progress and Cancel.
class ReportDialog : public ExportDialog {
    Q_OBJECT

  public:
    /// `source`: the shown data files; its dicomPath is set when they came
    /// from DICOM (enables anonymise).
    ReportDialog(const ViewerWidget& viewer, report::ReportSource source,
                 QWidget* parent = nullptr);

    [[nodiscard]] QLineEdit* pdfEdit() const noexcept { return pdf_; }
    /// Items "A4", "Letter" (item data = report::PaperSize as int).
    [[nodiscard]] QComboBox* paperChooser() const noexcept { return paper_; }
    [[nodiscard]] QPlainTextEdit* findingsEdit() const noexcept { return findings_; }
    /// Item 0 "None" (empty data), then the view names (data = the name).
    [[nodiscard]] QComboBox* secondViewChooser() const noexcept { return secondView_; }
    [[nodiscard]] QCheckBox* belowBox() const noexcept { return below_; }
    [[nodiscard]] QDoubleSpinBox* belowValue() const noexcept { return belowValue_; }
    [[nodiscard]] QCheckBox* aboveBox() const noexcept { return above_; }
    [[nodiscard]] QDoubleSpinBox* aboveValue() const noexcept { return aboveValue_; }
    [[nodiscard]] QCheckBox* anonymiseBox() const noexcept { return anonymise_; }
    [[nodiscard]] QCheckBox* dicomScBox() const noexcept { return dicomSc_; }
    [[nodiscard]] QLineEdit* dicomScEdit() const noexcept { return dicomScPath_; }
    [[nodiscard]] QCheckBox* dicomPdfBox() const noexcept { return dicomPdf_; }
    [[nodiscard]] QLineEdit* dicomPdfEdit() const noexcept { return dicomPdfPath_; }
    [[nodiscard]] QCheckBox* pngBox() const noexcept { return png_; }
    /// The patient and study entered for mesh data (checkable; hidden for
    /// DICOM data, which carries its own).
    [[nodiscard]] QGroupBox* patientGroup() const noexcept { return patientGroup_; }
    [[nodiscard]] QLineEdit* patientNameEdit() const noexcept { return patientName_; }
    [[nodiscard]] QLineEdit* patientIdEdit() const noexcept { return patientId_; }
    [[nodiscard]] QLineEdit* birthDateEdit() const noexcept { return birthDate_; }
    [[nodiscard]] QComboBox* sexChooser() const noexcept { return sex_; }
    [[nodiscard]] QLineEdit* studyDateEdit() const noexcept { return studyDate_; }
    [[nodiscard]] QLineEdit* accessionEdit() const noexcept { return accession_; }
    [[nodiscard]] QLineEdit* referringEdit() const noexcept { return referring_; }
    [[nodiscard]] QLineEdit* disclaimerEdit() const noexcept { return disclaimer_; }
    [[nodiscard]] QLineEdit* pngEdit() const noexcept { return pngPath_; }

    /// Offers a slice of the volume with its segmentation in the PDF (DICOM
    /// data): a check box "Slice with segmentation" (on) under the second view.
    void setSlice(const QImage& image, const QString& caption);
    /// Null until setSlice().
    [[nodiscard]] QCheckBox* sliceBox() const noexcept { return sliceBox_; }

    /// Offers the planning measurements (the Analysis panel's): a check box
    /// "Measurements" (on) under the second view, and the optional DICOM
    /// Structured Report output (TID 1500, `groups`) after the others.
    void setMeasurements(report::ReportMeasurementSection section,
                         std::vector<dicom::SrGroup> groups);
    /// Null until setMeasurements().
    [[nodiscard]] QCheckBox* measurementsBox() const noexcept { return measurementsBox_; }
    [[nodiscard]] QCheckBox* dicomSrBox() const noexcept { return dicomSr_; }
    [[nodiscard]] QLineEdit* dicomSrEdit() const noexcept { return dicomSrPath_; }

    /// The job the fields describe (view = the viewer's, at its size).
    [[nodiscard]] report::ReportJobOptions jobOptions() const;

    /// The disclaimer line of reports and the About box: what `settings`
    /// holds under kDisclaimerKey, else report::defaultDisclaimer() (translated).
    [[nodiscard]] static QString disclaimer(const QSettings& settings);
    /// The QSettings key of the disclaimer line (an empty value = none).
    static constexpr const char* kDisclaimerKey = "report/disclaimer";
    /// What is wrong with the fields (no PDF name, two outputs on one file,
    /// an output over a data file, a missing folder); empty when fine.
    [[nodiscard]] QString problem() const override;
    /// The PDF and each output checked, as the fields give them.
    [[nodiscard]] QStringList outputFiles() const override;

  protected:
    ExportWorker* startExport() override;

  private:
    /// One optional output: a check box and a path, filled from the PDF's name.
    void addPatientFields();
    [[nodiscard]] std::optional<report::ReportPatient> enteredPatient() const;
    /// At form row `row`, or at the end (-1).
    QCheckBox* addOutput(const QString& label, QLineEdit*& edit, const QString& suffix,
                         const QString& filter, int row = -1);
    /// The PDF and each output checked, with what it is ("PDF report").
    [[nodiscard]] std::vector<std::pair<std::filesystem::path, QString>> outputs() const;

    const ViewerWidget& viewer_;
    report::ReportSource source_;
    QLineEdit* pdf_ = nullptr;
    QComboBox* paper_ = nullptr;
    QPlainTextEdit* findings_ = nullptr;
    QComboBox* secondView_ = nullptr;
    QCheckBox* sliceBox_ = nullptr;
    QImage slice_;
    QString sliceCaption_;
    QCheckBox* below_ = nullptr;
    QDoubleSpinBox* belowValue_ = nullptr;
    QCheckBox* above_ = nullptr;
    QDoubleSpinBox* aboveValue_ = nullptr;
    QCheckBox* anonymise_ = nullptr;
    QCheckBox* dicomSc_ = nullptr;
    QLineEdit* dicomScPath_ = nullptr;
    QCheckBox* dicomPdf_ = nullptr;
    QLineEdit* dicomPdfPath_ = nullptr;
    QCheckBox* png_ = nullptr;
    QLineEdit* pngPath_ = nullptr;
    QCheckBox* measurementsBox_ = nullptr;
    report::ReportMeasurementSection measurements_;
    std::vector<dicom::SrGroup> measurementGroups_;
    QCheckBox* dicomSr_ = nullptr;
    QLineEdit* dicomSrPath_ = nullptr;
    QGroupBox* patientGroup_ = nullptr;
    QLineEdit* patientName_ = nullptr;
    QLineEdit* patientId_ = nullptr;
    QLineEdit* birthDate_ = nullptr;
    QComboBox* sex_ = nullptr;
    QLineEdit* studyDate_ = nullptr;
    QLineEdit* accession_ = nullptr;
    QLineEdit* referring_ = nullptr;
    QLineEdit* disclaimer_ = nullptr;
    QFormLayout* form_ = nullptr;
};

}  // namespace vv::gui
