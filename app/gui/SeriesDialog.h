// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QString>

#include "vv/dicom/Dicom.h"
#include "vv/segmentation/SceneSource.h"

class QCheckBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QSpinBox;
class QTreeWidget;
class QTreeWidgetItem;

namespace vv::gui {

/// The DICOM series chooser: a tree of patients → studies → series (modality,
/// description, image count, size, spacing) as vv::dicom::scanDicom() found
/// them, series that cannot be loaded and skipped files greyed with their
/// reason, and the segmentation options (threshold range: the modality's
/// default, shown as its rule (CT angiography: 200 to 700 HU; MR and others:
/// from the image histogram when loaded), or a range of one's own, components
/// to keep, bone removal). The patient name
/// is shown here for the user to recognise their data, and nowhere else.
/// The first loadable series is selected; OK is enabled while a loadable
/// series is selected.
class SeriesDialog : public QDialog {
    Q_OBJECT

  public:
    explicit SeriesDialog(const dicom::DicomScanResult& scan, QWidget* parent = nullptr);

    /// The chosen series' UID; empty when none is selected.
    [[nodiscard]] QString selectedSeriesUid() const;
    /// Selects the series with this UID (when loadable); false when not listed.
    bool selectSeries(const QString& uid);
    /// The chosen series and segmentation options for loadSceneSource().
    [[nodiscard]] segmentation::SceneSourceOptions sceneSourceOptions() const;
    /// How the window and the document name the chosen series (seriesName());
    /// empty when none is selected.
    [[nodiscard]] QString seriesTitle() const;
    /// What a clinician recognises a series by: its description, else its
    /// modality and number ("CT series 3"), else "DICOM series"; never its UID.
    [[nodiscard]] static QString seriesName(const dicom::DicomSeries& series);

    [[nodiscard]] QTreeWidget* tree() const noexcept { return tree_; }
    [[nodiscard]] QCheckBox* automaticThreshold() const noexcept { return autoThreshold_; }
    [[nodiscard]] QDoubleSpinBox* lowerThreshold() const noexcept { return lower_; }
    [[nodiscard]] QDoubleSpinBox* upperThreshold() const noexcept { return upper_; }
    [[nodiscard]] QSpinBox* componentsBox() const noexcept { return components_; }
    [[nodiscard]] QCheckBox* boneRemoval() const noexcept { return bone_; }

  private:
    /// The constructor's steps. The tree of what the scan found; returns the
    /// first loadable series' item (nullptr: none).
    QTreeWidgetItem* buildTree();
    /// One series' row under its study, greyed with the reason when it cannot be loaded.
    static QTreeWidgetItem* addSeriesItem(QTreeWidgetItem* studyItem,
                                          const dicom::DicomSeries& series);
    /// The skipped files, greyed with their reasons, under one node of their own.
    void addSkippedFiles();
    /// The segmentation options: threshold range, components, bone removal.
    QGroupBox* buildOptions();
    void selectionChanged();
    /// OK: a loadable series selected, and both ends of a range of one's own entered.
    void updateOk();
    [[nodiscard]] bool ownRangeMissing() const;
    [[nodiscard]] const dicom::DicomSeries* currentSeries() const;

    dicom::DicomScanResult scan_;
    QTreeWidget* tree_ = nullptr;
    QCheckBox* autoThreshold_ = nullptr;
    QDoubleSpinBox* lower_ = nullptr;
    QDoubleSpinBox* upper_ = nullptr;
    QLabel* thresholdRule_ = nullptr;
    QSpinBox* components_ = nullptr;
    QCheckBox* bone_ = nullptr;
    QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace vv::gui
