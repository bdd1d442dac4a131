// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/segmentation/SceneSource.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>

#include "vv/core/Error.h"
#include "vv/dicom/DicomSeg.h"

namespace vv::segmentation {

namespace fs = std::filesystem;

namespace {

/// SOP Class UID of DICOM Segmentation objects.
constexpr const char* kSegmentationStorage = "1.2.840.10008.5.1.4.1.1.66.4";

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

bool isMeshFile(const fs::path& path) {
    const auto& meshes = meshio::supportedMeshExtensions();
    return std::find(meshes.begin(), meshes.end(), lowerExtension(path)) != meshes.end();
}

double number(const std::string& text, const std::string& option) {
    double value = 0.0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
        throw InvalidArgumentError(option + ": invalid number '" + text + "'");
    }
    return value;
}

long long integer(const std::string& text, const std::string& option) {
    long long value = 0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (text.empty() || ec != std::errc() || ptr != end) {
        throw InvalidArgumentError(option + ": invalid integer '" + text + "'");
    }
    return value;
}

/// The Study Date of the study in `scan` that holds `series`; empty if none.
std::string studyDateOf(const dicom::DicomScanResult& scan, const dicom::DicomSeries& series) {
    for (const dicom::DicomPatient& patient : scan.patients) {
        for (const dicom::DicomStudy& study : patient.studies) {
            for (const dicom::DicomSeries& s : study.series) {
                if (&s == &series) {
                    return study.date;
                }
            }
        }
    }
    return {};
}

}  // namespace

bool setSceneSourceOption(const std::string& name, const std::string& value,
                          SceneSourceOptions& options) {
    if (name == "--series") {
        if (value.empty()) {
            throw InvalidArgumentError("--series needs a Series Instance UID");
        }
        options.seriesInstanceUid = value;
    } else if (name == "--threshold") {
        const auto split = value.find_first_of(":,");
        if (split == std::string::npos) {
            throw InvalidArgumentError("--threshold must be LO:HI (e.g. 200:700), got '" + value +
                                       "'");
        }
        const double lo = number(value.substr(0, split), name);
        const double hi = number(value.substr(split + 1), name);
        if (lo > hi) {
            throw InvalidArgumentError("--threshold: LO must not exceed HI, got '" + value + "'");
        }
        options.segmentation.range =
            ThresholdRange{static_cast<float>(lo), static_cast<float>(hi), "--threshold " + value};
    } else if (name == "--components") {
        const long long n = integer(value, name);
        if (n < 1 || n > 255) {
            throw InvalidArgumentError("--components must be within 1..255, got " + value);
        }
        options.segmentation.keepComponents = static_cast<int>(n);
    } else if (name == "--seed") {
        glm::ivec3 seed(0);
        std::size_t at = 0;
        for (int c = 0; c < 3; ++c) {
            const std::size_t comma = value.find(',', at);
            if ((c < 2) != (comma != std::string::npos)) {
                throw InvalidArgumentError("--seed must be I,J,K (voxel indices), got '" + value +
                                           "'");
            }
            const long long v = integer(
                value.substr(at, comma == std::string::npos ? std::string::npos : comma - at),
                name);
            if (v < 0 || v > 1000000) {
                throw InvalidArgumentError("--seed: index out of range in '" + value + "'");
            }
            seed[c] = static_cast<int>(v);
            at = comma + 1;
        }
        options.segmentation.seed = seed;
    } else if (name == "--bone-removal") {
        if (value != "on" && value != "off") {
            throw InvalidArgumentError("--bone-removal must be on or off, got '" + value + "'");
        }
        options.segmentation.removeBone = value == "on";
    } else if (name == "--intensity-correction") {
        if (value != "on" && value != "off") {
            throw InvalidArgumentError("--intensity-correction must be on or off, got '" + value +
                                       "'");
        }
        options.segmentation.correctIntensity = value == "on";
    } else if (name == "--triangles") {
        const long long n = integer(value, name);
        if (n != 0 && (n < 4 || n > 100000000)) {
            throw InvalidArgumentError(
                "--triangles must be 0 (no decimation) or within "
                "4..100000000, got " +
                value);
        }
        options.surface.targetTriangles = static_cast<std::size_t>(n);
    } else {
        return false;
    }
    return true;
}

bool isDicomSource(const fs::path& path) {
    return !isMeshFile(path) && dicom::looksLikeDicom(path);
}

scene::Scene loadSceneSource(const fs::path& path, const SceneSourceOptions& options,
                             const Progress& progress, SceneSourceReport* report) {
    scene::Scene scene;
    if (!isDicomSource(path)) {
        scene.meshes.push_back(meshio::loadMesh(path, options.mesh, progress));
        if (report != nullptr) {
            *report = {};
        }
        return scene;
    }

    // A DICOM Segmentation object: one mesh per segment.
    if (dicom::isDicomSegFile(path)) {
        scene = loadDicomSegMeshes(path, options.surface, progress);
        if (report != nullptr) {
            *report = {};
            report->fromSegmentationObject = true;
            report->componentsKept = scene.meshes.size();
        }
        return scene;
    }

    // DICOM. A single image file stands for its whole series: the series is
    // looked for in the file's folder.
    scene.frame = scene::SceneFrame::PatientLps;  // images and SEG: LPS mm
    fs::path where = path;
    std::string uid = options.seriesInstanceUid;
    std::error_code ec;
    std::string upperName = path.filename().string();
    std::transform(upperName.begin(), upperName.end(), upperName.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    if (fs::is_regular_file(path, ec) && upperName != "DICOMDIR" && uid.empty()) {
        const dicom::DicomScanResult one = dicom::scanDicom(path, progress.sub(0.0, 0.01));
        const auto series = one.allSeries();
        // Without a UID the file cannot be matched to its folder's series:
        // it is loaded on its own (and its own problem reported).
        if (series.size() == 1 && !series.front()->seriesInstanceUid.empty()) {
            uid = series.front()->seriesInstanceUid;
            where = path.has_parent_path() ? path.parent_path() : fs::path(".");
        }
    }
    // The series: the one named, or the only one. A SEG series gives one
    // mesh per segment; otherwise (none, several, unknown UID) loadDicomVolume
    // scans again and throws its own error listing the series.
    const dicom::DicomScanResult scan = dicom::scanDicom(where, progress.sub(0.01, 0.05));
    const auto all = scan.allSeries();
    const dicom::DicomSeries* chosen =
        uid.empty() ? (all.size() == 1 ? all.front() : nullptr) : scan.findSeries(uid);
    const auto nameSeries = [&](SceneSourceReport& r) {
        if (chosen != nullptr) {
            r.seriesDescription = chosen->description;
            r.modality = chosen->modality;
            r.seriesNumber = chosen->seriesNumber;
            r.studyDate = studyDateOf(scan, *chosen);
        }
    };
    if (chosen != nullptr && chosen->sopClassUid == kSegmentationStorage) {
        for (std::size_t f = 0; f < chosen->files.size(); ++f) {
            const double n = static_cast<double>(chosen->files.size());
            scene::Scene part =
                loadDicomSegMeshes(chosen->files[f], options.surface,
                                   progress.sub(0.05 + 0.95 * static_cast<double>(f) / n,
                                                0.05 + 0.95 * static_cast<double>(f + 1) / n));
            for (scene::Mesh& mesh : part.meshes) {
                scene.meshes.push_back(std::move(mesh));
            }
        }
        if (report != nullptr) {
            *report = {};
            report->fromSegmentationObject = true;
            report->seriesInstanceUid = chosen->seriesInstanceUid;
            report->componentsKept = scene.meshes.size();
            nameSeries(*report);
        }
        return scene;
    }
    dicom::DicomVolume loaded =
        chosen != nullptr
            ? dicom::loadDicomSeries(*chosen, options.dicom, progress.sub(0.05, 0.5))
            : dicom::loadDicomVolume(where, uid, options.dicom, progress.sub(0.05, 0.5));
    auto volume = std::make_shared<const scene::Volume>(std::move(loaded.volume));
    Segmentation segmentation =
        segmentVessels(*volume, options.segmentation, progress.sub(0.5, 0.7));
    scene::Mesh mesh =
        extractSurface(segmentation.labelMap, {}, options.surface, progress.sub(0.7, 1.0));
    mesh.name = "vessels";
    mesh.source = path;
    scene.meshes.push_back(std::move(mesh));
    if (report != nullptr) {
        *report = {};  // nothing of an earlier source's report stays
        report->fromVolume = true;
        report->seriesInstanceUid = loaded.seriesInstanceUid;
        nameSeries(*report);
        report->volumeDims = volume->dims();
        report->range = segmentation.range;
        report->componentsFound = segmentation.componentsFound;
        report->componentsKept = segmentation.labelMap.components.size();
        report->boneComponents = segmentation.boneComponents;
        report->intensityCorrected = segmentation.intensityCorrected;
        report->gainLowest = segmentation.gainLowest;
        report->gainHighest = segmentation.gainHighest;
        report->cutOff = std::move(segmentation.cutOff);
        report->warnings = std::move(loaded.warnings);
        report->volume = std::move(volume);
        report->labelMap =
            std::make_shared<const scene::LabelMap>(std::move(segmentation.labelMap));
    }
    return scene;
}

scene::Scene loadSceneSources(const std::vector<std::filesystem::path>& files,
                              const SceneSourceOptions& options, const Progress& progress,
                              SceneSourceReport* report) {
    if (std::none_of(files.begin(), files.end(), [](const auto& f) { return isDicomSource(f); })) {
        return meshio::loadScene(files, options.mesh, progress);
    }
    // DICOM sources are segmented one by one; meshes load as before.
    scene::Scene scene;
    const auto n = static_cast<double>(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) {
        const Progress part =
            progress.sub(static_cast<double>(i) / n, static_cast<double>(i + 1) / n);
        SceneSourceReport loaded;
        const bool dicomSource = isDicomSource(files[i]);
        scene::Scene one = dicomSource ? loadSceneSource(files[i], options, part, &loaded)
                                       : meshio::loadScene({files[i]}, options.mesh, part);
        if (dicomSource && report != nullptr) {
            *report = std::move(loaded);
        }
        if (one.frame == scene::SceneFrame::PatientLps) {
            scene.frame = one.frame;  // meshes opened with DICOM are shown in its frame
        }
        for (auto& mesh : one.meshes) {
            scene.meshes.push_back(std::move(mesh));
        }
    }
    return scene;
}

}  // namespace vv::segmentation
