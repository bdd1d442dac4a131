// SPDX-License-Identifier: GPL-3.0-or-later
// `render` and `report --centerlines on`: a Y-bifurcation phantom of known
// axes and radii, seen side-on. What changes in the image is a line along
// the true axes and nothing else; the parent's line has the colour map's
// colour of the widest diameter and the daughters' its narrowest; the
// report's legend names the quantity and spans the phantom's diameters;
// bad option values and a --raycast combination are usage errors, a surface
// that cannot be analysed exits 3.
#include <gtest/gtest.h>

#include <QColor>
#include <QImage>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/glm.hpp>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "CliRun.h"
#include "ReportTestUtil.h"
#include "vv/colormaps/ColorMap.h"
#include "vv/demo/BifurcationPhantom.h"
#include "vv/meshio/MeshWriter.h"
#include "vv/render/OffscreenRenderer.h"

namespace vv::test {
namespace {

constexpr int kWidth = 800;
constexpr int kHeight = 600;

/// The phantom turned so that it lies in the x-y plane (the default view
/// looks down -z): (x, y, z) -> (x, z, -y), a rotation.
glm::vec3 turned(const glm::vec3& p) {
    return {p.x, p.z, -p.y};
}

struct Phantom {
    demo::BifurcationPhantom truth;
    scene::Scene scene;
    std::filesystem::path file;
};

const Phantom& phantom() {
    static const Phantom made = [] {
        Phantom p;
        demo::BifurcationPhantomOptions o;
        o.angleDeg = 70.0;
        o.parentLengthMm = 50.0;
        o.daughterLengthMm = 45.0;
        o.targetTriangles = 30'000;
        p.truth = demo::makeBifurcationPhantom(o);
        scene::Mesh mesh = p.truth.mesh;
        for (auto& v : mesh.positions) {
            v = turned(v);
        }
        for (auto& n : mesh.normals) {
            n = turned(n);
        }
        const auto dir = processTestDir("centerline-render");
        std::filesystem::create_directories(dir);
        p.file = dir / "y.vtp";
        meshio::writeVtp(mesh, p.file);
        p.scene.meshes.push_back(std::move(mesh));
        return p;
    }();
    return made;
}

render::Camera defaultCamera() {
    render::OffscreenOptions options;
    options.width = kWidth;
    options.height = kHeight;
    return render::OffscreenRenderer::cameraFor(phantom().scene, options);
}

QPointF project(const render::Camera& camera, const glm::vec3& world) {
    const glm::vec4 clip = camera.projectionMatrix() * camera.viewMatrix() * glm::vec4(world, 1.0F);
    return {(clip.x / clip.w * 0.5 + 0.5) * kWidth, (0.5 - clip.y / clip.w * 0.5) * kHeight};
}

double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a;
    const double length2 = QPointF::dotProduct(ab, ab);
    const double t =
        length2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    const QPointF d = p - (a + t * ab);
    return std::hypot(d.x(), d.y());
}

/// The true axes in pixels: each segment's centreline, its free end
/// carried on by 1.5 radii (the centreline runs into the closed tip).
std::vector<std::vector<QPointF>> projectedAxes(const render::Camera& camera) {
    std::vector<std::vector<QPointF>> axes;
    const auto& segments = phantom().truth.tree.segments;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        std::vector<glm::vec3> points = segments[s].centerline;
        const float reach = 1.5F * static_cast<float>(segments[s].radiusMm);
        if (s == 0) {  // the parent's free end is its start
            points.insert(points.begin(),
                          points[0] + reach * glm::normalize(points[0] - points[1]));
        } else {
            const glm::vec3 last = points.back();
            points.push_back(last + reach * glm::normalize(last - points[points.size() - 2]));
        }
        std::vector<QPointF> pixels;
        pixels.reserve(points.size());
        for (const auto& p : points) {
            pixels.push_back(project(camera, turned(p)));
        }
        axes.push_back(std::move(pixels));
    }
    return axes;
}

double distanceToAxes(const QPointF& p, const std::vector<std::vector<QPointF>>& axes) {
    double best = 1e30;
    for (const auto& axis : axes) {
        for (std::size_t i = 0; i + 1 < axis.size(); ++i) {
            best = std::min(best, distanceToSegment(p, axis[i], axis[i + 1]));
        }
    }
    return best;
}

QImage renderPhantom(const std::string& name, const std::vector<std::string>& extra) {
    const auto out = phantom().file.parent_path() / name;
    std::vector<std::string> args{"render",
                                  phantom().file.string(),
                                  "-o",
                                  out.string(),
                                  "--size",
                                  "800x600",
                                  "--vss",
                                  "off",
                                  "--ao",
                                  "off",
                                  "--aa",
                                  "off",
                                  "--legends",
                                  "off",
                                  "--array",
                                  "none",
                                  "--orientation-marker",
                                  "off",
                                  "--scale-bar",
                                  "off"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto run = runCli(args);
    EXPECT_EQ(run.code, 0) << run.err;
    return QImage(QString::fromStdString(out.string())).convertToFormat(QImage::Format_RGB32);
}

TEST(CenterlineRender, TheLinesFollowTheTrueAxesInTheColourOfTheirDiameter) {
    const QImage off = renderPhantom("off.png", {});
    const QImage on = renderPhantom("on.png", {"--centerlines", "on"});
    ASSERT_EQ(off.size(), on.size());
    ASSERT_EQ(on.width(), kWidth);
    const render::Camera camera = defaultCamera();
    const auto axes = projectedAxes(camera);

    // Every changed pixel lies on a line along a true axis (the halo is
    // 4.5 px wide at this size); the line follows the axes' whole length.
    // So too in tiles, whose visibility is judged on the tiles' depth.
    const QImage tiledOff = renderPhantom("tiled-off.png", {"--tile", "256"});
    const QImage tiledOn = renderPhantom("tiled-on.png", {"--tile", "256", "--centerlines", "on"});
    for (const auto& [with, without] : {std::pair{&on, &off}, std::pair{&tiledOn, &tiledOff}}) {
        long changed = 0;
        double farthest = 0.0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                if (with->pixel(x, y) != without->pixel(x, y)) {
                    ++changed;
                    farthest = std::max(farthest, distanceToAxes(QPointF(x + 0.5, y + 0.5), axes));
                }
            }
        }
        EXPECT_GT(changed, 500);
        EXPECT_LT(farthest, 5.0);
    }

    // Away from the ends and the junction, the pixel on each true axis shows
    // the map's colour: the parent's diameter is the widest, the daughters'
    // the narrowest (Inferno: the vessels show no array).
    const auto& segments = phantom().truth.tree.segments;
    const auto& map = colormaps::ColorMap::Inferno;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        const float t = s == 0 ? 1.0F : 0.0F;
        const glm::vec3 want = colormaps::sample(map, t);
        const auto& c = segments[s].centerline;
        int covered = 0;
        int samples = 0;
        for (const double f : {0.35, 0.5, 0.65}) {
            const glm::vec3 world =
                turned(c.front() + static_cast<float>(f) * (c.back() - c.front()));
            const QPointF p = project(camera, world);
            const QColor got = on.pixelColor(static_cast<int>(p.x()), static_cast<int>(p.y()));
            ++samples;
            const double error =
                std::max({std::abs(got.redF() - want.r), std::abs(got.greenF() - want.g),
                          std::abs(got.blueF() - want.b)});
            covered += error < 0.12 ? 1 : 0;
            EXPECT_LT(error, 0.12)
                << "segment " << s << " at " << f << ": got " << got.name().toStdString();
        }
        EXPECT_EQ(covered, samples);
    }
}

TEST(CenterlineRender, TheReportsLegendNamesTheDiameterAndSpansThePhantoms) {
    if (!report::test::haveTool("pdftotext")) {
        GTEST_SKIP() << "pdftotext (poppler-utils) is missing";
    }
    const auto dir = phantom().file.parent_path();
    for (const bool on : {true, false}) {
        const auto pdf = dir / (on ? "on.pdf" : "off.pdf");
        std::vector<std::string> args{
            "report", phantom().file.string(), "-o", pdf.string(), "--array", "none", "--vss",
            "off"};
        if (on) {
            args.insert(args.end(), {"--centerlines", "on"});
        }
        const auto run = runCli(args);
        ASSERT_EQ(run.code, 0) << run.err;
        std::string text;
        ASSERT_EQ(report::test::runTool("pdftotext '" + pdf.string() + "' -", text), 0) << text;
        const auto at = text.find("Centreline: inscribed diameter (mm)");
        if (!on) {
            EXPECT_EQ(at, std::string::npos) << text;
            continue;
        }
        ASSERT_NE(at, std::string::npos) << text;
        // The bar's end ticks: the daughters' and the parent's diameters.
        std::vector<double> ticks;
        const std::regex number(R"(\d+\.\d+)");
        const std::string after = text.substr(at, 200);
        for (auto it = std::sregex_iterator(after.begin(), after.end(), number);
             it != std::sregex_iterator(); ++it) {
            ticks.push_back(std::stod(it->str()));
        }
        ASSERT_GE(ticks.size(), 2U) << after;
        const double parent = 2.0 * phantom().truth.tree.segments[0].radiusMm;
        const double daughter = 2.0 * phantom().truth.tree.segments[1].radiusMm;
        EXPECT_NEAR(*std::min_element(ticks.begin(), ticks.end()), daughter, 0.04 * daughter)
            << after;
        EXPECT_NEAR(*std::max_element(ticks.begin(), ticks.end()), parent, 0.04 * parent) << after;
    }
}

TEST(CenterlineRender, BadValuesAndSurfacesThatCannotBeAnalysedAreRefused) {
    const auto dir = phantom().file.parent_path();
    const auto png = (dir / "bad.png").string();
    auto run = runCli({"render", phantom().file.string(), "-o", png, "--centerlines", "maybe"});
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("--centerlines"), std::string::npos) << run.err;
    run = runCli({"render", phantom().file.string(), "-o", png, "--centerline-colour", "red"});
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("--centerline-colour"), std::string::npos) << run.err;
    run = runCli({"render", dir.string(), "--raycast", "-o", png, "--centerlines", "on"});
    EXPECT_EQ(run.code, 2);
    EXPECT_NE(run.err.find("--raycast"), std::string::npos) << run.err;

    // One flat triangle: no vessel to find a centreline in; nothing written.
    scene::Mesh flat;
    flat.positions = {{0.0F, 0.0F, 0.0F}, {10.0F, 0.0F, 0.0F}, {0.0F, 10.0F, 0.0F}};
    flat.indices = {0, 1, 2};
    const auto file = dir / "flat.vtp";
    meshio::writeVtp(flat, file);
    run = runCli({"render", file.string(), "-o", png, "--centerlines", "on"});
    EXPECT_EQ(run.code, 3) << run.err;
    EXPECT_NE(run.err.find("flat.vtp"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace vv::test
