// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces of the slope fit next to contours (vss::fittedSlopes): where it
// applies, and its smoothed samples, a band of rows at a time (private to the
// vss module).
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "vv/core/Image.h"

namespace vv::vss::detail {

/// Next to contours the plane is fitted over samples kContourStride pixels
/// apart, each the mean over kSampleRadius pixels around it (the
/// silhouette's pixel steps ripple the VSS there:
/// docs/benchmarks/artefacts.md); that 5x5 window reaches kContourReach pixels.
inline constexpr int kContourStride = 4;
inline constexpr int kContourReach = 2 * kContourStride;
inline constexpr int kSampleRadius = 2;

/// True where the plane fit may use the pixel: a void pixel with a VSS.
inline bool fittable(ImageView<const float> height, ImageView<const std::uint8_t> vessels, int x,
                     int y) {
    return vessels(x, y) == 0 && std::isfinite(height(x, y));
}

/// 1 where a pixel that the fit cannot use (a vessel, no VSS) lies within
/// kContourReach pixels (chessboard): where the wide window can miss a
/// sample; else 0. Running counts along rows, then down the columns a band of
/// rows at a time (row-major, in parallel). Throws nothing beyond bad_alloc;
/// `height` and `vessels` have the same size (the caller checks).
Image<std::uint8_t> nearGaps(ImageView<const float> height, ImageView<const std::uint8_t> vessels);

/// The wide fit's samples for the rows a band reads: for every fittable pixel
/// of sample row j, the mean offset (x, y) and height (z) of the fittable
/// pixels within kSampleRadius (chessboard) around it, NaN elsewhere (a
/// sample sits at its pixels' centroid, so a plane stays exact where vessels
/// cut its square off). Row j lives in slot j mod (2 * kContourReach + 1);
/// the box sums along x behind it in a ring of 2 * kSampleRadius + 1 rows.
/// Float sums (counts and offsets are small integers, heights in [0, 1]),
/// in the same order as the whole-image version before it, so the same bits.
class SampleRing {
  public:
    /// A ring for rows of `height` and `vessels` (same size).
    SampleRing(ImageView<const float> height, ImageView<const std::uint8_t> vessels);

    /// Prepares the ring so that advance(j0) is the next call.
    void start(int j0);

    /// Computes sample row j (after start(j0) and advance(j0 .. j - 1)):
    /// overwrites row j - (2 * kContourReach + 1). Rows outside the image
    /// are left as they are (the fit never reads them).
    void advance(int j);

    /// Sample row j: width() samples; j within the last 2 * kContourReach + 1
    /// rows advanced to, and inside the image.
    [[nodiscard]] const glm::vec3* row(int j) const;

    [[nodiscard]] int width() const { return static_cast<int>(width_); }
    [[nodiscard]] int height() const { return height_.height(); }

  private:
    void loadBoxRow(int r);
    [[nodiscard]] static std::size_t boxSlot(int r);
    [[nodiscard]] static std::size_t sampleSlot(int j);

    ImageView<const float> height_;
    ImageView<const std::uint8_t> vessels_;
    std::size_t width_;
    std::vector<float> box_;          // count, x offsets, heights per box row
    std::vector<glm::vec3> samples_;  // the sample rows
    std::vector<float> mask_;         // one row, padded by kSampleRadius
    std::vector<float> maskedHeight_;
};

}  // namespace vv::vss::detail
