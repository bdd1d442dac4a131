// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/RecentFiles.h"

#include <QFileInfo>
#include <QSettings>

namespace vv::gui::recent {

namespace {

const char* const kKey = "recentFiles";

}  // namespace

QStringList files() {
    QStringList list = QSettings().value(QLatin1String(kKey)).toStringList();
    list.removeAll(QString());
    while (list.size() > kMaxFiles) {
        list.removeLast();
    }
    return list;
}

QStringList merged(QStringList recent, const QStringList& opened) {
    // The last opened first, so that the first ends up in front.
    for (qsizetype i = opened.size() - 1; i >= 0; --i) {
        const QString absolute = QFileInfo(opened[i]).absoluteFilePath();
        recent.removeAll(absolute);
        recent.prepend(absolute);
    }
    while (recent.size() > kMaxFiles) {
        recent.removeLast();
    }
    return recent;
}

void add(const QStringList& opened) {
    if (opened.isEmpty()) {
        return;
    }
    QSettings().setValue(QLatin1String(kKey), merged(files(), opened));
}

void clear() {
    QSettings().remove(QLatin1String(kKey));
}

}  // namespace vv::gui::recent
