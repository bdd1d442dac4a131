// SPDX-License-Identifier: GPL-3.0-or-later
#include "vv/colormaps/ColorMap.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include "vv/core/AsciiText.h"
#include "vv/core/Error.h"

namespace vv::colormaps {

namespace {

/// One control point: the map's sRGB colour at t = at / 255.
struct ControlPoint {
    float at;  ///< position in 1/255 steps, 0..255, strictly increasing within a table
    float r;
    float g;
    float b;
};

// The control points are entries of matplotlib's published 256-entry tables
// (viridis: van der Walt & Smith 2015; cividis: Nuñez, Anderton & Renslow
// 2018), entry k sitting at t = k / 255. The entries were chosen so that
// linear interpolation between them reproduces every one of the 256 published
// colours within half an 8-bit step per channel.
constexpr std::array kViridis{
    ControlPoint{0, 0.267004F, 0.004874F, 0.329415F},
    ControlPoint{7, 0.276022F, 0.044167F, 0.370164F},
    ControlPoint{20, 0.283197F, 0.115680F, 0.436115F},
    ControlPoint{32, 0.278826F, 0.175490F, 0.483397F},
    ControlPoint{44, 0.265145F, 0.232956F, 0.516599F},
    ControlPoint{58, 0.241237F, 0.296485F, 0.539709F},
    ControlPoint{78, 0.203063F, 0.379716F, 0.553925F},
    ControlPoint{110, 0.151918F, 0.500685F, 0.557587F},
    ControlPoint{131, 0.124395F, 0.578002F, 0.548287F},
    ControlPoint{142, 0.119699F, 0.618490F, 0.536347F},
    ControlPoint{150, 0.128087F, 0.647749F, 0.523491F},
    ControlPoint{158, 0.150148F, 0.676631F, 0.506589F},
    ControlPoint{166, 0.185783F, 0.704891F, 0.485273F},
    ControlPoint{176, 0.246070F, 0.738910F, 0.452024F},
    ControlPoint{187, 0.327796F, 0.773980F, 0.406640F},
    ControlPoint{200, 0.440137F, 0.811138F, 0.340967F},
    ControlPoint{215, 0.585678F, 0.846661F, 0.249897F},
    ControlPoint{233, 0.772852F, 0.877868F, 0.131109F},
    ControlPoint{239, 0.835270F, 0.886029F, 0.102646F},
    ControlPoint{243, 0.876168F, 0.891125F, 0.095250F},
    ControlPoint{247, 0.916242F, 0.896091F, 0.100717F},
    ControlPoint{252, 0.964894F, 0.902323F, 0.123941F},
    ControlPoint{255, 0.993248F, 0.906157F, 0.143936F},
};

constexpr std::array kCividis{
    ControlPoint{0, 0.000000F, 0.135112F, 0.304751F},
    ControlPoint{13, 0.000000F, 0.170800F, 0.393100F},
    ControlPoint{19, 0.000000F, 0.186915F, 0.435532F},
    ControlPoint{21, 0.000000F, 0.190950F, 0.441085F},
    ControlPoint{23, 0.003602F, 0.195911F, 0.441564F},
    ControlPoint{27, 0.058378F, 0.206629F, 0.439531F},
    ControlPoint{31, 0.095645F, 0.217643F, 0.436593F},
    ControlPoint{38, 0.142852F, 0.236972F, 0.431404F},
    ControlPoint{50, 0.204385F, 0.269823F, 0.425126F},
    ControlPoint{70, 0.287065F, 0.324103F, 0.423373F},
    ControlPoint{96, 0.380830F, 0.395164F, 0.435653F},
    ControlPoint{118, 0.455072F, 0.456718F, 0.458976F},
    ControlPoint{129, 0.492278F, 0.488198F, 0.471453F},
    ControlPoint{149, 0.566802F, 0.546715F, 0.469988F},
    ControlPoint{171, 0.652178F, 0.613664F, 0.453689F},
    ControlPoint{192, 0.736488F, 0.680629F, 0.424028F},
    ControlPoint{210, 0.811054F, 0.740801F, 0.385198F},
    ControlPoint{225, 0.875057F, 0.793125F, 0.339685F},
    ControlPoint{237, 0.927724F, 0.836486F, 0.290611F},
    ControlPoint{246, 0.968469F, 0.869819F, 0.241310F},
    ControlPoint{251, 0.992218F, 0.888385F, 0.205468F},
    ControlPoint{252, 0.994847F, 0.892954F, 0.203445F},
    ControlPoint{255, 0.995737F, 0.909344F, 0.217772F},
};

// matplotlib's inferno (van der Walt & Smith 2015), chosen from its 256-entry
// table like the two above.
constexpr std::array kInferno{
    ControlPoint{0.0F, 0.001462F, 0.000466F, 0.013866F},
    ControlPoint{3.0F, 0.004547F, 0.003392F, 0.030909F},
    ControlPoint{11.0F, 0.022447F, 0.017199F, 0.097327F},
    ControlPoint{19.0F, 0.056449F, 0.034569F, 0.168414F},
    ControlPoint{28.0F, 0.104551F, 0.047008F, 0.253430F},
    ControlPoint{36.0F, 0.155850F, 0.044559F, 0.325338F},
    ControlPoint{42.0F, 0.197297F, 0.038400F, 0.367535F},
    ControlPoint{48.0F, 0.238273F, 0.036621F, 0.396353F},
    ControlPoint{56.0F, 0.290763F, 0.045644F, 0.418637F},
    ControlPoint{67.0F, 0.360284F, 0.069247F, 0.431497F},
    ControlPoint{81.0F, 0.447428F, 0.101597F, 0.431080F},
    ControlPoint{96.0F, 0.540920F, 0.134729F, 0.415123F},
    ControlPoint{111.0F, 0.633998F, 0.168992F, 0.383704F},
    ControlPoint{126.0F, 0.724103F, 0.209670F, 0.337424F},
    ControlPoint{141.0F, 0.807082F, 0.262692F, 0.278898F},
    ControlPoint{155.0F, 0.873741F, 0.326906F, 0.216886F},
    ControlPoint{169.0F, 0.926470F, 0.405389F, 0.150292F},
    ControlPoint{182.0F, 0.961293F, 0.488716F, 0.084289F},
    ControlPoint{192.0F, 0.978422F, 0.557937F, 0.034931F},
    ControlPoint{196.0F, 0.982881F, 0.586606F, 0.024661F},
    ControlPoint{200.0F, 0.985952F, 0.615750F, 0.025592F},
    ControlPoint{204.0F, 0.987622F, 0.645320F, 0.039886F},
    ControlPoint{210.0F, 0.987464F, 0.690366F, 0.079990F},
    ControlPoint{219.0F, 0.981173F, 0.759135F, 0.156863F},
    ControlPoint{227.0F, 0.969783F, 0.820825F, 0.238686F},
    ControlPoint{234.0F, 0.956834F, 0.874129F, 0.323974F},
    ControlPoint{240.0F, 0.947594F, 0.917399F, 0.410665F},
    ControlPoint{245.0F, 0.947937F, 0.949318F, 0.491426F},
    ControlPoint{250.0F, 0.961812F, 0.975924F, 0.571925F},
    ControlPoint{255.0F, 0.988362F, 0.998364F, 0.644924F},
};

// ColorBrewer's RdBu with 11 classes (Brewer & Harrower, colorbrewer2.org),
// reversed so that low values are blue: its 11 published colours, evenly
// spaced, centre #f7f7f7. Lightness falls off alike on both sides.
constexpr std::array kBlueWhiteRed{
    ControlPoint{0.0F, 0x05 / 255.0F, 0x30 / 255.0F, 0x61 / 255.0F},
    ControlPoint{25.5F, 0x21 / 255.0F, 0x66 / 255.0F, 0xac / 255.0F},
    ControlPoint{51.0F, 0x43 / 255.0F, 0x93 / 255.0F, 0xc3 / 255.0F},
    ControlPoint{76.5F, 0x92 / 255.0F, 0xc5 / 255.0F, 0xde / 255.0F},
    ControlPoint{102.0F, 0xd1 / 255.0F, 0xe5 / 255.0F, 0xf0 / 255.0F},
    ControlPoint{127.5F, 0xf7 / 255.0F, 0xf7 / 255.0F, 0xf7 / 255.0F},
    ControlPoint{153.0F, 0xfd / 255.0F, 0xdb / 255.0F, 0xc7 / 255.0F},
    ControlPoint{178.5F, 0xf4 / 255.0F, 0xa5 / 255.0F, 0x82 / 255.0F},
    ControlPoint{204.0F, 0xd6 / 255.0F, 0x60 / 255.0F, 0x4d / 255.0F},
    ControlPoint{229.5F, 0xb2 / 255.0F, 0x18 / 255.0F, 0x2b / 255.0F},
    ControlPoint{255.0F, 0x67 / 255.0F, 0x00 / 255.0F, 0x1f / 255.0F},
};

/// Everything the module knows about one map.
struct Definition {
    ColorMap id;
    std::string_view name;
    std::string_view displayName;
    std::span<const ControlPoint> points;
    glm::vec3 noData;
    std::array<std::string_view, 2> aliases{};  ///< other accepted names; empty = none
};

const glm::vec3 kLightGrey{0.80F, 0.80F, 0.80F};
const glm::vec3 kMidGrey{0.50F, 0.50F, 0.50F};

const std::array kDefinitions{
    Definition{ColorMap::Viridis, "viridis", "Viridis", kViridis, kLightGrey, {}},
    Definition{ColorMap::Cividis, "cividis", "Cividis", kCividis, kLightGrey, {}},
    Definition{ColorMap::Inferno, "inferno", "Inferno", kInferno, kLightGrey, {}},
    Definition{ColorMap::BlueWhiteRed,
               "blue-white-red",
               "Blue-white-red (diverging)",
               kBlueWhiteRed,
               kMidGrey,
               {"bwr", "diverging"}},
};

constexpr std::array kAll{ColorMap::Viridis, ColorMap::Cividis, ColorMap::Inferno,
                          ColorMap::BlueWhiteRed};

static_assert(kAll.size() == kDefinitions.size(), "every map needs a definition");

const Definition& definition(ColorMap map) noexcept {
    for (const auto& d : kDefinitions) {
        if (d.id == map) {
            return d;
        }
    }
    return kDefinitions.front();  // unreachable for valid enum values
}

glm::vec3 rgb(const ControlPoint& p) noexcept {
    return {p.r, p.g, p.b};
}

float srgbToLinear(float c) noexcept {
    return c <= 0.04045F ? c / 12.92F : std::pow((c + 0.055F) / 1.055F, 2.4F);
}

}  // namespace

std::span<const ColorMap> allColorMaps() noexcept {
    return kAll;
}

std::string_view name(ColorMap map) noexcept {
    return definition(map).name;
}

std::string_view displayName(ColorMap map) noexcept {
    return definition(map).displayName;
}

std::optional<ColorMap> colorMapFromName(std::string_view text) noexcept {
    const auto matches = [&](std::string_view candidate) {
        return !candidate.empty() && equalsIgnoringCase(candidate, text);
    };
    for (const auto& d : kDefinitions) {
        if (matches(d.name) || matches(d.aliases[0]) || matches(d.aliases[1])) {
            return d.id;
        }
    }
    return std::nullopt;
}

glm::vec3 noDataColor(ColorMap map) noexcept {
    return definition(map).noData;
}

glm::vec3 sample(ColorMap map, float t) noexcept {
    const Definition& d = definition(map);
    if (std::isnan(t)) {
        return d.noData;
    }
    const auto points = d.points;
    const float x = std::clamp(t, 0.0F, 1.0F) * 255.0F;
    // First control point strictly beyond x (the tables are short: a linear scan is fine).
    std::size_t upper = 1;
    while (upper + 1 < points.size() && static_cast<float>(points[upper].at) < x) {
        ++upper;
    }
    const ControlPoint& a = points[upper - 1];
    const ControlPoint& b = points[upper];
    const float span = static_cast<float>(b.at - a.at);
    const float f = std::clamp((x - static_cast<float>(a.at)) / span, 0.0F, 1.0F);
    return glm::mix(rgb(a), rgb(b), f);
}

void validateBins(int bins) {
    if (bins != 0 && (bins < 2 || bins > kMaxBins)) {
        throw InvalidArgumentError("colour map bins must be 0 (continuous) or within 2.." +
                                   std::to_string(kMaxBins) + ", got " + std::to_string(bins));
    }
}

int binIndex(float t, int bins) noexcept {
    if (bins < 2 || std::isnan(t)) {
        return 0;
    }
    const float x = std::clamp(t, 0.0F, 1.0F) * static_cast<float>(bins);
    return std::min(static_cast<int>(std::floor(x)), bins - 1);
}

glm::vec3 sample(ColorMap map, float t, int bins) noexcept {
    if (bins < 2 || std::isnan(t)) {
        return sample(map, t);
    }
    return sample(map, static_cast<float>(binIndex(t, bins)) / static_cast<float>(bins - 1));
}

std::vector<glm::u8vec4> lut(ColorMap map, int n) {
    if (n < 2 || n > 65536) {
        throw InvalidArgumentError("colour map look-up table size must be in [2, 65536], got " +
                                   std::to_string(n));
    }
    std::vector<glm::u8vec4> table(static_cast<std::size_t>(n));
    const float last = static_cast<float>(n - 1);
    for (int i = 0; i < n; ++i) {
        table[static_cast<std::size_t>(i)] = toRgba8(sample(map, static_cast<float>(i) / last));
    }
    return table;
}

glm::u8vec4 toRgba8(const glm::vec3& srgb) noexcept {
    const auto channel = [](float c) {
        const float v = std::isnan(c) ? 0.0F : std::clamp(c, 0.0F, 1.0F);
        return static_cast<std::uint8_t>(std::lround(v * 255.0F));
    };
    return {channel(srgb.r), channel(srgb.g), channel(srgb.b), std::uint8_t{255}};
}

float cieLightness(const glm::vec3& srgb) noexcept {
    // Relative luminance Y (sRGB primaries, D65) -> L*.
    const float y = 0.2126F * srgbToLinear(srgb.r) + 0.7152F * srgbToLinear(srgb.g) +
                    0.0722F * srgbToLinear(srgb.b);
    constexpr float kEpsilon = 216.0F / 24389.0F;
    constexpr float kKappa = 24389.0F / 27.0F;
    return y > kEpsilon ? 116.0F * std::cbrt(y) - 16.0F : kKappa * y;
}

}  // namespace vv::colormaps
