// SPDX-License-Identifier: GPL-3.0-or-later
#include "ArtefactBenchmark.h"

#include <cmath>
#include <glm/trigonometric.hpp>
#include <sstream>

#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/MeshStyle.h"
#include "vv/vss/Shading.h"
#include "vv/vss/Vss.h"

namespace vv::bench {

LitVss litVss(const scene::Scene& scene, const render::Camera& camera, double p,
              const std::stop_token& stop) {
    const Image<float> depth = render::rasterizeDepth(scene, camera, stop);
    LitVss lit;
    lit.vessels = Image<std::uint8_t>(depth.width(), depth.height(), 0);
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            lit.vessels(x, y) = std::isfinite(depth(x, y)) ? 1 : 0;
        }
    }
    vss::VssOptions options;
    options.solver.p = p;
    options.stop = stop;
    const vss::VssResult vss = vss::solve(depth.view(), lit.vessels.view(), options);
    Image<glm::vec4> slopes = vss::fittedSlopes(vss.height.view(), lit.vessels.view(), stop);
    VssLight light;
    light.dmin = vss.dmin;
    light.dmax = vss.dmax;
    light.pixelScale = 2.0 *
                       std::tan(glm::radians(static_cast<double>(camera.fieldOfView())) * 0.5) /
                       depth.height();
    vss::addNormalCoherence(slopes, vss.height.view(), lit.vessels.view(),
                            {vss.dmin, vss.dmax, light.pixelScale});
    const render::Lighting& sceneLight = render::sceneLighting();
    light.lightX = sceneLight.direction.x;
    light.lightY = sceneLight.direction.y;
    light.lightZ = sceneLight.direction.z;
    light.ambient = sceneLight.ambient;
    light.diffuse = sceneLight.diffuse;
    light.specular = sceneLight.specular;
    light.shininess = sceneLight.shininess;
    lit.luminance = vssLuminance(vss.height.view(), slopes.view(), lit.vessels.view(), light);
    return lit;
}

std::vector<ArtefactRow> runArtefactBenchmark(const std::vector<ArtefactCase>& cases,
                                              const ArtefactBenchmarkOptions& options) {
    if (cases.empty()) {
        throw InvalidArgumentError("runArtefactBenchmark: no case");
    }
    if (options.width < 1 || options.height < 1 || options.width > 8192 || options.height > 8192 ||
        !(options.p > 0.0) || !std::isfinite(options.p)) {
        throw InvalidArgumentError(
            "runArtefactBenchmark: needs a size of 1..8192 each and a finite p > 0");
    }
    const render::Camera camera =
        render::presetCamera(cases.front().scene, options.width, options.height, options.view);
    std::vector<ArtefactRow> rows;
    for (const ArtefactCase& c : cases) {
        const LitVss lit = litVss(c.scene, camera, options.p, options.stop);
        ArtefactRow row;
        row.label = c.label;
        for (const scene::Mesh& mesh : c.scene.meshes) {
            row.triangles += mesh.triangleCount();
        }
        row.score = artefactScore(lit.luminance.view(), lit.vessels.view(), options.score);
        rows.push_back(row);
    }
    return rows;
}

std::string artefactTable(const std::vector<ArtefactRow>& rows) {
    std::ostringstream out;
    out << "| mesh | triangles | band pixels | score (1/1000) | relative to the first |\n"
        << "|---|---:|---:|---:|---:|\n";
    const double first = rows.empty() ? 0.0 : rows.front().score.rms;
    for (const ArtefactRow& row : rows) {
        out << "| " << row.label << " | " << row.triangles << " | " << row.score.bandPixels << " | "
            << fixedText(row.score.rms * 1000.0, 3) << " | "
            << (first > 0.0 ? fixedText(row.score.rms / first, 2) : std::string("-")) << " |\n";
    }
    return out.str();
}

}  // namespace vv::bench
