// SPDX-License-Identifier: GPL-3.0-or-later
#include "evaluation/ArtefactBenchmark.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/trigonometric.hpp>
#include <sstream>
#include <vector>

#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/render/DepthRasterizer.h"
#include "vv/render/MeshStyle.h"
#include "vv/vss/Shading.h"
#include "vv/vss/Vss.h"

namespace vv::evaluation {

namespace {

constexpr int kMaxReferenceScale = 7;

/// The exact viewer frame's VSS of `scene` through `camera` (fast solver at
/// power p), over `range`, and what its lighting needs.
struct SolvedView {
    Image<std::uint8_t> vessels;
    vss::VssResult vss;
    double pixelScale = 0.0;
};

SolvedView solveView(const scene::Scene& scene, const render::Camera& camera, double p,
                     const vss::DepthRange& range, const std::stop_token& stop) {
    const Image<float> depth = render::rasterizeDepth(scene, camera, stop);
    SolvedView view;
    view.vessels = Image<std::uint8_t>(depth.width(), depth.height(), 0);
    for (int y = 0; y < depth.height(); ++y) {
        for (int x = 0; x < depth.width(); ++x) {
            view.vessels(x, y) = std::isfinite(depth(x, y)) ? 1 : 0;
        }
    }
    vss::VssOptions options;
    options.solver.p = p;
    options.range = range;
    options.stop = stop;
    view.vss = vss::solve(depth.view(), view.vessels.view(), options);
    view.pixelScale = 2.0 *
                      std::tan(glm::radians(static_cast<double>(camera.fieldOfView())) * 0.5) /
                      depth.height();
    return view;
}

/// vss::fittedSlopes, vss::addNormalCoherence and vssLuminance of `height`
/// (z' over the range of `view`) under `sceneLight`.
Image<float> lightVss(const SolvedView& view, ImageView<const float> height,
                      const std::stop_token& stop, const render::Lighting& sceneLight) {
    Image<glm::vec4> slopes = vss::fittedSlopes(height, view.vessels.view(), stop);
    VssLight light;
    light.dmin = view.vss.dmin;
    light.dmax = view.vss.dmax;
    light.pixelScale = view.pixelScale;
    vss::addNormalCoherence(slopes, height, view.vessels.view(),
                            {view.vss.dmin, view.vss.dmax, light.pixelScale});
    light.lightX = sceneLight.direction.x;
    light.lightY = sceneLight.direction.y;
    light.lightZ = sceneLight.direction.z;
    light.ambient = sceneLight.ambient;
    light.diffuse = sceneLight.diffuse;
    light.specular = sceneLight.specular;
    light.shininess = sceneLight.shininess;
    return vssLuminance(height, slopes.view(), view.vessels.view(), light);
}

}  // namespace

LitVss litVss(const scene::Scene& scene, const render::Camera& camera, double p,
              const std::stop_token& stop, const render::Lighting& lighting) {
    SolvedView view = solveView(scene, camera, p, {}, stop);
    LitVss lit;
    lit.luminance = lightVss(view, view.vss.height.view(), stop, lighting);
    lit.vessels = std::move(view.vessels);
    return lit;
}

LitVss referenceLitVss(const scene::Scene& scene, const render::Camera& camera, double p, int scale,
                       const std::stop_token& stop, const render::Lighting& lighting) {
    if (scale < 1 || scale % 2 == 0) {
        throw InvalidArgumentError("referenceLitVss: the scale must be odd and >= 1, got " +
                                   std::to_string(scale));
    }
    SolvedView view = solveView(scene, camera, p, {}, stop);
    render::Camera fineCamera = camera;
    fineCamera.setViewport(camera.viewportWidth() * scale, camera.viewportHeight() * scale);
    vss::DepthRange range;
    range.mode = vss::RangeMode::Fixed;
    range.dmin = view.vss.dmin;
    range.dmax = view.vss.dmax;
    const SolvedView fine = solveView(scene, fineCamera, p, range, stop);
    // z' at every void pixel's centre from the fine solve: the centre of
    // fine pixel (s x + s / 2, s y + s / 2) is that of pixel (x, y).
    Image<float> height = view.vss.height;
    for (int y = 0; y < height.height(); ++y) {
        for (int x = 0; x < height.width(); ++x) {
            const int fx = scale * x + scale / 2;
            const int fy = scale * y + scale / 2;
            if (view.vessels(x, y) == 0 && fine.vessels(fx, fy) == 0) {
                height(x, y) = fine.vss.height(fx, fy);
            }
        }
    }
    LitVss lit;
    lit.luminance = lightVss(view, height.view(), stop, lighting);
    lit.vessels = std::move(view.vessels);
    return lit;
}

double medianEdgePixels(const scene::Scene& scene, const render::Camera& camera) {
    const glm::mat4 toClip = camera.projectionMatrix() * camera.viewMatrix();
    const glm::vec2 half(0.5F * static_cast<float>(camera.viewportWidth()),
                         0.5F * static_cast<float>(camera.viewportHeight()));
    std::vector<double> lengths;
    for (const scene::Mesh& mesh : scene.meshes) {
        std::vector<glm::vec4> clip(mesh.positions.size());
        for (std::size_t i = 0; i < clip.size(); ++i) {
            clip[i] = toClip * glm::vec4(mesh.positions[i], 1.0F);
        }
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            for (std::size_t k = 0; k < 3; ++k) {
                const glm::vec4& a = clip[mesh.indices[t + k]];
                const glm::vec4& b = clip[mesh.indices[t + (k + 1) % 3]];
                if (!(a.w > 0.0F) || !(b.w > 0.0F)) {
                    continue;  // behind the camera
                }
                const glm::vec2 pa = glm::vec2(a) / a.w * half;
                const glm::vec2 pb = glm::vec2(b) / b.w * half;
                lengths.push_back(glm::length(pa - pb));
            }
        }
    }
    if (lengths.empty()) {
        return 0.0;
    }
    const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
    std::nth_element(lengths.begin(), middle, lengths.end());
    return *middle;
}

std::vector<ArtefactRow> runArtefactBenchmark(const std::vector<ArtefactCase>& cases,
                                              const ArtefactBenchmarkOptions& options) {
    if (cases.empty()) {
        throw InvalidArgumentError("runArtefactBenchmark: no case");
    }
    if (options.width < 1 || options.height < 1 || options.width > 8192 || options.height > 8192 ||
        !(options.p > 0.0) || !std::isfinite(options.p) ||
        (options.referenceScale != 0 &&
         (options.referenceScale < 3 || options.referenceScale > kMaxReferenceScale ||
          options.referenceScale % 2 == 0))) {
        throw InvalidArgumentError(
            "runArtefactBenchmark: needs a size of 1..8192 each, a finite p > 0 and a "
            "reference scale of 0, 3, 5 or 7");
    }
    const render::Camera camera =
        render::presetCamera(cases.front().scene, options.width, options.height, options.view);
    const render::Lighting lighting = render::lightingFor(options.light);
    std::vector<ArtefactRow> rows;
    for (const ArtefactCase& c : cases) {
        const LitVss lit = litVss(c.scene, camera, options.p, options.stop, lighting);
        ArtefactRow row;
        row.label = c.label;
        for (const scene::Mesh& mesh : c.scene.meshes) {
            row.triangles += mesh.triangleCount();
        }
        row.score = artefactScore(lit.luminance.view(), lit.vessels.view(), options.score);
        row.medianEdgePx = medianEdgePixels(c.scene, camera);
        ArtefactScoreOptions band = options.score;
        band.spacing = kBumpSpacing;
        band.bandNear = kNearBand[0];
        band.bandFar = kNearBand[1];
        row.near = artefactScore(lit.luminance.view(), lit.vessels.view(), band);
        band.bandNear = kFarBand[0];
        band.bandFar = kFarBand[1];
        row.far = artefactScore(lit.luminance.view(), lit.vessels.view(), band);
        if (options.referenceScale != 0) {
            const LitVss reference = referenceLitVss(
                c.scene, camera, options.p, options.referenceScale, options.stop, lighting);
            row.reference =
                artefactScore(reference.luminance.view(), reference.vessels.view(), options.score);
        }
        rows.push_back(row);
    }
    return rows;
}

std::string artefactTable(const std::vector<ArtefactRow>& rows) {
    std::ostringstream out;
    out << "| mesh | triangles | band pixels | score (1/1000) | reference (1/1000) | "
           "score / reference | relative to the first | 2-6 px (1/1000) | 12-30 px (1/1000) | "
           "2-6 px / 12-30 px | median edge (px) |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    const double first = rows.empty() ? 0.0 : rows.front().score.rms;
    const auto ratio = [](double a, double b) {
        return b > 0.0 ? fixedText(a / b, 2) : std::string("-");
    };
    for (const ArtefactRow& row : rows) {
        const bool referenced = row.reference.bandPixels > 0;
        out << "| " << row.label << " | " << row.triangles << " | " << row.score.bandPixels << " | "
            << fixedText(row.score.rms * 1000.0, 3) << " | "
            << (referenced ? fixedText(row.reference.rms * 1000.0, 3) : std::string("-")) << " | "
            << (referenced ? ratio(row.score.rms, row.reference.rms) : std::string("-")) << " | "
            << ratio(row.score.rms, first) << " | " << fixedText(row.near.rms * 1000.0, 3) << " | "
            << fixedText(row.far.rms * 1000.0, 3) << " | " << ratio(row.near.rms, row.far.rms)
            << " | " << fixedText(row.medianEdgePx, 1) << " |\n";
    }
    return out.str();
}

}  // namespace vv::evaluation
