// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: what one DICOM file's header says, read with DCMTK. Shared by the
// scanner and the volume loader. No DCMTK type leaks out of this header.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vv::dicom::detail {

/// Registers DCMTK's decoders (JPEG, JPEG-LS, RLE) once, thread-safely, and
/// silences DCMTK's own logger (its messages may quote attribute values,
/// i.e. patient data).
void ensureCodecs();

/// Geometry and value transform of one frame; unset fields fall back to the
/// file-level ones.
struct FrameInfo {
    std::optional<glm::dvec3> position;                ///< Image Position (Patient)
    std::optional<std::array<double, 6>> orientation;  ///< Image Orientation (Patient)
    std::optional<glm::dvec2> pixelSpacing;            ///< x = column spacing, y = row spacing
    std::optional<double> slope;
    std::optional<double> intercept;
};

struct FileHeader {
    std::filesystem::path file;

    // Classification. `skipReason` non-empty: not an image we list.
    std::string skipReason;
    bool isDicomdir = false;
    std::vector<std::string> dicomdirFiles;  ///< ReferencedFileIDs, '/' separated

    std::string sopClassUid, sopInstanceUid, studyUid, seriesUid, frameOfReferenceUid;
    std::string modality, seriesDescription, studyDescription, studyDate;
    std::string patientName, patientId;  // PHI: never into messages
    std::optional<int> seriesNumber;

    std::string transferSyntaxUid, transferSyntaxName;
    bool bigEndian = false;
    bool encapsulated = false;
    /// Non-empty: the pixel data cannot be decoded / used, and why.
    std::string unsupportedReason;

    int rows = 0, columns = 0;
    std::uint64_t frames = 1;  ///< Number of Frames (1 when absent)
    int samplesPerPixel = 1, bitsAllocated = 0, bitsStored = 0, highBit = 0;
    int pixelRepresentation = 0;
    std::string photometric;
    std::uint64_t pixelDataBytes = 0;  ///< length of native pixel data; 0 if encapsulated

    FrameInfo shared;                 ///< file level (or shared functional groups)
    std::vector<FrameInfo> perFrame;  ///< empty or one per frame
    /// Frames without their own positions: frame f is at shared.position +
    /// f * frameStep (NM Spacing Between Slices, RT dose offsets are in perFrame).
    std::optional<glm::dvec3> frameStep;
    bool framesWithoutGeometry = false;  ///< multi-frame, nothing says where frames lie
    double sliceThickness = 0.0;
    double spacingBetweenSlices = 0.0;
    bool hasModalityLut = false;  ///< Modality LUT Sequence present (not applied)
};

/// Reads the header of `file` (pixel data is not loaded). Never throws for a
/// bad file: problems end up in skipReason.
[[nodiscard]] FileHeader readHeader(const std::filesystem::path& file);

/// Size in bits of one native frame (rows x columns x samples x Bits Allocated).
[[nodiscard]] std::uint64_t nativeFrameBits(const FileHeader& h);

/// "12.3 MB" style text.
[[nodiscard]] std::string humanBytes(std::uint64_t bytes);

}  // namespace vv::dicom::detail
