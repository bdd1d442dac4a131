// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// The display settings of a view: what a person chooses to see, besides the
// camera and the data. Plain C++: no GL.

#include <glm/glm.hpp>

#include "vv/render/FrameSettings.h"
#include "vv/render/MeshStyle.h"

namespace vv::render {

/// Every display and VSS setting of a view, besides the camera and the data:
/// what the GUI's panels change, a session (.vvs) stores, QSettings remembers,
/// `vesselview-cli render` / `report` take as options and OffscreenRenderer
/// renders with (OffscreenOptions::display). The app's settings schema
/// (app/common/SettingsSchema.h) describes each one (name, type, range,
/// default, unit, label); the defaults are the engine's (VssSettings{},
/// AoSettings{}, MeshStyle{}, kDefaultBackground, ...).
struct DisplaySettings {
    VssSettings vss;
    AoSettings ao;
    VesselCueSettings cue;
    /// The mesh style. Its `lighting` (flat colours for checks) and `hidden`
    /// list are no settings of their own: `hidden` travels with the objects.
    MeshStyle style;
    glm::vec3 background{kDefaultBackground};  ///< sRGB
    /// Paint the legends of the scales in use (LegendPainter): the depth
    /// legend when a VSS is shown, the parameter legend when an array is.
    bool legends = true;
    /// The orientation marker (patient letters with a patient frame, else
    /// x / y / z) and the scale bar at the focal plane, over the view and in
    /// exports (ViewAnnotations).
    bool orientationMarker = true;
    bool scaleBar = true;
    /// FXAA; the GUI always runs it (only the command line turns it off).
    bool antialiasing = true;
    /// Coarse meshes drawn smooth where their facets are large on screen
    /// (FrameSettings::smoothCoarseMeshes).
    bool smoothCoarseMeshes = true;
};

/// What a still frame with `display` is drawn with: its background, VSS,
/// vessel cue, ambient occlusion and FXAA, at full resolution with the full
/// geometry (FrameSettings' defaults for the rest). The mesh style goes to
/// the mesh renderer; legends and annotations are painted over the frame.
[[nodiscard]] FrameSettings frameSettings(const DisplaySettings& display);

}  // namespace vv::render
