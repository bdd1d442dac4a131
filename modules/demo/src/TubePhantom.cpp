// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/demo/TubePhantom.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <tuple>

#include "PhantomJitter.h"
#include "vv/core/Error.h"

namespace vv::demo {
namespace {

constexpr double kPi = std::numbers::pi;

void require(bool ok, const std::string& what) {
    if (!ok) {
        throw InvalidArgumentError("tube phantom: " + what);
    }
}

void validate(const TubePhantomOptions& o) {
    require(std::isfinite(o.radiusMm) && o.radiusMm > 0.0, "radius must be positive");
    require(o.targetTriangles >= 200 && o.targetTriangles <= 20'000'000,
            "target triangles must be in 200..20000000");
    require(std::isfinite(o.jitterFraction) && o.jitterFraction >= 0.0 && o.jitterFraction <= 0.2,
            "jitter must be in [0, 0.2] of the radius");
    if (o.shape == TubeShape::TorusSegment) {
        require(std::isfinite(o.bendRadiusMm) && o.bendRadiusMm > o.radiusMm,
                "bend radius must exceed the tube's radius");
        require(std::isfinite(o.bendAngleDeg) && o.bendAngleDeg > 0.0 && o.bendAngleDeg <= 300.0,
                "bend angle must be in (0, 300] degrees");
    } else {
        require(std::isfinite(o.lengthMm) && o.lengthMm > 2.0 * o.radiusMm,
                "length must exceed the diameter");
    }
    if (o.shape == TubeShape::Stenosis) {
        require(
            std::isfinite(o.stenosisPercent) && o.stenosisPercent > 0.0 && o.stenosisPercent < 95.0,
            "stenosis must be in (0, 95) percent");
        require(std::isfinite(o.stenosisLengthMm) && o.stenosisLengthMm > 0.0 &&
                    o.stenosisLengthMm <= o.lengthMm / 2.0,
                "stenosis length must be in (0, length / 2]");
    }
}

double axisLength(const TubePhantomOptions& o) {
    return o.shape == TubeShape::TorusSegment ? o.bendRadiusMm * o.bendAngleDeg * kPi / 180.0
                                              : o.lengthMm;
}

double radiusAt(const TubePhantomOptions& o, double s) {
    if (o.shape != TubeShape::Stenosis) {
        return o.radiusMm;
    }
    const double offset = s - o.lengthMm / 2.0;
    if (std::abs(offset) >= o.stenosisLengthMm / 2.0) {
        return o.radiusMm;
    }
    const double shape = 0.5 * (1.0 + std::cos(2.0 * kPi * offset / o.stenosisLengthMm));
    return o.radiusMm * (1.0 - o.stenosisPercent / 100.0 * shape);
}

/// The axis at `s` with a rotation-minimising frame (n1, n2), n1 x n2 = tangent.
struct AxisFrame {
    AxisSample sample;
    glm::dvec3 n1{1.0, 0.0, 0.0};
    glm::dvec3 n2{0.0, 1.0, 0.0};
};

AxisFrame frameAt(const TubePhantomOptions& o, double s) {
    AxisFrame f;
    f.sample.abscissaMm = s;
    f.sample.radiusMm = radiusAt(o, s);
    if (o.shape == TubeShape::TorusSegment) {
        const double bend = o.bendRadiusMm;
        const double theta = s / bend;
        f.sample.position = {bend - bend * std::cos(theta), 0.0, bend * std::sin(theta)};
        f.sample.tangent = {std::sin(theta), 0.0, std::cos(theta)};
        f.sample.curvature = 1.0 / bend;
        f.n1 = {std::cos(theta), 0.0, -std::sin(theta)};
    } else {
        f.sample.position = {0.0, 0.0, s};
    }
    return f;
}

/// Rings x sides for about `target` triangles with near-square quads.
std::pair<int, int> ringsAndSides(const TubePhantomOptions& o, double length) {
    const auto target = static_cast<double>(o.targetTriangles);
    const int sides =
        std::max(8, static_cast<int>(std::lround(std::sqrt(target * kPi * o.radiusMm / length))));
    const int rings = std::max(3, static_cast<int>(std::lround(target / (2.0 * sides))) + 1);
    return {rings, sides};
}

const char* shapeName(TubeShape shape) {
    switch (shape) {
        case TubeShape::Cylinder:
            return "cylinder phantom";
        case TubeShape::TorusSegment:
            return "torus segment phantom";
        case TubeShape::Stenosis:
            return "stenosis phantom";
    }
    return "tube phantom";
}

scene::Mesh tubeMesh(const TubePhantomOptions& o, double length) {
    const auto [rings, sidesFound] = ringsAndSides(o, length);
    const int sides = sidesFound;  // a plain variable: lambdas capture it
    detail::PhantomJitter jitter(o.seed, o.jitterFraction * o.radiusMm);
    scene::Mesh mesh;
    mesh.name = shapeName(o.shape);
    auto add = [&](const glm::dvec3& p) {
        mesh.positions.emplace_back(p + jitter.next());
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };
    for (int i = 0; i < rings; ++i) {
        const double s = length * i / (rings - 1);
        const AxisFrame f = frameAt(o, s);
        for (int j = 0; j < sides; ++j) {
            const double phi = 2.0 * kPi * j / sides;
            add(f.sample.position +
                f.sample.radiusMm * (std::cos(phi) * f.n1 + std::sin(phi) * f.n2));
        }
    }
    const auto at = [sides](int ring, int side) {
        return static_cast<std::uint32_t>(ring * sides + (side % sides));
    };
    for (int i = 0; i + 1 < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    if (o.capped) {
        const std::uint32_t start = add(frameAt(o, 0.0).sample.position);
        const std::uint32_t end = add(frameAt(o, length).sample.position);
        for (int j = 0; j < sides; ++j) {
            mesh.indices.insert(mesh.indices.end(), {start, at(0, j + 1), at(0, j)});
            mesh.indices.insert(mesh.indices.end(), {end, at(rings - 1, j), at(rings - 1, j + 1)});
        }
    }
    scene::computeNormals(mesh);
    return mesh;
}

}  // namespace

AxisSample TubePhantom::axisAt(double s) const {
    return frameAt(options, std::clamp(s, 0.0, lengthMm)).sample;
}

std::pair<double, double> TubePhantom::distanceToAxis(const glm::dvec3& point) const {
    double s = 0.0;
    if (options.shape == TubeShape::TorusSegment) {
        // The bend's centre is (R, 0, 0); the axis point at angle theta is
        // centre + R (-cos theta, 0, sin theta).
        const double bend = options.bendRadiusMm;
        double theta = std::atan2(point.z, bend - point.x);
        const double gap = 2.0 * kPi - lengthMm / bend;  // the angles the arc leaves out
        if (theta < -gap / 2.0) {
            theta += 2.0 * kPi;
        }
        s = theta * bend;
    } else {
        s = point.z;
    }
    s = std::clamp(s, 0.0, lengthMm);
    return {glm::length(point - axisAt(s).position), s};
}

TubePhantom makeTubePhantom(const TubePhantomOptions& options) {
    validate(options);
    TubePhantom phantom;
    phantom.options = options;
    phantom.lengthMm = axisLength(options);
    const int samples = static_cast<int>(std::ceil(phantom.lengthMm / 0.1)) + 1;
    phantom.axis.reserve(static_cast<std::size_t>(samples));
    for (int i = 0; i < samples; ++i) {
        phantom.axis.push_back(phantom.axisAt(phantom.lengthMm * i / (samples - 1)));
    }
    phantom.chordMm = glm::length(phantom.axis.back().position - phantom.axis.front().position);
    phantom.narrowestAbscissaMm = phantom.lengthMm / 2.0;
    phantom.narrowestRadiusMm = radiusAt(options, phantom.narrowestAbscissaMm);
    phantom.mesh = tubeMesh(options, phantom.lengthMm);
    std::tie(phantom.rings, phantom.sides) = ringsAndSides(options, phantom.lengthMm);
    return phantom;
}

}  // namespace vv::demo
