// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "vv/render/FrameSettings.h"
#include "vv/render/MeshStyle.h"

namespace vv::gui {

class ViewerWidget;

/// The colour-bearing settings of a view: what a display preset changes.
struct DisplayState {
    render::VssSettings vss;
    render::MeshStyle style;
    render::VesselCueSettings cue;
};

/// The viewer's current display state.
[[nodiscard]] DisplayState displayState(const ViewerWidget& viewer);

/// Applies `state` to the viewer (VSS, mesh style, vessel cue); the legends
/// follow, as they are derived from these settings.
void applyDisplayState(ViewerWidget& viewer, const DisplayState& state);

/// True when `state` is colour-blind safe: the VSS (when on) uses
/// dark-means-deep; an array shown on the vessels uses cividis or viridis;
/// the vessel cue is none or fog (the chromadepth, pseudo-chromadepth and
/// Fresnel cues colour by red versus blue / green). These are the ramps that
/// tests/colormaps/CvdSafetyTest.cpp checks under protanopia, deuteranopia
/// and tritanopia.
[[nodiscard]] bool isColorBlindSafe(const DisplayState& state) noexcept;

/// `state` made colour-blind safe: the depth scale becomes dark-means-deep,
/// the colour map cividis (designed for colour-vision deficiency), and a
/// colour cue on the vessels none (fog stays). Everything else (VSS on/off,
/// p, arrays, ranges, bins) is kept.
[[nodiscard]] DisplayState colorBlindSafe(DisplayState state) noexcept;

}  // namespace vv::gui
