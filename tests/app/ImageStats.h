// SPDX-License-Identifier: GPL-3.0-or-later
// Pixel statistics the front-end tests share.
#pragma once

#include <QColor>
#include <QImage>
#include <cstddef>
#include <set>

namespace vv::test {

/// Number of 15-degree hue bins occupied by saturated, non-dark pixels
/// (saturation and value above 60 of 255): how many distinct colours a
/// colour-mapped image shows.
inline std::size_t hueBins(const QImage& image) {
    std::set<int> bins;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const QColor c(image.pixel(x, y));
            if (c.hsvSaturation() > 60 && c.value() > 60) {
                bins.insert(c.hsvHue() / 15);
            }
        }
    }
    return bins.size();
}

}  // namespace vv::test
