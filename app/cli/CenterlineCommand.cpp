// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli centerline FILE -o CENTERLINES.vtp [...]`: the centrelines
// of a vessel surface (a mesh file, or a DICOM series segmented as `render`
// segments it), their sections and stenoses (vv::analysis), written for
// VMTK, 3D Slicer and ParaView (VTK polylines with VMTK's array names), as a
// CSV of sections and as JSON.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cli/Arguments.h"
#include "cli/CenterlineDrawing.h"
#include "cli/CenterlineLandmarks.h"
#include "cli/Cli.h"
#include "cli/OutputFiles.h"
#include "common/MeasurementFile.h"
#include "common/SectionsCsv.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/analysis/SurfaceBranches.h"
#include "vv/core/AtomicFile.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/core/ProcessMemory.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::cli {

namespace {

constexpr const char* kCenterlineUsage =
    "usage: vesselview-cli centerline FILE -o CENTERLINES.vtp [--source X,Y,Z]\n"
    "       [--target X,Y,Z ...] [--step MM] [--scale F] [--sections SECTIONS.csv]\n"
    "       [--surface-out SURFACE.vtp] [--json [--landmark KEY=X,Y,Z ...]]\n"
    "       [--smooth-folded on|off]\n"
    "       [DICOM options as for segment]\n"
    "  The centrelines of a vessel surface (a mesh file, or a DICOM series\n"
    "  segmented as render and segment do), by VMTK's method: the internal\n"
    "  Voronoi diagram and minimal paths with cost 1/R, resampled every --step\n"
    "  mm (default 0.5). The ends are the open ends' centres and the closed\n"
    "  vessels' tips unless --source / --target give them (points near the\n"
    "  surface; the distance to it is reported). Scene units are mm: a mesh\n"
    "  in metres needs --scale 1000 (a warning says when the size suggests it).\n"
    "  -o, --output FILE    the centrelines, VTK polylines (.vtp), one line per\n"
    "                       branch, point arrays as VMTK names them\n"
    "                       (MaximumInscribedSphereRadius, Abscissas, Curvature,\n"
    "                       Torsion, ParallelTransportNormals) plus branch_id and\n"
    "                       the sections' CenterlineSectionArea,\n"
    "                       EquivalentDiameter, CenterlineSectionMinSize,\n"
    "                       CenterlineSectionMaxSize (mm, mm^2, 1/mm)\n"
    "  --sections FILE.csv  one row per section, units in the header\n"
    "  --surface-out FILE.vtp  the surface with the point array branch_id (which\n"
    "                       branch each vertex belongs to, named 'branch N': render\n"
    "                       --array branch_id shows it with swatches)\n"
    "  --json               the measurement file on stdout: branches with lengths,\n"
    "                       diameters at the narrowest and widest points, stenoses,\n"
    "                       bifurcation angles, and the diameter profile along the\n"
    "                       path from the source to the farthest end (report\n"
    "                       --measurements reads it)\n"
    "  --landmark KEY=X,Y,Z  with --json: a landmark at the centreline place\n"
    "                       nearest the point (repeatable). KEY: lowest_renal_artery,\n"
    "                       aneurysm_start, largest_aneurysm_diameter,\n"
    "                       aortic_bifurcation, left_internal_iliac_origin,\n"
    "                       right_internal_iliac_origin (one near a bifurcation\n"
    "                       goes to the bifurcation), or free:NAME. The JSON then\n"
    "                       gives each landmark's section, the lengths along the\n"
    "                       centreline and straight between every two, and with\n"
    "                       any preset the aortic sizing table (each value, or\n"
    "                       why it is blank)\n"
    "  --smooth-folded on|off  a wall whose noise is larger than its triangles\n"
    "                       folds over itself, and its inside breaks up where\n"
    "                       the vessel narrows: on (the default), such a wall is\n"
    "                       smoothed first (a low-pass filter that keeps the\n"
    "                       vessel's shape; a note says how far its points\n"
    "                       moved); off, it is analysed as it is, with a note\n"
    "  Diameters: equivalent = 2 sqrt(area / pi); minimum / maximum = the\n"
    "  smallest / largest caliper (Feret) width of the section; inscribed =\n"
    "  twice the largest sphere on the centreline inside the surface.\n"
    "  Exit code 3 when the surface cannot be analysed, with the reason.\n";

glm::dvec3 parsePoint(const std::string& text, const std::string& what) {
    const std::vector<std::string> items = splitList(text, what);
    if (items.size() != 3) {
        throw UsageError(what + " must be X,Y,Z (mm), got '" + text + "'");
    }
    return {parseNumber(items[0], what), parseNumber(items[1], what), parseNumber(items[2], what)};
}

struct CenterlineArgs {
    std::filesystem::path input;
    std::filesystem::path output;
    std::filesystem::path sectionsCsv;
    std::filesystem::path surfaceOut;
    bool json = false;
    std::vector<GivenLandmark> landmarks;
    analysis::CenterlineOptions options;
    segmentation::SceneSourceOptions source;
};

/// Parses the arguments; nullopt after printing --help.
std::optional<CenterlineArgs> parseArgs(const std::vector<std::string>& args, std::ostream& out) {
    CenterlineArgs c;
    bool haveInput = false;
    for (Arguments a("centerline", args); a.next();) {
        const std::string& name = a.name();
        if (name == "--help" || name == "-h") {
            out << kCenterlineUsage;
            return std::nullopt;
        }
        if (name == "-o" || name == "--output") {
            c.output = a.path();
        } else if (name == "--sections") {
            c.sectionsCsv = a.path();
        } else if (name == "--surface-out") {
            c.surfaceOut = a.path();
            if (c.surfaceOut.extension() != ".vtp") {
                a.fail("--surface-out must end in .vtp");
            }
        } else if (name == "--json") {
            c.json = true;
        } else if (name == "--landmark") {
            c.landmarks.push_back(parseLandmark(a.value()));
        } else if (name == "--source") {
            c.options.source = parsePoint(a.value(), "--source");
        } else if (name == "--target") {
            c.options.targets.push_back(parsePoint(a.value(), "--target"));
        } else if (name == "--step") {
            c.options.stepMm = parseNumber(a.value(), "--step");
            if (!(c.options.stepMm >= 0.01 && c.options.stepMm <= 10.0)) {
                a.fail("--step must be within 0.01..10 mm");
            }
        } else if (name == "--smooth-folded") {
            const std::string& value = a.value();
            if (value != "on" && value != "off") {
                a.fail("--smooth-folded must be on or off, not '" + value + "'");
            }
            c.options.smoothFoldedWall = value == "on";
        } else if (name == "--scale") {
            c.source.mesh.scale = parseNumber(a.value(), "--scale");
            if (!(c.source.mesh.scale > 0.0)) {
                a.fail("--scale must be > 0");
            }
        } else if (segmentation::setSceneSourceOption(name, a.peekValue(), c.source)) {
            a.takeValue();
        } else {
            a.takeOneInput(c.input, haveInput);
        }
    }
    if (!haveInput) {
        throw UsageError("centerline needs an input: a mesh file or a DICOM series");
    }
    if (c.output.empty()) {
        throw UsageError("centerline needs an output file: -o CENTERLINES.vtp");
    }
    if (!c.landmarks.empty() && !c.json) {
        throw UsageError("centerline: --landmark's measurements are written by --json");
    }
    if (c.output.extension() != ".vtp") {
        throw UsageError("centerline: the output must end in .vtp, not '" + c.output.string() +
                         "'");
    }
    return c;
}

float valueOr(bool ok, double value) {
    return ok ? static_cast<float>(value) : std::numeric_limits<float>::quiet_NaN();
}

/// The branches as polylines with VMTK's point arrays and the sections'.
meshio::PolylineSet polylines(const analysis::CenterlineTree& tree,
                              const std::vector<std::vector<analysis::CrossSection>>& sections) {
    meshio::PolylineSet set;
    const auto array = [](const char* name, int components, bool integer) {
        scene::DataArray a;
        a.name = name;
        a.components = components;
        a.integer = integer;
        return a;
    };
    scene::DataArray radius = array("MaximumInscribedSphereRadius", 1, false);
    scene::DataArray abscissa = array("Abscissas", 1, false);
    scene::DataArray curvature = array("Curvature", 1, false);
    scene::DataArray torsion = array("Torsion", 1, false);
    scene::DataArray normals = array("ParallelTransportNormals", 3, false);
    scene::DataArray branchId = array("branch_id", 1, true);
    scene::DataArray area = array("CenterlineSectionArea", 1, false);
    scene::DataArray equivalent = array("EquivalentDiameter", 1, false);
    scene::DataArray minSize = array("CenterlineSectionMinSize", 1, false);
    scene::DataArray maxSize = array("CenterlineSectionMaxSize", 1, false);
    scene::DataArray lineBranch = array("branch_id", 1, true);
    for (std::size_t b = 0; b < tree.branches.size(); ++b) {
        std::vector<std::uint32_t> line;
        const auto& branch = tree.branches[b];
        for (std::size_t i = 0; i < branch.points.size(); ++i) {
            const auto& p = branch.points[i];
            const auto& s = sections[b][i];
            const bool ok = s.status == analysis::CrossSection::Status::Ok;
            line.push_back(static_cast<std::uint32_t>(set.points.size()));
            set.points.push_back(p.position);
            radius.values.push_back(static_cast<float>(p.radiusMm));
            abscissa.values.push_back(static_cast<float>(p.abscissaMm));
            curvature.values.push_back(static_cast<float>(p.curvature));
            torsion.values.push_back(static_cast<float>(p.torsion));
            for (int c = 0; c < 3; ++c) {
                normals.values.push_back(static_cast<float>(p.normal[c]));
            }
            branchId.values.push_back(static_cast<float>(branch.id));
            area.values.push_back(valueOr(ok, s.areaMm2));
            equivalent.values.push_back(valueOr(ok, s.equivalentDiameterMm));
            minSize.values.push_back(valueOr(ok, s.minDiameterMm));
            maxSize.values.push_back(valueOr(ok, s.maxDiameterMm));
        }
        set.lines.push_back(std::move(line));
        lineBranch.values.push_back(static_cast<float>(branch.id));
    }
    set.pointArrays = {radius,   abscissa, curvature,  torsion, normals,
                       branchId, area,     equivalent, minSize, maxSize};
    set.lineArrays = {lineBranch};
    return set;
}

}  // namespace

int centerlineCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const auto parsed = parseArgs(args, out);
    if (!parsed) {
        return kOk;
    }
    const CenterlineArgs& c = *parsed;
    // The analysis frees its large arrays stage by stage, some on worker
    // threads: handed back at once, the resident peak is what it holds
    // (the demo tree's 53-83 -> 66-68 MiB above the mesh on any thread,
    // docs/benchmarks/analysis.md). This process does nothing else.
    static_cast<void>(handFreedMemoryBackAtOnce());
    std::error_code ec;
    if (!std::filesystem::exists(c.input, ec)) {
        throw IoError(c.input, "no such file or folder");
    }
    checkOutputPath(c.output);
    if (!c.sectionsCsv.empty()) {
        checkOutputPath(c.sectionsCsv);
    }
    if (!c.surfaceOut.empty()) {
        checkOutputPath(c.surfaceOut);
    }
    const scene::Scene scene = segmentation::loadSceneSource(c.input, c.source);
    const scene::Mesh& mesh = analysedSurface(scene, c.input, err);
    const analysis::VesselAnalysis analysed = analysis::analyseVessels(mesh, c.options);
    const analysis::CenterlineTree& tree = analysed.tree;
    const auto& sections = analysed.sections;
    for (const auto& note : tree.notes) {
        err << "vesselview-cli: note: " << note << "\n";
    }
    for (const auto& end : tree.ends) {
        if (end.kind == analysis::EndPoint::Kind::Given && end.offsetMm > 0.5) {
            err << "vesselview-cli: note: the point (" << fixedText(end.requested.x, 2) << ", "
                << fixedText(end.requested.y, 2) << ", " << fixedText(end.requested.z, 2) << ") is "
                << fixedText(end.offsetMm, 2) << " mm from the surface\n";
        }
    }
    meshio::MeshFileMetadata metadata;
    metadata.fields = {{"software", "VesselView"},
                       {"source", c.input.string()},
                       {"units", "mm"},
                       {"step_mm", shortestText(c.options.stepMm)}};
    try {
        meshio::writePolylinesVtp(polylines(tree, sections), c.output, metadata);
    } catch (const IoError& e) {
        throw OutputError(e.what());
    }
    if (!c.sectionsCsv.empty()) {
        try {
            app::writeSectionsCsv(c.sectionsCsv, analysed, app::allSectionRows(analysed));
        } catch (const IoError& e) {
            throw OutputError(e.what());
        }
    }
    if (!c.surfaceOut.empty()) {
        try {
            meshio::writeMeshFile(analysis::withBranchIds(mesh, tree), c.surfaceOut, metadata);
        } catch (const IoError& e) {
            throw OutputError(e.what());
        }
    }
    const std::vector<PlacedLandmark> landmarks = placeLandmarks(tree, c.landmarks, err);
    if (c.json) {
        app::MeasurementInput input;
        input.analysis = &analysed;
        input.landmarks = landmarks;
        app::writeMeasurementJson(out, input);
    } else {
        double length = 0.0;
        for (const auto& b : tree.branches) {
            length += b.lengthMm;
        }
        out << tree.branches.size() << " branches, " << tree.ends.size() << " ends, "
            << fixedText(length, 1) << " mm of centreline -> " << c.output.string() << "\n";
    }
    return kOk;
}

}  // namespace vv::cli
