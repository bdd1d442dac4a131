// SPDX-License-Identifier: GPL-3.0-or-later
// Colour differences as a person sees them (CIEDE2000 of 8-bit colours) and
// finding a legend's colour bar in a rendered image, for the tests of
// legends in exported files.
#pragma once

#include <QColor>
#include <QImage>
#include <QRect>
#include <optional>
#include <string>
#include <vector>

namespace vv::test {

/// CIEDE2000 colour difference of two 8-bit sRGB colours (alpha ignored):
/// colormaps::ciede2000 (Sharma, Wu and Dalal 2005). Below about 1 is
/// invisible, below 2 hardly noticeable side by side.
[[nodiscard]] double ciede2000(QRgb x, QRgb y) noexcept;

/// Where a horizontal colour bar lies in an image: its middle row and its
/// first and last column.
struct BarPosition {
    int row = 0;
    int left = 0;
    int right = 0;
};

/// Finds the colour bar that starts with `first` and ends with `last` inside
/// `area` of `image`: the row with the longest run of pixels within CIEDE2000
/// 2 of `first` followed (further right) by one of `last`, each run at least
/// `minRun` pixels. nullopt when no row holds both (e.g. a dimmed bar).
[[nodiscard]] std::optional<BarPosition> findBar(const QImage& image, const QRect& area, QRgb first,
                                                 QRgb last, int minRun);

/// Checks the bar at `bar` against `table` (the colour map's entries, left to
/// right): each entry's middle column for a binned table (few entries, each
/// at least 3 pixels wide), else `samples` columns evenly over the bar, each
/// matched against the entries within `slack` of its position. Returns one
/// line per column off by CIEDE2000 >= `tolerance`; empty = all match.
[[nodiscard]] std::vector<std::string> barMismatches(const QImage& image, const BarPosition& bar,
                                                     const std::vector<QRgb>& table,
                                                     double tolerance = 2.0, int samples = 64,
                                                     int slack = 3);

}  // namespace vv::test
