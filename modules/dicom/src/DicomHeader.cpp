// SPDX-License-Identifier: GPL-3.0-or-later
#include "DicomHeader.h"

#include <dcmtk/config/osconfig.h>  // must come first
#include <dcmtk/dcmdata/dcdatset.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfcache.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcmetinf.h>
#include <dcmtk/dcmdata/dcpixel.h>
#include <dcmtk/dcmdata/dcpixseq.h>
#include <dcmtk/dcmdata/dcpxitem.h>
#include <dcmtk/dcmdata/dcrledrg.h>
#include <dcmtk/dcmdata/dcsequen.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <dcmtk/dcmjpeg/djdecode.h>
#include <dcmtk/dcmjpls/djdecode.h>
#include <dcmtk/oflog/oflog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <mutex>
#include <sstream>
#include <string_view>

#include "vv/core/Error.h"

namespace vv::dicom::detail {

namespace fs = std::filesystem;

void ensureCodecs() {
    static std::once_flag once;
    std::call_once(once, [] {
        // DCMTK's messages may quote attribute values (patient data): off.
        OFLog::configure(OFLogger::OFF_LOG_LEVEL);
        DJDecoderRegistration::registerCodecs();
        DJLSDecoderRegistration::registerCodecs();
        DcmRLEDecoderRegistration::registerCodecs();
    });
}

std::string humanBytes(std::uint64_t bytes) {
    static constexpr std::array<const char*, 7> kUnits = {"bytes", "KB", "MB", "GB",
                                                          "TB",    "PB", "EB"};
    auto v = static_cast<double>(bytes);
    std::size_t u = 0;
    while (v >= 1000.0 && u + 1 < kUnits.size()) {
        v /= 1000.0;
        ++u;
    }
    if (u == 0) {
        return std::to_string(bytes) + " bytes";
    }
    std::ostringstream out;
    out << std::fixed << std::setprecision(1) << v << ' ' << kUnits.at(u);
    return out.str();
}

namespace {

std::string getString(DcmItem* item, const DcmTagKey& tag) {
    OFString s;
    if (item != nullptr && item->findAndGetOFStringArray(tag, s).good()) {
        std::string out(s.c_str(), s.length());
        while (!out.empty() && (out.back() == ' ' || out.back() == '\0')) {
            out.pop_back();
        }
        return out;
    }
    return {};
}

template <std::size_t N>
std::optional<std::array<double, N>> getDoubles(DcmItem* item, const DcmTagKey& tag) {
    if (item == nullptr) {
        return std::nullopt;
    }
    std::array<double, N> v{};
    for (std::size_t i = 0; i < N; ++i) {
        Float64 d = 0;
        if (item->findAndGetFloat64(tag, d, static_cast<unsigned long>(i)).bad() ||
            !std::isfinite(d)) {
            return std::nullopt;
        }
        v[i] = d;
    }
    return v;
}

std::optional<double> getDouble(DcmItem* item, const DcmTagKey& tag) {
    const auto v = getDoubles<1>(item, tag);
    return v ? std::optional<double>((*v)[0]) : std::nullopt;
}

int getInt(DcmItem* item, const DcmTagKey& tag, int fallback) {
    Uint16 v = 0;
    if (item != nullptr && item->findAndGetUint16(tag, v).good()) {
        return v;
    }
    return fallback;
}

DcmItem* firstItem(DcmItem* item, const DcmTagKey& seq) {
    DcmItem* out = nullptr;
    if (item != nullptr && item->findAndGetSequenceItem(seq, out, 0).good()) {
        return out;
    }
    return nullptr;
}

/// Fills `f` from a file-level data set or a functional groups item.
void readGeometry(DcmItem* item, FrameInfo& f, bool functionalGroups) {
    DcmItem* pos = functionalGroups ? firstItem(item, DCM_PlanePositionSequence) : item;
    DcmItem* ori = functionalGroups ? firstItem(item, DCM_PlaneOrientationSequence) : item;
    DcmItem* px = functionalGroups ? firstItem(item, DCM_PixelMeasuresSequence) : item;
    DcmItem* lut = functionalGroups ? firstItem(item, DCM_PixelValueTransformationSequence) : item;
    if (const auto p = getDoubles<3>(pos, DCM_ImagePositionPatient)) {
        f.position = glm::dvec3((*p)[0], (*p)[1], (*p)[2]);
    }
    if (const auto o = getDoubles<6>(ori, DCM_ImageOrientationPatient)) {
        f.orientation = *o;
    }
    auto ps = getDoubles<2>(px, DCM_PixelSpacing);
    if (!ps && !functionalGroups) {
        ps = getDoubles<2>(px, DCM_ImagerPixelSpacing);
    }
    if (ps && (*ps)[0] > 0 && (*ps)[1] > 0) {
        f.pixelSpacing = glm::dvec2((*ps)[1], (*ps)[0]);  // (column spacing, row spacing)
    }
    if (const auto s = getDouble(lut, DCM_RescaleSlope)) {
        f.slope = *s;
    }
    if (const auto i = getDouble(lut, DCM_RescaleIntercept)) {
        f.intercept = *i;
    }
}

void overlay(FrameInfo& base, const FrameInfo& top) {
    if (top.position) {
        base.position = top.position;
    }
    if (top.orientation) {
        base.orientation = top.orientation;
    }
    if (top.pixelSpacing) {
        base.pixelSpacing = top.pixelSpacing;
    }
    if (top.slope) {
        base.slope = top.slope;
    }
    if (top.intercept) {
        base.intercept = top.intercept;
    }
}

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

/// Why a file with this SOP class and no pixel data is skipped.
std::string nonImageReason(const std::string& sopClass, const std::string& modality) {
    const std::string name = sopClass.empty() ? "" : dcmFindNameOfUID(sopClass.c_str(), "");
    std::string what;
    if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.88.59")) {
        what = "key object selection";
    } else if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.88.") || modality == "SR") {
        what = "structured report";
    } else if (sopClass == "1.2.840.10008.5.1.4.1.1.481.5" ||
               sopClass == "1.2.840.10008.5.1.4.1.1.481.8" || modality == "RTPLAN") {
        what = "RT plan";
    } else if (sopClass == "1.2.840.10008.5.1.4.1.1.481.3") {
        what = "RT structure set";
    } else if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.481.") || startsWith(modality, "RT")) {
        what = "RT object";
    } else if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.9.")) {
        what = "waveform";
    } else if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.11.")) {
        what = "presentation state";
    } else if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.104.")) {
        what = "encapsulated document";
    } else if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.66")) {
        what = "raw data / registration / fiducials";
    } else if (sopClass.empty()) {
        return "no pixel data and no SOP Class UID (not a DICOM object VesselView can use)";
    } else if (startsWith(sopClass, "1.2.840.10008.5.1.4.1.1.")) {
        what = "image object without pixel data";
    } else {
        what = "non-image object";
    }
    return what + " (no pixel data" + (name.empty() ? "" : "; SOP class " + name) + ")";
}

/// Quick check before DCMTK parses: "DICM" at 128, or a data set without
/// preamble that starts with a plausible group in either byte order.
bool sniffDicom(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::array<char, 132> b{};
    in.read(b.data(), b.size());
    const auto n = in.gcount();
    if (n >= 132 && std::string_view(b.data() + 128, 4) == "DICM") {
        return true;
    }
    if (n < 8) {
        return false;
    }
    const auto b0 = static_cast<unsigned char>(b[0]);
    const auto b1 = static_cast<unsigned char>(b[1]);
    const unsigned le = b0 | (b1 << 8U);
    const unsigned be = (b0 << 8U) | b1;
    const auto plausible = [](unsigned g) {
        return g == 0x0002 || g == 0x0004 || g == 0x0008 || g == 0x0010 || g == 0x0018 ||
               g == 0x0020 || g == 0x0028;
    };
    return plausible(le) || plausible(be);
}

/// Why the pixel data of this transfer syntax cannot be decoded; empty if it can.
std::string transferSyntaxProblem(const std::string& uid, const std::string& name) {
    if (uid.empty()) {
        return {};
    }
    if (uid == "1.2.840.10008.1.2.4.90" || uid == "1.2.840.10008.1.2.4.91" ||
        uid == "1.2.840.10008.1.2.4.92" || uid == "1.2.840.10008.1.2.4.93") {
        return "JPEG 2000 is not supported (DCMTK has no decoder)";
    }
    if (uid == "1.2.840.10008.1.2.4.201" || uid == "1.2.840.10008.1.2.4.202" ||
        uid == "1.2.840.10008.1.2.4.203") {
        return "High-Throughput JPEG 2000 is not supported (DCMTK has no decoder)";
    }
    if (uid == "1.2.840.10008.1.2.4.94" || uid == "1.2.840.10008.1.2.4.95") {
        return "JPIP referenced pixel data is not supported";
    }
    const DcmXfer x(uid.c_str());
    if (x.getXfer() == EXS_Unknown) {
        return "unknown transfer syntax " + uid + " is not supported";
    }
    const E_TransferSyntax t = x.getXfer();
    const bool decodable = !x.isEncapsulated() || t == EXS_RLELossless || t == EXS_JPEGProcess1 ||
                           t == EXS_JPEGProcess2_4 || t == EXS_JPEGProcess14 ||
                           t == EXS_JPEGProcess14SV1 || t == EXS_JPEGLSLossless ||
                           t == EXS_JPEGLSLossy || t == EXS_JPEGProcess6_8 ||
                           t == EXS_JPEGProcess10_12;
    if (!decodable) {
        return "transfer syntax '" + name + "' (" + uid + ") is not supported";
    }
    return {};
}

/// Why `file` is not worth parsing: not a regular file, empty, or neither a
/// DICM prefix nor a plausible data set; empty when it is.
std::string whyNotDicom(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        return "not a regular file";
    }
    if (fs::file_size(file, ec) == 0) {
        return "empty file";
    }
    if (!sniffDicom(file)) {
        return "not a DICOM file (no DICM prefix, no data set)";
    }
    return {};
}

/// What parsing a file gave besides the data set.
struct Parsed {
    std::string damaged;     ///< why a truncated or corrupt file's pixel data is unusable
    std::string skipReason;  ///< non-empty: not even the header parses
};

/// Parses `file` into `ff`. A truncated or corrupt file is parsed again up to
/// its pixel data, so that an image still shows up in its series (and is
/// refused with `damaged` as the reason when loaded).
Parsed parse(DcmFileFormat& ff, const fs::path& file) {
    Parsed parsed;
    const OFCondition status =
        ff.loadFile(OFFilename(file.c_str()), EXS_Unknown, EGL_noChange, 4096, ERM_autoDetect);
    if (status.bad()) {
        parsed.damaged = status == EC_StreamNotifyClient
                             ? std::string("the file is truncated (premature end of stream)")
                             : std::string("the file is corrupt (") + status.text() + ")";
        ff.clear();
        const OFCondition header =
            ff.loadFileUntilTag(OFFilename(file.c_str()), EXS_Unknown, EGL_noChange, 4096,
                                ERM_autoDetect, DCM_PixelData);
        if (header.bad() || !ff.getDataset()->tagExists(DCM_Rows)) {
            parsed.skipReason = "cannot be parsed as DICOM: " + parsed.damaged;
        }
    }
    return parsed;
}

/// True, with `h` complete (skipped, its referenced files listed), when the
/// data set is a DICOMDIR.
bool readDicomdir(DcmDataset* ds, const std::string& mediaClass, FileHeader& h) {
    if (mediaClass != UID_MediaStorageDirectoryStorage &&
        !ds->tagExists(DCM_DirectoryRecordSequence)) {
        return false;
    }
    h.isDicomdir = true;
    h.skipReason = "DICOMDIR (a media index; the files it lists are read themselves)";
    DcmSequenceOfItems* seq = nullptr;
    if (ds->findAndGetSequence(DCM_DirectoryRecordSequence, seq).good() && seq != nullptr) {
        for (unsigned long i = 0; i < seq->card(); ++i) {
            std::string id = getString(seq->getItem(i), DCM_ReferencedFileID);
            if (!id.empty()) {
                std::replace(id.begin(), id.end(), '\\', '/');
                h.dicomdirFiles.push_back(id);
            }
        }
    }
    return true;
}

/// UIDs, modality, descriptions, patient and series number; the SOP class
/// from the meta header when the data set has none.
void readIdentity(DcmDataset* ds, const std::string& mediaClass, FileHeader& h) {
    h.sopClassUid = getString(ds, DCM_SOPClassUID);
    if (h.sopClassUid.empty()) {
        h.sopClassUid = mediaClass;
    }
    h.sopInstanceUid = getString(ds, DCM_SOPInstanceUID);
    h.studyUid = getString(ds, DCM_StudyInstanceUID);
    h.seriesUid = getString(ds, DCM_SeriesInstanceUID);
    h.frameOfReferenceUid = getString(ds, DCM_FrameOfReferenceUID);
    h.modality = getString(ds, DCM_Modality);
    h.seriesDescription = getString(ds, DCM_SeriesDescription);
    h.studyDescription = getString(ds, DCM_StudyDescription);
    h.studyDate = getString(ds, DCM_StudyDate);
    h.patientName = getString(ds, DCM_PatientName);
    h.patientId = getString(ds, DCM_PatientID);
    Sint32 seriesNumber = 0;
    if (ds->findAndGetSint32(DCM_SeriesNumber, seriesNumber).good()) {
        h.seriesNumber = seriesNumber;
    }
}

/// The transfer syntax (the meta header's, else the one the data set was
/// read in), its name, byte order and encapsulation.
void readTransferSyntax(DcmDataset* ds, DcmMetaInfo* meta, FileHeader& h) {
    h.transferSyntaxUid = getString(meta, DCM_TransferSyntaxUID);
    const E_TransferSyntax original = ds->getOriginalXfer();
    if (h.transferSyntaxUid.empty() && original != EXS_Unknown) {
        h.transferSyntaxUid = DcmXfer(original).getXferID();
    }
    const DcmXfer x(h.transferSyntaxUid.c_str());
    h.transferSyntaxName = x.getXfer() != EXS_Unknown ? x.getXferName() : h.transferSyntaxUid;
    const DcmXfer read(original);
    h.bigEndian = original != EXS_Unknown && read.isBigEndian();
    h.encapsulated = x.getXfer() != EXS_Unknown && x.isEncapsulated();
}

/// The image pixel attributes: size, frames, bits, photometric, native pixel
/// data length. False, with `h.skipReason` set, when the file has no pixel
/// data (a non-image object) or no size; a damaged file or float pixel data
/// keeps its `unsupportedReason`.
bool readImagePixel(DcmDataset* ds, const std::string& damaged, FileHeader& h) {
    DcmElement* pixel = nullptr;
    if (!damaged.empty()) {
        h.unsupportedReason = damaged;
    } else if (ds->findAndGetElement(DCM_PixelData, pixel).bad() || pixel == nullptr) {
        if (ds->tagExists(DCM_FloatPixelData) || ds->tagExists(DCM_DoubleFloatPixelData)) {
            h.unsupportedReason = "float pixel data (parametric maps) is not supported";
        } else {
            h.skipReason = nonImageReason(h.sopClassUid, h.modality);
            return false;
        }
    }
    h.rows = getInt(ds, DCM_Rows, 0);
    h.columns = getInt(ds, DCM_Columns, 0);
    if (h.rows <= 0 || h.columns <= 0) {
        h.skipReason = "pixel data without Rows / Columns";
        return false;
    }
    Sint32 frames = 1;
    if (ds->findAndGetSint32(DCM_NumberOfFrames, frames).good() && frames > 1) {
        h.frames = static_cast<std::uint64_t>(frames);
    }
    h.samplesPerPixel = getInt(ds, DCM_SamplesPerPixel, 1);
    h.bitsAllocated = getInt(ds, DCM_BitsAllocated, 0);
    h.bitsStored = getInt(ds, DCM_BitsStored, h.bitsAllocated);
    if (h.bitsStored <= 0 || h.bitsStored > h.bitsAllocated) {
        h.bitsStored = h.bitsAllocated;
    }
    h.highBit = getInt(ds, DCM_HighBit, h.bitsStored - 1);
    h.pixelRepresentation = getInt(ds, DCM_PixelRepresentation, 0);
    h.photometric = getString(ds, DCM_PhotometricInterpretation);
    if (pixel != nullptr && !h.encapsulated) {
        h.pixelDataBytes = pixel->getLengthField();
    }
    return true;
}

/// Sets `h.unsupportedReason` to what stops decoding, first reason wins (an
/// earlier one stays): transfer syntax, colour, photometric interpretation,
/// Bits Allocated, compressed 1-bit data.
void checkDecodable(FileHeader& h) {
    if (h.unsupportedReason.empty()) {
        h.unsupportedReason = transferSyntaxProblem(h.transferSyntaxUid, h.transferSyntaxName);
    }
    if (h.unsupportedReason.empty() && h.samplesPerPixel != 1) {
        h.unsupportedReason =
            "colour images (" +
            (h.photometric.empty() ? std::string("3 samples per pixel") : h.photometric) +
            ") cannot be loaded as a volume; VesselView loads greyscale images";
    }
    if (h.unsupportedReason.empty() && h.photometric != "MONOCHROME1" &&
        h.photometric != "MONOCHROME2" && !h.photometric.empty()) {
        h.unsupportedReason = "photometric interpretation " + h.photometric +
                              " cannot be loaded as a volume; VesselView loads greyscale images";
    }
    if (h.unsupportedReason.empty() && h.bitsAllocated != 1 && h.bitsAllocated != 8 &&
        h.bitsAllocated != 16 && h.bitsAllocated != 32) {
        h.unsupportedReason = "Bits Allocated " + std::to_string(h.bitsAllocated) +
                              " is not supported (1, 8, 16 or 32)";
    }
    if (h.unsupportedReason.empty() && h.bitsAllocated == 1 && h.encapsulated) {
        h.unsupportedReason = "compressed 1-bit pixel data is not supported";
    }
}

/// Geometry: file level (an NM detector's position and orientation where the
/// file has none), then shared functional groups, then per frame (kept only
/// when there is one item per frame); slice thickness and spacing; whether a
/// Modality LUT Sequence replaces the rescale.
void readFrameGeometry(DcmDataset* ds, FileHeader& h) {
    readGeometry(ds, h.shared, false);
    if (!h.shared.position || !h.shared.orientation) {
        // NM: position and orientation of the detector.
        if (DcmItem* det = firstItem(ds, DCM_DetectorInformationSequence)) {
            FrameInfo d;
            readGeometry(det, d, false);
            if (!h.shared.position) {
                h.shared.position = d.position;
            }
            if (!h.shared.orientation) {
                h.shared.orientation = d.orientation;
            }
        }
    }
    h.sliceThickness = getDouble(ds, DCM_SliceThickness).value_or(0.0);
    h.spacingBetweenSlices = getDouble(ds, DCM_SpacingBetweenSlices).value_or(0.0);
    if (DcmItem* shared = firstItem(ds, DCM_SharedFunctionalGroupsSequence)) {
        FrameInfo s;
        readGeometry(shared, s, true);
        overlay(h.shared, s);
        if (DcmItem* pm = firstItem(shared, DCM_PixelMeasuresSequence)) {
            h.sliceThickness = getDouble(pm, DCM_SliceThickness).value_or(h.sliceThickness);
            h.spacingBetweenSlices =
                getDouble(pm, DCM_SpacingBetweenSlices).value_or(h.spacingBetweenSlices);
        }
    }
    DcmSequenceOfItems* perFrame = nullptr;
    if (ds->findAndGetSequence(DCM_PerFrameFunctionalGroupsSequence, perFrame).good() &&
        perFrame != nullptr && perFrame->card() == h.frames) {
        h.perFrame.reserve(perFrame->card());
        for (unsigned long f = 0; f < perFrame->card(); ++f) {
            FrameInfo fi = h.shared;
            FrameInfo own;
            readGeometry(perFrame->getItem(f), own, true);
            overlay(fi, own);
            h.perFrame.push_back(fi);
        }
    }
    h.hasModalityLut = ds->tagExists(DCM_ModalityLUTSequence) && !h.shared.slope;
}

/// RT dose: the Grid Frame Offset Vector, one finite offset per frame; empty
/// when absent or unusable.
std::vector<double> gridFrameOffsets(DcmDataset* ds, std::uint64_t frames) {
    std::vector<double> offsets;
    DcmElement* g = nullptr;
    if (ds->findAndGetElement(DCM_GridFrameOffsetVector, g).good() && g != nullptr &&
        g->getVM() == frames) {
        for (unsigned long f = 0; f < frames; ++f) {
            Float64 d = 0;
            if (g->getFloat64(d, f).bad() || !std::isfinite(d)) {
                return {};
            }
            offsets.push_back(d);
        }
    }
    return offsets;
}

/// A multi-frame file without a position for every frame: the frames lie at
/// RT dose offsets along the normal (perFrame), or a step apart along it
/// (frameStep, from Spacing Between Slices or Slice Thickness), or nowhere
/// known (framesWithoutGeometry).
void placeFrames(DcmDataset* ds, FileHeader& h) {
    const bool perFramePositions =
        !h.perFrame.empty() &&
        std::all_of(h.perFrame.begin(), h.perFrame.end(),
                    [](const FrameInfo& f) { return f.position.has_value(); });
    if (h.frames <= 1 || perFramePositions) {
        return;
    }
    h.perFrame.clear();
    if (!h.shared.position || !h.shared.orientation) {
        h.framesWithoutGeometry = true;
        return;
    }
    const auto& o = *h.shared.orientation;
    const glm::dvec3 normal =
        glm::cross(glm::dvec3(o[0], o[1], o[2]), glm::dvec3(o[3], o[4], o[5]));
    const double nl = glm::length(normal);
    const std::vector<double> offsets =
        nl > 0 ? gridFrameOffsets(ds, h.frames) : std::vector<double>{};
    if (!offsets.empty()) {
        h.perFrame.assign(h.frames, h.shared);
        for (std::size_t f = 0; f < offsets.size(); ++f) {
            h.perFrame[f].position = *h.shared.position + (offsets[f] - offsets[0]) * normal / nl;
        }
    } else if (nl > 0 && (h.spacingBetweenSlices != 0.0 || h.sliceThickness > 0.0)) {
        const double step =
            h.spacingBetweenSlices != 0.0 ? h.spacingBetweenSlices : h.sliceThickness;
        h.frameStep = step * normal / nl;
    } else {
        h.framesWithoutGeometry = true;
    }
}

}  // namespace

FileHeader readHeader(const fs::path& file) {
    ensureCodecs();
    FileHeader h;
    h.file = file;
    h.skipReason = whyNotDicom(file);
    if (!h.skipReason.empty()) {
        return h;
    }
    DcmFileFormat ff;
    const Parsed parsed = parse(ff, file);
    if (!parsed.skipReason.empty()) {
        h.skipReason = parsed.skipReason;
        return h;
    }
    DcmDataset* ds = ff.getDataset();
    DcmMetaInfo* meta = ff.getMetaInfo();
    const std::string mediaClass = getString(meta, DCM_MediaStorageSOPClassUID);
    if (readDicomdir(ds, mediaClass, h)) {
        return h;
    }
    readIdentity(ds, mediaClass, h);
    readTransferSyntax(ds, meta, h);
    if (!readImagePixel(ds, parsed.damaged, h)) {
        return h;
    }
    checkDecodable(h);
    readFrameGeometry(ds, h);
    placeFrames(ds, h);
    return h;
}

std::uint64_t nativeFrameBits(const FileHeader& h) {
    return static_cast<std::uint64_t>(h.rows) * static_cast<std::uint64_t>(h.columns) *
           static_cast<std::uint64_t>(h.samplesPerPixel) *
           static_cast<std::uint64_t>(h.bitsAllocated);
}

}  // namespace vv::dicom::detail
