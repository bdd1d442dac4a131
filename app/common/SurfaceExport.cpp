// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SurfaceExport.h"

#include <array>
#include <chrono>
#include <ctime>
#include <utility>

#include "vv/Version.h"
#include "vv/core/NumberText.h"
#include "vv/segmentation/VolumeSurface.h"

namespace vv::app {

namespace {

std::string utcNow() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm utc{};
    gmtime_r(&now, &utc);
    std::array<char, 32> text{};
    std::strftime(text.data(), text.size(), "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text.data();
}

}  // namespace

meshio::MeshFileMetadata surfaceMetadata(const SegmentationProvenance& p) {
    meshio::MeshFileMetadata m;
    const auto add = [&m](const char* name, std::string value) {
        m.fields.emplace_back(name, std::move(value));
    };
    add("software", "VesselView " + std::string(kVersion));
    add("coordinates",
        "DICOM patient LPS, mm (x to the patient's left, y posterior, z head); RAS = (-x, -y, z)");
    add("created", utcNow());
    add("series_instance_uid", p.seriesInstanceUid);
    add("series_description", p.seriesDescription);
    add("series_number", p.seriesNumber ? std::to_string(*p.seriesNumber) : std::string());
    add("modality", p.modality);
    const bool fromSeg = !p.segmentNames.empty();
    if (fromSeg) {
        add("segments", "from a DICOM Segmentation object: " + segmentsText(p));
        add("label_meaning", "point array 'label': the segment (as 'segments')");
    } else {
        add("threshold", thresholdText(p));
        add("threshold_rule", p.range.rule);
        add("intensity_correction", correctionText(p));
        add("components", componentsText(p));
        add("bone_removal", p.boneRemoved ? "on" : "off");
        add("surface",
            "flying edges at 0.5, windowed-sinc smoothing, " +
                (p.targetTriangles == 0
                     ? std::string("no decimation")
                     : "decimated to at most " + std::to_string(p.targetTriangles) + " triangles"));
        add("label_meaning", "point array 'label': the kept component (1 = largest)");
    }
    std::string summary = "VesselView " + std::string(kVersion) + "; LPS mm; " +
                          (p.modality.empty() ? std::string("DICOM") : p.modality) + "; ";
    summary += fromSeg
                   ? "SEG"
                   : "thr " + thresholdText(p) + "; corr " + (p.intensityCorrected ? "on" : "off");
    if (!p.seriesDescription.empty()) {
        summary += "; " + p.seriesDescription;
    }
    m.summary = std::move(summary);
    return m;
}

scene::Mesh meshWithLabels(const scene::Scene& scene) {
    scene::Mesh merged;
    merged.name = "segments";
    scene::DataArray label;
    label.name = "label";
    label.integer = true;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const scene::Mesh& mesh = scene.meshes[i];
        const auto base = static_cast<std::uint32_t>(merged.positions.size());
        merged.positions.insert(merged.positions.end(), mesh.positions.begin(),
                                mesh.positions.end());
        merged.normals.insert(merged.normals.end(), mesh.normals.begin(), mesh.normals.end());
        if (mesh.normals.size() != mesh.positions.size()) {
            merged.normals.resize(merged.positions.size(), glm::vec3(0.0F, 0.0F, 1.0F));
        }
        for (const std::uint32_t index : mesh.indices) {
            merged.indices.push_back(base + index);
        }
        label.values.insert(label.values.end(), mesh.positions.size(), static_cast<float>(i + 1));
        merged.labelNames["label"][static_cast<std::int64_t>(i + 1)] = mesh.name;
    }
    merged.pointArrays.push_back(std::move(label));
    return merged;
}

void writeSegmentedSurface(scene::Mesh mesh, const scene::LabelMap* labels,
                           const std::filesystem::path& file,
                           const SegmentationProvenance& provenance) {
    if (labels != nullptr) {
        scene::DataArray label = segmentation::surfaceLabels(mesh, *labels);
        for (const scene::SegmentComponent& c : labels->components) {
            mesh.labelNames["label"][c.label] = "component " + std::to_string(c.label);
        }
        mesh.pointArrays.push_back(std::move(label));
    }
    meshio::writeMeshFile(mesh, file, surfaceMetadata(provenance));
}

}  // namespace vv::app
