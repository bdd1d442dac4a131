// SPDX-License-Identifier: GPL-3.0-or-later
// scanDicom: files -> patients / studies / series. Reads headers only.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <tuple>

#include "DicomHeader.h"
#include "vv/core/AsciiText.h"
#include "vv/core/Error.h"
#include "vv/core/Log.h"
#include "vv/dicom/Dicom.h"

namespace vv::dicom {

namespace fs = std::filesystem;

namespace {

const log::Category kLog("vv.dicom");

/// Resolves a DICOMDIR Referenced File ID below `root`, trying the exact
/// name first and then a case-insensitive match per component (media
/// written in upper case, copied to a case-sensitive file system).
fs::path resolveReferenced(const fs::path& root, const std::string& id) {
    fs::path exact = root / id;
    std::error_code ec;
    if (fs::exists(exact, ec)) {
        return exact;
    }
    fs::path current = root;
    std::stringstream parts(id);
    std::string part;
    while (std::getline(parts, part, '/')) {
        if (part.empty()) {
            continue;
        }
        fs::path next;
        for (fs::directory_iterator it(current, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string name = it->path().filename().string();
            if (equalsIgnoringCase(name, part)) {
                next = it->path();
                break;
            }
        }
        if (next.empty()) {
            return exact;  // reported as missing
        }
        current = next;
    }
    return current;
}

struct SeriesBuilder {
    DicomSeries series;
    std::vector<double> positionsAlongNormal;
    std::string patientName, patientId;
    std::string studyDescription, studyDate;
    std::optional<std::array<double, 6>> orientation;
    bool mixedOrientation = false;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// The files a scan reads, found before any header but a DICOMDIR's is read.
struct Listing {
    std::vector<fs::path> files;               ///< sorted, unique
    std::vector<DicomSkippedFile> missing;     ///< referenced by a DICOMDIR, not there
    std::optional<detail::FileHeader> single;  ///< a single file's header, read once
};

/// The regular files below `folder`, recursively, sorted; folders that cannot
/// be entered are passed over. Throws IoError when `folder` cannot be listed
/// and CancelledError when the scan is cancelled.
std::vector<fs::path> listFolder(const fs::path& folder, const Progress& progress) {
    std::vector<fs::path> files;
    std::error_code ec;
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        throw IoError(folder, "cannot be listed (" + ec.message() + ")");
    }
    for (fs::recursive_directory_iterator end; it != end; it.increment(ec)) {
        if (ec) {
            break;
        }
        std::error_code fec;
        if (it->is_regular_file(fec)) {
            files.push_back(it->path());
            if (files.size() % 1024 == 0) {
                progress.throwIfCancelled();
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// The files to scan for `path`: a folder's files, the files a DICOMDIR
/// references (it counts as examined; one that lists none is skipped), or a
/// single file with its header.
Listing listFiles(const fs::path& path, DicomScanResult& result, const Progress& progress) {
    Listing listing;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        listing.files = listFolder(path, progress);
        return listing;
    }
    // A DICOMDIR given directly: follow its references.
    detail::FileHeader h = detail::readHeader(path);
    if (!h.isDicomdir) {
        listing.files.push_back(path);
        listing.single = std::move(h);
        return listing;
    }
    result.filesExamined = 1;
    const fs::path root = path.parent_path();
    for (const auto& id : h.dicomdirFiles) {
        const fs::path f = resolveReferenced(root, id);
        if (fs::is_regular_file(f, ec)) {
            listing.files.push_back(f);
        } else {
            listing.missing.push_back({f, "referenced by the DICOMDIR but missing"});
        }
    }
    std::sort(listing.files.begin(), listing.files.end());
    listing.files.erase(std::unique(listing.files.begin(), listing.files.end()),
                        listing.files.end());
    if (h.dicomdirFiles.empty()) {
        result.skipped.push_back({path, "DICOMDIR that lists no files"});
    }
    return listing;
}

/// The file-level (or shared) `field` of a header, else its first frame's.
template <typename T>
std::optional<T> fileOrFirstFrame(const detail::FileHeader& h,
                                  std::optional<T> detail::FrameInfo::*field) {
    if (h.shared.*field || h.perFrame.empty()) {
        return h.shared.*field;
    }
    return h.perFrame.front().*field;
}

/// Starts a series with what its first file says.
void startSeries(SeriesBuilder& b, const detail::FileHeader& h) {
    DicomSeries& s = b.series;
    s.seriesInstanceUid = h.seriesUid;
    s.studyInstanceUid = h.studyUid;
    s.frameOfReferenceUid = h.frameOfReferenceUid;
    s.modality = h.modality;
    s.description = h.seriesDescription;
    s.seriesNumber = h.seriesNumber;
    s.sopClassUid = h.sopClassUid;
    s.transferSyntaxUid = h.transferSyntaxUid;
    s.transferSyntaxName = h.transferSyntaxName;
    s.rows = h.rows;
    s.columns = h.columns;
    s.pixelSpacing = fileOrFirstFrame(h, &detail::FrameInfo::pixelSpacing);
    s.unsupportedReason = h.unsupportedReason;
    b.patientName = h.patientName;
    b.patientId = h.patientId;
    b.studyDescription = h.studyDescription;
    b.studyDate = h.studyDate;
    b.orientation = fileOrFirstFrame(h, &detail::FrameInfo::orientation);
}

/// Whether an orientation of the file differs from the series' first one
/// (a localizer): known from headers alone.
bool orientationDiffers(const SeriesBuilder& b, const detail::FileHeader& h) {
    const auto differs = [&](const std::optional<std::array<double, 6>>& o) {
        if (!o || !b.orientation) {
            return false;
        }
        for (std::size_t k = 0; k < 6; ++k) {
            if (std::abs((*o)[k] - (*b.orientation)[k]) > 1e-3) {
                return true;
            }
        }
        return false;
    };
    bool mixedOrientation = differs(h.shared.orientation);
    for (const auto& f : h.perFrame) {
        mixedOrientation = mixedOrientation || differs(f.orientation);
    }
    return mixedOrientation;
}

/// Keeps the file's positions along the series' normal, for the slice
/// spacing shown in lists: per frame, or the file's (and the next frame's
/// when frames lie a step apart).
void addPositions(SeriesBuilder& b, const detail::FileHeader& h) {
    if (!b.orientation) {
        return;
    }
    const auto& o = *b.orientation;
    const glm::dvec3 n = glm::cross(glm::dvec3(o[0], o[1], o[2]), glm::dvec3(o[3], o[4], o[5]));
    if (!h.perFrame.empty()) {
        for (const auto& f : h.perFrame) {
            if (f.position) {
                b.positionsAlongNormal.push_back(glm::dot(*f.position, n));
            }
        }
    } else if (h.shared.position) {
        b.positionsAlongNormal.push_back(glm::dot(*h.shared.position, n));
        if (h.frameStep && h.frames > 1) {
            b.positionsAlongNormal.push_back(glm::dot(*h.shared.position + *h.frameStep, n));
        }
    }
}

/// Adds an image file to its series (`fresh`: the series' first file): its
/// frames, whether sizes or orientations mix, the first reason it cannot load.
void addFile(SeriesBuilder& b, bool fresh, const fs::path& file, const detail::FileHeader& h) {
    DicomSeries& s = b.series;
    if (fresh) {
        startSeries(b, h);
    } else {
        if (h.rows != s.rows || h.columns != s.columns) {
            s.mixedSizes = true;
        }
        if (s.unsupportedReason.empty()) {
            s.unsupportedReason = h.unsupportedReason;
        }
    }
    const bool mixedOrientation = orientationDiffers(b, h);
    b.mixedOrientation = b.mixedOrientation || mixedOrientation;
    if (mixedOrientation && s.unsupportedReason.empty()) {
        s.unsupportedReason =
            "images of different orientations (a localizer?); one volume needs one orientation";
    }
    s.files.push_back(file);
    s.imageCount += static_cast<std::size_t>(h.frames);
    s.multiFrame = s.multiFrame || h.frames > 1;
    addPositions(b, h);
}

/// Key: series (patient and study come with it).
using SeriesMap = std::map<std::string, SeriesBuilder>;

/// Reads every listed file's header into its series; skipped files (with
/// their reasons) go to `result.skipped`. Reports progress.
SeriesMap readSeries(Listing& listing, DicomScanResult& result, const Progress& progress) {
    SeriesMap bySeries;
    const std::vector<fs::path>& files = listing.files;
    std::size_t done = 0;
    for (const auto& file : files) {
        progress.report(
            static_cast<double>(done) / static_cast<double>(std::max<std::size_t>(files.size(), 1)),
            "Reading DICOM headers");
        ++done;
        ++result.filesExamined;
        detail::FileHeader h;
        try {
            h = listing.single ? std::move(*listing.single) : detail::readHeader(file);
        } catch (const std::bad_alloc&) {
            h.file = file;
            h.skipReason = "header too large to read";
        }
        if (!h.skipReason.empty()) {
            result.skipped.push_back({file, h.skipReason});
            log::debug(kLog, file.string() + ": skipped: " + h.skipReason);
            continue;
        }
        const std::string seriesKey =
            h.seriesUid.empty() ? "(no Series Instance UID) " + file.string() : h.seriesUid;
        auto [it, fresh] = bySeries.try_emplace(seriesKey);
        addFile(it->second, fresh, file, h);
    }
    progress.report(1.0, "Reading DICOM headers");
    return bySeries;
}

/// The median gap between distinct positions along the normal, when the
/// series has one orientation and two positions or more.
std::optional<double> sliceSpacing(SeriesBuilder& b) {
    auto& pos = b.positionsAlongNormal;
    if (pos.size() < 2 || b.mixedOrientation) {
        return std::nullopt;
    }
    std::sort(pos.begin(), pos.end());
    std::vector<double> gaps;
    for (std::size_t i = 1; i < pos.size(); ++i) {
        if (pos[i] - pos[i - 1] > 1e-4) {
            gaps.push_back(pos[i] - pos[i - 1]);
        }
    }
    if (gaps.empty()) {
        return std::nullopt;
    }
    return median(gaps);
}

/// The series grouped into patients (by ID and name) and studies, studies
/// by date then UID, series by number then UID.
std::vector<DicomPatient> groupSeries(SeriesMap& bySeries) {
    std::map<std::string, DicomPatient> patients;  // key: ID + name
    std::map<std::string, std::map<std::string, DicomStudy>> studies;
    for (auto& [key, b] : bySeries) {
        DicomSeries& s = b.series;
        s.sliceSpacing = sliceSpacing(b);
        const std::string patientKey = b.patientId + '\x1f' + b.patientName;
        DicomPatient& p = patients[patientKey];
        p.id = b.patientId;
        p.name = b.patientName;
        DicomStudy& st = studies[patientKey][s.studyInstanceUid];
        st.studyInstanceUid = s.studyInstanceUid;
        st.description = b.studyDescription;
        st.date = b.studyDate;
        st.series.push_back(std::move(s));
    }
    std::vector<DicomPatient> out;
    for (auto& [patientKey, p] : patients) {
        for (auto& [uid, st] : studies[patientKey]) {
            std::sort(st.series.begin(), st.series.end(),
                      [](const DicomSeries& a, const DicomSeries& b) {
                          return std::tuple(a.seriesNumber.value_or(0), a.seriesInstanceUid) <
                                 std::tuple(b.seriesNumber.value_or(0), b.seriesInstanceUid);
                      });
            p.studies.push_back(std::move(st));
        }
        std::sort(p.studies.begin(), p.studies.end(), [](const DicomStudy& a, const DicomStudy& b) {
            return std::tie(a.date, a.studyInstanceUid) < std::tie(b.date, b.studyInstanceUid);
        });
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace

std::vector<const DicomSeries*> DicomScanResult::allSeries() const {
    std::vector<const DicomSeries*> out;
    for (const auto& p : patients) {
        for (const auto& st : p.studies) {
            for (const auto& se : st.series) {
                out.push_back(&se);
            }
        }
    }
    return out;
}

const DicomSeries* DicomScanResult::findSeries(std::string_view uid) const {
    for (const DicomSeries* s : allSeries()) {
        if (s->seriesInstanceUid == uid) {
            return s;
        }
    }
    return nullptr;
}

bool looksLikeDicom(const fs::path& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        return true;
    }
    if (!fs::is_regular_file(path, ec)) {
        return false;
    }
    std::string name = path.filename().string();
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    if (name == "DICOMDIR") {
        return true;
    }
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".dcm" || ext == ".dicom") {
        return true;
    }
    std::ifstream in(path, std::ios::binary);
    std::array<char, 132> b{};
    in.read(b.data(), b.size());
    return in.gcount() == 132 && std::string_view(b.data() + 128, 4) == "DICM";
}

std::uint64_t availableMemoryBytes() {
    std::uint64_t available = 0;
    {
        std::ifstream in("/proc/meminfo");
        std::string key;
        std::uint64_t value = 0;
        std::string unit;
        while (in >> key >> value) {
            std::getline(in, unit);
            if (key == "MemAvailable:") {
                available = value * 1024;
                break;
            }
        }
    }
    if (available == 0) {
        const long pages = sysconf(_SC_AVPHYS_PAGES);
        const long size = sysconf(_SC_PAGESIZE);
        if (pages > 0 && size > 0) {
            available = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(size);
        }
    }
    // A cgroup v2 limit (containers) may be tighter than the machine.
    std::ifstream maxFile("/sys/fs/cgroup/memory.max");
    std::ifstream currentFile("/sys/fs/cgroup/memory.current");
    std::string max;
    std::uint64_t current = 0;
    if (maxFile >> max && max != "max" && currentFile >> current) {
        try {
            const std::uint64_t limit = std::stoull(max);
            const std::uint64_t left = limit > current ? limit - current : 0;
            available = std::min(available, left);
        } catch (const std::exception&) {
            // unreadable limit: keep the machine's figure
        }
    }
    return available;
}

DicomScanResult scanDicom(const fs::path& path, const Progress& progress) {
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        throw IoError(path, "does not exist");
    }
    DicomScanResult result;
    progress.report(0.0, "Listing DICOM files");
    Listing listing = listFiles(path, result, progress);
    SeriesMap bySeries = readSeries(listing, result, progress);
    result.patients = groupSeries(bySeries);
    result.skipped.insert(result.skipped.end(), listing.missing.begin(), listing.missing.end());
    log::debug(kLog, path.string() + ": " + std::to_string(bySeries.size()) + " series, " +
                         std::to_string(result.skipped.size()) + " files skipped");
    return result;
}

}  // namespace vv::dicom
