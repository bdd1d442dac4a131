// SPDX-License-Identifier: GPL-3.0-or-later
#include "ColourDifference.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace vv::test {

namespace {

double linear(int channel) {
    const double c = channel / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double labF(double t) {
    constexpr double delta = 6.0 / 29.0;
    return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

double degrees(double radians) {
    return radians * 180.0 / std::numbers::pi;
}

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

/// The hue angle in degrees, 0..360 (0 for a neutral colour).
double hue(double b, double a) {
    if (a == 0.0 && b == 0.0) {
        return 0.0;
    }
    const double h = degrees(std::atan2(b, a));
    return h < 0.0 ? h + 360.0 : h;
}

std::string describe(int column, QRgb got, QRgb want, double difference) {
    std::ostringstream out;
    out << "column " << column << ": (" << qRed(got) << "," << qGreen(got) << "," << qBlue(got)
        << ") instead of (" << qRed(want) << "," << qGreen(want) << "," << qBlue(want)
        << "), CIEDE2000 " << difference;
    return out.str();
}

}  // namespace

Lab toLab(QRgb rgb) noexcept {
    const double r = linear(qRed(rgb));
    const double g = linear(qGreen(rgb));
    const double b = linear(qBlue(rgb));
    // sRGB to XYZ (D65), relative to the white point.
    const double x = (0.4124564 * r + 0.3575761 * g + 0.1804375 * b) / 0.95047;
    const double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
    const double z = (0.0193339 * r + 0.1191920 * g + 0.9503041 * b) / 1.08883;
    const double fx = labF(x);
    const double fy = labF(y);
    const double fz = labF(z);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab& x, const Lab& y) noexcept {
    const double c1 = std::hypot(x.a, x.b);
    const double c2 = std::hypot(y.a, y.b);
    const double cMean7 = std::pow((c1 + c2) / 2.0, 7.0);
    const double g = 0.5 * (1.0 - std::sqrt(cMean7 / (cMean7 + std::pow(25.0, 7.0))));
    const double a1 = (1.0 + g) * x.a;
    const double a2 = (1.0 + g) * y.a;
    const double c1p = std::hypot(a1, x.b);
    const double c2p = std::hypot(a2, y.b);
    const double h1p = hue(x.b, a1);
    const double h2p = hue(y.b, a2);

    const double dL = y.l - x.l;
    const double dC = c2p - c1p;
    double dh = 0.0;
    if (c1p * c2p != 0.0) {
        dh = h2p - h1p;
        if (dh > 180.0) {
            dh -= 360.0;
        } else if (dh < -180.0) {
            dh += 360.0;
        }
    }
    const double dH = 2.0 * std::sqrt(c1p * c2p) * std::sin(radians(dh / 2.0));

    const double lMean = (x.l + y.l) / 2.0;
    const double cMean = (c1p + c2p) / 2.0;
    double hMean = h1p + h2p;
    if (c1p * c2p != 0.0) {
        if (std::abs(h1p - h2p) <= 180.0) {
            hMean /= 2.0;
        } else {
            hMean = hMean < 360.0 ? (hMean + 360.0) / 2.0 : (hMean - 360.0) / 2.0;
        }
    }
    const double t =
        1.0 - 0.17 * std::cos(radians(hMean - 30.0)) + 0.24 * std::cos(radians(2.0 * hMean)) +
        0.32 * std::cos(radians(3.0 * hMean + 6.0)) - 0.20 * std::cos(radians(4.0 * hMean - 63.0));
    const double dTheta = 30.0 * std::exp(-std::pow((hMean - 275.0) / 25.0, 2.0));
    const double cMeanP7 = std::pow(cMean, 7.0);
    const double rC = 2.0 * std::sqrt(cMeanP7 / (cMeanP7 + std::pow(25.0, 7.0)));
    const double lShift = (lMean - 50.0) * (lMean - 50.0);
    const double sL = 1.0 + 0.015 * lShift / std::sqrt(20.0 + lShift);
    const double sC = 1.0 + 0.045 * cMean;
    const double sH = 1.0 + 0.015 * cMean * t;
    const double rT = -std::sin(radians(2.0 * dTheta)) * rC;
    const double l = dL / sL;
    const double c = dC / sC;
    const double h = dH / sH;
    return std::sqrt(l * l + c * c + h * h + rT * c * h);
}

double ciede2000(QRgb x, QRgb y) noexcept {
    return ciede2000(toLab(x), toLab(y));
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
