// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <optional>

namespace vv::dicom {
struct DicomSeries;
}
namespace vv::segmentation {
struct SceneSourceReport;
}

/// How the GUI names a DICOM series to a user: by what the series says of
/// itself, in the UI language at the time it is shown, never by its UID (a
/// study store's folders are UIDs).
namespace vv::gui {

/// What a series says of itself.
struct SeriesIdentity {
    QString description;        ///< Series Description
    QString modality;           ///< "CT", "MR", ...
    std::optional<int> number;  ///< Series Number
    QString studyDate;          ///< its study's Study Date, YYYYMMDD as in the file
    QString uid;  ///< Series Instance UID: to find the series again, never shown

    bool operator==(const SeriesIdentity&) const = default;
};

/// The identity of a scanned series (no study date: the series alone does
/// not hold it).
[[nodiscard]] SeriesIdentity seriesIdentity(const dicom::DicomSeries& series);
/// The identity of the series loadSceneSource() loaded (its report).
[[nodiscard]] SeriesIdentity seriesIdentity(const segmentation::SceneSourceReport& report);

/// Its description (whitespace simplified), else its modality and number
/// ("CT series 3"), else "Series 3" / "CT series" / "DICOM series"; in the
/// UI language.
[[nodiscard]] QString seriesName(const SeriesIdentity& series);

/// seriesName(), followed by the study date in the UI locale's short format
/// when there is one ("Run-off CTA · 01/03/2024"): what File > Open Recent
/// shows, where several patients' series may share a description.
[[nodiscard]] QString seriesLabel(const SeriesIdentity& series);

}  // namespace vv::gui
