// SPDX-License-Identifier: GPL-3.0-or-later
#include "gui/RecentFiles.h"

#include <QFileInfo>
#include <QSettings>
#include <QVariantMap>

namespace vv::gui::recent {

namespace {

const char* const kKey = "recentFiles";
const char* const kSeriesKey = "recentSeries";

/// "recentSeries": absolute path -> {description, modality, number, studyDate}.
QVariantMap storedSeries() {
    return QSettings().value(QLatin1String(kSeriesKey)).toMap();
}

QVariantMap toVariant(const SeriesIdentity& series) {
    QVariantMap map;
    map.insert(QStringLiteral("description"), series.description);
    map.insert(QStringLiteral("modality"), series.modality);
    if (series.number) {
        map.insert(QStringLiteral("number"), *series.number);
    }
    map.insert(QStringLiteral("studyDate"), series.studyDate);
    return map;
}

/// A stored entry, or none when it is not one (settings edited by hand, or
/// from another version).
std::optional<SeriesIdentity> fromVariant(const QVariant& value) {
    if (value.typeId() != QMetaType::QVariantMap) {
        return std::nullopt;
    }
    const QVariantMap map = value.toMap();
    SeriesIdentity series;
    series.description = map.value(QStringLiteral("description")).toString();
    series.modality = map.value(QStringLiteral("modality")).toString();
    series.studyDate = map.value(QStringLiteral("studyDate")).toString();
    if (map.contains(QStringLiteral("number"))) {
        bool ok = false;
        const int number = map.value(QStringLiteral("number")).toInt(&ok);
        if (!ok) {
            return std::nullopt;
        }
        series.number = number;
    }
    return series;
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
    const QStringList list = merged(files(), opened);
    QVariantMap stored = storedSeries();
    for (const QString& file : opened) {
        stored.remove(QFileInfo(file).absoluteFilePath());
    }
    if (series && opened.size() == 1) {
        stored.insert(QFileInfo(opened.front()).absoluteFilePath(), toVariant(*series));
    }
    for (auto it = stored.begin(); it != stored.end();) {
        it = list.contains(it.key()) ? std::next(it) : stored.erase(it);
    }
    QSettings settings;
    settings.setValue(QLatin1String(kKey), list);
    if (stored.isEmpty()) {
        settings.remove(QLatin1String(kSeriesKey));
    } else {
        settings.setValue(QLatin1String(kSeriesKey), stored);
    }
}

std::optional<SeriesIdentity> series(const QString& file) {
    const QVariantMap stored = storedSeries();
    const auto it = stored.constFind(QFileInfo(file).absoluteFilePath());
    return it == stored.constEnd() ? std::nullopt : fromVariant(*it);
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
