// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "common/DisplaySettings.h"

class QSettings;

namespace vv::gui {

class ViewerWidget;

/// The viewer's display settings (common/DisplaySettings.h): VSS (the exact
/// solve, never the preview), ambient occlusion, vessel cue, mesh style,
/// background, legends; FXAA is always on in the viewer.
[[nodiscard]] app::DisplaySettings displaySettings(const ViewerWidget& viewer);

/// Shows `settings` in the viewer. The style's `lighting` stays the
/// viewer's (flat colours are for checks, no setting).
void applyDisplaySettings(ViewerWidget& viewer, const app::DisplaySettings& settings);

/// The viewer's display settings remembered between sessions, under the
/// group "view/" of a QSettings (common/StoredSettings.h says which).

/// Writes the viewer's settings into `settings`.
void saveViewSettings(const ViewerWidget& viewer, QSettings& settings);

/// Applies what `settings` holds to the viewer; missing or invalid entries
/// keep the viewer's current value (so an empty QSettings changes nothing).
void restoreViewSettings(ViewerWidget& viewer, const QSettings& settings);

/// The defaults (SettingsSchema.h: render::VssSettings{}, AoSettings{}, …)
/// for every setting but those of the data (array, ranges, legend title,
/// no-data colour, objects), which stay.
void resetViewSettings(ViewerWidget& viewer);

}  // namespace vv::gui
