// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Correction of a slow multiplicative intensity fall-off before thresholding:
// in MR the receive coils' sensitivity makes the same tissue darker far from
// them (a "bias field"), so that one threshold misses a vessel where the
// signal fades. The gain is estimated as a smooth field and divided out.
//
// Method: the logarithm of the body's voxels (air left out, airThreshold())
// is fitted with a low-degree polynomial in the volume's coordinates
// (products of Legendre polynomials, total degree <= 3) by iteratively
// reweighted least squares with Tukey's biweight at 2 robust standard
// deviations (1.4826 x the residuals' MAD): tight, so that the vessels, fat
// and other tissue classes — outliers to the dominant tissue — do not pull
// the fit. The exponential of the fit is the gain, scaled so that the
// best-lit tissue (98th percentile of the body's gain) has gain 1 and
// clamped to the range it takes over the body (at most a 10-fold
// amplification). A polynomial gain, the classic parametric bias model,
// cannot follow anatomy (a vessel, an organ), only the slow fall-off. It
// reads at most ~260,000 voxels sampled on a lattice, so its cost hardly
// depends on the volume's size. docs/benchmarks/dicom.md measures it and
// says why not ITK's N4.

#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "vv/core/Progress.h"
#include "vv/scene/Volume.h"

namespace vv::segmentation {

/// A smooth multiplicative gain over patient space (LPS mm): gain 1
/// everywhere when default-constructed. Defined in world coordinates, so it
/// applies to any grid over the same space (a preview's downsampled copy).
class GainField {
  public:
    GainField() = default;

    /// The gain at `world` (mm), within [lowest(), highest()].
    [[nodiscard]] double at(const glm::dvec3& world) const noexcept;
    /// The smallest and largest gain the field takes (over the body it was fitted to).
    [[nodiscard]] double lowest() const noexcept { return lowest_; }
    [[nodiscard]] double highest() const noexcept { return highest_; }
    /// True for the default field (no correction).
    [[nodiscard]] bool identity() const noexcept { return coefficients_.empty(); }

    /// Legendre coefficients of log gain for the exponents `terms` (per axis
    /// degrees); `worldToUnit` maps world to the fitted grid's [-1, 1]^3.
    /// `lowest` <= `highest`, both > 0. For estimateGainField().
    GainField(glm::dmat4 worldToUnit, std::vector<std::array<int, 3>> terms,
              std::vector<double> coefficients, double offset, double lowest, double highest);

  private:
    glm::dmat4 worldToUnit_{1.0};
    std::vector<std::array<int, 3>> terms_;
    std::vector<double> coefficients_;
    double offset_ = 0.0;  ///< subtracted from the polynomial: the best-lit tissue's log gain
    double lowest_ = 1.0;
    double highest_ = 1.0;
};

struct GainFieldOptions {
    int degree = 3;  ///< total degree of the log-gain polynomial, 0..6
    /// Fewer body voxels than this (sampled): no correction (identity field).
    std::size_t minimumSamples = 1000;
    /// The largest amplification: the gain is at least 1 / maxAmplification.
    double maxAmplification = 10.0;
};

/// Estimates the gain field of `volume` (see the top of this header).
/// Returns the identity field for a volume with too few positive voxels in
/// the body (nothing to fit). Reports progress ("Estimating the signal
/// fall-off"); throws InvalidArgumentError (empty volume, degree outside
/// 0..6, maxAmplification < 1), CancelledError.
[[nodiscard]] GainField estimateGainField(const scene::Volume& volume,
                                          const GainFieldOptions& options = {},
                                          const Progress& progress = {});

/// `volume` divided by `gain` voxel by voxel: a Float32 volume with the same
/// grid, modality and unit. The gain is evaluated on a lattice of every 4th
/// voxel and interpolated trilinearly (the field is smooth). Memory: 4 bytes
/// per voxel. Reports progress ("Correcting the signal fall-off"); throws
/// InvalidArgumentError for an empty volume, CancelledError.
[[nodiscard]] scene::Volume correctedVolume(const scene::Volume& volume, const GainField& gain,
                                            const Progress& progress = {});

/// The value below which a voxel of `volume` is taken to be air: -500 HU for
/// CT; otherwise, when the Otsu threshold of the logarithms of the positive
/// values leaves more than 15 % of them above it, that threshold (air and
/// noise below, the body above); else 0 (no air: a volume cropped to the body).
/// Sampled on at most ~260,000 voxels. Throws InvalidArgumentError for an
/// empty volume.
[[nodiscard]] float airThreshold(const scene::Volume& volume);

}  // namespace vv::segmentation
