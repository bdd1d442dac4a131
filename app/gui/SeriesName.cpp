// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/SeriesName.h"

#include <QCoreApplication>

#include "gui/pacs/PacsWidgets.h"
#include "vv/dicom/Dicom.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::gui {

SeriesIdentity seriesIdentity(const dicom::DicomSeries& series) {
    return {QString::fromStdString(series.description), QString::fromStdString(series.modality),
            series.seriesNumber, QString(), QString::fromStdString(series.seriesInstanceUid)};
}

SeriesIdentity seriesIdentity(const segmentation::SceneSourceReport& report) {
    return {QString::fromStdString(report.seriesDescription),
            QString::fromStdString(report.modality), report.seriesNumber,
            QString::fromStdString(report.studyDate),
            QString::fromStdString(report.seriesInstanceUid)};
}

QString seriesName(const SeriesIdentity& series) {
    QString description = series.description.simplified();
    if (!description.isEmpty()) {
        return description;
    }
    // The texts keep the series chooser's translation context, where they were
    // first translated.
    const QString modality = series.modality.simplified();
    if (series.number) {
        // An identifier, not a quantity: no group separators ("Series 10001").
        const QString number = QString::number(*series.number);
        return modality.isEmpty()
                   ? QCoreApplication::translate("vv::gui::SeriesDialog", "Series %1").arg(number)
                   : QCoreApplication::translate("vv::gui::SeriesDialog", "%1 series %2")
                         .arg(modality, number);
    }
    return modality.isEmpty()
               ? QCoreApplication::translate("vv::gui::SeriesDialog", "DICOM series")
               : QCoreApplication::translate("vv::gui::SeriesDialog", "%1 series").arg(modality);
}

QString seriesLabel(const SeriesIdentity& series) {
    const QString date = series.studyDate.trimmed();
    return date.isEmpty() ? seriesName(series)
                          : QStringLiteral("%1 · %2").arg(seriesName(series),
                                                          studyDateText(date.toStdString()));
}

}  // namespace vv::gui
