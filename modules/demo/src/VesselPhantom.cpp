// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/demo/VesselPhantom.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::demo {

namespace {

constexpr const char* kStage = "Building the vessel phantom";

// Geometry, LPS mm (x to the patient's left, y posterior, z to the head).
constexpr double kBodyCentreY = 10.0;
constexpr double kBodyA = 130.0;  ///< half width (left-right)
constexpr double kBodyB = 100.0;  ///< half depth (anterior-posterior)
constexpr double kFatLayer = 12.0;
constexpr double kSpineY = 62.0;
constexpr double kSpineRadius = 15.0;
constexpr double kAortaRadius = 10.0;
constexpr double kAortaTop = 165.0;  ///< beyond the head end of the default grid
constexpr double kBifurcation = -75.0;
/// The receive array covers the body up to this height (mm) and fades beyond
/// it over about kArrayFade mm.
constexpr double kArrayEnd = 80.0;
constexpr double kArrayFade = 25.0;
/// Near the front and back of the body its surface coils see more.
constexpr double kSurfaceGain = 0.35;
/// Centre-line points per mm of a vessel.
constexpr double kSamplesPerMm = 0.5;

struct Intensities {
    double air, fat, tissue, spine, lumen, noise;
};

Intensities intensitiesOf(PhantomModality modality) {
    if (modality == PhantomModality::CT) {
        return {-1000.0, -100.0, 40.0, 1100.0, 400.0, 15.0};
    }
    return {0.0, 70.0, 100.0, 80.0, 600.0, 8.0};
}

glm::dvec3 aortaAt(double z) {
    return {6.0 + 8.0 * std::sin(z / 80.0), 22.0 - 6.0 * std::cos(z / 100.0), z};
}

/// A quadratic Bezier from `a` over `c` to `b`, about kSamplesPerMm points per mm.
std::vector<glm::dvec3> bezier(const glm::dvec3& a, const glm::dvec3& c, const glm::dvec3& b) {
    const double length = glm::length(c - a) + glm::length(b - c);
    const int n = std::max(2, static_cast<int>(std::ceil(length * kSamplesPerMm)));
    std::vector<glm::dvec3> points;
    for (int i = 0; i <= n; ++i) {
        const double t = static_cast<double>(i) / n;
        points.push_back((1 - t) * (1 - t) * a + 2 * (1 - t) * t * c + t * t * b);
    }
    return points;
}

std::vector<PhantomVessel> phantomVessels() {
    std::vector<PhantomVessel> vessels;
    PhantomVessel aorta{"aorta", {}, kAortaRadius};
    const int n = static_cast<int>(std::ceil((kAortaTop - kBifurcation) * kSamplesPerMm));
    for (int i = 0; i <= n; ++i) {
        aorta.centerline.push_back(aortaAt(kAortaTop + (kBifurcation - kAortaTop) * i / n));
    }
    vessels.push_back(aorta);
    const glm::dvec3 renal = aortaAt(45.0);
    const glm::dvec3 fork = aortaAt(kBifurcation);
    for (const double side : {1.0, -1.0}) {
        const char* which = side > 0 ? "left" : "right";
        vessels.push_back(
            {std::string(which) + " renal artery",
             bezier(renal, {renal.x + side * 35.0, 28.0, 45.0}, {side * 72.0, 34.0, 33.0}), 3.0});
        vessels.push_back(
            {std::string(which) + " iliac artery",
             bezier(fork, {fork.x + side * 20.0, 25.0, -115.0}, {side * 50.0, 15.0, -165.0}), 6.0});
    }
    return vessels;
}

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

/// Approximate signed distance to an axis-aligned ellipse in the x-y plane
/// (exact on the axes): the normalised radius minus 1, scaled by the local
/// semi-axis. Good for a one-voxel partial-volume ramp.
double ellipseDistance(double x, double y, double a, double b) {
    const double r = std::hypot(x / a, y / b);
    if (r <= 0.0) {
        return -std::min(a, b);
    }
    const double scale = std::hypot(x, y) / r;  // the ellipse's radius in this direction
    return (r - 1.0) * scale;
}

double coilSensitivity(const glm::dvec3& p) {
    const double along = 1.0 / (1.0 + std::exp((p.z - kArrayEnd) / kArrayFade));
    const double depth = (p.y - kBodyCentreY) / kBodyB;
    return along * (1.0 + kSurfaceGain * depth * depth);
}

/// A partial-volume fraction from a signed distance and the voxel size.
double fraction(double signedDistance, double h) {
    return std::clamp(0.5 - signedDistance / h, 0.0, 1.0);
}

/// Standard normal numbers from std::mt19937's raw output (Box-Muller), so
/// the noise is the same with every standard library.
class Gaussian {
  public:
    explicit Gaussian(std::uint32_t seed) : random_(seed) {}
    double next() {
        if (spare_) {
            spare_ = false;
            return other_;
        }
        constexpr double kScale = 1.0 / 4294967296.0;
        const double u1 = (static_cast<double>(random_()) + 0.5) * kScale;
        const double u2 = (static_cast<double>(random_()) + 0.5) * kScale;
        const double r = std::sqrt(-2.0 * std::log(u1));
        other_ = r * std::sin(2.0 * std::numbers::pi * u2);
        spare_ = true;
        return r * std::cos(2.0 * std::numbers::pi * u2);
    }

  private:
    std::mt19937 random_;
    double other_ = 0.0;
    bool spare_ = false;
};

}  // namespace

double VesselPhantom::signedDistance(const glm::dvec3& world) const {
    double d = std::numeric_limits<double>::max();
    for (const PhantomVessel& v : vessels) {
        for (std::size_t i = 0; i + 1 < v.centerline.size(); ++i) {
            d = std::min(
                d, distanceToSegment(world, v.centerline[i], v.centerline[i + 1]) - v.radiusMm);
        }
    }
    return d;
}

double VesselPhantom::gain(const glm::dvec3& world) const {
    if (options.modality != PhantomModality::MR || options.minGain >= 1.0) {
        return 1.0;
    }
    const double t = (coilSensitivity(world) - gainLow) / (gainHigh - gainLow);
    return std::clamp(options.minGain + (1.0 - options.minGain) * t, options.minGain, 1.0);
}

VesselPhantom generateVesselPhantom(const VesselPhantomOptions& options, const Progress& progress) {
    const glm::ivec3 dims = options.dims;
    if (glm::any(glm::lessThan(dims, glm::ivec3(8))) ||
        glm::any(glm::greaterThan(dims, glm::ivec3(2048)))) {
        throw InvalidArgumentError("vessel phantom: dimensions must be 8..2048 voxels");
    }
    const glm::dvec3 fov = options.fieldOfViewMm;
    if (!(glm::all(glm::greaterThan(fov, glm::dvec3(0.0)))) ||
        !glm::all(glm::lessThan(fov, glm::dvec3(1e4)))) {
        throw InvalidArgumentError("vessel phantom: the field of view must be within (0, 10 m)");
    }
    if (!(options.minGain > 0.0) || options.minGain > 1.0) {
        throw InvalidArgumentError("vessel phantom: the lowest gain must be within (0, 1]");
    }
    if (!std::isfinite(options.noiseSigma)) {
        throw InvalidArgumentError("vessel phantom: the noise must be finite");
    }
    progress.report(0.0, kStage);
    VesselPhantom phantom;
    phantom.options = options;
    phantom.vessels = phantomVessels();
    const Intensities level = intensitiesOf(options.modality);
    const double sigma = options.noiseSigma < 0.0 ? level.noise : options.noiseSigma;

    const glm::dvec3 spacing = fov / glm::dvec3(dims);
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(spacing.x, 0.0, 0.0, 0.0);
    m[1] = glm::dvec4(0.0, spacing.y, 0.0, 0.0);
    m[2] = glm::dvec4(0.0, 0.0, spacing.z, 0.0);
    m[3] = glm::dvec4(-0.5 * fov + 0.5 * spacing, 1.0);
    scene::Volume& volume = phantom.volume;
    volume = scene::Volume(dims, scene::VoxelType::Int16);
    volume.setIndexToWorld(m);
    const bool ct = options.modality == PhantomModality::CT;
    volume.setModality(ct ? "CT" : "MR");
    volume.setUnit(ct ? "HU" : "");
    const double h = std::cbrt(spacing.x * spacing.y * spacing.z);

    // The coil sensitivity's extremes over the grid (a 33^3 lattice through its corners).
    phantom.gainLow = std::numeric_limits<double>::max();
    phantom.gainHigh = std::numeric_limits<double>::lowest();
    for (int c = 0; c < 33 * 33 * 33; ++c) {
        const glm::dvec3 t(c % 33, (c / 33) % 33, c / (33 * 33));
        const double s = coilSensitivity(volume.worldPosition(t / 32.0 * glm::dvec3(dims - 1)));
        phantom.gainLow = std::min(phantom.gainLow, s);
        phantom.gainHigh = std::max(phantom.gainHigh, s);
    }

    // Signed distance to the vessels, within each centre-line piece's box.
    std::vector<float> sd(volume.voxelCount(), std::numeric_limits<float>::max());
    const glm::dmat4 toIndex = glm::inverse(m);
    for (std::size_t v = 0; v < phantom.vessels.size(); ++v) {
        progress.report(0.3 * static_cast<double>(v) / static_cast<double>(phantom.vessels.size()),
                        kStage);
        const PhantomVessel& vessel = phantom.vessels[v];
        const double r = vessel.radiusMm;
        for (std::size_t n = 0; n + 1 < vessel.centerline.size(); ++n) {
            const glm::dvec3 p0 = vessel.centerline[n];
            const glm::dvec3 p1 = vessel.centerline[n + 1];
            const glm::dvec3 lo(toIndex * glm::dvec4(glm::min(p0, p1) - (r + 2.0 * h), 1.0));
            const glm::dvec3 hi(toIndex * glm::dvec4(glm::max(p0, p1) + (r + 2.0 * h), 1.0));
            const glm::ivec3 i0 = glm::max(glm::ivec3(glm::floor(glm::min(lo, hi))), glm::ivec3(0));
            const glm::ivec3 i1 = glm::min(glm::ivec3(glm::ceil(glm::max(lo, hi))), dims - 1);
            for (int k = i0.z; k <= i1.z; ++k) {
                for (int j = i0.y; j <= i1.y; ++j) {
                    for (int i = i0.x; i <= i1.x; ++i) {
                        const glm::dvec3 p = volume.worldPosition(glm::dvec3(i, j, k));
                        float& d = sd[volume.index(i, j, k)];
                        d = std::min(d, static_cast<float>(distanceToSegment(p, p0, p1) - r));
                    }
                }
            }
        }
    }

    phantom.truth.resize(sd.size());
    std::transform(sd.begin(), sd.end(), phantom.truth.begin(),
                   [](float d) { return static_cast<std::uint8_t>(d < 0.0F ? 1 : 0); });

    // Intensities slice by slice, each slice's noise from its own generator.
    parallelFor(
        0, dims.z, 1,
        [&](long k0, long k1) {
            for (long kk = k0; kk < k1; ++kk) {
                const int k = static_cast<int>(kk);
                Gaussian noise(options.noiseSeed + 7919U * static_cast<std::uint32_t>(k));
                for (int j = 0; j < dims.y; ++j) {
                    for (int i = 0; i < dims.x; ++i) {
                        const std::size_t n = volume.index(i, j, k);
                        const glm::dvec3 p = volume.worldPosition(glm::dvec3(i, j, k));
                        const double y = p.y - kBodyCentreY;
                        const double body = fraction(ellipseDistance(p.x, y, kBodyA, kBodyB), h);
                        const double inner = fraction(
                            ellipseDistance(p.x, y, kBodyA - kFatLayer, kBodyB - kFatLayer), h);
                        const double spine =
                            fraction(std::hypot(p.x, p.y - kSpineY) - kSpineRadius, h);
                        const double lumen = fraction(static_cast<double>(sd[n]), h);
                        double value = level.air * (1.0 - body) + level.fat * (body - inner) +
                                       level.tissue * inner;
                        value += (level.spine - value) * spine;
                        value += (level.lumen - value) * lumen;
                        if (ct) {
                            value += sigma * noise.next();
                        } else {
                            value *= phantom.gain(p);
                            // Rician: the magnitude of a complex signal with Gaussian noise.
                            const double re = value + sigma * noise.next();
                            const double im = sigma * noise.next();
                            value = std::hypot(re, im);
                        }
                        volume.setValueAt(n, static_cast<float>(
                                                 std::clamp(std::round(value), -32768.0, 32767.0)));
                    }
                }
            }
        },
        progress.stopToken());
    progress.report(1.0, kStage);
    return phantom;
}

}  // namespace vv::demo
