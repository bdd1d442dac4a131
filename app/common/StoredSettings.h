// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "common/DisplaySettings.h"

class QSettings;

namespace vv::app {

/// The display settings remembered between runs, under the group "view/" of
/// a QSettings: every setting with a storedKey in SettingsSchema.h (the VSS:
/// on/off, depth scale, p, solver, tolerance, step, iso-lines, lighting;
/// ambient occlusion, the colour map and bins, the vessels' material colour,
/// the vessel cue, the background, the legends and the light direction). The
/// array and ranges are not stored: they belong to the data.

/// Writes the stored settings of `settings` into `store`.
void writeStoredSettings(const DisplaySettings& settings, QSettings& store);

/// Reads what `store` holds into `settings`; missing entries, and entries of
/// the wrong type or out of their range, keep the value in `settings` (so an
/// empty QSettings changes nothing).
void readStoredSettings(const QSettings& store, DisplaySettings& settings);

}  // namespace vv::app
