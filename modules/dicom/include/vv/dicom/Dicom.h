// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// DICOM import (DCMTK behind this header; no DCMTK type shows here).
//
// Patient data: DicomPatient holds the patient's name and ID so that a user
// can choose what to open. They must never reach log messages, exception
// texts or reports written without the user asking; the functions here only
// ever name files and UIDs in their messages.

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Volume.h"

namespace vv::dicom {

/// One series (Series Instance UID) of images as found by scanDicom().
struct DicomSeries {
    std::string seriesInstanceUid;
    std::string studyInstanceUid;
    std::string frameOfReferenceUid;
    std::string modality;     ///< "CT", "MR", ...; empty when absent
    std::string description;  ///< Series Description; may be empty
    std::optional<int> seriesNumber;
    std::string sopClassUid;         ///< of the first file
    std::string transferSyntaxUid;   ///< of the first file
    std::string transferSyntaxName;  ///< e.g. "JPEG-LS Lossless"
    std::size_t imageCount = 0;      ///< images = frames, summed over the files
    bool multiFrame = false;         ///< at least one file holds several frames
    int rows = 0;                    ///< of the first image
    int columns = 0;
    bool mixedSizes = false;  ///< images of different rows x columns
    /// Pixel spacing in mm: x = between columns, y = between rows.
    std::optional<glm::dvec2> pixelSpacing;
    /// Distance between slice positions along the normal (median), mm; none
    /// for single images or without positions.
    std::optional<double> sliceSpacing;
    /// Non-empty when loadDicomSeries() will refuse the series, and why
    /// (JPEG 2000, colour images, ...).
    std::string unsupportedReason;
    /// The files, sorted by path (not a slice order).
    std::vector<std::filesystem::path> files;
};

struct DicomStudy {
    std::string studyInstanceUid;
    std::string description;  ///< Study Description
    std::string date;         ///< Study Date, YYYYMMDD as in the file
    std::vector<DicomSeries> series;
};

struct DicomPatient {
    /// Patient's Name and ID: protected health information. Show them to
    /// the user; never log them or put them in error messages.
    std::string name;
    std::string id;
    std::vector<DicomStudy> studies;
};

/// A file that is not an image scanDicom() could list, and why.
struct DicomSkippedFile {
    std::filesystem::path file;
    std::string reason;  ///< e.g. "structured report (no pixel data)"
};

struct DicomScanResult {
    std::vector<DicomPatient> patients;
    std::vector<DicomSkippedFile> skipped;
    std::size_t filesExamined = 0;

    /// Every series of every study of every patient, in listing order.
    [[nodiscard]] std::vector<const DicomSeries*> allSeries() const;
    /// The series with this Series Instance UID, or nullptr.
    [[nodiscard]] const DicomSeries* findSeries(std::string_view seriesInstanceUid) const;
};

/// Reads the headers of a DICOM file, of every file under a folder
/// (recursively), or of the files a DICOMDIR references, and groups the images
/// into patients / studies / series by their UIDs (sorted by patient ID,
/// study date, series number, UID). Files that are no images (structured
/// reports, RT plans and structure sets, waveforms, presentation states, key
/// object selections, encapsulated documents, files without pixel data, files
/// that are not DICOM or cannot be parsed) are listed in `skipped` with a
/// reason: one bad file never fails the scan. A DICOMDIR found while walking a
/// folder is skipped (the folder's files are read directly); a DICOMDIR given
/// as `path` is followed, and files it names but that are missing are skipped.
/// Pixel data is not read. Reports progress; throws IoError when `path` does
/// not exist or a folder cannot be listed, CancelledError.
[[nodiscard]] DicomScanResult scanDicom(const std::filesystem::path& path,
                                        const Progress& progress = {});

/// What loadDicomSeries() noticed but could work around.
struct DicomWarning {
    enum class Kind {
        NonUniformSpacing,  ///< gaps differ; resampled to a uniform grid
        MissingSlices,      ///< gaps of whole slices; filled by interpolation
        GantryTilt,         ///< positions drift in-plane; sheared grid kept
        NoGeometry,         ///< orientation / position / spacing absent; defaults used
        Other,
    };
    Kind kind = Kind::Other;
    std::string message;  ///< names the series UID, never the patient
};

struct DicomLoadOptions {
    /// Store Int16 whenever the rescaled values are integers that fit (the
    /// usual CT case); false: always Float32.
    bool allowInt16 = true;
    /// Memory the volume may use, in bytes; 0: the available physical memory
    /// (availableMemoryBytes()).
    std::uint64_t memoryLimitBytes = 0;
};

struct DicomVolume {
    scene::Volume volume;
    std::string seriesInstanceUid;
    std::string studyInstanceUid;
    std::string frameOfReferenceUid;
    std::size_t sourceImages = 0;  ///< images (frames) read
    std::vector<DicomWarning> warnings;
};

/// Assembles `series` into one volume. Slices are ordered by Image Position
/// (Patient) projected on the normal of Image Orientation (Patient) — never
/// by instance number or file name; multi-frame files contribute one slice
/// per frame (enhanced CT / MR per-frame functional groups, NM detector
/// geometry with Spacing Between Slices, RT dose Grid Frame Offset Vector).
/// Values are Rescale Slope * stored + Rescale Intercept (HU for CT), per
/// slice. The slice spacing comes from the positions; non-uniform spacing and
/// missing slices are resampled onto a uniform grid by linear interpolation
/// between the neighbouring slices, gantry tilt is kept as a sheared
/// index-to-world transform; each is reported in `warnings`.
/// Transfer syntaxes: implicit / explicit little endian, explicit big endian,
/// deflated, RLE, JPEG baseline / extended / lossless, JPEG-LS.
/// The size is checked against the memory limit before anything is
/// allocated; at most the volume plus three slices are held at once.
/// Reports progress. Throws FormatError (mixed image sizes or orientations,
/// several slices at one position, JPEG 2000 and other transfer syntaxes
/// DCMTK cannot decode, colour images, unreadable or truncated pixel data),
/// MemoryError (the volume would not fit), IoError (a file vanished or cannot
/// be read), CancelledError. Messages name a file or the series UID.
[[nodiscard]] DicomVolume loadDicomSeries(const DicomSeries& series,
                                          const DicomLoadOptions& options = {},
                                          const Progress& progress = {});

/// scanDicom(path) then loadDicomSeries() of the series `seriesInstanceUid`,
/// or of the only series when it is empty. Throws FormatError when there is
/// no image series, when the UID is not found, or when several series exist
/// and none was chosen (the message lists their UIDs); else as above.
[[nodiscard]] DicomVolume loadDicomVolume(const std::filesystem::path& path,
                                          std::string_view seriesInstanceUid = {},
                                          const DicomLoadOptions& options = {},
                                          const Progress& progress = {});

/// Physical memory available to this process now, in bytes: MemAvailable
/// from /proc/meminfo, lowered to the cgroup's remaining limit when there is
/// one; sysconf() when /proc is unavailable.
[[nodiscard]] std::uint64_t availableMemoryBytes();

/// True when `path` looks like DICOM: a file with "DICM" at offset 128, a
/// file called DICOMDIR, or a folder (which may hold DICOM files).
[[nodiscard]] bool looksLikeDicom(const std::filesystem::path& path);

}  // namespace vv::dicom
