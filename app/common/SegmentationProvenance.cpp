// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SegmentationProvenance.h"

#include "vv/core/NumberText.h"

namespace vv::app {

namespace {

std::string number(double v) {
    return significantText(v, 4);
}

}  // namespace

SegmentationProvenance provenanceOf(const segmentation::SceneSourceReport& report,
                                    const segmentation::SceneSourceOptions& options) {
    SegmentationProvenance p;
    p.seriesInstanceUid = report.seriesInstanceUid;
    p.seriesDescription = report.seriesDescription;
    p.modality = report.modality;
    p.seriesNumber = report.seriesNumber;
    if (report.volume) {
        p.unit = report.volume->unit();
        p.boneRemoved = options.segmentation.removeBone.value_or(
            report.volume->modality() == "CT" || report.volume->unit() == "HU");
    }
    p.range = report.range;
    p.intensityCorrected = report.intensityCorrected;
    p.gainLowest = report.gainLowest;
    p.gainHighest = report.gainHighest;
    p.seed = options.segmentation.seed;
    p.keepComponents = options.segmentation.keepComponents;
    p.componentsKept = report.componentsKept;
    p.componentsFound = report.componentsFound;
    p.targetTriangles = options.surface.targetTriangles;
    p.cutOff = report.cutOff;
    return p;
}

void describeSegmentation(SegmentationProvenance& p,
                          const segmentation::SegmentationRequest& request,
                          const segmentation::SegmentationOutcome& outcome) {
    const segmentation::SegmentationOptions& options = request.segmentation;
    if (request.volume) {
        p.unit = request.volume->unit();
        p.boneRemoved = options.removeBone.value_or(request.volume->modality() == "CT" ||
                                                    request.volume->unit() == "HU");
    }
    p.range = outcome.range;
    p.intensityCorrected = outcome.intensityCorrected;
    p.gainLowest = outcome.gainLowest;
    p.gainHighest = outcome.gainHighest;
    p.seed = options.seed;
    p.keepComponents = options.keepComponents;
    p.componentsKept = outcome.componentsKept;
    p.componentsFound = outcome.componentsFound;
    p.targetTriangles = request.surface.targetTriangles;
    p.cutOff = outcome.cutOff;
}

std::string thresholdText(const SegmentationProvenance& p) {
    return number(static_cast<double>(p.range.lower)) + ".." +
           number(static_cast<double>(p.range.upper)) + (p.unit.empty() ? "" : " " + p.unit);
}

std::string correctionText(const SegmentationProvenance& p) {
    return p.intensityCorrected
               ? "on (MR signal fall-off divided out; gain " + fixedText(p.gainLowest, 2) + ".." +
                     fixedText(p.gainHighest, 2) + ")"
               : "off";
}

std::string componentsText(const SegmentationProvenance& p) {
    return (p.seed ? "the one under voxel (" + std::to_string(p.seed->x) + ", " +
                         std::to_string(p.seed->y) + ", " + std::to_string(p.seed->z) + ")"
                   : "the " + std::to_string(p.keepComponents) + " largest") +
           ", 6-connected: kept " + std::to_string(p.componentsKept) + " of " +
           std::to_string(p.componentsFound);
}

std::string segmentsText(const SegmentationProvenance& p) {
    std::string names;
    for (std::size_t i = 0; i < p.segmentNames.size(); ++i) {
        names += (i > 0 ? "; " : "") + std::to_string(i + 1) + "=" + p.segmentNames[i];
    }
    return names;
}

std::string settingsDescription(const SegmentationProvenance& p) {
    if (!p.segmentNames.empty()) {
        return "segments: " + segmentsText(p);
    }
    return "threshold " + thresholdText(p) + " (" + p.range.rule + "); intensity correction " +
           correctionText(p) + "; components: " + componentsText(p) + "; bone removal " +
           (p.boneRemoved ? "on" : "off");
}

}  // namespace vv::app
