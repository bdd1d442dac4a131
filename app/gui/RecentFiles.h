// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

/// File > Open Recent: the recently opened files, kept in QSettings under
/// "recentFiles" (the application's default QSettings).
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

/// Stores merged(files(), opened).
void add(const QStringList& opened);

/// Forgets every recent file.
void clear();

}  // namespace vv::gui::recent
