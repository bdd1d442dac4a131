// SPDX-License-Identifier: GPL-3.0-or-later
#include "ColourDifference.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "vv/colormaps/ColorVision.h"

namespace vv::test {

namespace {

std::string describe(int column, QRgb got, QRgb want, double difference) {
    std::ostringstream out;
    out << "column " << column << ": (" << qRed(got) << "," << qGreen(got) << "," << qBlue(got)
        << ") instead of (" << qRed(want) << "," << qGreen(want) << "," << qBlue(want)
        << "), CIEDE2000 " << difference;
    return out.str();
}

}  // namespace

double ciede2000(QRgb x, QRgb y) noexcept {
    const auto srgb = [](QRgb c) {
        return glm::dvec3(qRed(c) / 255.0, qGreen(c) / 255.0, qBlue(c) / 255.0);
    };
    return colormaps::ciede2000(srgb(x), srgb(y));
}

std::optional<BarPosition> findBar(const QImage& image, const QRect& area, QRgb first, QRgb last,
                                   int minRun) {
    const QRect box = area.intersected(image.rect());
    std::optional<BarPosition> best;
    int bestLength = 0;
    for (int y = box.top(); y <= box.bottom(); ++y) {
        // The longest run of `first`, then the last run of `last` right of it.
        int runStart = -1;
        int firstStart = -1;
        int firstLength = 0;
        for (int x = box.left(); x <= box.right() + 1; ++x) {
            const bool match = x <= box.right() && ciede2000(image.pixel(x, y), first) < 2.0;
            if (match && runStart < 0) {
                runStart = x;
            } else if (!match && runStart >= 0) {
                if (x - runStart > firstLength) {
                    firstLength = x - runStart;
                    firstStart = runStart;
                }
                runStart = -1;
            }
        }
        if (firstLength < minRun) {
            continue;
        }
        int lastEnd = -1;
        int run = 0;
        for (int x = firstStart + firstLength; x <= box.right(); ++x) {
            if (ciede2000(image.pixel(x, y), last) < 2.0) {
                ++run;
                if (run >= minRun) {
                    lastEnd = x;
                }
            } else {
                run = 0;
            }
        }
        if (lastEnd < 0) {
            continue;
        }
        const int length = lastEnd - firstStart;
        if (length > bestLength) {
            bestLength = length;
            best = BarPosition{y, firstStart, lastEnd};
        }
    }
    return best;
}

std::vector<std::string> barMismatches(const QImage& image, const BarPosition& bar,
                                       const std::vector<QRgb>& table, double tolerance,
                                       int samples, int slack) {
    std::vector<std::string> mismatches;
    const int entries = static_cast<int>(table.size());
    const double width = bar.right - bar.left + 1;
    if (entries == 0 || width < 2) {
        return {"no bar"};
    }
    if (width / entries >= 3.0) {
        for (int i = 0; i < entries; ++i) {
            const int x = bar.left + static_cast<int>(std::floor((i + 0.5) * width / entries));
            const QRgb got = image.pixel(x, bar.row);
            const double d = ciede2000(got, table[static_cast<std::size_t>(i)]);
            if (d >= tolerance) {
                mismatches.push_back(describe(x, got, table[static_cast<std::size_t>(i)], d));
            }
        }
        return mismatches;
    }
    for (int s = 0; s < samples; ++s) {
        const double f = (s + 0.5) / samples;
        const int x = bar.left + static_cast<int>(std::floor(f * width));
        const int index = std::clamp(static_cast<int>(f * entries), 0, entries - 1);
        const QRgb got = image.pixel(x, bar.row);
        double d = 1e9;
        for (int i = std::max(0, index - slack); i <= std::min(entries - 1, index + slack); ++i) {
            d = std::min(d, ciede2000(got, table[static_cast<std::size_t>(i)]));
        }
        if (d >= tolerance) {
            mismatches.push_back(describe(x, got, table[static_cast<std::size_t>(index)], d));
        }
    }
    return mismatches;
}

}  // namespace vv::test
