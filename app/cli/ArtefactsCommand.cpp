// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli artefacts [--mesh FILE]... [--triangles 10000,30000,60000]
//                          [--size WxH] [--view far|medium|close] [--p P]
//                          [--reference-scale 3|5|7|none]
// The artefact score of the lit VSS along silhouettes (app/evaluation/ArtefactBenchmark.h)
// of the demo tree, its decimated copies and the given meshes, as a Markdown
// table (docs/benchmarks/artefacts.md).
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
#include "vv/demo/DemoTree.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/meshio/MeshSimplify.h"
#include "vv/render/ViewPresets.h"

namespace vv::cli {

namespace {

struct ArtefactsArguments {
    std::vector<std::filesystem::path> meshes;
    std::vector<int> triangles{10000, 30000, 60000};
    std::optional<std::pair<int, int>> size;
    render::ViewPreset view = render::ViewPreset::Close;
    double p = 2.0;
    int referenceScale = 3;
};

ArtefactsArguments parse(const std::vector<std::string>& args) {
    ArtefactsArguments parsed;
    for (Arguments arg("artefacts", args); arg.next();) {
        const std::string& a = arg.name();
        if (a == "--mesh") {
            parsed.meshes.push_back(arg.path());
        } else if (a == "--triangles") {
            const std::string list = arg.value();
            parsed.triangles.clear();
            if (list != "none") {
                for (const std::string& t : splitList(list, "artefacts: --triangles")) {
                    parsed.triangles.push_back(
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

}  // namespace

int artefactsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const ArtefactsArguments parsed = parse(args);
    evaluation::ArtefactBenchmarkOptions options;
    if (parsed.size) {
        options.width = parsed.size->first;
        options.height = parsed.size->second;
    }
    options.view = parsed.view;
    options.p = parsed.p;
    options.referenceScale = parsed.referenceScale;

    err << "artefacts: generating the demo vessel tree\n" << std::flush;
    std::vector<evaluation::ArtefactCase> cases;
    cases.push_back({"demo (smooth control)", scene::Scene{}});
    cases.front().scene.meshes.push_back(demo::generateDemoMesh());
    for (const int t : parsed.triangles) {
        err << "artefacts: decimating to " << t << " triangles\n" << std::flush;
        cases.push_back(
            {"demo decimated to " + std::to_string(t),
             meshio::simplifiedScene(cases.front().scene, static_cast<std::size_t>(t))});
    }
    for (const std::filesystem::path& file : parsed.meshes) {
        cases.push_back({file.filename().string(), scene::Scene{}});
        cases.back().scene.meshes.push_back(meshio::loadMesh(file));
    }
    err << "artefacts: scoring " << cases.size() << " meshes\n" << std::flush;
    const std::vector<evaluation::ArtefactRow> rows =
        evaluation::runArtefactBenchmark(cases, options);
    out << "View " << render::toString(options.view) << ", " << options.width << "x"
        << options.height << ", p = " << options.p
        << ", lighting on (headlight), AO off; all meshes through the demo's camera; "
        << (options.referenceScale == 0
                ? std::string("no reference")
                : "reference: the same view at " + std::to_string(options.referenceScale) +
                      "x the size, z' sampled at the pixel centres")
        << ".\n\n"
        << evaluation::artefactTable(rows);
    return kOk;
}

}  // namespace vv::cli
