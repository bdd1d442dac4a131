// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/slices/SliceOverlay.h"

#include <algorithm>
#include <cmath>

#include "vv/colormaps/LabelPalette.h"
#include "vv/core/Error.h"
#include "vv/core/Parallel.h"

namespace vv::slices {

namespace {

std::uint32_t channel(float v) noexcept {
    return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0F, 1.0F) * 255.0F));
}

std::uint32_t blend(std::uint8_t gray, std::uint32_t rgb, float alpha) noexcept {
    std::uint32_t out = 0xFF000000U;
    for (int shift = 16; shift >= 0; shift -= 8) {
        const auto c = static_cast<float>((rgb >> static_cast<unsigned>(shift)) & 0xFFU);
        const float v = static_cast<float>(gray) + alpha * (c - static_cast<float>(gray));
        out |= static_cast<std::uint32_t>(std::lround(v)) << static_cast<unsigned>(shift);
    }
    return out;
}

bool onEdge(ImageView<const std::uint8_t> labels, int c, int r) noexcept {
    const std::uint8_t l = labels(c, r);
    if (c == 0 || r == 0 || c == labels.width() - 1 || r == labels.height() - 1) {
        return true;
    }
    return labels(c - 1, r) != l || labels(c + 1, r) != l || labels(c, r - 1) != l ||
           labels(c, r + 1) != l;
}

}  // namespace

Image<std::uint8_t> labelOutline(ImageView<const std::uint8_t> labels) {
    Image<std::uint8_t> out(labels.width(), labels.height(), 0);
    parallelFor(0, labels.height(), 16, [&](long r0, long r1) {
        for (long r = r0; r < r1; ++r) {
            const int y = static_cast<int>(r);
            for (int c = 0; c < labels.width(); ++c) {
                out(c, y) = labels(c, y) != 0 && onEdge(labels, c, y) ? 1 : 0;
            }
        }
    });
    return out;
}

std::uint32_t overlayColor(std::uint8_t label) noexcept {
    const glm::vec3 rgb = colormaps::labelColor(label == 0 ? 0 : label - 1U);
    return (channel(rgb.r) << 16U) | (channel(rgb.g) << 8U) | channel(rgb.b);
}

Image<std::uint32_t> composeSlice(ImageView<const std::uint8_t> gray,
                                  ImageView<const std::uint8_t> labels, const OverlayStyle& style) {
    const bool overlay = !labels.empty();
    if (overlay && (labels.width() != gray.width() || labels.height() != gray.height())) {
        throw InvalidArgumentError("overlay labels and slice differ in size");
    }
    Image<std::uint32_t> out(gray.width(), gray.height(), UninitialisedPixels{});
    const float alpha = std::clamp(style.fillOpacity, 0.0F, 1.0F);
    parallelFor(0, gray.height(), 16, [&](long r0, long r1) {
        for (long r = r0; r < r1; ++r) {
            const int y = static_cast<int>(r);
            for (int c = 0; c < gray.width(); ++c) {
                const std::uint8_t g = gray(c, y);
                std::uint32_t pixel = 0xFF000000U | (std::uint32_t{g} * 0x010101U);
                const std::uint8_t l = overlay ? labels(c, y) : 0;
                if (l != 0) {
                    const std::uint32_t rgb = overlayColor(l);
                    if (style.outline && onEdge(labels, c, y)) {
                        pixel = 0xFF000000U | rgb;
                    } else if (style.fill) {
                        pixel = blend(g, rgb, alpha);
                    }
                }
                out(c, y) = pixel;
            }
        }
    });
    return out;
}

}  // namespace vv::slices
