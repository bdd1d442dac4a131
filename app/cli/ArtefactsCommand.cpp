// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli artefacts [--aorta] [--mesh FILE]... [--triangles 10000,30000,60000]
//                          [--size WxH] [--view far|medium|close] [--p P]
//                          [--reference-scale 3|5|7|none] [--light AZ,EL] [--save DIR]
//                          [--subdivide LEVELS]
// The artefact score of the lit VSS along silhouettes (app/evaluation/ArtefactBenchmark.h)
// of the demo tree (--aorta: an aorta with an aneurysm and both iliacs,
// vv::demo's aneurysm phantom at 60k triangles; decimated to 13k unless
// --triangles says otherwise), its decimated copies and the given meshes, as
// a Markdown table (docs/benchmarks/artefacts.md). --save writes the meshes
// it made (the control and its decimated copies) into DIR as VTP, to be
// rendered or compared. --subdivide adds each decimated copy refined by
// LEVELS steps of Loop subdivision (meshio::subdividedScene), with its
// Hausdorff distance from the copy (issue 36).
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

#include "cli/Arguments.h"
#include "cli/Cli.h"
#include "cli/RenderOptions.h"
#include "evaluation/ArtefactBenchmark.h"
#include "vv/core/NumberText.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/meshio/MeshSubdivide.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/render/ViewPresets.h"

namespace vv::cli {

namespace {

struct ArtefactsArguments {
    bool aorta = false;
    std::vector<std::filesystem::path> meshes;
    std::optional<std::filesystem::path> save;
    std::optional<std::vector<int>> triangles;
    std::optional<std::pair<int, int>> size;
    render::ViewPreset view = render::ViewPreset::Close;
    double p = 2.0;
    int referenceScale = 3;
    render::LightAngles light;
    int subdivide = 0;
};

ArtefactsArguments parseArtefactsArguments(const std::vector<std::string>& args) {
    ArtefactsArguments parsed;
    for (Arguments arg("artefacts", args); arg.next();) {
        const std::string& a = arg.name();
        if (a == "--aorta") {
            parsed.aorta = true;
        } else if (a == "--mesh") {
            parsed.meshes.push_back(arg.path());
        } else if (a == "--save") {
            parsed.save = arg.path();
        } else if (a == "--subdivide") {
            parsed.subdivide = parseWholeNumber(arg.value(), "artefacts: --subdivide", 1, 3);
        } else if (a == "--light") {
            parsed.light = parseLightAngles(arg.value());
        } else if (a == "--triangles") {
            const std::string list = arg.value();
            parsed.triangles.emplace();
            if (list != "none") {
                for (const std::string& t : splitList(list, "artefacts: --triangles")) {
                    parsed.triangles->push_back(
                        parseWholeNumber(t, "artefacts: --triangles", 4, 100000000));
                }
            }
        } else if (a == "--size") {
            parsed.size = parseSize(arg.value(), "artefacts: --size", 16, 8192);
        } else if (a == "--view") {
            const std::string name = arg.value();
            const auto view = render::viewPresetFromName(name);
            if (!view) {
                throw UsageError("artefacts: unknown view '" + name +
                                 "' (known: far, medium, close)");
            }
            parsed.view = *view;
        } else if (a == "--p") {
            // The VSS exponent's range and message, as `render --p` checks them.
            parsed.p = std::get<double>(parseSettingOption("vss.p", arg.value(), "artefacts: --p"));
        } else if (a == "--reference-scale") {
            const std::string value = arg.value();
            parsed.referenceScale =
                value == "none" ? 0 : parseWholeNumber(value, "artefacts: --reference-scale", 3, 7);
            if (parsed.referenceScale != 0 && parsed.referenceScale % 2 == 0) {
                throw UsageError("artefacts: --reference-scale must be 3, 5, 7 or none");
            }
        } else {
            arg.fail("unknown argument '" + arg.current() + "'");
        }
    }
    return parsed;
}

/// "aorta decimated to 13000" -> "aorta-decimated-to-13000"; what follows
/// " (" is left out ("..., subdivided 1x (within 0.3 mm of it)" ->
/// "...-subdivided-1x").
std::string labelFileName(const std::string& label) {
    std::string name;
    for (const char c : label.substr(0, label.find(" ("))) {
        const bool plain =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
        if (plain) {
            name += c;
        } else if (!name.empty() && name.back() != '-') {
            name += '-';
        }
    }
    while (!name.empty() && name.back() == '-') {
        name.pop_back();
    }
    return name;
}

}  // namespace

int artefactsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const ArtefactsArguments parsed = parseArtefactsArguments(args);
    evaluation::ArtefactBenchmarkOptions options;
    if (parsed.size) {
        options.width = parsed.size->first;
        options.height = parsed.size->second;
    }
    options.view = parsed.view;
    options.p = parsed.p;
    options.referenceScale = parsed.referenceScale;
    options.light = parsed.light;

    std::vector<evaluation::ArtefactCase> cases;
    const std::string control = parsed.aorta ? "aorta" : "demo";
    if (parsed.aorta) {
        err << "artefacts: generating the aorta (the aneurysm phantom)\n" << std::flush;
        demo::AneurysmPhantomOptions aorta;
        aorta.targetTriangles = 60'000;
        cases.push_back({"aorta (smooth control)", scene::Scene{}});
        cases.front().scene.meshes.push_back(demo::makeAneurysmPhantom(aorta).mesh);
    } else {
        err << "artefacts: generating the demo vessel tree\n" << std::flush;
        cases.push_back({"demo (smooth control)", scene::Scene{}});
        cases.front().scene.meshes.push_back(demo::generateDemoMesh());
    }
    const std::vector<int> triangles = parsed.triangles.value_or(
        parsed.aorta ? std::vector<int>{13000} : std::vector<int>{10000, 30000, 60000});
    for (const int t : triangles) {
        err << "artefacts: decimating to " << t << " triangles\n" << std::flush;
        cases.push_back(
            {control + " decimated to " + std::to_string(t),
             meshio::simplifiedScene(cases.front().scene, static_cast<std::size_t>(t))});
        if (parsed.subdivide > 0) {
            meshio::SubdividedScene refined =
                meshio::subdividedScene(cases.back().scene, parsed.subdivide);
            cases.push_back({control + " decimated to " + std::to_string(t) + ", subdivided " +
                                 std::to_string(parsed.subdivide) + "x (within " +
                                 fixedText(refined.largestDeviation, 3) + " mm of it)",
                             std::move(refined.scene)});
        }
    }
    if (parsed.save) {
        for (const evaluation::ArtefactCase& c : cases) {
            const std::filesystem::path file = *parsed.save / (labelFileName(c.label) + ".vtp");
            meshio::writeVtp(c.scene.meshes.front(), file);
            err << "artefacts: wrote " << file.string() << "\n";
        }
    }
    for (const std::filesystem::path& file : parsed.meshes) {
        cases.push_back({file.filename().string(), scene::Scene{}});
        cases.back().scene.meshes.push_back(meshio::loadMesh(file));
    }
    err << "artefacts: scoring " << cases.size() << " meshes\n" << std::flush;
    const std::vector<evaluation::ArtefactRow> rows =
        evaluation::runArtefactBenchmark(cases, options);
    out << "View " << render::toString(options.view) << ", " << options.width << "x"
        << options.height << ", p = " << options.p << ", key light at azimuth "
        << fixedText(options.light.azimuth, 1) << ", elevation "
        << fixedText(options.light.elevation, 1)
        << " degrees, AO off; all meshes through the first one's camera; "
        << (options.referenceScale == 0
                ? std::string("no reference")
                : "reference: the same view at " + std::to_string(options.referenceScale) +
                      "x the size, z' sampled at the pixel centres")
        << ".\n\n"
        << evaluation::artefactTable(rows);
    return kOk;
}

}  // namespace vv::cli
