// SPDX-License-Identifier: GPL-3.0-or-later
// analysis_accuracy: vessel analysis against analytic truth, with run time
// (issue 33; the tables of docs/benchmarks/analysis.md). Per phantom (tube
// phantoms and Y-bifurcations, at about 1k, 50k and 1M triangles, with and
// without a 2 % jitter) the centreline's largest distance from the true
// axis (per r), the length error, the equivalent diameter's largest error,
// the bifurcation angle's error; the aneurysm phantom's widest section,
// axes, trunk length and angle; then the demo tree's centrelines and
// sections against its construction: time and peak memory against the
// mesh's own size; and the synthetic CTA segmented as `render` segments a
// DICOM series, against the tree it was voxelised from.
//
//   build/release/bench/analysis_accuracy [--quick | --demo [whole] [--on-a-thread] | --cta
//                                          | --aneurysm | --huge | --slabs [ROUNDS]
//                                          | --tubes [TRIANGLES]] [--glibc-default]
//   (--quick: no 1M rows; --demo: the demo tree's rows alone, `whole`: without
//   the decimated ones, e.g. under heaptrack, `--on-a-thread`: analysed from a
//   worker thread, as the GUI runs it; --tubes: the
//   tube table alone at one density, 1M triangles unless given; --cta: the
//   synthetic CTA's table alone; --aneurysm: the aneurysm's table alone, 1M
//   rows included; --huge: a 10M-triangle cylinder alone; --slabs: the
//   Voronoi diagram in one slab, in slabs with one margin per cut, and in
//   slabs with margins per column, in turn; --glibc-default: the C library's
//   defaults for handing freed memory back, not the CLI's `centerline`'s,
//   vv::handFreedMemoryBackAtOnce)
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stop_token>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "AnalysisAgreement.h"
#include "PreparedSurface.h"
#include "VoronoiGraph.h"
#include "VoronoiSamples.h"
#include "vv/analysis/Bifurcations.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/core/Error.h"
#include "vv/core/ProcessMemory.h"
#include "vv/core/Progress.h"
#include "vv/demo/AneurysmPhantom.h"
#include "vv/demo/BifurcationPhantom.h"
#include "vv/demo/DemoCtSeries.h"
#include "vv/demo/DemoTree.h"
#include "vv/demo/TubePhantom.h"
#include "vv/meshio/MeshSimplify.h"

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

/// A surface's centrelines and sections, and how long each took.
struct Analysed {
    vv::analysis::CenterlineTree tree;
    std::vector<std::vector<CrossSection>> sections;
    double centrelineSeconds = 0.0;
    double sectionSeconds = 0.0;
};

/// The time from each stage the analysis reports (its progress messages)
/// to the next.
class StageClock {
  public:
    /// Memory is counted above the resident size at `baseKiB`.
    explicit StageClock(std::uint64_t baseKiB = 0) : baseKiB_(baseKiB) {
        static_cast<void>(vv::resetPeakResident());
    }
    /// A progress report of `stage`: a new stage starts when it changes.
    void record(std::string_view stage) {
        if (stages_.empty() || stages_.back().name != stage) {
            lap();
            stages_.push_back({std::string(stage), 0.0, 0.0});
        }
    }
    /// Ends the current stage: its time, and its peak resident size (the
    /// peak since the stage began; the kernel's peak is reset for the next).
    void lap() {
        const auto now = Clock::now();
        if (!stages_.empty()) {
            Stage& stage = stages_.back();
            stage.seconds += std::chrono::duration<double>(now - last_).count();
            const auto peak = vv::peakResidentKiB().value_or(0);
            stage.peakMiB = std::max(
                stage.peakMiB, static_cast<double>(peak > baseKiB_ ? peak - baseKiB_ : 0) / 1024.0);
            static_cast<void>(vv::resetPeakResident());
        }
        last_ = now;
    }
    struct Stage {
        std::string name;
        double seconds = 0.0;
        double peakMiB = 0.0;  ///< above the base
    };
    [[nodiscard]] const std::vector<Stage>& stages() const noexcept { return stages_; }

  private:
    std::uint64_t baseKiB_ = 0;
    std::vector<Stage> stages_;
    Clock::time_point last_ = Clock::now();
};

/// The resident size now, with what earlier rows freed handed back first
/// (else a row reuses it unseen and its peak above this reads too low); the
/// kernel's peak is reset.
std::uint64_t residentBaseKiB() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
    static_cast<void>(vv::resetPeakResident());
    return vv::residentKiB().value_or(0);
}

/// The peak resident size since residentBaseKiB() returned `base`, above it.
double peakAboveMiB(std::uint64_t base) {
    const auto peak = vv::peakResidentKiB().value_or(0);
    return static_cast<double>(peak > base ? peak - base : 0) / 1024.0;
}

/// analyseVessels(), timed: the centrelines up to the first section, the
/// sections from there.
Analysed analyse(const vv::scene::Mesh& mesh, StageClock* clock = nullptr) {
    Analysed a;
    const auto start = Clock::now();
    std::optional<Clock::time_point> sectionsStart;
    const vv::Progress progress(
        [&](double fraction, std::string_view stage) {
            if (!sectionsStart && stage == "Cutting the sections") {
                sectionsStart = Clock::now();
            }
            if (clock != nullptr) {
                clock->record(stage);
            }
            static_cast<void>(fraction);
        },
        std::stop_token());
    vv::analysis::VesselAnalysis analysed = vv::analysis::analyseVessels(mesh, {}, progress);
    const auto end = Clock::now();
    a.tree = std::move(analysed.tree);
    a.sections = std::move(analysed.sections);
    const auto split = sectionsStart.value_or(end);
    a.centrelineSeconds = std::chrono::duration<double>(split - start).count();
    a.sectionSeconds = std::chrono::duration<double>(end - split).count();
    if (clock != nullptr) {
        clock->lap();
    }
    return a;
}

struct TubeRow {
    const char* name;
    vv::demo::TubeShape shape;
    double radius;
};

/// A tube phantom's errors: the largest axis distance (per r) and section
/// diameter error at least one radius from the ends, the length's error.
struct TubeErrors {
    double worstAxisPerR = 0.0;
    double lengthError = 0.0;
    double diameterError = 0.0;
    /// The mesh's own largest distance from the true wall over the same
    /// stretch (along the radius), per r: the input's own error.
    double worstWallPerR = 0.0;
};

TubeErrors tubeErrors(const vv::demo::TubePhantom& truth, const Analysed& analysed) {
    const double radius = truth.options.radiusMm;
    const auto& tree = analysed.tree;
    double worst = 0.0;
    double length = 0.0;
    double diameterError = 0.0;
    for (std::size_t b = 0; b < tree.branches.size(); ++b) {
        length += tree.branches[b].lengthMm;
        for (std::size_t i = 0; i < tree.branches[b].points.size(); ++i) {
            const auto [d, s] = truth.distanceToAxis(tree.branches[b].points[i].position);
            if (s < radius || s > truth.lengthMm - radius) {
                continue;
            }
            worst = std::max(worst, d);
            const CrossSection& section = analysed.sections[b][i];
            if (section.status == CrossSection::Status::Ok) {
                diameterError = std::max(
                    diameterError,
                    std::abs(section.equivalentDiameterMm / (2.0 * truth.axisAt(s).radiusMm) -
                             1.0));
            }
        }
    }
    const double wall = vv::bench::worstOverFacets(truth.mesh, [&](const glm::dvec3& q) {
        const auto [d, s] = truth.distanceToAxis(q);
        return s < radius || s > truth.lengthMm - radius ? std::nan("")
                                                         : std::abs(d - truth.axisAt(s).radiusMm);
    });
    return {.worstAxisPerR = worst / radius,
            .lengthError = length / truth.lengthMm - 1.0,
            .diameterError = diameterError,
            .worstWallPerR = wall / radius};
}

/// A 10-million-triangle cylinder (r = 10 mm): coarsened to the analysis'
/// limit (CenterlineOptions::maxTriangles), then measured; time and memory.
void hugeTable() {
    std::printf(
        "| cylinder r = 10 mm | triangles | analysed as | axis distance (%% r) | length error "
        "(%%) | equiv. diameter error, max (%%) | centrelines (s) | sections (s) | peak memory "
        "above the mesh (MiB) | mesh (MiB) |\n|---|---|---|---|---|---|---|---|---|---|\n");
    vv::demo::TubePhantomOptions o;
    o.radiusMm = 10.0;
    o.lengthMm = 200.0;
    o.targetTriangles = 10'000'000;
    const auto truth = vv::demo::makeTubePhantom(o);
    const auto base = residentBaseKiB();
    const Analysed analysed = analyse(truth.mesh);
    const double peak = peakAboveMiB(base);
    const TubeErrors e = tubeErrors(truth, analysed);
    std::string analysedAs = "all";
    for (const auto& note : analysed.tree.notes) {
        const auto at = note.find("leaving ");
        if (at != std::string::npos) {
            analysedAs = note.substr(at + 8);
        }
    }
    std::printf("| unjittered | %zu | %s | %.2f | %+.2f | %.2f | %.2f | %.2f | %.0f | %.0f |\n",
                truth.mesh.triangleCount(), analysedAs.c_str(), 100.0 * e.worstAxisPerR,
                100.0 * e.lengthError, 100.0 * e.diameterError, analysed.centrelineSeconds,
                analysed.sectionSeconds, peak, meshMiB(truth.mesh));
    for (const auto& note : analysed.tree.notes) {
        std::printf("\nnote: %s\n", note.c_str());
    }
}

void tubeTable(const std::vector<std::size_t>& densities) {
    std::printf(
        "| phantom | r (mm) | triangles | jitter | axis distance (%% r) | the wall's own distance "
        "from the true wall (%% r) | length error (%%) | equiv. diameter error, max (%%) | "
        "centrelines (s) | sections (s) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
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
                std::printf("| %s | %g | %zu | %g %% | ", row.name, row.radius,
                            truth.mesh.triangleCount(), jitter * 100.0);
                try {
                    const Analysed analysed = analyse(truth.mesh);
                    const TubeErrors e = tubeErrors(truth, analysed);
                    std::printf("%.2f | %.2f | %+.2f | %.2f | %.2f | %.2f |\n",
                                100.0 * e.worstAxisPerR, 100.0 * e.worstWallPerR,
                                100.0 * e.lengthError, 100.0 * e.diameterError,
                                analysed.centrelineSeconds, analysed.sectionSeconds);
                } catch (const vv::Error& e) {
                    std::printf("the analysis failed: %s |\n", e.what());
                }
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

/// The measured columns of one aneurysm row.
void aneurysmRow(const vv::demo::AneurysmPhantom& truth) {
    const auto base = residentBaseKiB();
    const Analysed analysed = analyse(truth.mesh);
    const double peak = peakAboveMiB(base);
    const auto a = vv::bench::measureAneurysm(truth, analysed.tree, analysed.sections);
    std::printf(
        "%zu / %zu | %+.2f | %+.2f | %.2f | %.2f | %+.2f | %+.2f | %.2f | %.2f | %.0f / %.1f (%.1f "
        "x) "
        "|\n",
        a.branches, a.ends, 100.0 * a.maxDiameterError,
        a.widestAbscissaMm - truth.maxDiameterAbscissaMm, 100.0 * a.worstAxisDistancePerR,
        100.0 * a.worstWallDistancePerR, 100.0 * a.trunkLengthError, a.angleErrorDeg,
        analysed.centrelineSeconds, analysed.sectionSeconds, peak, meshMiB(truth.mesh),
        peak / meshMiB(truth.mesh));
}

void aneurysmTable(const std::vector<std::size_t>& densities) {
    std::printf(
        "\n| aneurysm | triangles | jitter | branches / ends | max. equiv. diameter error (%%) "
        "| widest at, off the truth (mm) | axis distance (%% r) | the wall's own distance from the "
        "true wall (%% r) | trunk length error (%%) | "
        "angle error (deg) | centrelines (s) | sections (s) | peak memory above the mesh / "
        "mesh (MiB) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::size_t triangles : densities) {
        for (const bool open : {false, true}) {
            for (const double jitter : {0.0, 0.02}) {
                vv::demo::AneurysmPhantomOptions o;
                o.targetTriangles = std::max<std::size_t>(triangles, 1000);
                o.openEnds = open;
                o.jitterFraction = jitter;
                const auto truth = vv::demo::makeAneurysmPhantom(o);
                std::printf("| %s | %zu | %g %% | ", open ? "open ends" : "closed",
                            truth.mesh.triangleCount(), jitter * 100.0);
                try {
                    aneurysmRow(truth);
                } catch (const vv::Error& e) {
                    std::printf("the analysis failed: %s |\n", e.what());
                }
                std::fflush(stdout);
            }
        }
    }
}

void printAgreement(const vv::bench::ConstructionAgreement& a) {
    std::printf("%zu / %zu | %zu | %zu | %zu / %zu | %.1f / %.1f | %.1f | %+.1f / %.1f", a.segments,
                a.leaves, a.leavesFound, a.endsElsewhere, a.sectionsOk, a.sectionsAll,
                100.0 * a.offAxisMedian, 100.0 * a.offAxisP95, 100.0 * a.centroidOffAxisMedian,
                100.0 * a.diameterErrorMedian, 100.0 * a.diameterErrorP95);
}

/// The demo tree's row and stages; then, when `withDecimated`, the tree
/// decimated as a coarse segmentation comes.
void demoTree(bool withDecimated = true) {
    const vv::demo::DemoTreeOptions options;
    const vv::demo::VesselTree truth = vv::demo::generateVesselTree(options);
    const auto mesh = vv::demo::buildVesselSurface(truth, options);
    StageClock clock(residentBaseKiB());
    const Analysed analysed = analyse(mesh, &clock);
    double peakMiB = 0.0;  // the stages' peaks: the clock resets the kernel's at each
    for (const auto& stage : clock.stages()) {
        peakMiB = std::max(peakMiB, stage.peakMiB);
    }
    std::printf(
        "| demo tree | triangles | segments / leaves built | leaves found | other ends | "
        "sections (ok / all) | off the built axis, median / 95 %% (%% r) | lumen centroid "
        "off the built axis, median (%% r) | equiv. "
        "diameter against the built, median / 95 %% of its size (%%) | centrelines (s) | "
        "sections (s) | peak memory above the mesh (MiB) | mesh (MiB) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::printf("| default | %zu | ", mesh.triangleCount());
    printAgreement(vv::bench::compareWithConstruction(truth, analysed.tree, analysed.sections));
    std::printf(" | %.2f | %.2f | %.0f | %.1f |\n", analysed.centrelineSeconds,
                analysed.sectionSeconds, peakMiB, meshMiB(mesh));
    for (const auto& note : analysed.tree.notes) {
        std::printf("\nnote: %s\n", note.c_str());
    }
    std::printf(
        "\n| stage (as the progress names it) | seconds | peak memory above the mesh (MiB) "
        "|\n|---|---|---|\n");
    for (const auto& stage : clock.stages()) {
        std::printf("| %s | %.2f | %.0f |\n", stage.name.c_str(), stage.seconds, stage.peakMiB);
    }
    if (!withDecimated) {
        return;
    }
    // The same tree as a coarse segmentation comes: decimated (quadric edge
    // collapse) to 60k, 20k and 8k triangles.
    std::printf(
        "\n| demo tree, decimated | triangles | segments / leaves built | leaves found | other "
        "ends | sections (ok / all) | off the built axis, median / 95 %% (%% r) | lumen "
        "centroid off the built axis, median (%% r) | equiv. diameter against the built, median "
        "/ 95 %% of its size (%%) | centrelines (s) | sections (s) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const std::size_t triangles : {60'000U, 20'000U, 8'000U}) {
        const auto coarse = vv::meshio::simplifiedMesh(mesh, triangles);
        std::printf("| to %zu | %zu | ", triangles, coarse.triangleCount());
        try {
            const Analysed decimated = analyse(coarse);
            printAgreement(
                vv::bench::compareWithConstruction(truth, decimated.tree, decimated.sections));
            std::printf(" | %.2f | %.2f |\n", decimated.centrelineSeconds,
                        decimated.sectionSeconds);
        } catch (const vv::Error& e) {
            std::printf("the analysis failed: %s |\n", e.what());
        }
        std::fflush(stdout);
    }
}

/// The synthetic CTA (the demo tree voxelised, vv/demo/DemoCtSeries.h)
/// written as a CT series, segmented as `vesselview-cli render` segments it,
/// analysed, and compared with the tree it was made from.
void ctaTable() {
    std::printf(
        "\n| synthetic CTA | voxels | voxel (mm) | triangles | segments / leaves built | "
        "leaves found | other ends | sections (ok / all) | off the built axis, median / 95 "
        "%% (%% r) | lumen centroid off the built axis, median (%% r) | equiv. diameter against "
        "the built, median / 95 %% of its size (%%) | "
        "segmentation (s) | centrelines (s) | sections (s) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    struct Row {
        int generations;
        glm::ivec3 dims;
    };
    const std::array<Row, 4> rows{
        {{3, {64, 64, 64}}, {4, {96, 96, 80}}, {4, {192, 192, 160}}, {5, {192, 192, 160}}}};
    const auto folder = std::filesystem::temp_directory_path() / "vv_analysis_accuracy_cta";
    for (const Row& row : rows) {
        vv::demo::DemoCtOptions options;
        options.generations = row.generations;
        options.dims = row.dims;
        const vv::demo::DemoCt ct = vv::demo::generateDemoCt(options);
        std::filesystem::remove_all(folder);
        const auto start = Clock::now();
        const auto mesh = vv::bench::segmentAsRenderDoes(ct, folder);
        const double segmentationSeconds = secondsSince(start);
        std::filesystem::remove_all(folder);
        const Analysed analysed = analyse(mesh);
        const glm::dvec3 spacing = ct.volume.spacing();
        const double voxel = std::max({spacing.x, spacing.y, spacing.z});
        std::printf("| %d generations | %d x %d x %d | %.2f x %.2f x %.2f | %zu | ",
                    row.generations, row.dims.x, row.dims.y, row.dims.z, spacing.x, spacing.y,
                    spacing.z, mesh.triangleCount());
        printAgreement(
            vv::bench::compareWithConstruction(ct.tree, analysed.tree, analysed.sections, voxel));
        std::printf(" | %.2f | %.2f | %.2f |\n", segmentationSeconds, analysed.centrelineSeconds,
                    analysed.sectionSeconds);
        std::fflush(stdout);
    }
}

}  // namespace

/// The diagram step alone on the demo tree (and its 1M-triangle aneurysm
/// phantom): in one slab against the default slabs (one per core), taken in
/// turn `rounds` times; the median and the fastest time. (The peak memory is
/// --demo's: within one process the second run reuses the first's pages.)
void slabTable(int rounds) {
    namespace detail = vv::analysis::detail;
    const vv::demo::DemoTreeOptions treeOptions;
    vv::demo::AneurysmPhantomOptions aneurysmOptions;
    aneurysmOptions.targetTriangles = 1'000'000;
    aneurysmOptions.jitterFraction = 0.02;  // rough: every point is kept
    const std::vector<std::pair<std::string, vv::scene::Mesh>> meshes{
        {"demo tree",
         vv::demo::buildVesselSurface(vv::demo::generateVesselTree(treeOptions), treeOptions)},
        {"aneurysm, closed, 2 % jitter", vv::demo::makeAneurysmPhantom(aneurysmOptions).mesh}};
    std::printf(
        "| surface | triangles | points | slabs | margins | points tetrahedralised | "
        "seconds, median / fastest | peak resident above the start, median (MiB) | "
        "diagram vertices |\n|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& [name, mesh] : meshes) {
        const detail::PreparedSurface s =
            detail::prepareSurface(mesh, std::nullopt, {}, vv::analysis::kDefaultMaxTriangles);
        const detail::VoronoiSamples samples = detail::chooseVoronoiSamples(s, {});
        detail::SlabPolicy whole;
        whole.splitFrom = SIZE_MAX;
        detail::SlabPolicy perCut;
        perCut.marginColumns = 1;
        const std::array<std::pair<const char*, detail::SlabPolicy>, 3> policies{
            {{"-", whole}, {"one per cut", perCut}, {"per column", detail::SlabPolicy{}}}};
        std::array<std::vector<double>, 3> seconds;
        std::array<std::vector<double>, 3> peaks;
        std::array<int, 3> slabs{};
        std::array<std::size_t, 3> taken{};
        std::size_t vertices = 0;
        for (int round = 0; round < rounds; ++round) {
            for (std::size_t p = 0; p < policies.size(); ++p) {
                const auto base = residentBaseKiB();
                const auto start = Clock::now();
                const detail::VoronoiGraph g =
                    detail::buildVoronoiGraph(s, samples, {}, policies[p].second);
                seconds[p].push_back(std::chrono::duration<double>(Clock::now() - start).count());
                peaks[p].push_back(peakAboveMiB(base));
                slabs[p] = g.slabs;
                taken[p] = g.tetrahedralisedPoints;
                vertices = g.size();
            }
        }
        for (std::size_t p = 0; p < policies.size(); ++p) {
            std::ranges::sort(seconds[p]);
            std::ranges::sort(peaks[p]);
            std::printf("| %s | %zu | %zu | %d | %s | %zu | %.2f / %.2f | %.0f | %zu |\n",
                        name.c_str(), mesh.triangleCount(),
                        samples.kept.size() + samples.addedPositions.size(), slabs[p],
                        policies[p].first, taken[p], seconds[p][seconds[p].size() / 2],
                        seconds[p].front(), peaks[p][peaks[p].size() / 2], vertices);
        }
        std::fflush(stdout);
    }
}

int main(int argc, char** argv) {
    const auto mode = [&](const char* name) { return argc > 1 && std::strcmp(argv[1], name) == 0; };
    const auto flag = [&](const char* name) {
        return std::any_of(argv + 1, argv + argc,
                           [name](const char* arg) { return std::strcmp(arg, name) == 0; });
    };
    // The memory the CLI's `centerline` reads (it asks the same), unless the
    // C library's defaults are asked for.
    if (!flag("--glibc-default") && !vv::handFreedMemoryBackAtOnce()) {
        std::printf("(the C library does not hand freed memory back at once here)\n");
    }
    std::vector<std::size_t> densities{1'000, 50'000};
    if (!mode("--quick")) {
        densities.push_back(1'000'000);
    }
    if (mode("--aneurysm")) {
        aneurysmTable(densities);
        return 0;
    }
    if (mode("--huge")) {
        hugeTable();
        return 0;
    }
    if (mode("--slabs")) {
        slabTable(argc > 2 ? std::max(1, std::atoi(argv[2])) : 5);
        return 0;
    }
    if (mode("--tubes")) {  // the tube table at one density: --tubes [TRIANGLES]
        tubeTable({argc > 2 ? static_cast<std::size_t>(std::atol(argv[2])) : 1'000'000});
        return 0;
    }
    if (mode("--cta")) {
        ctaTable();
        return 0;
    }
    if (mode("--demo")) {  // --demo [whole] [--on-a-thread]
        const bool whole = argc > 2 && std::strcmp(argv[2], "whole") == 0;
        if (flag("--on-a-thread")) {  // as the GUI runs it: from a worker thread, the main one
                                      // waiting
            std::thread worker([whole] { demoTree(!whole); });
            worker.join();
        } else {
            demoTree(!whole);
        }
        return 0;
    }
    demoTree();
    std::printf("\n");
    tubeTable(densities);
    bifurcationTable(densities);
    aneurysmTable(densities);
    ctaTable();
    return 0;
}
// NOLINTEND(cppcoreguidelines-pro-type-vararg)
