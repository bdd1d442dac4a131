// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/glm.hpp>

#include "vv/render/FrameRenderer.h"
#include "vv/render/MeshStyle.h"

namespace vv::app {

/// Every display and VSS setting of a view, besides the camera and the data:
/// what the GUI's panels change, a session (.vvs) stores, QSettings remembers
/// and `vesselview-cli render` / `report` take as options. SettingsSchema.h
/// describes each one (name, type, range, default, unit, label); the defaults
/// are the engine's (render::VssSettings{}, AoSettings{}, MeshStyle{}, ...).
struct DisplaySettings {
    render::VssSettings vss;
    render::AoSettings ao;
    render::VesselCueSettings cue;
    /// The mesh style. Its `lighting` (flat colours for checks) and `hidden`
    /// list are no settings of their own: `hidden` travels with the objects.
    render::MeshStyle style;
    glm::vec3 background{render::FrameSettings{}.background};  ///< sRGB
    bool legends = true;
    /// The orientation marker (patient letters with a patient frame, else
    /// x / y / z) and the scale bar at the focal plane, over the view and in
    /// exports (render::ViewAnnotations).
    bool orientationMarker = true;
    bool scaleBar = true;
    /// FXAA; the GUI always runs it (only the command line turns it off).
    bool antialiasing = true;
};

}  // namespace vv::app
