// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QSettings;

namespace vv::gui {

class ViewerWidget;

/// The viewer's display settings remembered between sessions, under the
/// group "view/" of a QSettings: the VSS (on/off, depth scale, p, solver,
/// tolerance, step, iso-lines, lighting), ambient occlusion, the colour map
/// and bins, the vessels' material colour, the vessel cue, the background,
/// the legends and the light direction. The array and
/// range are not stored (they belong to the data).

/// Writes the viewer's settings into `settings`.
void saveViewSettings(const ViewerWidget& viewer, QSettings& settings);

/// Applies what `settings` holds to the viewer; missing or invalid entries
/// keep the viewer's current value (so an empty QSettings changes nothing).
void restoreViewSettings(ViewerWidget& viewer, const QSettings& settings);

/// The defaults of a fresh viewer (render::VssSettings{}, AoSettings{}, …)
/// for everything restoreViewSettings() covers; the array and range stay.
void resetViewSettings(ViewerWidget& viewer);

}  // namespace vv::gui
