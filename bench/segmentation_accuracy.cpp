// SPDX-License-Identifier: GPL-3.0-or-later
// segmentation_accuracy: the vessel segmentation against the analytic vessel
// phantom (vv/demo/VesselPhantom.h), CT and MR, with and without a receive
// gain (0.3-1.0 over the volume), with and without the MR intensity
// correction: Dice, symmetric surface distance, the aorta's centre line
// missed, the cut-off warnings; then the run time of each step on a big MR
// volume. Prints Markdown tables (docs/benchmarks/dicom.md).
//
//   segmentation_accuracy [--dims 112,96,120] [--timing-dims 512,512,300|none]
//   segmentation_accuracy --write-series DIR [--dims ...] [--min-gain 0.3]
//       writes the MR phantom (gain 0.3-1.0 by default) as an MR series instead
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "BenchArgs.h"
#include "SegmentationAccuracy.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/demo/VesselPhantom.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/segmentation/CutOffVessels.h"
#include "vv/segmentation/IntensityCorrection.h"
#include "vv/segmentation/SegmentationPipeline.h"

namespace {

using vv::demo::PhantomModality;

std::string fixed(double v, int decimals) {
    return vv::fixedText(v, decimals);
}

double secondsOf(const std::function<void()>& step) {
    const auto start = std::chrono::steady_clock::now();
    step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Case {
    const char* name;
    PhantomModality modality;
    double minGain;
    bool correct;
};

void accuracyTable(glm::ivec3 dims) {
    const std::vector<Case> cases = {
        {"CT", PhantomModality::CT, 1.0, false},
        {"MR, no gain", PhantomModality::MR, 1.0, false},
        {"MR, no gain", PhantomModality::MR, 1.0, true},
        {"MR, gain 0.3-1.0", PhantomModality::MR, 0.3, false},
        {"MR, gain 0.3-1.0", PhantomModality::MR, 0.3, true},
    };
    vv::demo::VesselPhantomOptions options;
    options.dims = dims;
    const vv::demo::VesselPhantom probe = vv::demo::generateVesselPhantom(options);
    const glm::dvec3 s = probe.volume.spacing();
    std::printf("Phantom %d x %d x %d voxels of %s x %s x %s mm:\n\n", dims.x, dims.y, dims.z,
                fixed(s.x, 2).c_str(), fixed(s.y, 2).c_str(), fixed(s.z, 2).c_str());
    std::printf(
        "| Volume | Intensity correction | Threshold | Dice | Mean distance (mm) | 95 %% "
        "distance (mm) | Aorta missed (mm of centre line) | Cut-off warnings | Time (s) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (const Case& c : cases) {
        options.modality = c.modality;
        options.minGain = c.minGain;
        const vv::demo::VesselPhantom phantom = vv::demo::generateVesselPhantom(options);
        vv::segmentation::SegmentationRequest request;
        request.volume = std::make_shared<const vv::scene::Volume>(phantom.volume);
        request.segmentation.correctIntensity = c.correct;
        vv::segmentation::SegmentationOutcome outcome;
        const double seconds =
            secondsOf([&] { outcome = vv::segmentation::runSegmentation(request); });
        const vv::bench::SegmentationAccuracy a = vv::bench::measureSegmentation(
            phantom, *outcome.labelMap, outcome.scene->meshes.front());
        std::string warnings = std::to_string(outcome.cutOff.size());
        if (!outcome.cutOff.empty()) {
            warnings += " (" + fixed(outcome.cutOff.front().lengthMm, 0) + " mm)";
        }
        const std::string correction =
            c.modality == PhantomModality::CT
                ? "— (CT)"
                : (c.correct ? "on (gain " + fixed(outcome.gainLowest, 2) + "–" +
                                   fixed(outcome.gainHighest, 2) + ")"
                             : "off");
        std::printf("| %s | %s | %s–%s | %s | %s | %s | %s of %s | %s | %s |\n", c.name,
                    correction.c_str(), fixed(outcome.range.lower, 0).c_str(),
                    fixed(outcome.range.upper, 0).c_str(), fixed(a.dice, 3).c_str(),
                    fixed(a.meanDistanceMm, 2).c_str(), fixed(a.p95DistanceMm, 2).c_str(),
                    fixed(a.aortaMissedMm, 0).c_str(), fixed(a.aortaLengthMm, 0).c_str(),
                    warnings.c_str(), fixed(seconds, 2).c_str());
        std::fflush(stdout);
    }
}

void timingTable(glm::ivec3 dims) {
    vv::demo::VesselPhantomOptions options;
    options.dims = dims;
    options.minGain = 0.3;
    std::fprintf(stderr, "building the %d x %d x %d phantom...\n", dims.x, dims.y, dims.z);
    const auto volume =
        std::make_shared<const vv::scene::Volume>(vv::demo::generateVesselPhantom(options).volume);
    std::printf("\nMR phantom with gain, %d x %d x %d voxels (%s Mvoxels), run time:\n\n", dims.x,
                dims.y, dims.z, fixed(static_cast<double>(volume->voxelCount()) / 1e6, 1).c_str());
    std::printf("| Step | Time (s) |\n|---|---|\n");
    vv::segmentation::GainField gain;
    const double estimate = secondsOf([&] { gain = vv::segmentation::estimateGainField(*volume); });
    std::printf("| estimate the gain field | %s |\n", fixed(estimate, 2).c_str());
    vv::scene::Volume corrected;
    const double correct =
        secondsOf([&] { corrected = vv::segmentation::correctedVolume(*volume, gain); });
    std::printf("| divide it out (Float32 copy) | %s |\n", fixed(correct, 2).c_str());
    vv::segmentation::SegmentationOptions plain;
    plain.correctIntensity = false;
    vv::segmentation::Segmentation segmented;
    const double segment =
        secondsOf([&] { segmented = vv::segmentation::segmentVessels(corrected, plain); });
    std::vector<vv::segmentation::CutOffVessel> cutOff;
    const double check = secondsOf([&] {
        cutOff =
            vv::segmentation::findCutOffVessels(corrected, segmented.labelMap, segmented.range);
    });
    std::printf("| threshold, components (and the cut-off check, %s s of it) | %s |\n",
                fixed(check, 2).c_str(), fixed(segment, 2).c_str());
    vv::segmentation::SegmentationRequest request;
    request.volume = volume;
    request.step = vv::segmentation::previewStep(volume->dims());
    request.surface.targetTriangles = 40000;
    vv::segmentation::SegmentationOutcome preview;
    const double previewSeconds =
        secondsOf([&] { preview = vv::segmentation::runSegmentation(request); });
    std::printf("| live preview (every %dth voxel, correction included, surface) | %s |\n",
                request.step, fixed(previewSeconds, 2).c_str());
    request.step = 1;
    request.surface = {};
    vv::segmentation::SegmentationOutcome full;
    const double fullSeconds =
        secondsOf([&] { full = vv::segmentation::runSegmentation(request); });
    request.segmentation.correctIntensity = false;
    vv::segmentation::SegmentationOutcome uncorrected;
    const double uncorrectedSeconds =
        secondsOf([&] { uncorrected = vv::segmentation::runSegmentation(request); });
    std::printf("| Apply: the whole pipeline with the correction (surface included) | %s |\n",
                fixed(fullSeconds, 2).c_str());
    std::printf("| Apply without the correction | %s |\n", fixed(uncorrectedSeconds, 2).c_str());
}

/// The MR phantom as an MR image series in `folder` (for the GUI and CLI).
void writeSeries(const std::filesystem::path& folder, glm::ivec3 dims, double minGain) {
    vv::demo::VesselPhantomOptions options;
    options.dims = dims;
    options.minGain = minGain;
    const vv::demo::VesselPhantom phantom = vv::demo::generateVesselPhantom(options);
    vv::dicom::CtSeriesWriteOptions write;
    write.modality = "MR";
    write.seriesDescription = "synthetic CE-MRA, gain " + fixed(minGain, 2) + "-1.0";
    write.studyDescription = "VesselView vessel phantom";
    const std::string uid = vv::dicom::writeCtSeries(folder, phantom.volume, write);
    std::printf("wrote %s: MR series %s, %d x %d x %d voxels\n", folder.string().c_str(),
                uid.c_str(), dims.x, dims.y, dims.z);
}

int run(int argc, char** argv) {
    glm::ivec3 dims{112, 96, 120};
    std::optional<glm::ivec3> timing = glm::ivec3{512, 512, 300};
    std::filesystem::path series;
    double minGain = 0.3;
    vv::bench::forEachOption(argc, argv, [&](const std::string& a, const std::string& value) {
        if (a == "--dims") {
            dims = vv::bench::parseDims(value);
        } else if (a == "--write-series") {
            series = value;
        } else if (a == "--min-gain") {
            minGain = std::stod(value);
        } else if (a == "--timing-dims") {
            timing = value == "none" ? std::nullopt : std::optional(vv::bench::parseDims(value, a));
        } else {
            return false;
        }
        return true;
    });
    if (!series.empty()) {
        writeSeries(series, dims, minGain);
        return 0;
    }
    accuracyTable(dims);
    if (timing) {
        timingTable(*timing);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "segmentation_accuracy: %s\n", e.what());
        return 1;
    }
}
