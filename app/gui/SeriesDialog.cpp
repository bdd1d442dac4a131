// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/SeriesDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSpinBox>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QVBoxLayout>
#include <algorithm>

#include "gui/SeriesName.h"
#include "gui/pacs/PacsWidgets.h"
#include "vv/dicom/PersonName.h"

namespace vv::gui {

namespace {

constexpr int kUidRole = Qt::UserRole + 1;
enum Column { Name, Modality, Description, Images, Size, Spacing, ColumnCount };

QString fromStd(const std::string& s) {
    return QString::fromStdString(s);
}

/// The spin boxes' "nothing entered" value (their minimum, shown empty).
constexpr double kUnset = -100000.0;
/// The CT angiography default (segmentation::defaultThresholdRange()), HU.
constexpr double kCtLower = 200.0;
constexpr double kCtUpper = 700.0;

bool isCt(const dicom::DicomSeries& s) {
    return s.modality == "CT";
}

void greyOut(QTreeWidgetItem* item) {
    item->setFlags(item->flags() & ~(Qt::ItemIsSelectable | Qt::ItemIsEnabled));
}

}  // namespace

SeriesDialog::SeriesDialog(const dicom::DicomScanResult& scan, QWidget* parent)
    : QDialog(parent), scan_(scan) {
    setWindowTitle(tr("Choose a DICOM Series"));
    setObjectName(QStringLiteral("seriesDialog"));
    resize(900, 560);

    QTreeWidgetItem* first = buildTree();
    QGroupBox* options = buildOptions();

    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Load Series"));
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto* layout = new QVBoxLayout(this);
    layout->addWidget(tree_, 1);
    layout->addWidget(options);
    layout->addWidget(buttons_);

    connect(tree_, &QTreeWidget::itemSelectionChanged, this, &SeriesDialog::selectionChanged);
    connect(tree_, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        if (!item->data(Name, kUidRole).toString().isEmpty() && item->isSelected()) {
            accept();
        }
    });
    if (first != nullptr) {
        tree_->setCurrentItem(first);
        first->setSelected(true);
    }
    selectionChanged();
}

QTreeWidgetItem* SeriesDialog::buildTree() {
    tree_ = new QTreeWidget(this);
    tree_->setObjectName(QStringLiteral("seriesTree"));
    tree_->setColumnCount(ColumnCount);
    tree_->setHeaderLabels({tr("Patient / study / series"), tr("Modality"), tr("Description"),
                            tr("Images"), tr("Size"), tr("Voxel spacing (mm)")});
    tree_->setSelectionMode(QAbstractItemView::SingleSelection);
    tree_->setAlternatingRowColors(true);

    QTreeWidgetItem* first = nullptr;
    for (std::size_t p = 0; p < scan_.patients.size(); ++p) {
        const dicom::DicomPatient& patient = scan_.patients[p];
        auto* patientItem = new QTreeWidgetItem(tree_);
        // "Family, Given", as every dialog and the report show a name.
        const QString name = fromStd(dicom::personNameText(patient.name));
        patientItem->setText(
            Name, name.isEmpty() ? tr("Patient %1").arg(p + 1) : tr("Patient: %1").arg(name));
        patientItem->setFlags(Qt::ItemIsEnabled);
        for (const dicom::DicomStudy& study : patient.studies) {
            auto* studyItem = new QTreeWidgetItem(patientItem);
            // In the UI locale, as in the study browsers and Open Recent.
            const QString date = studyDateText(study.date);
            studyItem->setText(Name, date.isEmpty() ? tr("Study") : tr("Study %1").arg(date));
            studyItem->setText(Description, fromStd(study.description));
            studyItem->setFlags(Qt::ItemIsEnabled);
            for (const dicom::DicomSeries& series : study.series) {
                QTreeWidgetItem* item = addSeriesItem(studyItem, series);
                if (series.unsupportedReason.empty() && first == nullptr) {
                    first = item;
                }
            }
        }
    }
    addSkippedFiles();
    tree_->expandAll();
    for (int c = 0; c < ColumnCount; ++c) {
        tree_->resizeColumnToContents(c);
    }
    return first;
}

QTreeWidgetItem* SeriesDialog::addSeriesItem(QTreeWidgetItem* studyItem,
                                             const dicom::DicomSeries& series) {
    auto* item = new QTreeWidgetItem(studyItem);
    item->setData(Name, kUidRole, fromStd(series.seriesInstanceUid));
    item->setText(Name,
                  series.seriesNumber ? tr("Series %1").arg(*series.seriesNumber) : tr("Series"));
    item->setToolTip(Name, fromStd(series.seriesInstanceUid));
    item->setText(Modality, fromStd(series.modality));
    item->setText(Description, fromStd(series.description));
    item->setText(Images, QString::number(series.imageCount));
    item->setText(Size, tr("%1 × %2").arg(series.columns).arg(series.rows));
    QString spacing;
    if (series.pixelSpacing) {
        spacing = QStringLiteral("%L1 × %L2")
                      .arg(series.pixelSpacing->x, 0, 'g', 4)
                      .arg(series.pixelSpacing->y, 0, 'g', 4);
        if (series.sliceSpacing) {
            spacing += QStringLiteral(" × %L1").arg(*series.sliceSpacing, 0, 'g', 4);
        }
    }
    item->setText(Spacing, spacing);
    if (!series.unsupportedReason.empty()) {
        item->setText(Description,
                      tr("%1 — cannot be loaded: %2")
                          .arg(fromStd(series.description), fromStd(series.unsupportedReason)));
        greyOut(item);
    }
    return item;
}

void SeriesDialog::addSkippedFiles() {
    if (!scan_.skipped.empty()) {
        auto* skipped = new QTreeWidgetItem(tree_);
        skipped->setText(Name, tr("Skipped files: %1").arg(scan_.skipped.size()));
        skipped->setFlags(Qt::ItemIsEnabled);
        for (const dicom::DicomSkippedFile& file : scan_.skipped) {
            auto* item = new QTreeWidgetItem(skipped);
            item->setText(Name, fromStd(file.file.filename().string()));
            item->setToolTip(Name, fromStd(file.file.string()));
            item->setText(Description, fromStd(file.reason));
            greyOut(item);
        }
    }
}

QGroupBox* SeriesDialog::buildOptions() {
    auto* options = new QGroupBox(tr("Vessel segmentation"), this);
    auto* form = new QFormLayout(options);
    autoThreshold_ = new QCheckBox(tr("Default for the modality"), options);
    autoThreshold_->setChecked(true);
    lower_ = new QDoubleSpinBox(options);
    lower_->setObjectName(QStringLiteral("seriesThresholdLower"));
    upper_ = new QDoubleSpinBox(options);
    upper_->setObjectName(QStringLiteral("seriesThresholdUpper"));
    for (QDoubleSpinBox* box : {lower_, upper_}) {
        // The lowest value means "not entered yet" (shown empty).
        box->setRange(kUnset, 100000.0);
        box->setDecimals(0);
        box->setSpecialValueText(QStringLiteral(" "));
        box->setValue(kUnset);
    }
    thresholdRule_ = new QLabel(options);
    thresholdRule_->setObjectName(QStringLiteral("seriesThresholdRule"));
    auto* to = new QLabel(tr("to"), options);
    auto* range = new QHBoxLayout;
    range->addWidget(autoThreshold_);
    range->addWidget(lower_);
    range->addWidget(to);
    range->addWidget(upper_);
    range->addWidget(thresholdRule_, 1);
    // The modality's default shows as its rule; numbers only for a range of one's own.
    const auto showRange = [this, to](bool own) {
        lower_->setVisible(own);
        to->setVisible(own);
        upper_->setVisible(own);
        thresholdRule_->setVisible(!own);
    };
    showRange(false);
    form->addRow(tr("Threshold range:"), range);
    components_ = new QSpinBox(options);
    components_->setRange(1, 255);
    components_->setValue(1);
    components_->setToolTip(tr("Keep this many of the largest connected components"));
    form->addRow(tr("Components to keep:"), components_);
    bone_ = new QCheckBox(tr("Remove bone-like components"), options);
    form->addRow(QString(), bone_);
    connect(autoThreshold_, &QCheckBox::toggled, this, [this, showRange](bool automatic) {
        showRange(!automatic);
        if (const dicom::DicomSeries* series = currentSeries();
            !automatic && series != nullptr && isCt(*series) && lower_->value() == kUnset &&
            upper_->value() == kUnset) {
            // A CT range of one's own starts from the CT default.
            lower_->setValue(kCtLower);
            upper_->setValue(kCtUpper);
        }
        updateOk();
    });
    for (QDoubleSpinBox* box : {lower_, upper_}) {
        connect(box, &QDoubleSpinBox::valueChanged, this, &SeriesDialog::updateOk);
    }
    return options;
}

const dicom::DicomSeries* SeriesDialog::currentSeries() const {
    const QString uid = selectedSeriesUid();
    return uid.isEmpty() ? nullptr : scan_.findSeries(uid.toStdString());
}

QString SeriesDialog::selectedSeriesUid() const {
    const QList<QTreeWidgetItem*> items = tree_->selectedItems();
    return items.isEmpty() ? QString() : items.front()->data(Name, kUidRole).toString();
}

bool SeriesDialog::selectSeries(const QString& uid) {
    for (QTreeWidgetItemIterator it(tree_); *it != nullptr; ++it) {
        if ((*it)->data(Name, kUidRole).toString() == uid &&
            ((*it)->flags() & Qt::ItemIsSelectable) != 0) {
            tree_->clearSelection();
            tree_->setCurrentItem(*it);
            (*it)->setSelected(true);
            return true;
        }
    }
    return false;
}

bool SeriesDialog::ownRangeMissing() const {
    return !autoThreshold_->isChecked() && (lower_->value() == kUnset || upper_->value() == kUnset);
}

void SeriesDialog::updateOk() {
    QPushButton* ok = buttons_->button(QDialogButtonBox::Ok);
    ok->setEnabled(currentSeries() != nullptr && !ownRangeMissing());
    ok->setToolTip(ownRangeMissing() ? tr("Enter both ends of the threshold range, or use the "
                                          "default for the modality")
                                     : QString());
}

void SeriesDialog::selectionChanged() {
    const dicom::DicomSeries* series = currentSeries();
    updateOk();
    if (series == nullptr) {
        return;
    }
    // The modality's defaults (as vv::segmentation::segmentVessels would choose them).
    bone_->setChecked(isCt(*series));
    if (isCt(*series)) {
        thresholdRule_->setText(tr("CT angiography: 200 to 700 HU"));
    } else {
        // MR and others: the default comes from the image values, not known before loading.
        thresholdRule_->setText(
            tr("%1: from the image histogram when loaded")
                .arg(series->modality.empty() ? tr("This series") : fromStd(series->modality)));
    }
}

QString SeriesDialog::seriesTitle() const {
    const dicom::DicomSeries* series = currentSeries();
    return series != nullptr ? seriesName(*series) : QString();
}

QString SeriesDialog::seriesName(const dicom::DicomSeries& series) {
    return gui::seriesName(seriesIdentity(series));
}

segmentation::SceneSourceOptions SeriesDialog::sceneSourceOptions() const {
    segmentation::SceneSourceOptions options;
    options.seriesInstanceUid = selectedSeriesUid().toStdString();
    if (!autoThreshold_->isChecked()) {
        segmentation::ThresholdRange range;
        range.lower = static_cast<float>(std::min(lower_->value(), upper_->value()));
        range.upper = static_cast<float>(std::max(lower_->value(), upper_->value()));
        range.rule = "chosen in the series dialog";
        options.segmentation.range = range;
    }
    options.segmentation.keepComponents = components_->value();
    options.segmentation.removeBone = bone_->isChecked();
    return options;
}

}  // namespace vv::gui
