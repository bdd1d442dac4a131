// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>
#include <optional>

#include "gui/SeriesName.h"

/// File > Open Recent: the recently opened files, kept in QSettings under
/// "recentFiles" (the application's default QSettings), and for a DICOM
/// series opened on its own what it says of itself and its UID, under
/// "recentSeries" (never the patient's name or ID: they are not written to
/// the settings).
namespace vv::gui::recent {

/// The longest list kept.
inline constexpr int kMaxFiles = 8;

/// The list as stored: most recent first, at most kMaxFiles, no empty entries.
[[nodiscard]] QStringList files();

/// `recent` after opening `opened` (one scene, in the order given): each
/// opened file as an absolute path, in front of the older ones in the order
/// given, an older entry of the same file removed, cut to kMaxFiles.
/// Nothing changes when `opened` is empty. Pure: the rule files() and add()
/// follow.
[[nodiscard]] QStringList merged(QStringList recent, const QStringList& opened);

/// Stores merged(files(), opened). `series`: what the one file opened (a
/// DICOM folder or file) showed, remembered for it; an older entry of the
/// same series (Series Instance UID) under another path — the study's folder
/// and its copy in the local study store — is removed, so that a series is
/// listed once. Without `series`, whatever was remembered for the opened
/// files is forgotten. Series of files that drop off the list are forgotten too.
void add(const QStringList& opened, const std::optional<SeriesIdentity>& series = std::nullopt);

/// What add() remembered for `file` (an entry of files()); none for files
/// shown under their own names.
[[nodiscard]] std::optional<SeriesIdentity> series(const QString& file);

/// What File > Open Recent shows for `file`: seriesLabel() of its series,
/// else its file name.
[[nodiscard]] QString label(const QString& file);

/// Forgets every recent file.
void clear();

}  // namespace vv::gui::recent
