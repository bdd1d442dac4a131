// SPDX-License-Identifier: GPL-3.0-or-later
// `vesselview-cli demo -o FILE.vtp [--seed N] [--generations G] [--voxel-size MM]`:
// writes the synthetic demo vessel tree; `demo --dicom DIR` writes it as a CT series;
// `demo --aorta -o FILE.vtp [--triangles N]` an aorta with an aneurysm, coarse on request.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/OutputFiles.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
#include "vv/dicom/SeriesWriter.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/meshio/MeshWriter.h"

namespace vv::cli {

namespace {

constexpr const char* kDemoUsage =
    "usage: vesselview-cli demo -o FILE.vtp [--seed N] [--generations G] [--voxel-size MM]\n"
    "       vesselview-cli demo --dicom DIR\n"
    "  --dicom DIR         instead: write the tree (4 generations) voxelised as a\n"
    "                      CT angiography series into DIR (lumen ~400 HU, tissue\n"
    "                      ~40 HU with noise, a bone-like block ~1000 HU; 96 x 96\n"
    "                      x 80 voxels, one file per slice)\n"
    "       vesselview-cli demo --aorta -o FILE.vtp [--triangles N]\n"
    "  Writes the synthetic demo vessel tree with pressure [mmHg], wss [Pa],\n"
    "  segment_id and generation point arrays as VTK XML polydata.\n"
    "  -o, --output FILE   the .vtp file to write (required)\n"
    "  --seed N            random seed (same seed, same tree)\n"
    "  --generations G     branching generations, 1..10 (default 6)\n"
    "  --voxel-size MM     surface sampling grid in mm (default: automatic)\n"
    "  --aorta             instead: an abdominal aorta with a fusiform aneurysm and\n"
    "                      both iliacs (the analysis' aneurysm phantom, 60k\n"
    "                      triangles), decimated to N triangles with --triangles\n"
    "                      (at least 100), as a coarse segmentation comes\n";

std::uint64_t parseUnsigned(const std::string& option, const std::string& text) {
    const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](unsigned char c) {
        return std::isdigit(c) != 0;
    });
    errno = 0;
    char* end = nullptr;
    const unsigned long long v = digits ? std::strtoull(text.c_str(), &end, 10) : 0;
    if (!digits || errno == ERANGE) {
        throw UsageError(option + " needs a whole number >= 0, not '" + text + "'");
    }
    return v;
}

bool hasVtpExtension(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".vtp";
}

/// `demo --dicom DIR`: the voxelised demo tree as a CT series.
int writeDemoDicom(const std::filesystem::path& folder, std::ostream& out) {
    std::error_code ec;
    if (std::filesystem::exists(folder, ec) && !std::filesystem::is_directory(folder, ec)) {
        throw OutputError(folder.string() + ": cannot write: not a folder");
    }
    const vv::demo::DemoCt cta = vv::demo::generateDemoCt();
    std::string uid;
    try {
        uid = vv::dicom::writeCtSeries(folder, cta.volume);
    } catch (const vv::IoError& e) {
        throw OutputError(e.what());
    }
    const glm::ivec3 dims = cta.volume.dims();
    const glm::dvec3 spacing = cta.volume.spacing();
    out << "wrote " << folder.string() << ": CT series of " << dims.z << " slices, " << dims.x
        << " x " << dims.y << " x " << dims.z << " voxels, " << vv::significantText(spacing.x, 3)
        << " x " << vv::significantText(spacing.y, 3) << " x " << vv::significantText(spacing.z, 3)
        << " mm, series " << uid << "\n";
    return kOk;
}

/// `demo --aorta`: the aneurysm phantom, decimated to `triangles` when given.
vv::scene::Mesh aortaMesh(std::optional<std::size_t> triangles) {
    vv::demo::AneurysmPhantomOptions options;
    options.targetTriangles = 60'000;
    vv::scene::Mesh mesh = vv::demo::makeAneurysmPhantom(options).mesh;
    if (triangles) {
        mesh = vv::meshio::simplifiedMesh(mesh, *triangles);
    }
    mesh.name = "aorta";
    return mesh;
}

}  // namespace

int demoCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& /*err*/) {
    std::filesystem::path output;
    std::filesystem::path dicomFolder;
    vv::demo::DemoTreeOptions options;
    bool treeOptionGiven = false;
    bool aorta = false;
    std::optional<std::size_t> aortaTriangles;
    for (Arguments arg("demo", args); arg.next();) {
        const std::string& name = arg.name();
        if (name == "--help" || name == "-h") {
            out << kDemoUsage;
            return kOk;
        }
        if (name == "-o" || name == "--output") {
            output = arg.value();
        } else if (name == "--dicom") {
            dicomFolder = arg.path();
        } else if (name == "--seed") {
            options.seed = parseUnsigned(name, arg.value());
            treeOptionGiven = true;
        } else if (name == "--generations") {
            options.generations = parseWholeNumber(arg.value(), name, 0);
            treeOptionGiven = true;
        } else if (name == "--voxel-size") {
            options.voxelSizeMm = parseNumber(arg.value(), name);
            treeOptionGiven = true;
        } else if (name == "--aorta") {
            aorta = true;
        } else if (name == "--triangles") {
            aortaTriangles = static_cast<std::size_t>(parseWholeNumber(arg.value(), name, 100));
        } else if (arg.isOption()) {
            arg.fail("unknown option '" + arg.current() + "'");
        } else {
            arg.fail("unexpected argument '" + arg.current() + "' (the output goes after -o)");
        }
    }
    if (aortaTriangles && !aorta) {
        throw UsageError("demo --triangles N goes with --aorta");
    }
    if (aorta && (treeOptionGiven || !dicomFolder.empty())) {
        throw UsageError("demo --aorta takes no tree option and no --dicom");
    }
    if (!dicomFolder.empty()) {
        if (!output.empty() || treeOptionGiven) {
            throw UsageError("demo --dicom DIR takes no other option");
        }
        return writeDemoDicom(dicomFolder, out);
    }
    if (output.empty()) {
        throw UsageError("demo needs an output file: -o FILE.vtp or --dicom DIR");
    }
    if (!hasVtpExtension(output)) {
        throw UsageError("the demo output must be a .vtp file, not '" + output.string() + "'");
    }

    // Fail before the (slow) generation when the output folder is missing.
    checkOutputPath(output);

    // Out-of-range options throw InvalidArgumentError, which run() maps to a usage error.
    const vv::scene::Mesh mesh =
        aorta ? aortaMesh(aortaTriangles) : vv::demo::generateDemoMesh(options);
    try {
        vv::meshio::writeVtp(mesh, output);
    } catch (const vv::IoError& e) {
        throw OutputError(e.what());
    } catch (const vv::InvalidArgumentError& e) {
        // The generated mesh is inconsistent: a bug, not the user's fault.
        throw std::logic_error(std::string("the demo mesh cannot be written: ") + e.what());
    }
    out << "wrote " << output.string() << ": " << mesh.vertexCount() << " vertices, "
        << mesh.triangleCount() << " triangles, " << mesh.pointArrays.size() << " point arrays\n";
    return kOk;
}

}  // namespace vv::cli
