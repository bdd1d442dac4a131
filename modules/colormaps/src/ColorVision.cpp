// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/colormaps/ColorVision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

namespace vv::colormaps {

namespace {

constexpr std::array kAllVisions{ColorVision::Normal, ColorVision::Protanopia,
                                 ColorVision::Deuteranopia, ColorVision::Tritanopia};

using Matrix = std::array<std::array<double, 3>, 3>;

constexpr Matrix kIdentity{{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
// Machado, Oliveira & Fernandes (2009), "A Physiologically-based Model for
// Simulation of Color Vision Deficiency", IEEE TVCG 15(6); the severity 1.0
// matrices of their published table (linear RGB).
constexpr Matrix kProtanopia{{{0.152286, 1.052583, -0.204868},
                              {0.114503, 0.786281, 0.099216},
                              {-0.003882, -0.048116, 1.051998}}};
constexpr Matrix kDeuteranopia{{{0.367322, 0.860646, -0.227968},
                                {0.280085, 0.672501, 0.047413},
                                {-0.011820, 0.042940, 0.968881}}};
constexpr Matrix kTritanopia{{{1.255528, -0.076749, -0.178779},
                              {-0.078411, 0.930809, 0.147602},
                              {0.004733, 0.691367, 0.303900}}};

// D65 reference white of sRGB (Y normalised to 1).
constexpr double kWhiteX = 0.95047;
constexpr double kWhiteY = 1.0;
constexpr double kWhiteZ = 1.08883;

double labF(double t) noexcept {
    constexpr double kDelta = 6.0 / 29.0;
    return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

double clamp01(double v) noexcept {
    return std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
}

double degrees(double radians) noexcept {
    return radians * 180.0 / std::numbers::pi;
}

double radians(double degrees) noexcept {
    return degrees * std::numbers::pi / 180.0;
}

double pow7(double v) noexcept {
    const double v2 = v * v;
    return v2 * v2 * v2 * v;
}

}  // namespace

std::span<const ColorVision> allColorVisions() noexcept {
    return kAllVisions;
}

std::string_view name(ColorVision vision) noexcept {
    switch (vision) {
        case ColorVision::Normal:
            return "normal";
        case ColorVision::Protanopia:
            return "protanopia";
        case ColorVision::Deuteranopia:
            return "deuteranopia";
        case ColorVision::Tritanopia:
            return "tritanopia";
    }
    return "normal";
}

double srgbToLinear(double encoded) noexcept {
    const double c = clamp01(encoded);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double linear) noexcept {
    const double c = clamp01(linear);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

glm::dvec3 srgbToLinear(const glm::dvec3& srgb) noexcept {
    return {srgbToLinear(srgb.r), srgbToLinear(srgb.g), srgbToLinear(srgb.b)};
}

glm::dvec3 linearToSrgb(const glm::dvec3& linear) noexcept {
    return {linearToSrgb(linear.r), linearToSrgb(linear.g), linearToSrgb(linear.b)};
}

Lab srgbToLab(const glm::dvec3& srgb) noexcept {
    const glm::dvec3 c = srgbToLinear(srgb);
    // sRGB primaries, D65 (IEC 61966-2-1).
    const double x = 0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b;
    const double y = 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b;
    const double z = 0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b;
    const double fx = labF(x / kWhiteX);
    const double fy = labF(y / kWhiteY);
    const double fz = labF(z / kWhiteZ);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(const Lab& first, const Lab& second) noexcept {
    // Sharma, Wu & Dalal (2005), equations (1)-(17), kL = kC = kH = 1.
    const double c1 = std::hypot(first.a, first.b);
    const double c2 = std::hypot(second.a, second.b);
    const double cMean7 = pow7((c1 + c2) / 2.0);
    const double g = 0.5 * (1.0 - std::sqrt(cMean7 / (cMean7 + pow7(25.0))));
    const double a1 = (1.0 + g) * first.a;
    const double a2 = (1.0 + g) * second.a;
    const double cp1 = std::hypot(a1, first.b);
    const double cp2 = std::hypot(a2, second.b);
    auto hue = [](double b, double a) {
        if (b == 0.0 && a == 0.0) {
            return 0.0;
        }
        const double h = degrees(std::atan2(b, a));
        return h < 0.0 ? h + 360.0 : h;
    };
    const double h1 = hue(first.b, a1);
    const double h2 = hue(second.b, a2);

    const double dL = second.l - first.l;
    const double dC = cp2 - cp1;
    double dh = 0.0;
    if (cp1 * cp2 != 0.0) {
        dh = h2 - h1;
        if (dh > 180.0) {
            dh -= 360.0;
        } else if (dh < -180.0) {
            dh += 360.0;
        }
    }
    const double dH = 2.0 * std::sqrt(cp1 * cp2) * std::sin(radians(dh / 2.0));

    const double lMean = (first.l + second.l) / 2.0;
    const double cpMean = (cp1 + cp2) / 2.0;
    double hMean = h1 + h2;
    if (cp1 * cp2 != 0.0) {
        if (std::abs(h1 - h2) <= 180.0) {
            hMean = (h1 + h2) / 2.0;
        } else if (h1 + h2 < 360.0) {
            hMean = (h1 + h2 + 360.0) / 2.0;
        } else {
            hMean = (h1 + h2 - 360.0) / 2.0;
        }
    }
    const double t =
        1.0 - 0.17 * std::cos(radians(hMean - 30.0)) + 0.24 * std::cos(radians(2.0 * hMean)) +
        0.32 * std::cos(radians(3.0 * hMean + 6.0)) - 0.20 * std::cos(radians(4.0 * hMean - 63.0));
    const double dTheta = 30.0 * std::exp(-std::pow((hMean - 275.0) / 25.0, 2.0));
    const double cpMean7 = pow7(cpMean);
    const double rc = 2.0 * std::sqrt(cpMean7 / (cpMean7 + pow7(25.0)));
    const double l50 = (lMean - 50.0) * (lMean - 50.0);
    const double sl = 1.0 + 0.015 * l50 / std::sqrt(20.0 + l50);
    const double sc = 1.0 + 0.045 * cpMean;
    const double sh = 1.0 + 0.015 * cpMean * t;
    const double rt = -std::sin(radians(2.0 * dTheta)) * rc;
    const double tl = dL / sl;
    const double tc = dC / sc;
    const double th = dH / sh;
    return std::sqrt(std::max(0.0, tl * tl + tc * tc + th * th + rt * tc * th));
}

double ciede2000(const glm::dvec3& srgbFirst, const glm::dvec3& srgbSecond) noexcept {
    return ciede2000(srgbToLab(srgbFirst), srgbToLab(srgbSecond));
}

const std::array<std::array<double, 3>, 3>& machadoMatrix(ColorVision vision) noexcept {
    switch (vision) {
        case ColorVision::Normal:
            return kIdentity;
        case ColorVision::Protanopia:
            return kProtanopia;
        case ColorVision::Deuteranopia:
            return kDeuteranopia;
        case ColorVision::Tritanopia:
            return kTritanopia;
    }
    return kIdentity;
}

glm::dvec3 simulate(ColorVision vision, const glm::dvec3& srgb) noexcept {
    if (vision == ColorVision::Normal) {
        return {clamp01(srgb.r), clamp01(srgb.g), clamp01(srgb.b)};
    }
    const Matrix& m = machadoMatrix(vision);
    const glm::dvec3 c = srgbToLinear(srgb);
    glm::dvec3 out;
    for (int i = 0; i < 3; ++i) {
        const auto row = static_cast<std::size_t>(i);
        out[i] = m[row][0] * c.r + m[row][1] * c.g + m[row][2] * c.b;
    }
    return linearToSrgb(out);  // clamps to [0, 1]
}

RampCheck checkRamp(std::span<const glm::dvec3> steps, ColorVision vision,
                    double lightnessTolerance) {
    RampCheck check;
    if (steps.size() < 2) {
        return check;
    }
    std::vector<Lab> labs;
    labs.reserve(steps.size());
    for (const glm::dvec3& step : steps) {
        labs.push_back(srgbToLab(simulate(vision, step)));
        check.lightness.push_back(labs.back().l);
    }
    const double direction = labs.back().l >= labs.front().l ? 1.0 : -1.0;
    check.monotonicLightness = true;
    check.minAdjacentDelta = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < labs.size(); ++i) {
        const double rise = direction * (labs[i + 1].l - labs[i].l);
        if (!(rise > 0.0 && rise >= lightnessTolerance)) {
            check.monotonicLightness = false;
        }
        const double delta = ciede2000(labs[i], labs[i + 1]);
        if (delta < check.minAdjacentDelta) {
            check.minAdjacentDelta = delta;
            check.minAdjacentIndex = static_cast<int>(i);
        }
    }
    return check;
}

std::vector<PaletteEntry> dominantColors(std::span<const glm::u8vec3> pixels, int levels,
                                         double minFraction) {
    std::vector<PaletteEntry> palette;
    if (pixels.empty()) {
        return palette;
    }
    levels = std::clamp(levels, 2, 256);
    struct Bin {
        glm::dvec3 sum{0.0};
        std::size_t count = 0;
    };
    std::unordered_map<std::uint32_t, Bin> bins;
    for (const glm::u8vec3& p : pixels) {
        auto index = [levels](std::uint8_t v) {
            return static_cast<std::uint32_t>(static_cast<int>(v) * levels / 256);
        };
        const std::uint32_t key = (index(p.r) * 256U + index(p.g)) * 256U + index(p.b);
        Bin& bin = bins[key];
        bin.sum += glm::dvec3(p) / 255.0;
        ++bin.count;
    }
    const auto total = static_cast<double>(pixels.size());
    for (const auto& [key, bin] : bins) {
        const double fraction = static_cast<double>(bin.count) / total;
        if (fraction >= minFraction) {
            palette.push_back({bin.sum / static_cast<double>(bin.count), fraction});
        }
    }
    std::sort(palette.begin(), palette.end(),
              [](const PaletteEntry& a, const PaletteEntry& b) { return a.fraction > b.fraction; });
    return palette;
}

std::vector<ConfusionPair> findRedGreenConfusions(std::span<const glm::dvec3> colors,
                                                  const ConfusionCriteria& criteria) {
    std::vector<Lab> normal;
    std::vector<Lab> protan;
    std::vector<Lab> deutan;
    for (const glm::dvec3& c : colors) {
        normal.push_back(srgbToLab(c));
        protan.push_back(srgbToLab(simulate(ColorVision::Protanopia, c)));
        deutan.push_back(srgbToLab(simulate(ColorVision::Deuteranopia, c)));
    }
    std::vector<ConfusionPair> pairs;
    for (std::size_t i = 0; i < colors.size(); ++i) {
        for (std::size_t j = i + 1; j < colors.size(); ++j) {
            const double normalDelta = ciede2000(normal[i], normal[j]);
            if (normalDelta < criteria.minNormalDelta) {
                continue;
            }
            const double p = ciede2000(protan[i], protan[j]);
            const double d = ciede2000(deutan[i], deutan[j]);
            const bool protanWorse = p <= d;
            const double simulated = protanWorse ? p : d;
            if (simulated < criteria.maxSimulatedDelta) {
                pairs.push_back({colors[i], colors[j],
                                 protanWorse ? ColorVision::Protanopia : ColorVision::Deuteranopia,
                                 normalDelta, simulated});
            }
        }
    }
    return pairs;
}

}  // namespace vv::colormaps
