// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/demo/AneurysmPhantom.h"

#include <vtkClipPolyData.h>
#include <vtkPlane.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "FieldSurface.h"
#include "PhantomJitter.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"
#include "vv/meshio/MeshSimplify.h"

namespace vv::demo {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTrianglesPerVoxelArea = 2.9;   // flying edges: per h^2 of surface (DemoSurface)
constexpr double kBlendPerRadius = 0.6;          // smooth-union width / the branch's radius
constexpr double kOpenExtensionPerRadius = 2.0;  // an open end's tube runs on past its cut

void require(bool ok, const std::string& what) {
    if (!ok) {
        throw InvalidArgumentError("aneurysm phantom: " + what);
    }
}

bool finite(double v) {
    return std::isfinite(v);
}

void validate(const AneurysmPhantomOptions& o) {
    require(finite(o.radiusMm) && o.radiusMm > 0.0, "radius must be positive");
    require(
        finite(o.maxRadiusMm) && o.maxRadiusMm > o.radiusMm && o.maxRadiusMm <= 4.0 * o.radiusMm,
        "maximum radius must be in (radius, 4 radius]");
    const double shortest = kPi * std::sqrt(2.0 * (o.maxRadiusMm - o.radiusMm) * o.maxRadiusMm);
    require(
        finite(o.bulgeLengthMm) && o.bulgeLengthMm >= shortest,
        "bulge length must be at least pi sqrt(2 (R - r) R) = " + std::to_string(shortest) + " mm");
    require(finite(o.trunkLengthMm) && o.trunkLengthMm > 0.0, "trunk length must be positive");
    require(finite(o.bulgeCentreMm) &&
                o.bulgeCentreMm - o.bulgeLengthMm / 2.0 >= 2.0 * o.radiusMm &&
                o.bulgeCentreMm + o.bulgeLengthMm / 2.0 <= o.trunkLengthMm - 4.0 * o.radiusMm,
            "the bulge must lie 2 radii clear of the trunk's start and 4 radii clear of the "
            "bifurcation");
    require(finite(o.iliacRadiusMm) && o.iliacRadiusMm > 0.0 && o.iliacRadiusMm <= o.radiusMm,
            "iliac radius must be in (0, radius]");
    require(finite(o.bifurcationAngleDeg) && o.bifurcationAngleDeg >= 20.0 &&
                o.bifurcationAngleDeg <= 120.0,
            "bifurcation angle must be in [20, 120] degrees");
    require(finite(o.iliacLengthMm) && o.iliacLengthMm >= 4.0 * o.radiusMm,
            "iliac length must be at least 4 radii");
    require(o.targetTriangles >= 1000 && o.targetTriangles <= 5'000'000,
            "target triangles must be in 1000..5000000");
    require(finite(o.jitterFraction) && o.jitterFraction >= 0.0 && o.jitterFraction <= 0.2,
            "jitter must be in [0, 0.2] of the radius");
}

double profileRadius(const AneurysmPhantomOptions& o, double s) {
    const double offset = s - o.bulgeCentreMm;
    if (std::abs(offset) >= o.bulgeLengthMm / 2.0) {
        return o.radiusMm;
    }
    const double shape = 0.5 * (1.0 + std::cos(2.0 * kPi * offset / o.bulgeLengthMm));
    return o.radiusMm + (o.maxRadiusMm - o.radiusMm) * shape;
}

/// The field whose zero level is the surface: per part a distance-like
/// function (exact on the trunk's surface of revolution: radial distance
/// minus the profile's radius), joined by smooth unions where the parts meet.
class Field {
  public:
    explicit Field(const AneurysmPhantom& p)
        : o_(p.options),
          bifurcation_(p.bifurcationPoint),
          iliacs_(p.iliacDirections),
          extension_(o_.openEnds ? kOpenExtensionPerRadius : 0.0),
          trunkStart_(-extension_ * o_.radiusMm),
          iliacLength_(o_.iliacLengthMm + extension_ * o_.iliacRadiusMm),
          blend_(kBlendPerRadius * o_.iliacRadiusMm) {}

    /// Where the field's tubes end (past the cut for open ends).
    [[nodiscard]] double trunkStart() const { return trunkStart_; }
    [[nodiscard]] glm::dvec3 iliacEnd(int i) const {
        return bifurcation_ + iliacLength_ * iliacs_[static_cast<std::size_t>(i)];
    }

    [[nodiscard]] double at(const glm::dvec3& p) const {
        const double trunk = trunkAt(p);
        const double a = iliacAt(p, 0);
        const double b = iliacAt(p, 1);
        const auto k = static_cast<float>(blend_);
        const float joined =
            std::min({detail::smoothMin(static_cast<float>(trunk), static_cast<float>(a), k),
                      detail::smoothMin(static_cast<float>(trunk), static_cast<float>(b), k),
                      detail::smoothMin(static_cast<float>(a), static_cast<float>(b), k)});
        return static_cast<double>(joined);
    }

  private:
    [[nodiscard]] double trunkAt(const glm::dvec3& p) const {
        if (p.z < trunkStart_) {
            return glm::length(p - glm::dvec3(0.0, 0.0, trunkStart_)) - o_.radiusMm;
        }
        if (p.z > o_.trunkLengthMm) {
            return glm::length(p - bifurcation_) - o_.radiusMm;
        }
        return std::hypot(p.x, p.y) - profileRadius(o_, p.z);
    }
    [[nodiscard]] double iliacAt(const glm::dvec3& p, int i) const {
        const glm::dvec3& d = iliacs_[static_cast<std::size_t>(i)];
        const double t = std::clamp(glm::dot(p - bifurcation_, d), 0.0, iliacLength_);
        return glm::length(p - (bifurcation_ + t * d)) - o_.iliacRadiusMm;
    }

    AneurysmPhantomOptions o_;
    glm::dvec3 bifurcation_;
    std::array<glm::dvec3, 2> iliacs_;
    double extension_;
    double trunkStart_;
    double iliacLength_;
    double blend_;
};

/// Moves every vertex of `mesh` onto the field's zero level (Newton steps
/// along its gradient, by central differences) and recomputes the normals.
/// The extraction and its smoothing leave the vertices up to 0.15 voxel off
/// it (0.3 mm at 20k triangles: 5 % of an iliac's radius); on it, only the
/// facets' chords depart from the truth.
void projectOntoTheWall(scene::Mesh& mesh, const Field& field) {
    constexpr int kSteps = 4;
    constexpr double kH = 1e-3;  // mm, the differences' half-step
    for (glm::vec3& position : mesh.positions) {
        glm::dvec3 q(position);
        for (int step = 0; step < kSteps; ++step) {
            const double f = field.at(q);
            const glm::dvec3 gradient(
                field.at(q + glm::dvec3(kH, 0.0, 0.0)) - field.at(q - glm::dvec3(kH, 0.0, 0.0)),
                field.at(q + glm::dvec3(0.0, kH, 0.0)) - field.at(q - glm::dvec3(0.0, kH, 0.0)),
                field.at(q + glm::dvec3(0.0, 0.0, kH)) - field.at(q - glm::dvec3(0.0, 0.0, kH)));
            const double squared = glm::dot(gradient, gradient) / (4.0 * kH * kH);
            if (!(squared > 1e-6)) {
                break;  // a flat spot (never on a tube's wall): leave the vertex
            }
            q -= f * gradient / (2.0 * kH * squared);
        }
        position = glm::vec3(q);
    }
    scene::computeNormals(mesh);
}

/// The surface's area, roughly (for the voxel size of a triangle count).
double surfaceArea(const AneurysmPhantomOptions& o) {
    const double trunk =
        2.0 * kPi *
        (o.radiusMm * o.trunkLengthMm + (o.maxRadiusMm - o.radiusMm) * o.bulgeLengthMm / 2.0);
    const double iliacs = 2.0 * 2.0 * kPi * o.iliacRadiusMm * o.iliacLengthMm;
    const double caps =
        o.openEnds
            ? 0.0
            : 2.0 * kPi * (o.radiusMm * o.radiusMm + 2.0 * o.iliacRadiusMm * o.iliacRadiusMm);
    return trunk + iliacs + caps;
}

detail::FieldGrid gridFor(const Field& field, const AneurysmPhantom& p, double spacing) {
    const AneurysmPhantomOptions& o = p.options;
    glm::dvec3 lo(-o.maxRadiusMm, -o.maxRadiusMm, field.trunkStart() - o.radiusMm);
    glm::dvec3 hi(o.maxRadiusMm, o.maxRadiusMm, o.trunkLengthMm + o.radiusMm);
    for (int i = 0; i < 2; ++i) {
        lo = glm::min(lo, field.iliacEnd(i) - o.iliacRadiusMm);
        hi = glm::max(hi, field.iliacEnd(i) + o.iliacRadiusMm);
    }
    const double padding = (detail::kBandVoxels + 2.0) * spacing + kBlendPerRadius * o.radiusMm;
    detail::FieldGrid grid;
    grid.spacing = spacing;
    grid.origin = lo - padding;
    const glm::dvec3 size = hi - lo + 2.0 * padding;
    grid.nx = static_cast<int>(std::ceil(size.x / spacing)) + 1;
    grid.ny = static_cast<int>(std::ceil(size.y / spacing)) + 1;
    grid.nz = static_cast<int>(std::ceil(size.z / spacing)) + 1;
    return grid;
}

vtkSmartPointer<vtkPolyData> extract(const Field& field, const detail::FieldGrid& grid,
                                     const Progress& progress) {
    const auto band = static_cast<float>(detail::kBandVoxels * grid.spacing);
    const auto guard = static_cast<float>(detail::kZeroGuardVoxels * grid.spacing);
    const long nx = grid.nx;
    const long ny = grid.ny;
    const auto sample = [&](int z0, int z1, float* values) {
        const auto rows = [&](long begin, long end) {
            for (long row = begin; row < end; ++row) {
                const long y = row % ny;
                const long z = z0 + row / ny;
                float* out = values + row * nx;
                for (long x = 0; x < nx; ++x) {
                    const glm::dvec3 p =
                        grid.origin + grid.spacing * glm::dvec3(static_cast<double>(x),
                                                                static_cast<double>(y),
                                                                static_cast<double>(z));
                    out[x] =
                        detail::guardedFieldValue(static_cast<float>(field.at(p)), band, guard);
                }
            }
        };
        parallelFor(0, ny * (z1 - z0 + 1), 8, rows, progress.stopToken());
        return true;
    };
    return detail::extractZeroLevel(grid, sample, progress);
}

/// Cuts the surface open at each axis' end: keeps the side of the plane
/// through `origin` that `normal` points to.
vtkSmartPointer<vtkPolyData> cut(vtkPolyData* surface, const glm::dvec3& origin,
                                 const glm::dvec3& normal, const Progress& progress) {
    auto plane = vtkSmartPointer<vtkPlane>::New();
    plane->SetOrigin(origin.x, origin.y, origin.z);
    plane->SetNormal(normal.x, normal.y, normal.z);
    auto clip = vtkSmartPointer<vtkClipPolyData>::New();
    clip->SetInputData(surface);
    clip->SetClipFunction(plane);
    clip->SetValue(0.0);
    return detail::runFilter(clip, progress, "Opening the ends");
}

}  // namespace

double AneurysmPhantom::trunkRadiusAt(double s) const noexcept {
    return profileRadius(options, std::clamp(s, 0.0, options.trunkLengthMm));
}

AneurysmAxisPoint AneurysmPhantom::nearestAxisPoint(const glm::dvec3& point) const noexcept {
    AneurysmAxisPoint best;
    best.abscissaMm = std::clamp(point.z, 0.0, options.trunkLengthMm);
    best.position = glm::dvec3(0.0, 0.0, best.abscissaMm);
    best.distanceMm = glm::length(point - best.position);
    best.radiusMm = profileRadius(options, best.abscissaMm);
    for (int i = 0; i < 2; ++i) {
        const glm::dvec3& d = iliacDirections[static_cast<std::size_t>(i)];
        const double t =
            std::clamp(glm::dot(point - bifurcationPoint, d), 0.0, options.iliacLengthMm);
        const glm::dvec3 q = bifurcationPoint + t * d;
        const double distance = glm::length(point - q);
        if (distance < best.distanceMm) {
            best = {i == 0 ? AneurysmPart::IliacPlusX : AneurysmPart::IliacMinusX, t, q, distance,
                    options.iliacRadiusMm};
        }
    }
    return best;
}

AneurysmPhantom makeAneurysmPhantom(const AneurysmPhantomOptions& options,
                                    const Progress& progress) {
    validate(options);
    progress.throwIfCancelled();
    AneurysmPhantom phantom;
    phantom.options = options;
    phantom.bifurcationPoint = {0.0, 0.0, options.trunkLengthMm};
    const double half = options.bifurcationAngleDeg * kPi / 360.0;
    phantom.iliacDirections = {glm::dvec3(std::sin(half), 0.0, std::cos(half)),
                               glm::dvec3(-std::sin(half), 0.0, std::cos(half))};
    phantom.maxDiameterMm = 2.0 * options.maxRadiusMm;
    phantom.maxDiameterAbscissaMm = options.bulgeCentreMm;
    const Field field(phantom);

    // The voxel size for the triangle count; one more extraction corrects
    // the guess when it is more than 10 % off. A coarse phantom is a finer
    // one decimated (kFinestExtractionTriangles).
    const auto target =
        static_cast<double>(std::max(options.targetTriangles, detail::kFinestExtractionTriangles));
    double spacing = std::sqrt(kTrianglesPerVoxelArea * surfaceArea(options) / target);
    vtkSmartPointer<vtkPolyData> surface =
        extract(field, gridFor(field, phantom, spacing), progress.sub(0.0, 0.4));
    const auto got = static_cast<double>(surface->GetNumberOfPolys());
    if (std::abs(got / target - 1.0) > 0.1) {
        spacing *= std::sqrt(got / target);
        surface = extract(field, gridFor(field, phantom, spacing), progress.sub(0.4, 0.7));
    }
    phantom.voxelSizeMm = spacing;
    surface = detail::smoothSurface(surface, progress.sub(0.7, 0.85));
    if (options.openEnds) {
        const Progress opening = progress.sub(0.85, 0.9);
        surface = cut(surface, glm::dvec3(0.0), {0.0, 0.0, 1.0}, opening);
        for (const glm::dvec3& d : phantom.iliacDirections) {
            surface =
                cut(surface, phantom.bifurcationPoint + options.iliacLengthMm * d, -d, opening);
        }
    }
    phantom.mesh = detail::finishSurface(std::move(surface), progress.sub(0.9, 0.95));
    projectOntoTheWall(phantom.mesh, field);
    if (options.targetTriangles < detail::kFinestExtractionTriangles) {
        phantom.mesh =
            meshio::simplifiedMesh(phantom.mesh, options.targetTriangles, progress.sub(0.95, 1.0));
        projectOntoTheWall(phantom.mesh, field);  // decimation moves the vertices it keeps
    }
    if (options.jitterFraction > 0.0) {
        detail::PhantomJitter jitter(options.seed, options.jitterFraction * options.radiusMm);
        for (glm::vec3& p : phantom.mesh.positions) {
            p = glm::vec3(glm::dvec3(p) + jitter.next());
        }
        scene::computeNormals(phantom.mesh);
    }
    phantom.mesh.name = "aneurysm phantom";
    return phantom;
}

}  // namespace vv::demo
