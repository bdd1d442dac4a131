// SPDX-License-Identifier: GPL-3.0-or-later
// dicom_pipeline: time and peak memory of a big CT angiography series through
// the DICOM pipeline (issue 5: "a 512×512×600 CT must load with progress,
// cancellable, without holding more than ~2× the volume in memory"): header
// scan, volume assembly, vessel segmentation, surface extraction. Prints a
// Markdown table (docs/benchmarks/dicom.md). The series is the voxelised demo
// tree (vv::demo::generateDemoCt) written once with DCMTK and kept.
//
//   dicom_pipeline [--dims 512,512,600] [--dir DIR] [--triangles N]
//
// Peak memory per step: the kernel's high-water mark (VmHWM) is reset before
// the step (/proc/self/clear_refs = 5) and read after it; "growth" is the peak
// minus the resident memory before the step.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "BenchArgs.h"
#include "vv/core/Error.h"
#include "vv/core/ProcessMemory.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/dicom/Dicom.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/segmentation/VolumeSegmentation.h"
#include "vv/segmentation/VolumeSurface.h"

namespace {

namespace fs = std::filesystem;

struct StepFigures {
    std::string name;
    double seconds = 0.0;
    double residentBeforeMb = 0.0;
    double peakGrowthMb = 0.0;
    std::string note;
};

/// Runs `step`, measuring wall time and the growth of the resident peak.
StepFigures measure(const std::string& name, const std::function<std::string()>& step) {
    (void)vv::resetPeakResident();
    const double before = static_cast<double>(vv::residentKiB().value_or(0));
    const auto start = std::chrono::steady_clock::now();
    StepFigures f;
    f.name = name;
    f.note = step();
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double peak = static_cast<double>(vv::peakResidentKiB().value_or(0));
    f.residentBeforeMb = before / 1024.0;
    f.peakGrowthMb = (peak - before) / 1024.0;
    std::fprintf(stderr, "%s: %.1f s\n", name.c_str(), f.seconds);
    return f;
}

int run(int argc, char** argv) {
    glm::ivec3 dims{512, 512, 600};
    fs::path dir;
    std::size_t triangles = 300000;
    vv::bench::forEachOption(argc, argv, [&](const std::string& a, const std::string& value) {
        if (a == "--dims") {
            dims = vv::bench::parseDims(value);
        } else if (a == "--dir") {
            dir = value;
        } else if (a == "--triangles") {
            triangles = std::stoul(value);
        } else {
            return false;
        }
        return true;
    });
    if (dir.empty()) {
        dir = fs::temp_directory_path() / ("vv-dicom-bench-" + std::to_string(dims.x) + "x" +
                                           std::to_string(dims.y) + "x" + std::to_string(dims.z));
    }

    std::vector<StepFigures> rows;
    if (!fs::exists(dir / "complete")) {
        fs::remove_all(dir);
        rows.push_back(measure("write series (once)", [&] {
            vv::demo::DemoCtOptions options;
            options.dims = dims;
            const vv::demo::DemoCt ct = vv::demo::generateDemoCt(options);
            (void)vv::dicom::writeCtSeries(dir, ct.volume);
            std::ofstream(dir / "complete") << "ok\n";
            return std::string("voxelised demo tree");
        }));
    }

    vv::dicom::DicomScanResult scan;
    rows.push_back(measure("scan headers", [&] {
        scan = vv::dicom::scanDicom(dir);
        return std::to_string(scan.allSeries().size()) + " series";
    }));
    if (scan.allSeries().size() != 1) {
        throw std::runtime_error(dir.string() + ": expected one series");
    }
    std::size_t progressCalls = 0;
    const vv::Progress progress([&](double, std::string_view) { ++progressCalls; }, {});
    vv::dicom::DicomVolume loaded;
    double volumeMb = 0.0;
    rows.push_back(measure("load volume", [&] {
        loaded = vv::dicom::loadDicomSeries(*scan.allSeries()[0], {}, progress);
        volumeMb = static_cast<double>(loaded.volume.byteSize()) / (1024.0 * 1024.0);
        char note[128];
        std::snprintf(note, sizeof note, "%.0f MiB volume, %zu progress reports", volumeMb,
                      progressCalls);
        return std::string(note);
    }));
    vv::segmentation::Segmentation segmentation;
    rows.push_back(measure("segment (CTA default, bone removal)", [&] {
        segmentation = vv::segmentation::segmentVessels(loaded.volume);
        return std::to_string(segmentation.labelMap.components.size()) + " component(s) of " +
               std::to_string(segmentation.componentsFound);
    }));
    rows.push_back(measure("surface (flying edges, smoothing, decimation)", [&] {
        vv::segmentation::SurfaceOptions options;
        options.targetTriangles = triangles;
        const vv::scene::Mesh mesh =
            vv::segmentation::extractSurface(segmentation.labelMap, {}, options);
        return std::to_string(mesh.triangleCount()) + " triangles";
    }));

    std::printf("Series %d x %d x %d (%.0f MiB as Int16), %s\n\n", dims.x, dims.y, dims.z, volumeMb,
                dir.c_str());
    std::printf(
        "| Step | Time (s) | Resident before (MiB) | Peak growth (MiB) | Peak growth / "
        "volume | Note |\n|---|---|---|---|---|---|\n");
    for (const StepFigures& f : rows) {
        std::printf("| %s | %.2f | %.0f | %.0f | %.2f | %s |\n", f.name.c_str(), f.seconds,
                    f.residentBeforeMb, f.peakGrowthMb,
                    volumeMb > 0.0 ? f.peakGrowthMb / volumeMb : 0.0, f.note.c_str());
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "dicom_pipeline: %s\n", e.what());
        return 1;
    }
}
