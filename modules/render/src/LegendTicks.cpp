// SPDX-License-Identifier: GPL-3.0-or-later
// The legends' ticks and their text (LegendPainter.h): values, positions and
// labels in the UI locale (QLocale()), one precision per legend.
#include <QLocale>
#include <QString>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "vv/render/LegendPainter.h"

namespace vv::render {

namespace {

constexpr int kMaxDecimals = 9;

/// Decimals a step needs (0.25 -> 2, 5 -> 0).
int decimalsFor(double step) {
    if (!(step > 0.0)) {
        return 0;
    }
    int decimals = 0;
    double scaled = step;
    while (decimals < kMaxDecimals &&
           std::abs(scaled - std::round(scaled)) > 1e-6 * std::max(1.0, scaled)) {
        scaled *= 10.0;
        ++decimals;
    }
    return decimals;
}

double roundTo(double value, int decimals) {
    const double scale = std::pow(10.0, decimals);
    return std::round(value * scale) / scale;
}

/// Decimals that show `lo` and `hi` to 3 significant digits of the larger
/// magnitude, without trailing zeros both share (1 and 3 need none).
int endDecimals(double lo, double hi) {
    const double magnitude = std::max(std::abs(lo), std::abs(hi));
    if (!(magnitude > 0.0)) {
        return 0;
    }
    const int digits = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    const int most = std::clamp(3 - digits, 0, kMaxDecimals);
    int decimals = 0;
    while (decimals < most && (roundTo(lo, decimals) != roundTo(lo, most) ||
                               roundTo(hi, decimals) != roundTo(hi, most))) {
        ++decimals;
    }
    return decimals;
}

double niceStep(double span, int maxTicks) {
    const double raw = span / static_cast<double>(std::max(maxTicks - 1, 1));
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    const double normalized = raw / magnitude;
    double nice = 10.0;
    if (normalized <= 1.0) {
        nice = 1.0;
    } else if (normalized <= 2.0) {
        nice = 2.0;
    } else if (normalized <= 2.5) {
        nice = 2.5;
    } else if (normalized <= 5.0) {
        nice = 5.0;
    }
    return nice * magnitude;
}

/// Every tick's label with `decimals` digits.
void label(std::vector<LegendTick>& ticks, int decimals) {
    for (LegendTick& tick : ticks) {
        tick.label = legendNumber(tick.value, decimals);
    }
}

}  // namespace

QString legendNumber(double value, int decimals) {
    const int d = std::clamp(decimals, 0, kMaxDecimals);
    // "-0.0" reads as a sign error: a value that rounds to zero is zero.
    const double shown = roundTo(value, d) == 0.0 ? 0.0 : value;
    const double magnitude = std::abs(shown);
    if (magnitude >= 1e9 || (magnitude > 0.0 && magnitude < 1e-6)) {
        return QLocale().toString(shown, 'g', 3);
    }
    return QLocale().toString(shown, 'f', d);
}

std::vector<LegendTick> legendTicks(double lo, double hi, int maxTicks) {
    std::vector<LegendTick> ticks;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
        const double value = std::isfinite(lo) ? lo : 0.0;
        ticks.push_back({value, 0.0, {}});
        label(ticks, endDecimals(value, value));
        return ticks;
    }
    const double span = hi - lo;
    const double step = niceStep(span, std::max(maxTicks, 2));
    ticks.push_back({lo, 0.0, {}});
    const double first = std::ceil(lo / step) * step;
    for (int k = 0;; ++k) {
        const double value = first + static_cast<double>(k) * step;
        if (value > hi - 0.35 * step) {
            break;
        }
        if (value < lo + 0.35 * step) {
            continue;
        }
        ticks.push_back({value, (value - lo) / span, {}});
    }
    ticks.push_back({hi, 1.0, {}});
    label(ticks, std::max(decimalsFor(step), endDecimals(lo, hi)));
    return ticks;
}

std::vector<LegendTick> binEdgeTicks(double lo, double hi, int bins) {
    if (bins < 2 || !std::isfinite(lo) || !std::isfinite(hi) || !(hi > lo)) {
        return legendTicks(lo, hi);
    }
    std::vector<LegendTick> ticks;
    for (int i = 0; i <= bins; ++i) {
        const double position = static_cast<double>(i) / static_cast<double>(bins);
        const double value = i == bins ? hi : lo + (hi - lo) * position;
        ticks.push_back({value, position, {}});
    }
    // Enough digits that neighbouring edges read differently.
    int decimals = endDecimals(lo, hi);
    const auto distinct = [&](int d) {
        for (std::size_t i = 1; i < ticks.size(); ++i) {
            if (roundTo(ticks[i].value, d) == roundTo(ticks[i - 1].value, d)) {
                return false;
            }
        }
        return true;
    };
    while (decimals < kMaxDecimals && !distinct(decimals)) {
        ++decimals;
    }
    label(ticks, decimals);
    return ticks;
}

std::vector<std::size_t> labelledTicks(const std::vector<double>& centres,
                                       const std::vector<double>& widths, double gap) {
    const std::size_t n = std::min(centres.size(), widths.size());
    if (n < 2) {
        return n == 0 ? std::vector<std::size_t>{} : std::vector<std::size_t>{0};
    }
    const auto fits = [&](std::size_t a, std::size_t b) {
        return centres[a] + widths[a] / 2.0 + gap <= centres[b] - widths[b] / 2.0;
    };
    // Chains of labels from the first tick: spread[c][i] is the widest
    // smallest distance between neighbours of a chain of c + 1 labels that
    // ends at tick i (negative: no such chain); from[c][i] its label before i.
    constexpr double kNone = -1.0;
    std::vector<std::vector<double>> spread(n, std::vector<double>(n, kNone));
    std::vector<std::vector<std::size_t>> from(n, std::vector<std::size_t>(n, 0));
    spread[0][0] = std::numeric_limits<double>::infinity();
    std::size_t most = 0;  // labels - 1 of the longest chain that reaches the last tick
    for (std::size_t c = 1; c < n; ++c) {
        for (std::size_t i = c; i < n; ++i) {
            for (std::size_t j = c - 1; j < i; ++j) {
                if (spread[c - 1][j] < 0.0 || !fits(j, i)) {
                    continue;
                }
                const double s = std::min(spread[c - 1][j], centres[i] - centres[j]);
                if (s > spread[c][i]) {
                    spread[c][i] = s;
                    from[c][i] = j;
                }
            }
        }
        if (spread[c][n - 1] >= 0.0) {
            most = c;
        }
    }
    if (most == 0) {
        return {0, n - 1};  // even the ends alone collide: both are shown anyway
    }
    std::vector<std::size_t> chosen(most + 1);
    std::size_t at = n - 1;
    for (std::size_t c = most + 1; c-- > 0;) {
        chosen[c] = at;
        at = from[c][at];
    }
    return chosen;
}

std::vector<LegendTick> depthLegendTicks(const DepthLegend& legend, int maxTicks) {
    const double dmin = legend.dmin;
    const double dmax = legend.dmax;
    if (legend.reference == DepthReference::Camera) {
        return legendTicks(dmin, dmax, maxTicks);
    }
    const double span = (std::isfinite(dmin) && std::isfinite(dmax)) ? dmax - dmin : 0.0;
    return legendTicks(0.0, span, maxTicks);
}

}  // namespace vv::render
