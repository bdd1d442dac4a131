// SPDX-License-Identifier: GPL-3.0-or-later
// The render options shared by `render` and `report`: every display setting
// with a command-line option in the settings schema (common/SettingsSchema.h:
// --vss, --scale, --p, --solver, --tolerance, --isolines, --cue, --colormap,
// --bins, --background, --legends, --ao, --aa, ...), --array, --light,
// --size, --view, the DICOM options (--series, --threshold, ...) and
// --session F.vvs.
#pragma once

#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/Arguments.h"
#include "common/DisplaySettings.h"
#include "common/Session.h"
#include "common/SettingsSchema.h"
#include "vv/render/CenterlineOverlay.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/ViewPresets.h"
#include "vv/scene/Mesh.h"
#include "vv/segmentation/SceneSource.h"

namespace vv::cli {

/// The values of the shared render options (defaults = the render command's).
/// The display settings are the schema's (app::DisplaySettings); the array
/// and the light are kept in `array` and `light` (style.array and
/// style.light are not read).
struct RenderOptionValues : app::DisplaySettings {
    int width = 1600;
    int height = 1200;
    std::optional<std::string> array;  ///< nullopt: default (wss when present); "" = none
    /// --view: nullopt = the default orientation fitted to the bounding box.
    std::optional<render::NamedView> view;
    std::string viewName;  ///< as given to --view; empty = default
    /// --light AZ,EL: the key light's azimuth and elevation in degrees.
    render::LightAngles light;
    /// DICOM input: the series, its segmentation and surface (--series, ...).
    segmentation::SceneSourceOptions source;
    /// --session F.vvs: the session read; its files are the input and its
    /// camera the view (unless --view follows). Options after --session
    /// override its values; options before it are overridden by them.
    std::optional<app::Session> session;
    std::filesystem::path sessionFile;
    bool sessionCamera = false;     ///< the session's camera is the view
    bool arrayFromSession = false;  ///< `array` is the session's
    /// --centerlines on|off: the surface's centrelines (vv::analysis) drawn
    /// over the view (CenterlineOverlay.h); off by default.
    bool centerlines = false;
    /// --centerline-colour diameter|branch: by the inscribed diameter (with a
    /// legend) or one colour and number per branch.
    render::CenterlineColouring centerlineColouring =
        render::CenterlineColouring::InscribedDiameter;
};

/// "AZ,EL" (degrees; within the ranges of the settings style.light[0] and
/// style.light[1]) as light angles. Throws UsageError naming --light for
/// anything else.
[[nodiscard]] render::LightAngles parseLightAngles(const std::string& text);

/// When the current argument of `args` is one of the shared render options,
/// reads it and its value (leaving `args` on the value) into `values` and
/// returns true; else returns false and changes nothing. Throws UsageError
/// for a missing or bad value (naming the option); --session throws
/// IoError / FormatError (exit code 3) for a session that cannot be read or
/// holds an invalid value, naming the file and the field.
bool parseRenderOption(Arguments& args, RenderOptionValues& values);

/// As above for args[i] (leaving i on the value); messages start with `command`.
bool parseRenderOption(const std::vector<std::string>& args, std::size_t& i,
                       RenderOptionValues& values, const std::string& command);

/// Reads the current option's value of `args` (text as on the command line)
/// into the display setting `key` (SettingsSchema.h) of `settings`. Throws
/// UsageError naming the option for an invalid value.
void parseSettingValue(Arguments& args, std::string_view key, app::DisplaySettings& settings);

/// `text` (as on the command line) as a value of the display setting `key`
/// (SettingsSchema.h: its type and range), for commands that take a setting
/// their own way (a list of them: `bench --p 2,4,8`). Throws UsageError
/// "<what> <problem>" for an invalid value, as parseSettingValue() does
/// ("bench: --p must be within 0.25..64, not 100").
[[nodiscard]] app::SettingValue parseSettingOption(std::string_view key, std::string_view text,
                                                   const std::string& what);

/// `render --tile N`: the largest side of one rendered piece, at least
/// report::kMinTileSide (larger images are rendered in tiles that give the
/// same image, report::renderView). Throws UsageError otherwise.
[[nodiscard]] int parseTileSide(const std::string& text);

/// The camera of `values` for `scene` at width x height: the session's
/// (app::sessionCamera), the named view (presetCamera fits the vertices) or
/// the scene's home orientation (render::homeRotation: anterior for DICOM)
/// fitted to the bounding box, as OffscreenRenderer and the GUI do.
[[nodiscard]] render::Camera cameraFor(const RenderOptionValues& values, const scene::Scene& scene,
                                       int width, int height);

/// Loads the input of `values` when it comes from a session: its files, as
/// the GUI loads them (app::loadSessionScene, with the DICOM options of
/// `values`). Throws as app::loadSessionScene.
[[nodiscard]] scene::Scene loadSessionInput(const RenderOptionValues& values,
                                            segmentation::SceneSourceReport* report);

/// Offscreen options for `scene` from `values` (camera included). The array
/// defaults to render::defaultArrayName(scene). Throws UsageError when the
/// first mesh (loaded from `input`) has no such point array, FormatError
/// naming the session file and "view.style.array" when a session's array is
/// on no mesh.
[[nodiscard]] render::OffscreenOptions offscreenOptions(const RenderOptionValues& values,
                                                        const scene::Scene& scene,
                                                        const std::filesystem::path& input);

}  // namespace vv::cli
