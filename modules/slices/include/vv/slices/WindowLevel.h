// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Window / level: which values a slice shows from black to white, and the
// presets a volume offers.

#include <cstdint>
#include <string_view>
#include <vector>

#include "vv/core/Image.h"
#include "vv/scene/Volume.h"

namespace vv::slices {

/// Values center - width / 2 and below are black, center + width / 2 and
/// above white, linear between.
struct Window {
    double center = 0.0;
    double width = 1.0;  ///< > 0
};

/// The grey level (0..255) of `value` in `window`: round(255 (value - lo) / width)
/// clamped, lo = center - width / 2; 0 for NaN (outside the volume). A width
/// <= 0 counts as the smallest positive width (a step at center).
[[nodiscard]] std::uint8_t windowGray(float value, const Window& window) noexcept;

/// windowGray of every pixel of `values`, rows in parallel.
[[nodiscard]] Image<std::uint8_t> applyWindow(ImageView<const float> values, const Window& window);

enum class WindowPreset : std::uint8_t { Cta, Mra, SoftTissue, Bone, FullRange };

/// A stable English key for sessions and the command line: "cta", "mra",
/// "soft-tissue", "bone", "full-range".
[[nodiscard]] std::string_view presetKey(WindowPreset preset) noexcept;

struct PresetWindow {
    WindowPreset preset = WindowPreset::FullRange;
    Window window;
};

/// The presets offered for `volume`, the first the default:
/// - CT (modality "CT" or unit "HU"): CTA (center 300, width 600 HU: lumen
///   bright, tissue dark), soft tissue (40 / 400), bone (400 / 1800), full range.
/// - Otherwise (MR, unknown), from the value histogram of at most about a
///   million voxels spread over the volume: MRA (from the median to the
///   99.9th percentile: bright vessels over the darker body), soft tissue
///   (1st to 99th percentile), full range (minimum to maximum).
/// A window is never narrower than 1e-3 of the value range (nor than 1e-6).
/// Throws InvalidArgumentError for an empty volume.
[[nodiscard]] std::vector<PresetWindow> windowPresets(const scene::Volume& volume);

/// The window after a mouse drag of (dx, dy) pixels from `start` in a view of
/// a volume whose values span `valueSpan`: each pixel to the right widens the
/// window by valueSpan / 500 (to the left narrows it, down to valueSpan / 1000),
/// each pixel down raises the center by valueSpan / 1000 (the image darkens).
[[nodiscard]] Window dragWindow(const Window& start, double dx, double dy,
                                double valueSpan) noexcept;

}  // namespace vv::slices
