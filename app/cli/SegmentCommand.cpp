// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli segment DICOM -o SURFACE.stl|.vtp|.ply [segmentation options]`:
// segments a DICOM series (or reads a DICOM SEG) and writes the vessel surface
// in patient LPS millimetres with its label array and provenance
// (common/SurfaceExport.h), for 3-D printing, CFD and other tools.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/OutputFiles.h"
#include "cli/SegmentSummary.h"
#include "common/SurfaceExport.h"
#include "vv/core/Error.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::cli {

namespace {

constexpr const char* kSegmentUsage =
    "usage: vesselview-cli segment DICOM -o SURFACE.stl|.vtp|.ply [--series UID]\n"
    "       [--threshold LO:HI] [--components N] [--seed I,J,K] [--bone-removal on|off]\n"
    "       [--intensity-correction on|off] [--triangles N]\n"
    "  Segments the vessels of a DICOM image series (a folder, a DICOMDIR or a\n"
    "  file; the options as the GUI's Segmentation panel has them) or reads the\n"
    "  segments of a DICOM SEG, and writes the surface in patient coordinates\n"
    "  (DICOM LPS, millimetres; RAS = (-x, -y, z)) for 3-D printing, CFD and\n"
    "  other tools. The format follows the extension: .vtp (normals, the point\n"
    "  array 'label' with its names, and the series and settings as field data),\n"
    "  .stl (binary; the 80-byte header names software, frame, modality,\n"
    "  threshold and correction) or .ply (binary; the same as comments).\n"
    "  A bright tube that continues past the segmentation is reported as a\n"
    "  warning (the vessel may be cut off where its signal fades).\n"
    "  -o, --output FILE              the surface file to write (required)\n"
    "  --series UID                   the series, when the input holds several\n"
    "  --threshold LO:HI              threshold range (default: CT 200:700 HU, MR\n"
    "                                 from the histogram)\n"
    "  --components N                 keep the N largest components (default 1)\n"
    "  --seed I,J,K                   keep the component under voxel (I, J, K)\n"
    "  --bone-removal on|off          drop bone-like components (default: on for CT)\n"
    "  --intensity-correction on|off  divide out the MR signal fall-off before\n"
    "                                 thresholding (default: on for MR; not for CT)\n"
    "  --triangles N                  decimate to about N triangles (0 = none;\n"
    "                                 default 300000)\n";

bool writable(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    for (char& c : ext) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return std::ranges::any_of(meshio::writableMeshExtensions(),
                               [&ext](const std::string& known) { return ext == known; });
}

}  // namespace

int segmentCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    std::filesystem::path input;
    bool haveInput = false;
    std::filesystem::path output;
    segmentation::SceneSourceOptions options;
    for (Arguments a("segment", args); a.next();) {
        const std::string& name = a.name();
        if (name == "--help" || name == "-h") {
            out << kSegmentUsage;
            return kOk;
        }
        if (name == "-o" || name == "--output") {
            output = a.path();
        } else if (segmentation::setSceneSourceOption(name, a.peekValue(), options)) {
            a.takeValue();
        } else {
            a.takeOneInput(input, haveInput);
        }
    }
    if (!haveInput) {
        throw UsageError("segment needs a DICOM input (a folder, a DICOMDIR or a file)");
    }
    if (output.empty()) {
        throw UsageError("segment needs an output file: -o SURFACE.stl, .vtp or .ply");
    }
    if (!writable(output)) {
        throw UsageError("segment: the output must end in .stl, .vtp or .ply, not '" +
                         output.string() + "'");
    }
    std::error_code ec;
    if (!std::filesystem::exists(input, ec)) {
        throw IoError(input, "no such file or folder");
    }
    if (!segmentation::isDicomSource(input)) {
        throw FormatError(input,
                          "not DICOM (a folder, a DICOMDIR or a DICOM file); segment reads DICOM "
                          "image series and SEG objects");
    }
    checkOutputPath(output);

    segmentation::SceneSourceReport report;
    const scene::Scene scene = segmentation::loadSceneSource(input, options, {}, &report);
    app::SegmentationProvenance provenance = app::provenanceOf(report, options);
    try {
        if (report.fromVolume) {
            app::writeSegmentedSurface(scene.meshes.front(), report.labelMap.get(), output,
                                       provenance);
        } else {
            for (const scene::Mesh& mesh : scene.meshes) {
                provenance.segmentNames.push_back(mesh.name);
            }
            app::writeSegmentedSurface(app::meshWithLabels(scene), nullptr, output, provenance);
        }
    } catch (const IoError& e) {
        throw OutputError(e.what());
    }
    printSegmentationSummary(out, err, report, scene);
    out << "wrote " << output.string() << " (" << scene.triangleCount()
        << " triangles, patient LPS mm)\n";
    return kOk;
}

}  // namespace vv::cli
