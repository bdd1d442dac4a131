// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SettingsSchema.h"

#include <QtGlobal>
#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "vv/colormaps/ColorMap.h"
#include "vv/colormaps/DepthScale.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"
#include "vv/vss/DepthNormalization.h"
#include "vv/vss/Solver.h"

namespace vv::app {

namespace {

// --- Fields: a value of the schema's types from a struct member and back ----

template <typename T>
SettingValue toValue(const T& field) {
    if constexpr (std::is_enum_v<T>) {
        return static_cast<int>(field);
    } else if constexpr (std::is_same_v<T, float>) {
        return static_cast<double>(field);
    } else if constexpr (std::is_same_v<T, std::optional<glm::vec3>>) {
        return field ? SettingValue(*field) : SettingValue(NoValue{});
    } else {
        return field;
    }
}

template <typename T>
void assign(T& field, const SettingValue& value) {
    if constexpr (std::is_enum_v<T>) {
        field = static_cast<T>(std::get<int>(value));
    } else if constexpr (std::is_same_v<T, float>) {
        field = static_cast<float>(std::get<double>(value));
    } else if constexpr (std::is_same_v<T, std::optional<glm::vec3>>) {
        field = std::holds_alternative<NoValue>(value)
                    ? std::nullopt
                    : std::optional<glm::vec3>(std::get<glm::vec3>(value));
    } else {
        field = std::get<T>(value);
    }
}

/// The field that `Access` (a captureless lambda `(auto& d) -> auto&`) reaches.
template <typename Access>
SettingField field(Access /*access*/) {
    return {[](const DisplaySettings& d) { return toValue(Access{}(d)); },
            [](DisplaySettings& d, const SettingValue& v) { assign(Access{}(d), v); }};
}

/// A per-object setting: no field of its own; reads as `object`'s default.
template <typename Access>
SettingField objectDefault(Access /*access*/) {
    return {[](const DisplaySettings& /*d*/) {
                static const render::ObjectStyle kDefault;
                return toValue(Access{}(kDefault));
            },
            nullptr};
}

// --- The choices ---------------------------------------------------------------

template <typename Enum, std::size_t N>
std::vector<int> valuesOf(const std::span<const Enum, N> all) {
    std::vector<int> out;
    for (const Enum e : all) {
        out.push_back(static_cast<int>(e));
    }
    return out;
}

template <typename Enum>
std::optional<int> optionalInt(std::optional<Enum> e) {
    return e ? std::optional<int>(static_cast<int>(*e)) : std::nullopt;
}

const ChoiceSet kDepthScales{
    [] { return valuesOf(colormaps::allDepthScales()); },
    [](int v) { return colormaps::name(static_cast<colormaps::DepthScale>(v)); },
    [](std::string_view n) { return optionalInt(colormaps::depthScaleFromName(n)); }};

constexpr std::array kSolverKinds{vss::SolverKind::Reference, vss::SolverKind::Brute,
                                  vss::SolverKind::Step, vss::SolverKind::Fast};
const ChoiceSet kSolvers{[] { return valuesOf(std::span<const vss::SolverKind>(kSolverKinds)); },
                         [](int v) { return vss::toString(static_cast<vss::SolverKind>(v)); },
                         [](std::string_view n) -> std::optional<int> {
                             try {
                                 return static_cast<int>(vss::parseSolverKind(n));
                             } catch (const InvalidArgumentError&) {
                                 return std::nullopt;
                             }
                         }};

constexpr std::array kRangeModes{vss::RangeMode::Visible, vss::RangeMode::Fixed};
std::string_view rangeModeName(int v) {
    return static_cast<vss::RangeMode>(v) == vss::RangeMode::Fixed ? "fixed" : "visible";
}
const ChoiceSet kRangeModeSet{[] { return valuesOf(std::span<const vss::RangeMode>(kRangeModes)); },
                              rangeModeName,
                              [](std::string_view n) -> std::optional<int> {
                                  for (const auto mode : kRangeModes) {
                                      if (rangeModeName(static_cast<int>(mode)) == n) {
                                          return static_cast<int>(mode);
                                      }
                                  }
                                  return std::nullopt;
                              }};

const ChoiceSet kCues{[] { return valuesOf(render::allVesselCues()); },
                      [](int v) { return render::name(static_cast<render::VesselCue>(v)); },
                      [](std::string_view n) { return optionalInt(render::vesselCueFromName(n)); }};

const ChoiceSet kArrayValues{
    [] { return valuesOf(render::allArrayValues()); },
    [](int v) { return render::name(static_cast<render::ArrayValues>(v)); },
    [](std::string_view n) { return optionalInt(render::arrayValuesFromName(n)); }};

const ChoiceSet kColorMaps{
    [] { return valuesOf(colormaps::allColorMaps()); },
    [](int v) { return colormaps::name(static_cast<colormaps::ColorMap>(v)); },
    [](std::string_view n) { return optionalInt(colormaps::colorMapFromName(n)); }};

// --- The table -------------------------------------------------------------------

constexpr double kMaxDepth = 1.0e6;        ///< fixed VSS depth range, scene units
constexpr double kMaxArrayValue = 1.0e12;  ///< colour-map range
constexpr WidgetHint kPercent{.decimals = 0, .step = 1.0, .scale = 100.0, .suffix = " %"};

using enum SettingType;

// Each entry names only what differs from Setting's defaults; GCC 12 warns
// about every member a designated initializer leaves to its default.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
/// The Void Space Surface and ambient occlusion.
std::vector<Setting> surfaceSettings() {
    return {
        // The Void Space Surface.
        {.key = "vss.enabled",
         .storedKey = "vss",
         .cliOption = "--vss",
         .type = Bool,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Show the Void Space Surface"),
         .field = field([](auto& d) -> auto& { return d.vss.enabled; })},
        {.key = "vss.p",
         .storedKey = "power",
         .cliOption = "--p",
         .min = 0.25,
         .max = 64.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Power p"),
         .widget = {.decimals = 2, .step = 0.25},
         .field = field([](auto& d) -> auto& { return d.vss.solver.p; })},
        {.key = "vss.solver",
         .storedKey = "solver",
         .cliOption = "--solver",
         .type = Choice,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Solver"),
         .choices = &kSolvers,
         .field = field([](auto& d) -> auto& { return d.vss.solver.kind; })},
        {.key = "vss.tolerance",
         .storedKey = "tolerance",
         .cliOption = "--tolerance",
         .min = 0.05 / 255.0,
         .max = 32.0 / 255.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Tolerance"),
         .widget = {.decimals = 2, .step = 0.25, .scale = 255.0, .suffix = " / 255"},
         .field = field([](auto& d) -> auto& { return d.vss.solver.tolerance; })},
        {.key = "vss.step",
         .storedKey = "step",
         .cliOption = "--step",
         .type = Int,
         .min = 1,
         .max = 64,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Step k"),
         .field = field([](auto& d) -> auto& { return d.vss.solver.step; })},
        {.key = "vss.scale",
         .storedKey = "depthScale",
         .cliOption = "--scale",
         .type = Choice,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Colour scale"),
         .choices = &kDepthScales,
         .field = field([](auto& d) -> auto& { return d.vss.scale; })},
        {.key = "vss.isoLines",
         .storedKey = "isoLines",
         .cliOption = "--isolines",
         .type = Int,
         .min = 0,
         .max = 64,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Iso-lines"),
         .field = field([](auto& d) -> auto& { return d.vss.isoLines; })},
        {.key = "vss.isoLineWidth",
         .cliOption = "--isoline-width",
         .min = 0.0,
         .max = 64.0,
         .unit = "px",
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Iso-line width"),
         .widget = {.decimals = 1, .step = 0.5, .suffix = " px"},
         .field = field([](auto& d) -> auto& { return d.vss.isoLineWidth; })},
        {.key = "vss.isoLineStrength",
         .storedKey = "isoLineStrength",
         .cliOption = "--isoline-strength",
         .min = 0.0,
         .max = 1.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Iso-line strength"),
         .widget = kPercent,
         .field = field([](auto& d) -> auto& { return d.vss.isoLineStrength; })},
        {.key = "vss.lighting",
         .storedKey = "lighting",
         .cliOption = "--vss-lighting",
         .min = 0.0,
         .max = 1.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Lighting"),
         .widget = kPercent,
         .field = field([](auto& d) -> auto& { return d.vss.lighting; })},
        {.key = "vss.opacity",
         .cliOption = "--vss-opacity",
         .min = 0.0,
         .max = 1.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "VSS opacity"),
         .widget = kPercent,
         .field = field([](auto& d) -> auto& { return d.vss.opacity; })},
        {.key = "vss.range.mode",
         .type = Choice,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Depth range"),
         .session = SessionForm::Structured,
         .choices = &kRangeModeSet,
         .field = field([](auto& d) -> auto& { return d.vss.range.mode; })},
        {.key = "vss.range.near",
         .min = -kMaxDepth,
         .max = kMaxDepth,
         .unit = "mm",
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Near depth"),
         .session = SessionForm::Structured,
         .widget = {.decimals = 1, .step = 1.0, .suffix = " mm"},
         .field = field([](auto& d) -> auto& { return d.vss.range.dmin; })},
        {.key = "vss.range.far",
         .min = -kMaxDepth,
         .max = kMaxDepth,
         .unit = "mm",
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Far depth"),
         .session = SessionForm::Structured,
         .widget = {.decimals = 1, .step = 1.0, .suffix = " mm"},
         .field = field([](auto& d) -> auto& { return d.vss.range.dmax; })},
        // Ambient occlusion.
        {.key = "ao.enabled",
         .storedKey = "ao",
         .cliOption = "--ao",
         .type = Bool,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Ambient occlusion"),
         .field = field([](auto& d) -> auto& { return d.ao.enabled; })},
        {.key = "ao.radius",
         .storedKey = "aoRadius",
         .cliOption = "--ao-radius",
         .min = 0.01,
         .max = 1000.0,
         .unit = "mm",
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "AO radius"),
         .widget = {.decimals = 2, .step = 0.5},
         .field = field([](auto& d) -> auto& { return d.ao.radius; })},
        {.key = "ao.strength",
         .cliOption = "--ao-strength",
         .min = 0.0,
         .max = 1.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "AO strength"),
         .widget = kPercent,
         .field = field([](auto& d) -> auto& { return d.ao.strength; })},
    };
}

/// The vessels: cue, array colouring, material, light.
std::vector<Setting> vesselSettings() {
    return {
        // The vessels.
        {.key = "cue.cue",
         .storedKey = "vesselCue",
         .cliOption = "--cue",
         .type = Choice,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Vessel cue"),
         .storedAsIndex = true,
         .choices = &kCues,
         .field = field([](auto& d) -> auto& { return d.cue.cue; })},
        {.key = "cue.fogStrength",
         .cliOption = "--fog-strength",
         .min = 0.0,
         .max = 1.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Fog strength"),
         .widget = kPercent,
         .field = field([](auto& d) -> auto& { return d.cue.fogStrength; })},
        {.key = "cue.fresnelExponent",
         .cliOption = "--fresnel-exponent",
         .min = 0.25,
         .max = 8.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Fresnel exponent"),
         .widget = {.decimals = 2, .step = 0.25},
         .field = field([](auto& d) -> auto& { return d.cue.fresnelExponent; })},
        {.key = "style.array",
         .cliOption = "--array",
         .type = Text,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Array"),
         .keepOnReset = true,
         .field = field([](auto& d) -> auto& { return d.style.array; })},
        {.key = "style.colorMap",
         .storedKey = "colorMap",
         .cliOption = "--colormap",
         .type = Choice,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Colour map"),
         .choices = &kColorMaps,
         .field = field([](auto& d) -> auto& { return d.style.colorMap; })},
        {.key = "style.bins",
         .storedKey = "bins",
         .cliOption = "--bins",
         .type = Int,
         .min = 2,
         .max = colormaps::kMaxBins,
         .zeroAllowed = true,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Colour-map bins"),
         .field = field([](auto& d) -> auto& { return d.style.bins; })},
        {.key = "style.range[0]",
         .min = -kMaxArrayValue,
         .max = kMaxArrayValue,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Colour range minimum"),
         .session = SessionForm::Structured,
         .keepOnReset = true,
         .widget = {.decimals = 3},
         .field = {[](const DisplaySettings& d) -> SettingValue {
                       return d.style.range ? static_cast<double>(d.style.range->first) : 0.0;
                   },
                   nullptr}},
        {.key = "style.range[1]",
         .min = -kMaxArrayValue,
         .max = kMaxArrayValue,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Colour range maximum"),
         .session = SessionForm::Structured,
         .keepOnReset = true,
         .widget = {.decimals = 3},
         .field = {[](const DisplaySettings& d) -> SettingValue {
                       return d.style.range ? static_cast<double>(d.style.range->second) : 0.0;
                   },
                   nullptr}},
        {.key = "style.noDataColor",
         .type = Color,
         .nullable = true,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "No-data colour"),
         .session = SessionForm::Optional,
         .keepOnReset = true,
         .field = field([](auto& d) -> auto& { return d.style.noDataColor; })},
        {.key = "style.legendTitle",
         .cliOption = "--legend-title",
         .type = Text,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Legend title"),
         .session = SessionForm::Optional,
         .keepOnReset = true,
         .field = field([](auto& d) -> auto& { return d.style.legendTitle; })},
        {.key = "style.values",
         .cliOption = "--values",
         .type = Choice,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Values"),
         .session = SessionForm::Optional,
         .keepOnReset = true,
         .choices = &kArrayValues,
         .field = field([](auto& d) -> auto& { return d.style.values; })},
        {.key = "style.vesselColor",
         .storedKey = "vesselColor",
         .cliOption = "--vessel-color",
         .type = Color,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Vessel colour"),
         .field = field([](auto& d) -> auto& { return d.style.vesselColor; })},
        {.key = "style.light[0]",
         .storedKey = "lightAzimuth",
         .cliOption = "--light",
         .min = -180.0,
         .max = 180.0,
         .unit = "°",
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Light azimuth"),
         .session = SessionForm::Optional,
         .widget = {.decimals = 1, .step = 5.0, .suffix = "°"},
         .field = field([](auto& d) -> auto& { return d.style.light.azimuth; })},
        {.key = "style.light[1]",
         .storedKey = "lightElevation",
         .cliOption = "--light",
         .min = -90.0,
         .max = 90.0,
         .unit = "°",
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Light elevation"),
         .session = SessionForm::Optional,
         .widget = {.decimals = 1, .step = 5.0, .suffix = "°"},
         .field = field([](auto& d) -> auto& { return d.style.light.elevation; })},
    };
}

/// Per object, and the frame: background, legends, annotations, anti-aliasing.
std::vector<Setting> objectAndFrameSettings() {
    return {
        // Per object (view.style.objects).
        {.key = "objects[].opacity",
         .min = 0.0,
         .max = 1.0,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Opacity"),
         .session = SessionForm::Structured,
         .keepOnReset = true,
         .widget = {.decimals = 0, .step = 10.0, .scale = 100.0, .suffix = " %"},
         .field = objectDefault([](auto& o) -> auto& { return o.opacity; })},
        {.key = "objects[].color",
         .type = Color,
         .nullable = true,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Object colour"),
         .session = SessionForm::Structured,
         .keepOnReset = true,
         .field = objectDefault([](auto& o) -> auto& { return o.color; })},
        // The frame.
        {.key = "background",
         .storedKey = "background",
         .cliOption = "--background",
         .type = Color,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Background"),
         .field = field([](auto& d) -> auto& { return d.background; })},
        {.key = "legends",
         .storedKey = "legends",
         .cliOption = "--legends",
         .type = Bool,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Show legends"),
         .field = field([](auto& d) -> auto& { return d.legends; })},
        {.key = "orientationMarker",
         .storedKey = "orientationMarker",
         .cliOption = "--orientation-marker",
         .type = Bool,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Show the orientation marker"),
         .session = SessionForm::Optional,
         .field = field([](auto& d) -> auto& { return d.orientationMarker; })},
        {.key = "scaleBar",
         .storedKey = "scaleBar",
         .cliOption = "--scale-bar",
         .type = Bool,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Show the scale bar (at the focal plane)"),
         .session = SessionForm::Optional,
         .field = field([](auto& d) -> auto& { return d.scaleBar; })},
        {.key = "smoothCoarseMeshes",
         .storedKey = "smoothCoarseMeshes",
         .cliOption = "--smooth-coarse",
         .type = Bool,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Smooth coarse meshes up close"),
         .session = SessionForm::Optional,
         .field = field([](auto& d) -> auto& { return d.smoothCoarseMeshes; })},
        {.key = "antialiasing",
         .cliOption = "--aa",
         .type = Bool,
         .label = QT_TRANSLATE_NOOP("vv::app::Settings", "Anti-aliasing (FXAA)"),
         .session = SessionForm::None,
         .field = field([](auto& d) -> auto& { return d.antialiasing; })},
    };
}
#pragma GCC diagnostic pop

const std::vector<Setting>& table() {
    static const std::vector<Setting> settings = [] {
        std::vector<Setting> all = surfaceSettings();
        for (const std::vector<Setting>& part : {vesselSettings(), objectAndFrameSettings()}) {
            all.insert(all.end(), part.begin(), part.end());
        }
        return all;
    }();
    return settings;
}

std::string quoted(std::string_view text) {
    return "'" + std::string(text) + "'";
}

std::string colorText(const glm::vec3& c) {
    std::string text = "#";
    constexpr std::string_view kHex = "0123456789abcdef";
    for (int i = 0; i < 3; ++i) {
        const int byte = static_cast<int>(std::lround(std::clamp(c[i], 0.0F, 1.0F) * 255.0F));
        text += kHex[byte / 16];
        text += kHex[byte % 16];
    }
    return text;
}

std::optional<glm::vec3> parseColor(std::string_view text) {
    if (text.size() != 7 || text[0] != '#' ||
        text.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string_view::npos) {
        return std::nullopt;
    }
    glm::vec3 color{0.0F};
    for (int i = 0; i < 3; ++i) {
        const std::string byte(text.substr(1 + 2 * static_cast<std::size_t>(i), 2));
        color[i] = static_cast<float>(std::stoi(byte, nullptr, 16)) / 255.0F;
    }
    return color;
}

}  // namespace

std::span<const Setting> settingsSchema() noexcept {
    return table();
}

const Setting& setting(std::string_view key) {
    for (const Setting& s : table()) {
        if (s.key == key) {
            return s;
        }
    }
    throw InvalidArgumentError("no setting is named '" + std::string(key) + "'");
}

const Setting* settingForOption(std::string_view option) noexcept {
    for (const Setting& s : table()) {
        if (!s.cliOption.empty() && s.cliOption == option) {
            return &s;
        }
    }
    return nullptr;
}

SettingValue defaultValue(const Setting& setting) {
    return setting.field.get(DisplaySettings{});
}

std::optional<int> choiceFromName(const Setting& setting, std::string_view name) {
    return setting.choices != nullptr ? setting.choices->fromName(name) : std::nullopt;
}

std::string choiceNames(const Setting& setting) {
    std::string names;
    if (setting.choices != nullptr) {
        for (const int v : setting.choices->values()) {
            names += (names.empty() ? "" : ", ") + std::string(setting.choices->name(v));
        }
    }
    return names;
}

std::string validValues(const Setting& s) {
    std::string range = readableText(s.min) + ".." + readableText(s.max);
    switch (s.type) {
        case Bool:
            return "on or off";
        case Int:
            return s.zeroAllowed ? "0 or " + range : range;
        case Real:
            return range;
        case Choice:
            return choiceNames(s);
        case Color:
            return s.nullable ? "#rrggbb or none" : "#rrggbb";
        case Text:
            return "any text";
    }
    return {};
}

std::string problemWith(const Setting& s, const SettingValue& value) {
    if (std::holds_alternative<NoValue>(value)) {
        return s.nullable ? std::string() : "must have a value";
    }
    const auto within = [&s](double v) { return v >= s.min && v <= s.max; };
    switch (s.type) {
        case Bool:
            return std::holds_alternative<bool>(value) ? "" : "must be true or false";
        case Int: {
            if (const double* d = std::get_if<double>(&value)) {
                return "must be a whole number, not " + shortestText(*d);
            }
            if (!std::holds_alternative<int>(value)) {
                return "must be a whole number";
            }
            const int v = std::get<int>(value);
            const bool valid = within(v) || (s.zeroAllowed && v == 0);
            return valid ? "" : "must be " + validValues(s) + ", not " + std::to_string(v);
        }
        case Real: {
            if (!std::holds_alternative<double>(value)) {
                return "must be a number";
            }
            const double v = std::get<double>(value);
            return std::isfinite(v) && within(v)
                       ? ""
                       : "must be a number within " + validValues(s) + ", not " + shortestText(v);
        }
        case Choice: {
            const int* v = std::get_if<int>(&value);
            const auto values = s.choices->values();
            return v != nullptr && std::find(values.begin(), values.end(), *v) != values.end()
                       ? ""
                       : "must be one of " + choiceNames(s);
        }
        case Color: {
            const glm::vec3* c = std::get_if<glm::vec3>(&value);
            if (c == nullptr) {
                return "must be a colour (red, green, blue in [0, 1])";
            }
            for (int i = 0; i < 3; ++i) {
                if (!((*c)[i] >= 0.0F && (*c)[i] <= 1.0F)) {
                    return "must have red, green and blue within [0, 1], not " +
                           shortestText((*c)[i]);
                }
            }
            return {};
        }
        case Text:
            return std::holds_alternative<std::string>(value) ? "" : "must be text";
    }
    return {};
}

SettingValue parseSettingText(const Setting& s, std::string_view text) {
    SettingValue value;
    switch (s.type) {
        case Bool:
            if (text != "on" && text != "off") {
                throw InvalidArgumentError("must be on or off, not " + quoted(text));
            }
            value = text == "on";
            break;
        case Int: {
            const auto v = parseWholeNumber(text);
            if (!v) {
                throw InvalidArgumentError("must be a whole number, not " + quoted(text));
            }
            value = *v;
            break;
        }
        case Real: {
            const auto v = parseFiniteNumber(text);
            if (!v) {
                throw InvalidArgumentError("must be a number, not " + quoted(text));
            }
            value = *v;
            break;
        }
        case Choice: {
            const auto v = choiceFromName(s, text);
            if (!v) {
                throw InvalidArgumentError("must be one of " + choiceNames(s) + ", not " +
                                           quoted(text));
            }
            value = *v;
            break;
        }
        case Color: {
            if (s.nullable && text == "none") {
                value = NoValue{};
                break;
            }
            const auto c = parseColor(text);
            if (!c) {
                throw InvalidArgumentError("must be #rrggbb, not " + quoted(text));
            }
            value = *c;
            break;
        }
        case Text:
            value = std::string(text);
            break;
    }
    if (const std::string problem = problemWith(s, value); !problem.empty()) {
        throw InvalidArgumentError(problem);
    }
    return value;
}

std::string settingText(const Setting& s, const SettingValue& value) {
    if (std::holds_alternative<NoValue>(value)) {
        return "none";
    }
    switch (s.type) {
        case Bool:
            return std::get<bool>(value) ? "on" : "off";
        case Int:
            return std::to_string(std::get<int>(value));
        case Real: {
            // A float field's value as the float it is ("0.55", not 0.550000011920929).
            const double v = std::get<double>(value);
            const auto f = static_cast<float>(v);
            return static_cast<double>(f) == v ? shortestText(f) : shortestText(v);
        }
        case Choice:
            return std::string(s.choices->name(std::get<int>(value)));
        case Color:
            return colorText(std::get<glm::vec3>(value));
        case Text:
            return std::get<std::string>(value);
    }
    return {};
}

void resetToDefaults(DisplaySettings& settings) {
    for (const Setting& s : table()) {
        if (!s.keepOnReset && s.field.set != nullptr) {
            s.field.set(settings, defaultValue(s));
        }
    }
}

}  // namespace vv::app
