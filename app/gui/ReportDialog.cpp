// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/ReportDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDate>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

#include "gui/DateText.h"
#include "gui/ExportImageDialog.h"
#include "gui/ExportWorker.h"
#include "gui/PathField.h"
#include "gui/ViewerWidget.h"
#include "gui/panels/DisplayPanel.h"
#include "vv/dicom/PersonName.h"
#include "vv/render/ViewPresets.h"
#include "vv/report/ParameterStats.h"
#include "vv/report/PdfReport.h"

namespace vv::gui {

namespace {

const char* const kPaperKey = "report/paper";
const char* const kAnonymiseKey = "report/anonymise";

std::filesystem::path toPath(const QString& file) {
    return {QFile::encodeName(file).toStdString()};
}

/// A DICOM date (YYYYMMDD) from what the user typed (parseUiDate(): the UI
/// language's format, ISO or DICOM); "" for an empty field; nullopt when it
/// is no valid date.
std::optional<std::string> dicomDate(const QString& typed) {
    const std::optional<QDate> date = parseUiDate(typed);
    if (!date) {
        return std::nullopt;
    }
    return date->isNull() ? std::string()
                          : date->toString(QStringLiteral("yyyyMMdd")).toStdString();
}

/// `pdf` with its suffix replaced: "report.pdf" -> "report-sc.dcm".
QString besidePdf(const QString& pdf, const QString& suffix) {
    const QFileInfo info(pdf);
    return QDir(info.path()).filePath(info.completeBaseName() + suffix);
}

}  // namespace

void setReportView(const ViewerWidget& viewer, report::ReportJobOptions& job) {
    const QSize size = viewPixelSize(viewer);
    job.view = currentViewOptions(viewer, size.width(), size.height());
    job.secondViewDepthRange = viewer.vssSettings().range;
    job.viewCaption = ReportDialog::tr("The view as shown on screen").toStdString();
    job.viewDescription = ReportDialog::tr("as shown on screen").toStdString();
    job.legends = viewer.legendsVisible();
}

ReportDialog::ReportDialog(const ViewerWidget& viewer, report::ReportSource source, QWidget* parent)
    : ExportDialog(parent), viewer_(viewer), source_(std::move(source)) {
    setObjectName(QStringLiteral("reportDialog"));
    setWindowTitle(tr("Export Report"));
    const QSettings settings;
    form_ = new QFormLayout(this);

    pdf_ = new QLineEdit(unusedFileName(lastExportFolder(), QStringLiteral("report.pdf")), this);
    addBuddyRow(form_, tr("&Report (PDF):"), pdf_,
                browseRow(pdf_, tr("Export report"), tr("PDF documents (*.pdf)"), this));

    paper_ = new QComboBox(this);
    paper_->addItem(tr("A4"), static_cast<int>(report::PaperSize::A4));
    paper_->addItem(tr("Letter"), static_cast<int>(report::PaperSize::Letter));
    const int paper = paper_->findData(settings.value(QLatin1String(kPaperKey), 0).toInt());
    paper_->setCurrentIndex(std::max(0, paper));
    form_->addRow(tr("&Paper:"), paper_);

    findings_ = new QPlainTextEdit(this);
    findings_->setPlaceholderText(tr("Findings, printed first, right after the patient"));
    findings_->setTabChangesFocus(true);
    form_->addRow(tr("&Findings:"), findings_);

    secondView_ = new QComboBox(this);
    secondView_->addItem(tr("None"), QString());
    // The viewer's own names for its views ("Left lateral" for a patient).
    for (const render::ViewPreset preset : render::allViewPresets()) {
        secondView_->addItem(panels::DisplayPanel::presetLabel(preset),
                             QString::fromLatin1(render::toString(preset)));
    }
    const scene::SceneFrame frame =
        viewer.scene() ? viewer.scene()->frame : scene::SceneFrame::Unknown;
    for (const render::AnatomicalView view : render::allAnatomicalViews()) {
        secondView_->addItem(panels::DisplayPanel::anatomicalLabel(view, frame),
                             QString::fromLatin1(render::toString(view)));
    }
    secondView_->setToolTip(tr("A second image from a camera preset, below the view"));
    form_->addRow(tr("&Second view:"), secondView_);

    // Statistics thresholds: only with a parameter on the vessels.
    const std::string& array = viewer.style().array;
    // In the array's unit, as the legend and the data panel name it.
    const std::string unit = array.empty() || !viewer.scene()
                                 ? std::string()
                                 : report::arrayUnit(*viewer.scene(), array);
    const auto threshold = [this, &array, &unit](QCheckBox*& box, QDoubleSpinBox*& value,
                                                 const QString& label) {
        box = new QCheckBox(label, this);
        value = new QDoubleSpinBox(this);
        value->setRange(-1e9, 1e9);
        value->setDecimals(3);
        if (!unit.empty()) {
            value->setSuffix(QLatin1Char(' ') + QString::fromStdString(unit));
        }
        value->setEnabled(false);
        connect(box, &QCheckBox::toggled, value, &QWidget::setEnabled);
        if (array.empty()) {
            box->setEnabled(false);
            box->setToolTip(
                tr("No parameter is shown on the vessels: the report has no "
                   "statistics"));
        }
        auto* row = new QHBoxLayout;
        row->addWidget(box);
        row->addWidget(value, 1);
        return row;
    };
    form_->addRow(tr("Statistics:"), threshold(below_, belowValue_, tr("Area &below")));
    form_->addRow(QString(), threshold(above_, aboveValue_, tr("Area abo&ve")));
    if (array == "wss") {
        below_->setChecked(true);  // low wall shear stress, as the CLI's default
        belowValue_->setValue(0.4);
    }

    anonymise_ = new QCheckBox(tr("&Anonymise the patient"), this);
    if (source_.dicomPath.empty()) {
        anonymise_->setEnabled(false);  // until a patient is entered (addPatientFields)
        anonymise_->setToolTip(
            tr("Meshes carry no patient data: enter the patient and study below to print them, "
               "or anonymised"));
    } else {
        anonymise_->setChecked(settings.value(QLatin1String(kAnonymiseKey), false).toBool());
        anonymise_->setToolTip(
            tr("Print \"anonymised\" instead of the patient's data and leave the identifiers out "
               "of the DICOM exports"));
    }
    form_->addRow(QString(), anonymise_);
    addPatientFields();

    disclaimer_ = new QLineEdit(disclaimer(settings), this);
    disclaimer_->setToolTip(tr("Printed under the report's title; empty = no line"));
    form_->addRow(tr("Disclai&mer:"), disclaimer_);

    dicomSc_ = addOutput(tr("DICOM Secondary &Capture"), dicomScPath_, QStringLiteral("-sc.dcm"),
                         tr("DICOM files (*.dcm)"));
    dicomPdf_ = addOutput(tr("DICOM Encapsulated P&DF"), dicomPdfPath_,
                          QStringLiteral("-report.dcm"), tr("DICOM files (*.dcm)"));
    png_ = addOutput(tr("PNG &image"), pngPath_, QStringLiteral(".png"), tr("PNG images (*.png)"));

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setText(tr("&Export"));
    connect(buttons, &QDialogButtonBox::accepted, this, &ReportDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form_->addRow(buttons);
}

QString ReportDialog::disclaimer(const QSettings& settings) {
    // The default, also as an earlier version stored it in English, follows
    // the UI language.
    const QVariant stored = settings.value(QLatin1String(kDisclaimerKey));
    return stored.isValid() && !report::isDefaultDisclaimer(stored.toString().toStdString())
               ? stored.toString()
               : QString::fromStdString(report::defaultDisclaimer());
}

void ReportDialog::addPatientFields() {
    patientGroup_ = new QGroupBox(tr("Patient and stud&y"), this);
    patientGroup_->setCheckable(true);
    patientGroup_->setChecked(false);
    patientGroup_->setToolTip(
        tr("Meshes carry no patient data: what you enter here is printed in the report and "
           "written to its DICOM exports"));
    // The fields follow the group's check box in the tab order: no mnemonics
    // of their own (the dialog's letters are taken).
    auto* fields = new QFormLayout(patientGroup_);
    const auto line = [&](QLineEdit*& edit, const QString& label, const QString& placeholder) {
        edit = new QLineEdit(patientGroup_);
        edit->setPlaceholderText(placeholder);
        fields->addRow(label, edit);
    };
    // Names as every dialog and the report write them (Family^Given also works).
    line(patientName_, tr("Name:"), tr("Family, Given"));
    line(patientId_, tr("Patient ID:"), QString());
    line(birthDate_, tr("Birth date:"), uiDatePlaceholder());
    sex_ = new QComboBox(patientGroup_);
    sex_->addItem(tr("not given"), QString());
    sex_->addItem(tr("female"), QStringLiteral("F"));
    sex_->addItem(tr("male"), QStringLiteral("M"));
    sex_->addItem(tr("other"), QStringLiteral("O"));
    fields->addRow(tr("Sex:"), sex_);
    line(studyDate_, tr("Study date:"), uiDatePlaceholder());
    line(accession_, tr("Accession number:"), QString());
    line(referring_, tr("Referring physician:"), tr("Family, Given"));
    form_->addRow(patientGroup_);
    // DICOM data brings its own patient and study.
    patientGroup_->setVisible(source_.dicomPath.empty());
    if (source_.dicomPath.empty()) {
        connect(patientGroup_, &QGroupBox::toggled, anonymise_, &QWidget::setEnabled);
    }
}

std::optional<report::ReportPatient> ReportDialog::enteredPatient() const {
    if (!source_.dicomPath.empty() || !patientGroup_->isChecked()) {
        return std::nullopt;
    }
    report::ReportPatient p;
    p.name = dicom::personNameFromText(patientName_->text().toStdString());
    p.id = patientId_->text().trimmed().toStdString();
    p.birthDate = dicomDate(birthDate_->text()).value_or(std::string());
    p.sex = sex_->currentData().toString().toStdString();
    p.studyDate = dicomDate(studyDate_->text()).value_or(std::string());
    p.accession = accession_->text().trimmed().toStdString();
    p.referringPhysician = dicom::personNameFromText(referring_->text().toStdString());
    return p;
}

QCheckBox* ReportDialog::addOutput(const QString& label, QLineEdit*& edit, const QString& suffix,
                                   const QString& filter, int row) {
    auto* box = new QCheckBox(label, this);
    edit = new QLineEdit(this);
    edit->setEnabled(false);
    QLineEdit* path = edit;
    connect(box, &QCheckBox::toggled, this, [this, path, suffix](bool on) {
        path->setEnabled(on);
        if (on && path->text().isEmpty()) {
            path->setText(besidePdf(pdf_->text(), suffix));
        }
    });
    if (row >= 0) {
        form_->insertRow(row, box, browseRow(edit, label, filter, this));
    } else {
        form_->addRow(box, browseRow(edit, label, filter, this));
    }
    return box;
}

void ReportDialog::setMeasurements(report::ReportMeasurementSection section,
                                   std::vector<dicom::SrGroup> groups) {
    measurements_ = std::move(section);
    measurementGroups_ = std::move(groups);
    if (measurementsBox_ != nullptr) {
        return;
    }
    measurementsBox_ = new QCheckBox(tr("I&nclude them"), this);
    measurementsBox_->setObjectName(QStringLiteral("reportMeasurementsBox"));
    measurementsBox_->setChecked(true);
    measurementsBox_->setToolTip(
        tr("The sizing and branch tables, the diameter profile, the curved reformation and the "
           "cross-section at each landmark (Analysis panel)"));
    const int secondRow = form_->indexOf(secondView_);
    int at = 0;
    QFormLayout::ItemRole role{};
    form_->getItemPosition(secondRow, &at, &role);
    form_->insertRow(at + (sliceBox_ != nullptr ? 2 : 1), tr("Measurements:"), measurementsBox_);
    // The SR after the other outputs, before the buttons.
    int pngRow = 0;
    form_->getItemPosition(form_->indexOf(png_), &pngRow, &role);
    dicomSr_ = addOutput(tr("DICOM St&ructured Report (measurements)"), dicomSrPath_,
                         QStringLiteral("-sr.dcm"), tr("DICOM files (*.dcm)"), pngRow + 1);
    dicomSr_->setObjectName(QStringLiteral("reportDicomSrBox"));
    dicomSr_->setToolTip(
        tr("The measurements as a DICOM TID 1500 Measurement Report, read as "
           "data by a PACS and other viewers"));
    connect(measurementsBox_, &QCheckBox::toggled, dicomSr_, [this](bool on) {
        dicomSr_->setEnabled(on);
        if (!on) {
            dicomSr_->setChecked(false);
        }
    });
}

void ReportDialog::setSlice(const QImage& image, const QString& caption) {
    slice_ = image;
    sliceCaption_ = caption;
    if (sliceBox_ == nullptr) {
        sliceBox_ = new QCheckBox(tr("&Include it"), this);
        sliceBox_->setObjectName(QStringLiteral("reportSliceBox"));
        sliceBox_->setChecked(true);
        const int row = form_->indexOf(secondView_);
        int at = 0;
        QFormLayout::ItemRole role{};
        form_->getItemPosition(row, &at, &role);
        form_->insertRow(at + 1, tr("Slice with segmentation:"), sliceBox_);
    }
    sliceBox_->setToolTip(caption);
}

report::ReportJobOptions ReportDialog::jobOptions() const {
    report::ReportJobOptions job;
    setReportView(viewer_, job);
    const QString second = secondView_->currentData().toString();
    if (!second.isEmpty()) {
        job.secondView = render::namedViewFromName(second.toStdString());
        job.secondViewName = second.toStdString();
    }
    if (sliceBox_ != nullptr && sliceBox_->isChecked()) {
        job.slice = slice_;
        job.sliceCaption = sliceCaption_.toStdString();
    }
    job.anonymise = anonymise_->isEnabled() && anonymise_->isChecked();
    job.patient = enteredPatient();
    job.disclaimer = disclaimer_->text().trimmed().toStdString();
    job.findings = findings_->toPlainText().toStdString();
    job.paper = static_cast<report::PaperSize>(paper_->currentData().toInt());
    if (below_->isEnabled() && below_->isChecked()) {
        job.thresholds.below = belowValue_->value();
    }
    if (above_->isEnabled() && above_->isChecked()) {
        job.thresholds.above = aboveValue_->value();
    }
    job.source = source_;
    job.outputs.pdf = toPath(pdf_->text().trimmed());
    const auto optional = [](const QCheckBox* box, const QLineEdit* edit) {
        return box->isChecked() ? toPath(edit->text().trimmed()) : std::filesystem::path();
    };
    job.outputs.dicomSc = optional(dicomSc_, dicomScPath_);
    job.outputs.dicomPdf = optional(dicomPdf_, dicomPdfPath_);
    job.outputs.png = optional(png_, pngPath_);
    if (measurementsBox_ != nullptr && measurementsBox_->isChecked()) {
        job.measurements = measurements_;
        job.measurementGroups = measurementGroups_;
        job.outputs.dicomSr = optional(dicomSr_, dicomSrPath_);
    }
    return job;
}

std::vector<std::pair<std::filesystem::path, QString>> ReportDialog::outputs() const {
    const report::ReportJobOptions job = jobOptions();
    std::vector<std::pair<std::filesystem::path, QString>> outputs{
        {job.outputs.pdf, tr("PDF report")}};
    const std::array<std::pair<const QCheckBox*, const std::filesystem::path*>, 3> optional{
        {{dicomSc_, &job.outputs.dicomSc},
         {dicomPdf_, &job.outputs.dicomPdf},
         {png_, &job.outputs.png}}};
    for (const auto& [box, path] : optional) {
        if (box->isChecked()) {
            outputs.emplace_back(*path, box->text().remove(QLatin1Char('&')));
        }
    }
    if (!job.outputs.dicomSr.empty()) {
        outputs.emplace_back(job.outputs.dicomSr, dicomSr_->text().remove(QLatin1Char('&')));
    }
    return outputs;
}

QStringList ReportDialog::outputFiles() const {
    QStringList files;
    for (const auto& output : outputs()) {
        files << QFileInfo(QFile::decodeName(output.first.c_str())).absoluteFilePath();
    }
    return files;
}

QString ReportDialog::problem() const {
    if (!viewer_.scene()) {
        return tr("There is no data on screen to report on.");
    }
    if (source_.dicomPath.empty() && patientGroup_->isChecked()) {
        for (const auto& [edit, what] :
             {std::pair{birthDate_, tr("birth date")}, std::pair{studyDate_, tr("study date")}}) {
            if (!dicomDate(edit->text())) {
                return tr("The %1 \"%2\" is not a date: enter it as %3 (for example %4).")
                    .arg(what, edit->text().trimmed(), uiDatePlaceholder(),
                         QLocale().toString(QDate(1960, 5, 17), uiDateFormat()));
            }
        }
    }
    std::vector<std::filesystem::path> seen;
    for (const auto& [path, what] : outputs()) {
        if (path.empty()) {
            return tr("Choose a file name for the %1.").arg(what);
        }
        const QFileInfo info(QFile::decodeName(path.c_str()));
        if (info.isDir()) {
            return tr("%1 is a folder; choose a file name for the %2.").arg(info.filePath(), what);
        }
        if (!info.absoluteDir().exists()) {
            return tr("%1: the folder %2 does not exist.")
                .arg(info.filePath(), info.absolutePath());
        }
        const auto same = [&info](const std::filesystem::path& other) {
            return QFileInfo(QFile::decodeName(other.c_str())).absoluteFilePath() ==
                   info.absoluteFilePath();
        };
        if (std::any_of(seen.begin(), seen.end(), same)) {
            return tr("%1 is chosen for two outputs.").arg(info.filePath());
        }
        if (std::any_of(source_.files.begin(), source_.files.end(), same)) {
            return tr("%1 is the data file shown: choose another name.").arg(info.filePath());
        }
        seen.push_back(path);
    }
    return {};
}

ExportWorker* ReportDialog::startExport() {
    const report::ReportJobOptions job = jobOptions();
    QSettings settings;
    rememberExportFolder(pdf_->text().trimmed());
    settings.setValue(QLatin1String(kPaperKey), paper_->currentData().toInt());
    if (anonymise_->isEnabled()) {
        settings.setValue(QLatin1String(kAnonymiseKey), anonymise_->isChecked());
    }
    const QString disclaimerText = disclaimer_->text().trimmed();
    if (report::isDefaultDisclaimer(disclaimerText.toStdString())) {
        settings.remove(QLatin1String(kDisclaimerKey));  // the default, in whichever language
    } else {
        settings.setValue(QLatin1String(kDisclaimerKey), disclaimerText);
    }
    const std::shared_ptr<const scene::Scene> scene = viewer_.scene();
    const QString pdf = pdf_->text().trimmed();
    return ExportWorker::launch(
        tr("Exporting the report %1").arg(QFileInfo(pdf).fileName()),
        [scene, job](render::OffscreenRenderer& renderer, const Progress& progress) {
            const auto written = report::runReportJob(renderer, *scene, job, progress);
            QStringList files;
            for (const auto& file : written) {
                files << QFile::decodeName(file.path.c_str());
            }
            return tr("Exported %1").arg(files.join(QStringLiteral(", ")));
        },
        this);
}

}  // namespace vv::gui
