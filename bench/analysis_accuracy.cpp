// SPDX-License-Identifier: GPL-3.0-or-later
// analysis_accuracy: vessel analysis against analytic truth, with run time
// (issue 33; the tables of docs/benchmarks/analysis.md). Per phantom (tube
// phantoms and Y-bifurcations, at about 1k, 50k and 1M triangles, with and
// without a 2 % jitter) the centreline's largest distance from the true
// axis (per r), the length error, the equivalent diameter's largest error,
// the bifurcation angle's error; then the demo tree's centrelines and
// sections: time and peak memory against the mesh's own size.
//
//   build/release/bench/analysis_accuracy [--quick | --demo]
//   (--quick: no 1M rows; --demo: the demo tree's row alone)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "vv/analysis/Bifurcations.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/core/ProcessMemory.h"
#include "vv/demo/BifurcationPhantom.h"
#include "vv/demo/DemoTree.h"
#include "vv/demo/TubePhantom.h"

// A benchmark prints tables: printf's formats are the plain tool for that.
// NOLINTBEGIN(cppcoreguidelines-pro-type-vararg)
namespace {

using Clock = std::chrono::steady_clock;
using vv::analysis::CrossSection;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double meshMiB(const vv::scene::Mesh& mesh) {
    const double bytes = static_cast<double>(mesh.positions.size()) * 24.0 +
                         static_cast<double>(mesh.indices.size()) * 4.0;
    return bytes / (1024.0 * 1024.0);
}

struct TubeRow {
    const char* name;
    vv::demo::TubeShape shape;
    double radius;
};

void tubeTable(const std::vector<std::size_t>& densities) {
    std::printf(
        "| phantom | r (mm) | triangles | jitter | axis distance (%% r) | length error (%%) "
        "| equiv. diameter error, max (%%) | centrelines (s) | sections (s) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    const std::array<TubeRow, 6> rows{{{"cylinder", vv::demo::TubeShape::Cylinder, 1.0},
                                       {"cylinder", vv::demo::TubeShape::Cylinder, 5.0},
                                       {"cylinder", vv::demo::TubeShape::Cylinder, 15.0},
                                       {"torus 120 deg", vv::demo::TubeShape::TorusSegment, 5.0},
                                       {"stenosis 50 %", vv::demo::TubeShape::Stenosis, 5.0},
                                       {"stenosis 70 %", vv::demo::TubeShape::Stenosis, 5.0}}};
    for (const TubeRow& row : rows) {
        for (const std::size_t triangles : densities) {
            for (const double jitter : {0.0, 0.02}) {
                vv::demo::TubePhantomOptions o;
                o.shape = row.shape;
                o.radiusMm = row.radius;
                o.lengthMm = 20.0 * row.radius;
                o.bendRadiusMm = 10.0 * row.radius;
                o.stenosisLengthMm = 4.0 * row.radius;
                o.stenosisPercent = std::strstr(row.name, "70") != nullptr ? 70.0 : 50.0;
                o.targetTriangles = triangles;
                o.jitterFraction = jitter;
                const auto truth = vv::demo::makeTubePhantom(o);
                auto start = Clock::now();
                const auto tree = vv::analysis::computeCenterlines(truth.mesh);
                const double centrelineSeconds = secondsSince(start);
                start = Clock::now();
                const auto sections = vv::analysis::computeSections(truth.mesh, tree);
                const double sectionSeconds = secondsSince(start);
                double worst = 0.0;
                double length = 0.0;
                double diameterError = 0.0;
                for (std::size_t b = 0; b < tree.branches.size(); ++b) {
                    length += tree.branches[b].lengthMm;
                    for (std::size_t i = 0; i < tree.branches[b].points.size(); ++i) {
                        const auto& p = tree.branches[b].points[i];
                        const auto [d, s] = truth.distanceToAxis(p.position);
                        if (s < row.radius || s > truth.lengthMm - row.radius) {
                            continue;
                        }
                        worst = std::max(worst, d);
                        const CrossSection& section = sections[b][i];
                        const double trueDiameter = 2.0 * truth.axisAt(s).radiusMm;
                        if (section.status == CrossSection::Status::Ok) {
                            diameterError = std::max(
                                diameterError,
                                std::abs(section.equivalentDiameterMm / trueDiameter - 1.0));
                        }
                    }
                }
                std::printf("| %s | %g | %zu | %g %% | %.2f | %+.2f | %.2f | %.2f | %.2f |\n",
                            row.name, row.radius, truth.mesh.triangleCount(), jitter * 100.0,
                            100.0 * worst / row.radius, 100.0 * (length / truth.lengthMm - 1.0),
                            100.0 * diameterError, centrelineSeconds, sectionSeconds);
                std::fflush(stdout);
            }
        }
    }
}

void bifurcationTable(const std::vector<std::size_t>& densities) {
    std::printf(
        "\n| Y-bifurcation | triangles | angle error (deg) | branches | centrelines (s) |\n");
    std::printf("|---|---|---|---|---|\n");
    for (const double angle : {30.0, 60.0, 90.0}) {
        for (const std::size_t triangles : densities) {
            vv::demo::BifurcationPhantomOptions o;
            o.angleDeg = angle;
            o.targetTriangles = std::max<std::size_t>(triangles, 1000);
            const auto truth = vv::demo::makeBifurcationPhantom(o);
            const auto start = Clock::now();
            const auto tree = vv::analysis::computeCenterlines(truth.mesh);
            const double seconds = secondsSince(start);
            const auto bifurcations = vv::analysis::findBifurcations(tree);
            const double error =
                bifurcations.empty() ? std::nan("") : bifurcations.front().angleDeg - angle;
            std::printf("| %g deg | %zu | %+.2f | %zu | %.2f |\n", angle,
                        truth.mesh.triangleCount(), error, tree.branches.size(), seconds);
            std::fflush(stdout);
        }
    }
}

/// Distance from `p` to the polyline `line`.
double distanceToPolyline(const glm::dvec3& p, const std::vector<glm::vec3>& line) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const glm::dvec3 a(line[i]);
        const glm::dvec3 ab = glm::dvec3(line[i + 1]) - a;
        const double t =
            std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-12), 0.0, 1.0);
        best = std::min(best, glm::length(p - (a + t * ab)));
    }
    return best;
}

double percentile(std::vector<double> values, double q) {
    if (values.empty()) {
        return std::nan("");
    }
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
}

void demoTree() {
    const vv::demo::DemoTreeOptions options;
    const vv::demo::VesselTree truth = vv::demo::generateVesselTree(options);
    const auto mesh = vv::demo::buildVesselSurface(truth, options);
    vv::resetPeakResident();
    const auto before = vv::residentKiB().value_or(0);
    auto start = Clock::now();
    const auto tree = vv::analysis::computeCenterlines(mesh);
    const double centrelineSeconds = secondsSince(start);
    start = Clock::now();
    const auto sections = vv::analysis::computeSections(mesh, tree);
    const double sectionSeconds = secondsSince(start);
    const auto peak = vv::peakResidentKiB().value_or(0);
    std::size_t ok = 0;
    std::size_t all = 0;
    std::vector<double> offAxis;  // per r of the nearest construction segment
    std::vector<double> diameterError;
    for (std::size_t b = 0; b < sections.size(); ++b) {
        for (std::size_t i = 0; i < sections[b].size(); ++i) {
            const auto& s = sections[b][i];
            ok += s.status == CrossSection::Status::Ok ? 1 : 0;
            ++all;
            if (s.inEndZone) {
                continue;  // caps and junctions: the construction has no axis there
            }
            const glm::dvec3 p = tree.branches[b].points[i].position;
            double nearest = std::numeric_limits<double>::max();
            double radius = 0.0;
            for (const auto& segment : truth.segments) {
                const double d = distanceToPolyline(p, segment.centerline);
                if (d < nearest) {
                    nearest = d;
                    radius = segment.radiusMm;
                }
            }
            offAxis.push_back(nearest / radius);
            if (s.status == CrossSection::Status::Ok) {
                diameterError.push_back(s.equivalentDiameterMm / (2.0 * radius) - 1.0);
            }
        }
    }
    std::size_t leaves = 0;
    for (const auto& segment : truth.segments) {
        leaves += segment.children.empty() ? 1 : 0;
    }
    std::printf(
        "| demo tree | triangles | segments / leaves built | branches / ends found | "
        "sections (ok / all) | off the built axis, median / 95 %% (%% r) | equiv. "
        "diameter against the built, median / 95 %% (%%) | centrelines (s) | sections (s) "
        "| peak memory above the mesh (MiB) | mesh (MiB) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::printf(
        "| default | %zu | %zu / %zu | %zu / %zu | %zu / %zu | %.1f / %.1f | %+.1f / %+.1f | "
        "%.2f | %.2f | %.0f | %.1f |\n",
        mesh.triangleCount(), truth.segments.size(), leaves, tree.branches.size(), tree.ends.size(),
        ok, all, 100.0 * percentile(offAxis, 0.5), 100.0 * percentile(offAxis, 0.95),
        100.0 * percentile(diameterError, 0.5), 100.0 * percentile(diameterError, 0.95),
        centrelineSeconds, sectionSeconds,
        static_cast<double>(peak > before ? peak - before : 0) / 1024.0, meshMiB(mesh));
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const bool demoOnly = argc > 1 && std::strcmp(argv[1], "--demo") == 0;
    std::vector<std::size_t> densities{1'000, 50'000};
    if (!quick) {
        densities.push_back(1'000'000);
    }
    demoTree();
    if (demoOnly) {
        return 0;
    }
    std::printf("\n");
    tubeTable(densities);
    bifurcationTable(densities);
    return 0;
}
// NOLINTEND(cppcoreguidelines-pro-type-vararg)
