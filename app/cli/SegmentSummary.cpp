// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/SegmentSummary.h"

#include <cmath>
#include <sstream>

#include "vv/core/NumberText.h"

namespace vv::cli {

std::string segmentationSummary(const segmentation::SceneSourceReport& report,
                                const scene::Scene& scene) {
    std::ostringstream s;
    if (report.fromVolume) {
        s << "segmented series " << report.seriesInstanceUid << " (" << report.volumeDims.x << "x"
          << report.volumeDims.y << "x" << report.volumeDims.z << "): " << report.range.rule;
        if (report.intensityCorrected) {
            s << ", intensity correction on (gain " << fixedText(report.gainLowest, 2) << ".."
              << fixedText(report.gainHighest, 2) << ")";
        }
        s << ", kept " << report.componentsKept << " of " << report.componentsFound
          << " components, " << report.boneComponents << " bone-like removed, "
          << scene.triangleCount() << " triangles";
    } else if (report.fromSegmentationObject) {
        s << "read " << scene.meshes.size() << " segment(s) from the DICOM SEG:";
        for (const scene::Mesh& mesh : scene.meshes) {
            s << " '" << mesh.name << "'";
        }
    }
    return s.str();
}

std::string cutOffWarning(const segmentation::CutOffVessel& vessel, bool suggestCorrection) {
    const auto mm = [](double v) { return fixedText(v, 0); };
    std::ostringstream s;
    s << "warning: a bright tube continues " << mm(vessel.lengthMm) << " mm "
      << segmentation::directionName(segmentation::dominantDirection(vessel.farEnd - vessel.end))
      << " (radius about " << mm(vessel.radiusMm) << " mm) past the segmentation's end at ("
      << mm(vessel.end.x) << ", " << mm(vessel.end.y) << ", " << mm(vessel.end.z)
      << ") mm (patient LPS): the vessel may be cut off where its signal fades; "
      << (suggestCorrection ? "try --intensity-correction on or a lower --threshold"
                            : "try a lower --threshold");
    return s.str();
}

void printSegmentationSummary(std::ostream& out, std::ostream& err,
                              const segmentation::SceneSourceReport& report,
                              const scene::Scene& scene) {
    const std::string summary = segmentationSummary(report, scene);
    if (!summary.empty()) {
        out << summary << "\n";
    }
    printCutOffWarnings(err, report);
}

void printCutOffWarnings(std::ostream& err, const segmentation::SceneSourceReport& report) {
    const bool ct =
        report.volume && (report.volume->modality() == "CT" || report.volume->unit() == "HU");
    for (const segmentation::CutOffVessel& vessel : report.cutOff) {
        err << cutOffWarning(vessel, !report.intensityCorrected && !ct) << "\n";
    }
}

}  // namespace vv::cli
