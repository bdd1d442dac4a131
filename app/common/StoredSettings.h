// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QVariant>

#include "common/DisplaySettings.h"
#include "common/SettingsSchema.h"

class QSettings;

namespace vv::app {

/// The display settings remembered between runs, under the group "view/" of
/// a QSettings: every setting with a storedKey in SettingsSchema.h (the VSS:
/// on/off, depth scale, p, solver, tolerance, step, iso-lines, lighting;
/// ambient occlusion, the colour map and bins, the vessels' material colour,
/// the vessel cue, the background, the legends and the light direction). The
/// array and ranges are not stored: they belong to the data.

/// `value` of `setting` as a QVariant: a bool, int, double or text, a colour
/// as a list of three doubles, a Choice's name (its enum value instead when
/// `indexChoices` and the setting is storedAsIndex), an invalid QVariant for
/// NoValue. QSettings store it; sessions write it as JSON
/// (QJsonValue::fromVariant).
[[nodiscard]] QVariant settingToVariant(const Setting& setting, const SettingValue& value,
                                        bool indexChoices = false);

/// Writes the stored settings of `settings` into `store`.
void writeStoredSettings(const DisplaySettings& settings, QSettings& store);

/// Reads what `store` holds into `settings`; missing entries, and entries of
/// the wrong type or out of their range, keep the value in `settings` (so an
/// empty QSettings changes nothing).
void readStoredSettings(const QSettings& store, DisplaySettings& settings);

}  // namespace vv::app
