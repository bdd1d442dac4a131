// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/DisplaySettings.h"

/// The one description of every display and VSS setting (as f3d's
/// library/options.json): its key, where sessions, QSettings and the command
/// line keep it, its type, range, default, unit and label. CLI parsing
/// (app/cli/RenderOptions.cpp), sessions (common/SessionView.cpp), QSettings
/// (common/StoredSettings.cpp) and the GUI's widgets (gui/panels/PanelUtil.h)
/// all take them from here; nothing else decides what a valid value is. The
/// engine's own preconditions (e.g. vss::makeSolver refusing p <= 0) stay as
/// documented preconditions behind these ranges.
namespace vv::app {

/// The translation context of the labels (QCoreApplication::translate).
inline constexpr const char* kSettingsContext = "vv::app::Settings";

enum class SettingType {
    Bool,    ///< on / off
    Int,     ///< a whole number in [min, max] (or 0 when zeroAllowed)
    Real,    ///< a finite number in [min, max]
    Choice,  ///< one of a fixed set of names (Setting::choices)
    Color,   ///< sRGB: three components in [0, 1]
    Text,    ///< free text
};

/// How a setting appears in a session's "view" object (Session.h).
enum class SessionForm {
    None,      ///< not stored
    Required,  ///< at its key in every version-1 session
    Optional,  ///< added within version 1: a session without it loads the default
    /// Part of a larger value that the session code reads and writes itself
    /// (the fixed depth range, the colour range, the objects), with the
    /// type and range given here.
    Structured,
};

/// A nullable setting without a value (the no-data colour: the map's own).
using NoValue = std::monostate;

/// A setting's value: Bool -> bool; Int and Choice -> int (for a Choice the
/// enum's value); Real -> double; Color -> glm::vec3; Text -> std::string;
/// NoValue for a nullable setting without a value.
using SettingValue = std::variant<NoValue, bool, int, double, glm::vec3, std::string>;

/// The values of a Choice setting and their names.
struct ChoiceSet {
    std::vector<int> (*values)();         ///< every value, in UI order
    std::string_view (*name)(int value);  ///< the stable name (sessions, QSettings, CLI)
    /// The value of a name or alias, ignoring ASCII case; nullopt when unknown.
    std::optional<int> (*fromName)(std::string_view name);
};

/// Reads and writes one setting's field of a DisplaySettings.
struct SettingField {
    /// The value in `settings`. Per-object settings ("objects[]...") give
    /// the default object's (render::ObjectStyle{}).
    SettingValue (*get)(const DisplaySettings& settings) = nullptr;
    /// Writes a valid value (problemWith() is empty) into `settings`;
    /// nullptr for per-object settings.
    void (*set)(DisplaySettings& settings, const SettingValue& value) = nullptr;
};

/// How a widget shows a Real / Int setting: value * scale, with `decimals`
/// decimals, `step` per arrow press and `suffix` (" mm", " %", " / 255").
struct WidgetHint {
    int decimals = 2;
    double step = 1.0;
    double scale = 1.0;
    std::string_view suffix;
};

/// One setting.
struct Setting {
    /// The setting's name and its session key below "view" ("vss.p" is
    /// view.vss.p); "style.light[1]" is element 1 of the array view.style.light;
    /// "objects[].opacity" is a member of each entry of view.style.objects.
    std::string_view key;
    /// Its key below "view/" in QSettings ("power"); empty = not remembered.
    std::string_view storedKey;
    /// Its command-line option of `render` and `report` ("--p"); empty = none.
    std::string_view cliOption;
    SettingType type = SettingType::Real;
    double min = 0.0;          ///< Int, Real: the smallest valid value
    double max = 0.0;          ///< Int, Real: the largest valid value
    bool zeroAllowed = false;  ///< Int: 0 ("off") is valid besides min..max
    bool nullable = false;     ///< NoValue is valid (JSON null)
    std::string_view unit;     ///< of the value: "mm", "°", "px"; empty = none
    const char* label = "";    ///< English; QT_TRANSLATE_NOOP(kSettingsContext, ...)
    SessionForm session = SessionForm::Required;
    /// Belongs to the data shown (array, ranges, titles): not remembered in
    /// QSettings and kept by "Reset to Defaults".
    bool keepOnReset = false;
    /// QSettings holds the Choice's enum value instead of its name (the cue).
    bool storedAsIndex = false;
    WidgetHint widget;
    const ChoiceSet* choices = nullptr;  ///< Choice only
    /// Where the value lives in a DisplaySettings.
    SettingField field;
};

/// Every setting, in the order the GUI shows them.
[[nodiscard]] std::span<const Setting> settingsSchema() noexcept;

/// The setting named `key`. Throws InvalidArgumentError for an unknown key.
[[nodiscard]] const Setting& setting(std::string_view key);

/// The setting whose cliOption is `option`; nullptr when none is.
[[nodiscard]] const Setting* settingForOption(std::string_view option) noexcept;

/// The default value: the setting's value in DisplaySettings{}.
[[nodiscard]] SettingValue defaultValue(const Setting& setting);

/// What is wrong with `value` for `setting` ("must be within 0.25..64, not
/// 100"; "must be a whole number, not 2.5"); empty when it is valid.
[[nodiscard]] std::string problemWith(const Setting& setting, const SettingValue& value);

/// The valid values in words: "0.25..64", "0 or 2..256", "on or off",
/// "none, vessel-cd, ...", "#rrggbb".
[[nodiscard]] std::string validValues(const Setting& setting);

/// Command-line text as a value: on / off, numbers (C locale), names,
/// #rrggbb colours, free text. Throws InvalidArgumentError with the problem
/// ("must be a number, not 'x'", or problemWith()) for anything invalid.
[[nodiscard]] SettingValue parseSettingText(const Setting& setting, std::string_view text);

/// The value as command-line text (the inverse of parseSettingText).
[[nodiscard]] std::string settingText(const Setting& setting, const SettingValue& value);

/// The choice value named `name` for a Choice setting; nullopt when unknown.
[[nodiscard]] std::optional<int> choiceFromName(const Setting& setting, std::string_view name);
/// Every name of a Choice setting, in UI order ("a, b, c").
[[nodiscard]] std::string choiceNames(const Setting& setting);

/// Sets every setting that is not keepOnReset to its default.
void resetToDefaults(DisplaySettings& settings);

}  // namespace vv::app
