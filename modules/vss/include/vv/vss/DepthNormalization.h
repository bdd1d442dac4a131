// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

#include "vv/core/Image.h"

namespace vv::vss {

/// Which depth range maps to the normalised depth z in [0, 1] (VSS.md, definition 1).
enum class RangeMode {
    Visible,  ///< min / max of the depth over the (finite) vessel pixels of this image
    Fixed,    ///< a given range, e.g. the scene's bounding sphere: colours stay still
};

struct DepthRange {
    RangeMode mode = RangeMode::Visible;
    double dmin = 0.0;  ///< Fixed mode only: scene units, finite, dmin <= dmax
    double dmax = 0.0;
    /// Fixed mode only: dmin / dmax are not distances someone chose but a
    /// view's visible range, kept for another render of that view (an export
    /// framed as the view, so that its colours match the screen's): dmin is
    /// that view's frontmost vessel point. Normalisation treats it as any
    /// fixed range; it tells what the depth is measured from (the legends
    /// say "behind the frontmost vessel", not "viewing distance").
    bool pinnedVisible = false;
};

/// The result of normalisation.
struct NormalizedDepth {
    /// z = (depth - dmin) / (dmax - dmin) clamped to [0, 1] on vessel pixels
    /// (0 everywhere in a flat scene); NaN on background pixels.
    Image<float> z;
    /// 1 on vessel pixels (mask set and depth finite), 0 elsewhere.
    Image<std::uint8_t> vessel;
    /// The range used, in scene units. Visible mode without any vessel pixel: NaN.
    double dmin = 0.0;
    double dmax = 0.0;
    /// True when dmax - dmin < flatEpsilon(dmax) (or there is no vessel pixel):
    /// z is then 0 on every vessel pixel.
    bool flat = false;
    std::int64_t vesselPixels = 0;  ///< number of pixels with vessel == 1
};

/// The relative epsilon below which a range counts as flat: 1e-6 * max(1, |dmax|).
[[nodiscard]] double flatEpsilon(double dmax) noexcept;

/// Normalises `depth` over the vessel pixels of `mask` (nonzero = vessel).
/// A vessel pixel whose depth is not finite (NaN, ±Inf) is treated as
/// background: it gets z = NaN and vessel = 0, and it does not enter the visible
/// range. Depth outside a fixed range is clamped to z = 0 or 1. Never produces
/// NaN on a vessel pixel, also for a flat scene (z = 0 there).
/// Throws InvalidArgumentError when the sizes of depth and mask differ, or in
/// Fixed mode when dmin / dmax are not finite or dmin > dmax.
[[nodiscard]] NormalizedDepth normalizeDepth(ImageView<const float> depth,
                                             ImageView<const std::uint8_t> mask,
                                             const DepthRange& range = {});

/// A vessel mask from a depth image whose background is marked non-finite
/// (+Inf or NaN, as in the PFM files of the CLI): 1 where depth is finite.
[[nodiscard]] Image<std::uint8_t> maskFromFiniteDepth(ImageView<const float> depth);

}  // namespace vv::vss
