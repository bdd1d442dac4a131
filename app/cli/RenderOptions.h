// SPDX-License-Identifier: GPL-3.0-or-later
// The render options shared by `render` and `report`: --size, --array,
// --colormap, --bins, --cue, --legends, --background, --ao, --aa, --vss,
// --scale, --p, --isolines, --solver, --tolerance, --view, --light.
#pragma once

#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "vv/colormaps/ColorMap.h"
#include "vv/render/FrameRenderer.h"
#include "vv/render/OffscreenRenderer.h"
#include "vv/render/ViewPresets.h"
#include "vv/scene/Mesh.h"

namespace vv::cli {

/// The values of the shared render options (defaults = the render command's).
struct RenderOptionValues {
    int width = 1600;
    int height = 1200;
    std::optional<std::string> array;  ///< nullopt: default (wss when present); "" = none
    colormaps::ColorMap colorMap = colormaps::ColorMap::Viridis;
    int bins = 0;  ///< colour-map bins, 0 = continuous
    render::VesselCueSettings cue;
    bool legends = true;
    glm::vec3 background{0.13F, 0.14F, 0.16F};
    render::VssSettings vss;
    bool ao = true;  ///< ambient occlusion over vessels + VSS
    bool aa = true;  ///< FXAA
    /// --view: nullopt = the default orientation fitted to the bounding box.
    std::optional<render::NamedView> view;
    std::string viewName;  ///< as given to --view; empty = default
    /// --light AZ,EL: the key light's azimuth and elevation in degrees.
    render::LightAngles light;
};

/// "AZ,EL" (degrees; azimuth -180..180, elevation -90..90) as light angles.
/// Throws UsageError naming --light for anything else.
[[nodiscard]] render::LightAngles parseLightAngles(const std::string& text);

/// When args[i] is one of the shared render options, reads it and its value
/// (leaving i on the value) into `values` and returns true; else returns false
/// and changes nothing. Throws UsageError for a missing or bad value (the
/// message starts with `command` for a missing one).
bool parseRenderOption(const std::vector<std::string>& args, std::size_t& i,
                       RenderOptionValues& values, const std::string& command);

/// `render --tile N`: the largest side of one rendered piece, at least
/// report::kMinTileSide (larger images are rendered in tiles that give the
/// same image, report::renderView). Throws UsageError otherwise.
[[nodiscard]] int parseTileSide(const std::string& text);

/// `text` as a finite double / an int; UsageError naming `what` otherwise.
double parseDouble(const std::string& text, const std::string& what);
int parseInt(const std::string& text, const std::string& what);

/// The camera of `values` for `scene` at width x height: the named view
/// (presetCamera fits the vertices) or the default orientation fitted to the
/// bounding box, as OffscreenRenderer does.
[[nodiscard]] render::Camera cameraFor(const RenderOptionValues& values, const scene::Scene& scene,
                                       int width, int height);

/// Offscreen options for `scene` from `values` (camera included). The array
/// defaults to render::defaultArrayName(scene). Throws UsageError when the
/// first mesh (loaded from `input`) has no such point array.
[[nodiscard]] render::OffscreenOptions offscreenOptions(const RenderOptionValues& values,
                                                        const scene::Scene& scene,
                                                        const std::filesystem::path& input);

/// Throws OutputError when `output` cannot be a new file: its folder does not
/// exist or it is a folder. Call before long work.
void checkOutputPath(const std::filesystem::path& output);

}  // namespace vv::cli
