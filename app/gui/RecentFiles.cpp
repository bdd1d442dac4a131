// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/RecentFiles.h"

#include <QFileInfo>
#include <QMap>
#include <QSettings>

namespace vv::gui::recent {

namespace {

const char* const kKey = "recentFiles";
const char* const kSeriesKey = "recentSeries";

/// "recentSeries": an array of {file (absolute), description, modality,
/// number, studyDate, uid}, readable in the settings file. An entry that is not
/// one (edited by hand, another version) is left out.
QMap<QString, SeriesIdentity> storedSeries() {
    QMap<QString, SeriesIdentity> stored;
    QSettings settings;
    const int size = settings.beginReadArray(QLatin1String(kSeriesKey));
    for (int i = 0; i < size; ++i) {
        settings.setArrayIndex(i);
        const QString file = settings.value(QStringLiteral("file")).toString();
        SeriesIdentity series;
        series.description = settings.value(QStringLiteral("description")).toString();
        series.modality = settings.value(QStringLiteral("modality")).toString();
        series.studyDate = settings.value(QStringLiteral("studyDate")).toString();
        series.uid = settings.value(QStringLiteral("uid")).toString();
        bool ok = true;
        if (settings.contains(QStringLiteral("number"))) {
            series.number = settings.value(QStringLiteral("number")).toInt(&ok);
        }
        if (ok && !file.isEmpty()) {
            stored.insert(file, series);
        }
    }
    settings.endArray();
    return stored;
}

void storeSeries(const QMap<QString, SeriesIdentity>& stored) {
    QSettings settings;
    settings.remove(QLatin1String(kSeriesKey));
    if (stored.isEmpty()) {
        return;
    }
    settings.beginWriteArray(QLatin1String(kSeriesKey), static_cast<int>(stored.size()));
    int i = 0;
    for (auto it = stored.begin(); it != stored.end(); ++it, ++i) {
        settings.setArrayIndex(i);
        settings.setValue(QStringLiteral("file"), it.key());
        settings.setValue(QStringLiteral("description"), it->description);
        settings.setValue(QStringLiteral("modality"), it->modality);
        if (it->number) {
            settings.setValue(QStringLiteral("number"), *it->number);
        }
        settings.setValue(QStringLiteral("studyDate"), it->studyDate);
        settings.setValue(QStringLiteral("uid"), it->uid);
    }
    settings.endArray();
}

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

void add(const QStringList& opened, const std::optional<SeriesIdentity>& series) {
    if (opened.isEmpty()) {
        return;
    }
    QStringList list = merged(files(), opened);
    QMap<QString, SeriesIdentity> stored = storedSeries();
    for (const QString& file : opened) {
        stored.remove(QFileInfo(file).absoluteFilePath());
    }
    if (series && opened.size() == 1) {
        // One series is one entry, wherever it was opened from (its folder,
        // the local study store): an older entry of the same series goes.
        if (!series->uid.isEmpty()) {
            for (auto it = stored.begin(); it != stored.end(); ++it) {
                if (it->uid == series->uid) {
                    list.removeAll(it.key());
                }
            }
        }
        stored.insert(QFileInfo(opened.front()).absoluteFilePath(), *series);
    }
    stored.removeIf([&list](const auto& entry) { return !list.contains(entry.key()); });
    QSettings().setValue(QLatin1String(kKey), list);
    storeSeries(stored);
}

std::optional<SeriesIdentity> series(const QString& file) {
    const QMap<QString, SeriesIdentity> stored = storedSeries();
    const auto it = stored.constFind(QFileInfo(file).absoluteFilePath());
    return it == stored.constEnd() ? std::nullopt : std::optional(*it);
}

QString label(const QString& file) {
    const std::optional<SeriesIdentity> identity = series(file);
    return identity ? seriesLabel(*identity) : QFileInfo(file).fileName();
}

void clear() {
    QSettings settings;
    settings.remove(QLatin1String(kKey));
    settings.remove(QLatin1String(kSeriesKey));
}

}  // namespace vv::gui::recent
