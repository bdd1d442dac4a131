// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A windowed slice with the segmentation drawn over it: a translucent fill
// of every labelled pixel and / or an opaque outline along each segment's
// edge, in the label colours of the 3-D view.

#include <cstdint>

#include "vv/core/Image.h"

namespace vv::slices {

struct OverlayStyle {
    bool fill = true;           ///< translucent fill of labelled pixels
    bool outline = true;        ///< opaque edge pixels
    float fillOpacity = 0.35F;  ///< in [0, 1]
};

/// The edge pixels of a label image: labelled pixels (non-zero) with a
/// 4-neighbour of another label or background, or on the image border.
/// 1 on an edge, else 0.
[[nodiscard]] Image<std::uint8_t> labelOutline(ImageView<const std::uint8_t> labels);

/// The colour of label `label` (>= 1) as 0xRRGGBB: the label palette
/// (vv/colormaps/LabelPalette.h) entry label - 1, as the 3-D view colours
/// label arrays.
[[nodiscard]] std::uint32_t overlayColor(std::uint8_t label) noexcept;

/// The slice as opaque 0xAARRGGBB pixels (QImage::Format_ARGB32's layout):
/// grey from `gray`; where `labels` is non-zero, the label colour blended
/// over it with fillOpacity (fill) and, on labelOutline() pixels, the label
/// colour itself (outline). `labels` may be empty (no overlay); otherwise
/// its size must equal gray's: throws InvalidArgumentError if not.
[[nodiscard]] Image<std::uint32_t> composeSlice(ImageView<const std::uint8_t> gray,
                                                ImageView<const std::uint8_t> labels,
                                                const OverlayStyle& style = {});

}  // namespace vv::slices
