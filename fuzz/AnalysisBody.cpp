// SPDX-License-Identifier: GPL-3.0-or-later
// The analysis target's body (FuzzBodies.h, feedAnalysis): separate because
// it needs vv::analysis (CGAL, OpenCV); the other bodies need only the
// readers. The bytes become a surface (a file through vv::meshio::loadMesh,
// or the compact mesh of encodeAnalysisInput), which goes through every
// analysis step the application runs; their results are checked against the
// invariants the headers document, and a broken one aborts.
#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <stop_token>
#include <string>
#include <utility>

#include "FuzzBodies.h"
#include "vv/analysis/Bifurcations.h"
#include "vv/analysis/Centerlines.h"
#include "vv/analysis/Sections.h"
#include "vv/analysis/Stenosis.h"
#include "vv/analysis/SurfaceBranches.h"
#include "vv/core/Error.h"
#include "vv/core/Progress.h"
#include "vv/meshio/MeshLoader.h"
#include "vv/scene/Mesh.h"

namespace vv::fuzz {
namespace {

using analysis::Branch;
using analysis::CenterlineTree;
using analysis::CrossSection;
using Sections = std::vector<std::vector<CrossSection>>;

/// What the compact mesh's name and messages call it; no file is written.
const std::filesystem::path kCompactLabel = "/dev/shm/vv-fuzz/input.mesh";

constexpr std::uint8_t kSourceBit = 0x08U;
constexpr std::uint8_t kTargetBit = 0x10U;
constexpr std::uint8_t kStepBits = 0x07U;

/// A broken invariant: reported and aborted, so that libFuzzer keeps the input.
[[noreturn]] void violated(const std::string& what) {
    std::cerr << "vv::fuzz::feedAnalysis: invariant broken: " << what << "\n";
    std::abort();
}

void require(bool holds, const char* what, std::size_t branch = 0, std::size_t index = 0) {
    if (!holds) {
        violated(std::string(what) + " (branch " + std::to_string(branch) + ", index " +
                 std::to_string(index) + ")");
    }
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finiteAtLeastZero(double value) {
    return std::isfinite(value) && value >= 0.0;
}

bool unit(const glm::dvec3& v) {
    return finite(v) && std::abs(glm::length(v) - 1.0) < 1e-6;
}

/// Little-endian reads; past the end they give 0.
class Reader {
  public:
    explicit Reader(Bytes bytes) : bytes_(bytes) {}
    [[nodiscard]] std::size_t left() const noexcept { return bytes_.size() - at_; }
    std::uint32_t next(std::size_t width) {
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < width && at_ < bytes_.size(); ++i, ++at_) {
            value |= static_cast<std::uint32_t>(bytes_[at_]) << (8U * i);
        }
        return value;
    }
    float f32() { return std::bit_cast<float>(next(4)); }
    std::array<float, 3> point() { return {f32(), f32(), f32()}; }

  private:
    Bytes bytes_;
    std::size_t at_ = 0;
};

glm::dvec3 toPoint(const std::array<float, 3>& p) {
    return {p[0], p[1], p[2]};
}

/// The compact mesh (FuzzBodies.h, AnalysisInput) and its options.
std::pair<scene::Mesh, analysis::CenterlineOptions> decodeCompact(Bytes bytes) {
    Reader in(bytes);
    static_cast<void>(in.next(1));
    const auto options = static_cast<std::uint8_t>(in.next(1));
    std::size_t vertices = in.next(2);
    std::size_t triangles = in.next(2);
    analysis::CenterlineOptions centerline;
    centerline.stepMm = kAnalysisSteps[options & kStepBits];
    if ((options & kSourceBit) != 0) {
        centerline.source = toPoint(in.point());
    }
    if ((options & kTargetBit) != 0) {
        centerline.targets.push_back(toPoint(in.point()));
    }
    vertices = std::min({vertices, kAnalysisMaxVertices, in.left() / 12});
    scene::Mesh mesh;
    mesh.name = "input";
    mesh.source = kCompactLabel;
    mesh.positions.reserve(vertices);
    for (std::size_t v = 0; v < vertices; ++v) {
        const auto [x, y, z] = in.point();
        mesh.positions.emplace_back(x, y, z);
    }
    triangles = std::min({triangles, kAnalysisMaxTriangles, in.left() / 6});
    mesh.indices.reserve(3 * triangles);
    for (std::size_t i = 0; i < 3 * triangles; ++i) {
        mesh.indices.push_back(in.next(2));
    }
    return {std::move(mesh), std::move(centerline)};
}

void checkTree(const CenterlineTree& tree) {
    require(!tree.branches.empty(), "a tree without branches");
    require(tree.ends.size() >= 2, "a tree with fewer than two ends");
    for (std::size_t b = 0; b < tree.branches.size(); ++b) {
        const Branch& branch = tree.branches[b];
        require(branch.id == static_cast<int>(b), "a branch id is not its index", b);
        require(b == 0 ? branch.parent == -1 : branch.parent >= 0 && branch.parent < branch.id,
                "a parent after its child (or none)", b);
        for (const int child : branch.children) {
            require(child > branch.id && static_cast<std::size_t>(child) < tree.branches.size() &&
                        tree.branches[static_cast<std::size_t>(child)].parent == branch.id,
                    "a child out of range or not pointing back", b);
        }
        require(branch.endIndex >= -1 && branch.endIndex < static_cast<int>(tree.ends.size()),
                "an end index out of range", b);
        require(branch.points.size() >= 2, "a branch of fewer than two points", b);
        require(finiteAtLeastZero(branch.lengthMm) && finiteAtLeastZero(branch.chordMm),
                "a branch length or chord not finite and >= 0", b);
        for (std::size_t i = 0; i < branch.points.size(); ++i) {
            const analysis::CenterlinePoint& p = branch.points[i];
            require(finite(p.position), "a centreline point not finite", b, i);
            require(finiteAtLeastZero(p.radiusMm), "a radius not finite and >= 0", b, i);
            require(std::isfinite(p.abscissaMm), "an abscissa not finite", b, i);
            require(i == 0 || p.abscissaMm >= branch.points[i - 1].abscissaMm,
                    "the abscissae go back", b, i);
            require(unit(p.tangent), "a tangent not a unit vector", b, i);
            require(unit(p.normal), "a normal not a unit vector", b, i);
            require(finiteAtLeastZero(p.curvature) && std::isfinite(p.torsion),
                    "a curvature not finite and >= 0, or a torsion not finite", b, i);
        }
    }
}

void checkSections(const CenterlineTree& tree, const Sections& sections) {
    require(sections.size() == tree.branches.size(), "not one section list per branch");
    for (std::size_t b = 0; b < sections.size(); ++b) {
        require(sections[b].size() == tree.branches[b].points.size(),
                "not one section per centreline point", b);
        for (std::size_t i = 0; i < sections[b].size(); ++i) {
            const CrossSection& s = sections[b][i];
            require(s.branch == static_cast<int>(b) && s.pointIndex == i,
                    "a section names another point", b, i);
            require(finiteAtLeastZero(s.inscribedDiameterMm), "an inscribed diameter", b, i);
            if (s.status != CrossSection::Status::Ok) {
                continue;
            }
            require(s.contour.size() >= 3, "a measured section without a contour", b, i);
            require(finiteAtLeastZero(s.areaMm2) && finiteAtLeastZero(s.perimeterMm) &&
                        finiteAtLeastZero(s.equivalentDiameterMm) &&
                        finiteAtLeastZero(s.circularity) && finiteAtLeastZero(s.centreOffsetMm),
                    "a section size not finite and >= 0", b, i);
            require(finiteAtLeastZero(s.minDiameterMm) && finiteAtLeastZero(s.maxDiameterMm) &&
                        s.minDiameterMm <= s.maxDiameterMm * (1.0 + 1e-6) + 1e-9,
                    "the Feret diameters not finite, >= 0 and in order", b, i);
        }
    }
}

bool angle(double degrees) {
    return std::isfinite(degrees) && degrees >= 0.0 && degrees <= 180.0;
}

void checkBifurcations(const CenterlineTree& tree,
                       const std::vector<analysis::Bifurcation>& bifurcations) {
    for (const analysis::Bifurcation& f : bifurcations) {
        const auto parent = static_cast<std::size_t>(f.parent);
        require(f.parent >= 0 && parent < tree.branches.size() && f.children.size() >= 2 &&
                    f.childDirections.size() == f.children.size() &&
                    f.deviationDeg.size() == f.children.size(),
                "a bifurcation's parent or children", parent);
        require(angle(f.angleDeg), "a bifurcation angle outside [0, 180]", parent);
        for (std::size_t c = 0; c < f.children.size(); ++c) {
            require(angle(f.deviationDeg[c]) && finite(f.childDirections[c]),
                    "a child's deviation or direction", parent, c);
        }
    }
}

void checkStenosis(const std::optional<analysis::Stenosis>& grade, std::size_t branch) {
    if (!grade) {
        return;
    }
    require(grade->branch == static_cast<int>(branch), "a grade of another branch", branch);
    require(finiteAtLeastZero(grade->minimumDiameterMm) &&
                finiteAtLeastZero(grade->minimumAreaMm2) && grade->referenceDiameterMm > 0.0 &&
                std::isfinite(grade->referenceDiameterMm) && grade->referenceAreaMm2 > 0.0 &&
                std::isfinite(grade->referenceAreaMm2),
            "a stenosis' sizes not finite and >= 0", branch);
    require(std::isfinite(grade->diameterPercent) && grade->diameterPercent <= 100.0 &&
                std::isfinite(grade->areaPercent) && grade->areaPercent <= 100.0,
            "a stenosis percentage not finite and <= 100", branch);
}

/// The steps after the centrelines and the sections: their arguments are in
/// range, so they must not throw.
void gradeAndLabel(const scene::Mesh& mesh, const CenterlineTree& tree, const Sections& sections) {
    try {
        checkBifurcations(tree, analysis::findBifurcations(tree));
        for (std::size_t b = 0; b < tree.branches.size(); ++b) {
            const Branch& branch = tree.branches[b];
            const int id = static_cast<int>(b);
            analysis::StenosisReference given;
            given.kind = analysis::StenosisReference::Kind::Given;
            given.proximalMm = branch.points.front().abscissaMm;
            given.distalMm = branch.points.back().abscissaMm;
            analysis::StenosisReference nascet;
            nascet.kind = analysis::StenosisReference::Kind::Nascet;
            nascet.distalMm = branch.points[branch.points.size() / 2].abscissaMm;
            for (const analysis::StenosisReference& reference :
                 {analysis::StenosisReference{}, given, nascet}) {
                checkStenosis(analysis::gradeStenosis(tree, sections, id, reference), b);
            }
        }
        const std::vector<std::int32_t> ids = analysis::surfaceBranchIds(mesh, tree);
        require(ids.size() == mesh.positions.size(), "not one branch id per vertex");
        for (std::size_t v = 0; v < ids.size(); ++v) {
            require(ids[v] >= -1 && ids[v] < static_cast<std::int32_t>(tree.branches.size()),
                    "a branch id out of range", 0, v);
        }
    } catch (const vv::Error& e) {
        violated(std::string("a step with arguments in range threw: ") + e.what());
    }
}

/// Stops the analysis at its next progress report after the budget.
class Budget {
  public:
    Budget() : deadline_(std::chrono::steady_clock::now() + kBudget) {}
    [[nodiscard]] Progress progress() {
        return {[this](double /*fraction*/, std::string_view /*stage*/) {
                    if (std::chrono::steady_clock::now() > deadline_) {
                        stop_.request_stop();
                    }
                },
                stop_.get_token()};
    }

  private:
    static constexpr auto kBudget = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(kAnalysisBudgetSeconds));
    std::chrono::steady_clock::time_point deadline_;
    std::stop_source stop_;
};

/// Every step, as the application runs them; a vv::Error from the
/// centrelines or the sections is the outcome's error.
Outcome analyse(const scene::Mesh& mesh, const analysis::CenterlineOptions& options) {
    Outcome outcome;
    outcome.file = mesh.source;
    Budget budget;
    const Progress progress = budget.progress();
    try {
        // The application's path: one preparation for both (analyseVessels).
        const analysis::VesselAnalysis analysed = analysis::analyseVessels(mesh, options, progress);
        const CenterlineTree& tree = analysed.tree;
        checkTree(tree);
        const Sections& sections = analysed.sections;
        checkSections(tree, sections);
        gradeAndLabel(mesh, tree, sections);
        outcome.loaded = true;
    } catch (const CancelledError&) {
        outcome.error = mesh.source.string() + ": the analysis ran over the fuzz budget of " +
                        std::to_string(kAnalysisBudgetSeconds) + " s and was stopped";
    } catch (const vv::Error& e) {
        outcome.error = e.what();
    }
    return outcome;
}

void put(std::vector<std::uint8_t>& out, std::uint32_t value, std::size_t width) {
    for (std::size_t i = 0; i < width; ++i) {
        out.push_back(static_cast<std::uint8_t>(value >> (8U * i)));
    }
}

void putPoint(std::vector<std::uint8_t>& out, const std::array<float, 3>& p) {
    for (const float value : p) {
        put(out, std::bit_cast<std::uint32_t>(value), 4);
    }
}

}  // namespace

Outcome feedAnalysis(Bytes bytes) {
    if (!bytes.empty() && (bytes[0] == 'S' || bytes[0] == 'P')) {
        const std::filesystem::path file =
            writeScratch(bytes[0] == 'S' ? "input.stl" : "input.ply", bytes.subspan(1));
        scene::Mesh mesh;
        try {
            mesh = meshio::loadMesh(file);
        } catch (const vv::Error& e) {
            return {.loaded = false, .error = e.what(), .file = file};
        }
        if (mesh.triangleCount() > kAnalysisMaxTriangles) {
            return {.loaded = true, .error = {}, .file = file};  // loaded, too large to analyse
        }
        return analyse(mesh, {});
    }
    const auto [mesh, options] = decodeCompact(bytes);
    return analyse(mesh, options);
}

std::vector<std::uint8_t> encodeAnalysisInput(const scene::Mesh& mesh, const AnalysisInput& input) {
    if (mesh.positions.size() > kAnalysisMaxVertices ||
        mesh.triangleCount() > kAnalysisMaxTriangles || input.step >= kAnalysisSteps.size()) {
        throw InvalidArgumentError("encodeAnalysisInput: " + std::to_string(mesh.positions.size()) +
                                   " vertices, " + std::to_string(mesh.triangleCount()) +
                                   " triangles or step " + std::to_string(input.step) +
                                   " above the analysis target's limits");
    }
    std::vector<std::uint8_t> out{'M'};
    out.push_back(static_cast<std::uint8_t>(input.step | (input.source ? kSourceBit : 0U) |
                                            (input.target ? kTargetBit : 0U)));
    put(out, static_cast<std::uint32_t>(mesh.positions.size()), 2);
    put(out, static_cast<std::uint32_t>(mesh.triangleCount()), 2);
    for (const auto& point : {input.source, input.target}) {
        if (point) {
            putPoint(out, *point);
        }
    }
    for (const glm::vec3& p : mesh.positions) {
        putPoint(out, {p.x, p.y, p.z});
    }
    for (std::size_t i = 0; i < 3 * mesh.triangleCount(); ++i) {
        put(out, mesh.indices[i], 2);
    }
    return out;
}

}  // namespace vv::fuzz
