// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/report/DicomSource.h"

namespace vv::report {

std::optional<SourceStudy> sourceStudy(const dicom::DicomScanResult& scan,
                                       std::string_view seriesInstanceUid) {
    for (const dicom::DicomPatient& patient : scan.patients) {
        for (const dicom::DicomStudy& study : patient.studies) {
            for (const dicom::DicomSeries& series : study.series) {
                if (series.seriesInstanceUid != seriesInstanceUid) {
                    continue;
                }
                SourceStudy source;
                source.patient.name = patient.name;
                source.patient.id = patient.id;
                source.patient.studyDate = study.date;
                source.study.studyInstanceUid = study.studyInstanceUid;
                source.study.studyDate = study.date;
                source.study.studyDateTime = QDateTime::currentDateTime();
                source.study.patient = source.patient;
                return source;
            }
        }
    }
    return std::nullopt;
}

}  // namespace vv::report
