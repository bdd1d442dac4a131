// SPDX-License-Identifier: GPL-3.0-or-later
// Older session versions, converted one step at a time (Session.h).
#include <QJsonObject>
#include <QJsonValue>
#include <cmath>
#include <string>

#include "common/Session.h"
#include "common/SessionReader.h"
#include "vv/core/Error.h"

namespace vv::app::detail {

namespace {

const QString kFormat = QStringLiteral("vesselview-session");

/// Version 0 (the first prototype): no "version"; the display settings in one
/// flat "settings" object under their QSettings keys (SettingsSchema.h:
/// storedKey; the cue as its index in the UI order) plus "array". Missing
/// keys took the defaults then, and do now.
QJsonObject migrate0To1(const QJsonObject& old, const SessionReader& reader) {
    const QJsonValue settingsValue = old.value(QLatin1String("settings"));
    if (!settingsValue.isObject()) {
        reader.fail(QStringLiteral("settings"), QStringLiteral("must be an object (version 0)"));
    }
    const QJsonObject settings = settingsValue.toObject();
    QJsonObject view = viewToJson(DisplaySettings{});
    for (const Setting& s : settingsSchema()) {
        const QJsonValue value = settings.value(text(s.storedKey));
        if (s.storedKey.empty() || s.session != SessionForm::Required || value.isUndefined()) {
            continue;
        }
        if (s.storedAsIndex) {
            // Version 0 stored the cue as its index in the UI order.
            const auto values = s.choices->values();
            const double i = value.toDouble(-1.0);
            if (!value.isDouble() || i < 0 || i != std::floor(i) ||
                i >= static_cast<double>(values.size())) {
                reader.fail(QStringLiteral("settings.") + text(s.storedKey),
                            QStringLiteral("must be an index 0..%1").arg(values.size() - 1));
            }
            insertSetting(view, s, text(s.choices->name(values[static_cast<std::size_t>(i)])));
        } else {
            insertSetting(view, s, value);  // checked as version 1 by readView
        }
    }
    if (const QJsonValue array = settings.value(QLatin1String("array")); !array.isUndefined()) {
        insertSetting(view, setting("style.array"), array);
    }
    QJsonObject next;
    next.insert(QStringLiteral("format"), kFormat);
    next.insert(QStringLiteral("version"), 1);
    next.insert(QStringLiteral("files"), old.value(QLatin1String("files")));
    next.insert(QStringLiteral("camera"), old.value(QLatin1String("camera")));
    next.insert(QStringLiteral("view"), view);
    return next;
}

}  // namespace

QJsonObject migrateSession(QJsonObject root, const SessionReader& reader) {
    int version = 0;
    const QJsonValue v = root.value(QLatin1String("version"));
    if (v.isUndefined()) {
        if (!root.contains(QLatin1String("settings"))) {
            reader.fail(QStringLiteral("version"), QStringLiteral("is missing"));
        }
        version = 0;  // the prototype's files had no version
    } else {
        version = reader.integer(root, QString(), "version", 0, 1 << 20);
    }
    if (version > kSessionVersion) {
        throw FormatError(reader.file(), "session version " + std::to_string(version) +
                                             " is newer than this VesselView supports (" +
                                             std::to_string(kSessionVersion) +
                                             "); update VesselView");
    }
    if (version == 0) {
        root = migrate0To1(root, reader);
        version = 1;
    }
    // Future: if (version == 1) { root = migrate1To2(root, reader); version = 2; }
    return root;
}

}  // namespace vv::app::detail
