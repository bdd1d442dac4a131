// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/segmentation/IntensityCorrection.h"

#include <vtkMath.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "Histogram.h"
#include "VolumeSampling.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::segmentation {

namespace {

constexpr const char* kEstimateStage = "Estimating the signal fall-off";
constexpr const char* kCorrectStage = "Correcting the signal fall-off";
/// The log-intensity histogram's bins (air threshold).
constexpr std::size_t kLogBins = 256;
/// A bright Otsu class larger than this share is the body (smaller: vessels).
constexpr double kBodyShare = 0.15;
constexpr int kIterations = 10;
/// Tukey's biweight cut-off in robust standard deviations: tight, so that a second
/// tissue class (fat) falls outside and does not pull the fit.
constexpr double kTukey = 2.0;
/// The residual scale never falls below this (log units): noise-free data.
constexpr double kMinimumScale = 0.01;
/// The best-lit tissue: this quantile of the body's fitted gain is gain 1.
constexpr double kReferenceQuantile = 0.98;
/// The gain is evaluated on a lattice of every kLatticeStep-th voxel.
constexpr int kLatticeStep = 4;
constexpr float kCtAir = -500.0F;

/// Legendre polynomials P_0..P_degree at x.
void legendre(double x, int degree, double* p) {
    p[0] = 1.0;
    if (degree >= 1) {
        p[1] = x;
    }
    for (int n = 1; n < degree; ++n) {
        p[n + 1] = ((2.0 * n + 1.0) * x * p[n] - n * p[n - 1]) / (n + 1.0);
    }
}

constexpr int kMaxDegree = 6;
/// Terms of total degree <= kMaxDegree in three variables: (6 + 3 choose 3).
constexpr std::size_t kMaxTerms = 84;

/// The basis values of `terms` at unit coordinates `u`.
void basis(const glm::dvec3& u, const std::vector<std::array<int, 3>>& terms, int degree,
           double* out) {
    std::array<double, kMaxDegree + 1> px{};
    std::array<double, kMaxDegree + 1> py{};
    std::array<double, kMaxDegree + 1> pz{};
    legendre(u.x, degree, px.data());
    legendre(u.y, degree, py.data());
    legendre(u.z, degree, pz.data());
    for (std::size_t t = 0; t < terms.size(); ++t) {
        out[t] = px.at(static_cast<std::size_t>(terms[t][0])) *
                 py.at(static_cast<std::size_t>(terms[t][1])) *
                 pz.at(static_cast<std::size_t>(terms[t][2]));
    }
}

int maxDegreeOf(const std::vector<std::array<int, 3>>& terms) {
    int d = 0;
    for (const auto& t : terms) {
        d = std::max({d, t[0], t[1], t[2]});
    }
    return d;
}

struct Sample {
    glm::dvec3 unit;
    double logValue;
};

double quantile(std::vector<double> values, double q) {
    const auto at = static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + at, values.end());
    return values[static_cast<std::size_t>(at)];
}

/// Solves the symmetric system `m` x = `rhs` (VTK's LU with partial
/// pivoting); a tiny ridge keeps an unconstrained term at zero.
std::vector<double> solve(std::vector<double> m, std::vector<double> rhs) {
    const std::size_t n = rhs.size();
    double trace = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        trace += m[i * n + i];
    }
    std::vector<double*> rows(n);
    for (std::size_t i = 0; i < n; ++i) {
        m[i * n + i] += 1e-9 * trace / static_cast<double>(n) + 1e-300;
        rows[i] = &m[i * n];
    }
    if (vtkMath::SolveLinearSystem(rows.data(), rhs.data(), static_cast<int>(n)) == 0) {
        throw FormatError("the signal fall-off fit is singular");
    }
    return rhs;
}

}  // namespace

GainField::GainField(glm::dmat4 worldToUnit, std::vector<std::array<int, 3>> terms,
                     std::vector<double> coefficients, double offset, double lowest, double highest)
    : worldToUnit_(worldToUnit),
      terms_(std::move(terms)),
      coefficients_(std::move(coefficients)),
      offset_(offset),
      lowest_(lowest),
      highest_(highest) {}

double GainField::at(const glm::dvec3& world) const noexcept {
    if (coefficients_.empty()) {
        return 1.0;
    }
    const glm::dvec3 u(worldToUnit_ * glm::dvec4(world, 1.0));
    std::array<double, kMaxTerms> values{};
    basis(u, terms_, maxDegreeOf(terms_), values.data());
    double log = -offset_;
    for (std::size_t t = 0; t < terms_.size(); ++t) {
        log += coefficients_[t] * values[t];
    }
    return std::clamp(std::exp(log), lowest_, highest_);
}

float airThreshold(const scene::Volume& volume) {
    if (volume.empty()) {
        throw InvalidArgumentError("cannot find the air in an empty volume");
    }
    if (volume.unit() == "HU" || volume.modality() == "CT") {
        return kCtAir;
    }
    std::vector<double> logs;
    detail::forSampledVoxels(volume, [&](const glm::ivec3&, float v) {
        if (v > 0.0F && std::isfinite(v)) {
            logs.push_back(std::log(static_cast<double>(v)));
        }
    });
    if (logs.size() < 2) {
        return 0.0F;
    }
    const auto [lo, hi] = std::minmax_element(logs.begin(), logs.end());
    const double low = *lo;
    const double span = *hi - *lo;
    if (!(span > 0.0)) {
        return 0.0F;
    }
    std::vector<std::size_t> histogram(kLogBins, 0);
    for (const double l : logs) {
        const auto b = static_cast<std::size_t>((l - low) / span * static_cast<double>(kLogBins));
        ++histogram[std::min(b, kLogBins - 1)];
    }
    const std::size_t split = detail::otsuBin(histogram);
    const std::size_t above = std::accumulate(
        histogram.begin() + static_cast<std::ptrdiff_t>(split), histogram.end(), std::size_t{0});
    if (static_cast<double>(above) <= kBodyShare * static_cast<double>(logs.size())) {
        return 0.0F;  // the bright class is small: vessels in a volume without air
    }
    return static_cast<float>(
        std::exp(low + span * static_cast<double>(split) / static_cast<double>(kLogBins)));
}

GainField estimateGainField(const scene::Volume& volume, const GainFieldOptions& options,
                            const Progress& progress) {
    if (volume.empty()) {
        throw InvalidArgumentError("cannot estimate the signal fall-off of an empty volume");
    }
    if (options.degree < 0 || options.degree > kMaxDegree) {
        throw InvalidArgumentError("the signal fall-off's degree must be within 0..6");
    }
    if (!(options.maxAmplification >= 1.0)) {
        throw InvalidArgumentError("the largest amplification must be at least 1");
    }
    progress.report(0.0, kEstimateStage);
    const float air = std::max(airThreshold(volume), 0.0F);
    const glm::ivec3 dims = volume.dims();
    // Index -> [-1, 1]^3 (a flat axis maps to 0).
    glm::dmat4 indexToUnit(1.0);
    for (int c = 0; c < 3; ++c) {
        const double scale = dims[c] > 1 ? 2.0 / static_cast<double>(dims[c] - 1) : 0.0;
        indexToUnit[c][c] = scale;
        indexToUnit[3][c] = dims[c] > 1 ? -1.0 : 0.0;
    }
    std::vector<Sample> samples;
    glm::ivec3 positions(0);  // lattice positions per axis
    detail::forSampledVoxels(volume, [&](const glm::ivec3& ijk, float v) {
        positions = glm::max(positions, ijk);
        if (v > air && std::isfinite(v)) {
            samples.push_back({glm::dvec3(indexToUnit * glm::dvec4(glm::dvec3(ijk), 1.0)),
                               std::log(static_cast<double>(v))});
        }
    });
    if (samples.size() < options.minimumSamples) {
        return {};
    }
    // Terms of total degree <= degree; an axis with few lattice positions gets fewer.
    const int step = detail::samplingStep(volume.dims());
    std::vector<std::array<int, 3>> terms;
    glm::ivec3 axisDegree(0);
    for (int c = 0; c < 3; ++c) {
        axisDegree[c] = std::min(options.degree, positions[c] / step);
    }
    for (int a = 0; a <= axisDegree.x; ++a) {
        for (int b = 0; b <= axisDegree.y; ++b) {
            for (int c = 0; c <= axisDegree.z; ++c) {
                if (a + b + c <= options.degree) {
                    terms.push_back({a, b, c});
                }
            }
        }
    }
    const std::size_t n = terms.size();
    const int degree = maxDegreeOf(terms);
    std::vector<double> weights(samples.size(), 1.0);
    std::vector<double> coefficients(n, 0.0);
    std::vector<double> residuals(samples.size());
    std::vector<double> phi(n);
    for (int iteration = 0; iteration < kIterations; ++iteration) {
        progress.report(0.05 + 0.9 * iteration / kIterations, kEstimateStage);
        std::vector<double> m(n * n, 0.0);
        std::vector<double> rhs(n, 0.0);
        for (std::size_t s = 0; s < samples.size(); ++s) {
            const double w = weights[s];
            if (w <= 0.0) {
                continue;
            }
            basis(samples[s].unit, terms, degree, phi.data());
            for (std::size_t r = 0; r < n; ++r) {
                const double wr = w * phi[r];
                rhs[r] += wr * samples[s].logValue;
                for (std::size_t c = 0; c <= r; ++c) {
                    m[r * n + c] += wr * phi[c];
                }
            }
        }
        for (std::size_t r = 0; r < n; ++r) {
            for (std::size_t c = r + 1; c < n; ++c) {
                m[r * n + c] = m[c * n + r];
            }
        }
        coefficients = solve(std::move(m), std::move(rhs));
        for (std::size_t s = 0; s < samples.size(); ++s) {
            basis(samples[s].unit, terms, degree, phi.data());
            residuals[s] = samples[s].logValue -
                           std::inner_product(phi.begin(), phi.end(), coefficients.begin(), 0.0);
        }
        // Tukey's biweight around the fit, its scale from the residuals' MAD.
        const double centre = quantile(residuals, 0.5);
        std::vector<double> deviations(residuals.size());
        std::transform(residuals.begin(), residuals.end(), deviations.begin(),
                       [centre](double r) { return std::abs(r - centre); });
        const double scale = std::max(1.4826 * quantile(deviations, 0.5), kMinimumScale);
        const double cut = kTukey * scale;
        for (std::size_t s = 0; s < samples.size(); ++s) {
            const double x = residuals[s] / cut;
            weights[s] = std::abs(x) < 1.0 ? (1.0 - x * x) * (1.0 - x * x) : 0.0;
        }
    }
    // Gain 1 at the best-lit tissue; clamped to what the body's tissue takes.
    std::vector<double> fitted;
    fitted.reserve(samples.size());
    for (std::size_t s = 0; s < samples.size(); ++s) {
        if (weights[s] > 0.0) {
            basis(samples[s].unit, terms, degree, phi.data());
            fitted.push_back(std::inner_product(phi.begin(), phi.end(), coefficients.begin(), 0.0));
        }
    }
    if (fitted.empty()) {
        return {};
    }
    const double offset = quantile(fitted, kReferenceQuantile);
    const auto [lo, hi] = std::minmax_element(fitted.begin(), fitted.end());
    const double lowest = std::max(std::exp(*lo - offset), 1.0 / options.maxAmplification);
    const double highest = std::max(std::exp(*hi - offset), lowest);
    progress.report(1.0, kEstimateStage);
    return {indexToUnit * volume.worldToIndex(),
            std::move(terms),
            std::move(coefficients),
            offset,
            lowest,
            highest};
}

scene::Volume correctedVolume(const scene::Volume& volume, const GainField& gain,
                              const Progress& progress) {
    if (volume.empty()) {
        throw InvalidArgumentError("cannot correct an empty volume");
    }
    progress.report(0.0, kCorrectStage);
    const glm::ivec3 dims = volume.dims();
    // Lattice nodes per axis (every kLatticeStep-th voxel and the last) and,
    // per voxel index, its lattice cell and the weight of the cell's far node.
    std::array<std::vector<int>, 3> nodes;
    std::array<std::vector<int>, 3> cellOf;
    std::array<std::vector<float>, 3> weightOf;
    for (int c = 0; c < 3; ++c) {
        for (int i = 0; i < dims[c]; i += kLatticeStep) {
            nodes[c].push_back(i);
        }
        if (nodes[c].back() != dims[c] - 1) {
            nodes[c].push_back(dims[c] - 1);
        }
        for (int i = 0; i < dims[c]; ++i) {
            const int cell = std::min(i / kLatticeStep, static_cast<int>(nodes[c].size()) - 2);
            const int a = nodes[c][static_cast<std::size_t>(std::max(cell, 0))];
            const int b = nodes[c][static_cast<std::size_t>(
                std::min(cell + 1, static_cast<int>(nodes[c].size()) - 1))];
            cellOf[c].push_back(std::max(cell, 0));
            weightOf[c].push_back(b > a ? static_cast<float>(i - a) / static_cast<float>(b - a)
                                        : 0.0F);
        }
    }
    const std::size_t nx = nodes[0].size();
    const std::size_t ny = nodes[1].size();
    const std::size_t nz = nodes[2].size();
    std::vector<float> lattice(nx * ny * nz);
    for (std::size_t z = 0; z < nz; ++z) {
        for (std::size_t y = 0; y < ny; ++y) {
            for (std::size_t x = 0; x < nx; ++x) {
                const glm::dvec3 ijk(nodes[0][x], nodes[1][y], nodes[2][z]);
                lattice[(z * ny + y) * nx + x] =
                    static_cast<float>(gain.at(volume.worldPosition(ijk)));
            }
        }
    }
    const auto node = [&](std::size_t x, std::size_t y, std::size_t z) {
        return lattice[(std::min(z, nz - 1) * ny + std::min(y, ny - 1)) * nx + std::min(x, nx - 1)];
    };

    scene::Volume corrected(dims, scene::VoxelType::Float32);
    corrected.setIndexToWorld(volume.indexToWorld());
    corrected.setModality(volume.modality());
    corrected.setUnit(volume.unit());
    const std::span<float> out = corrected.floatVoxels();
    constexpr int kSlicesPerReport = 16;
    for (int k0 = 0; k0 < dims.z; k0 += kSlicesPerReport) {
        progress.report(static_cast<double>(k0) / dims.z, kCorrectStage);
        const int k1 = std::min(dims.z, k0 + kSlicesPerReport);
        parallelFor(
            k0, k1, 1,
            [&](long from, long to) {
                std::vector<float> row(nx);
                for (auto k = static_cast<int>(from); k < static_cast<int>(to); ++k) {
                    const auto cz =
                        static_cast<std::size_t>(cellOf[2][static_cast<std::size_t>(k)]);
                    const float tz = weightOf[2][static_cast<std::size_t>(k)];
                    for (int j = 0; j < dims.y; ++j) {
                        const auto cy =
                            static_cast<std::size_t>(cellOf[1][static_cast<std::size_t>(j)]);
                        const float ty = weightOf[1][static_cast<std::size_t>(j)];
                        for (std::size_t x = 0; x < nx; ++x) {
                            const float a =
                                node(x, cy, cz) + ty * (node(x, cy + 1, cz) - node(x, cy, cz));
                            const float b = node(x, cy, cz + 1) +
                                            ty * (node(x, cy + 1, cz + 1) - node(x, cy, cz + 1));
                            row[x] = a + tz * (b - a);
                        }
                        std::size_t n = volume.index(0, j, k);
                        for (int i = 0; i < dims.x; ++i, ++n) {
                            const auto cx =
                                static_cast<std::size_t>(cellOf[0][static_cast<std::size_t>(i)]);
                            const float g = row[cx] + weightOf[0][static_cast<std::size_t>(i)] *
                                                          (row[std::min(cx + 1, nx - 1)] - row[cx]);
                            out[n] = volume.valueAt(n) / g;
                        }
                    }
                }
            },
            progress.stopToken());
    }
    progress.report(1.0, kCorrectStage);
    return corrected;
}

}  // namespace vv::segmentation
