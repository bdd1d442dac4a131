// SPDX-License-Identifier: GPL-3.0-or-later
// A session's "view" object: the display settings, laid out by their keys in
// the settings schema (SettingsSchema.h).
#include <QJsonArray>
#include <QJsonObject>
#include <QStringList>
#include <algorithm>
#include <cstddef>
#include <utility>

#include "common/SessionReader.h"

namespace vv::app::detail {

namespace {

/// Where a setting's key puts it: "style.light[1]" is element 1 of the array
/// "light" in the object "style".
struct KeyPath {
    QStringList parents;
    QString name;
    int element = -1;
};

KeyPath keyPath(std::string_view key) {
    KeyPath path;
    QStringList parts = text(key).split(QLatin1Char('.'));
    QString last = parts.takeLast();
    if (const qsizetype bracket = last.indexOf(QLatin1Char('[')); bracket >= 0) {
        path.element = last.mid(bracket + 1, last.size() - bracket - 2).toInt();
        last = last.left(bracket);
    }
    path.parents = parts;
    path.name = last;
    return path;
}

bool inView(const Setting& s) {
    return s.session == SessionForm::Required || s.session == SessionForm::Optional;
}

/// How many settings are elements of the array `key` names (the light: 2).
qsizetype elementCount(const KeyPath& key) {
    qsizetype n = 0;
    for (const Setting& s : settingsSchema()) {
        const KeyPath other = keyPath(s.key);
        n += other.element >= 0 && other.parents == key.parents && other.name == key.name ? 1 : 0;
    }
    return n;
}

void insertAt(QJsonObject& root, const QStringList& parents, const QString& name,
              const QJsonValue& value) {
    if (parents.isEmpty()) {
        root.insert(name, value);
        return;
    }
    QJsonObject child = root.value(parents.front()).toObject();
    insertAt(child, parents.mid(1), name, value);
    root.insert(parents.front(), child);
}

QJsonValue valueAt(const QJsonObject& root, const QStringList& parents, const QString& name) {
    QJsonObject o = root;
    for (const QString& p : parents) {
        o = o.value(p).toObject();
    }
    return o.value(name);
}

QString joined(const QString& where, const QString& name) {
    return where + QLatin1Char('.') + name;
}

QJsonValue json(const char* key, const DisplaySettings& d) {
    const Setting& s = setting(key);
    return settingToJson(s, s.field.get(d));
}

/// The fixed VSS depth range: {"mode": "visible"} or {"mode": "fixed", "near", "far"}.
QJsonObject depthRangeToJson(const DisplaySettings& d) {
    QJsonObject range{{QStringLiteral("mode"), json("vss.range.mode", d)}};
    if (d.vss.range.mode == vss::RangeMode::Fixed) {
        range.insert(QStringLiteral("near"), json("vss.range.near", d));
        range.insert(QStringLiteral("far"), json("vss.range.far", d));
    }
    return range;
}

void readDepthRange(const SessionReader& r, const QJsonObject& vssObject, const QString& where,
                    DisplaySettings& d) {
    // Optional in version 1 (files written before it: the visible range).
    if (!vssObject.contains(QStringLiteral("range"))) {
        return;
    }
    const QString w = joined(where, QStringLiteral("range"));
    const QJsonObject range = r.object(vssObject, where, "range");
    const auto read = [&](const char* key, const char* name) {
        const Setting& s = setting(key);
        s.field.set(d, r.setting(s, r.get(range, w, name), SessionReader::path(w, name)));
    };
    read("vss.range.mode", "mode");
    if (d.vss.range.mode == vss::RangeMode::Fixed) {
        read("vss.range.near", "near");
        read("vss.range.far", "far");
        if (d.vss.range.dmax < d.vss.range.dmin) {
            r.fail(joined(w, QStringLiteral("far")),
                   QStringLiteral("must not be nearer than near (%1)").arg(d.vss.range.dmin));
        }
    }
}

/// The colour range: null (the array's own) or [min, max].
QJsonValue colorRangeToJson(const DisplaySettings& d) {
    if (!d.style.range) {
        return {QJsonValue::Null};
    }
    return QJsonArray{static_cast<double>(d.style.range->first),
                      static_cast<double>(d.style.range->second)};
}

void readColorRange(const SessionReader& r, const QJsonObject& style, const QString& where,
                    DisplaySettings& d) {
    const QJsonValue range = r.get(style, where, "range");
    if (range.isNull()) {
        d.style.range.reset();
        return;
    }
    const QString field = joined(where, QStringLiteral("range"));
    const Setting& lo = setting("style.range[0]");
    const Setting& hi = setting("style.range[1]");
    const auto n = r.numbers(range, field, 2, -detail::kHuge, detail::kHuge);
    const double low = std::get<double>(r.setting(lo, n[0], field + QStringLiteral("[0]")));
    const double high = std::get<double>(r.setting(hi, n[1], field + QStringLiteral("[1]")));
    if (!(low < high)) {
        r.fail(field, QStringLiteral("must have min < max"));
    }
    d.style.range = std::make_pair(static_cast<float>(low), static_cast<float>(high));
}

/// Per object: "visible", "opacity", "color" (null = the vessel colour) and
/// "array" (null = the scene's array, "" = none), in mesh order.
QJsonArray objectsToJson(const render::MeshStyle& style) {
    const Setting& opacity = setting("objects[].opacity");
    const Setting& color = setting("objects[].color");
    QJsonArray objects;
    std::size_t count = style.objects.size();
    for (const std::size_t hidden : style.hidden) {
        count = std::max(count, hidden + 1);
    }
    for (std::size_t i = 0; i < count; ++i) {
        const render::ObjectStyle& o = style.object(i);
        const bool hidden =
            std::find(style.hidden.begin(), style.hidden.end(), i) != style.hidden.end();
        objects.append(QJsonObject{
            {QStringLiteral("visible"), !hidden},
            {QStringLiteral("opacity"), settingToJson(opacity, static_cast<double>(o.opacity))},
            {QStringLiteral("color"),
             settingToJson(color, o.color ? SettingValue(*o.color) : SettingValue(NoValue{}))},
            {QStringLiteral("array"),
             o.array ? QJsonValue(QString::fromStdString(*o.array)) : QJsonValue()},
        });
    }
    return objects;
}

/// The objects objectsToJson() wrote, into `style` (objects and hidden).
void readObjects(const SessionReader& r, const QJsonValue& value, const QString& where,
                 render::MeshStyle& style) {
    if (!value.isArray()) {
        r.fail(where, QStringLiteral("must be an array"));
    }
    const Setting& opacity = setting("objects[].opacity");
    const Setting& color = setting("objects[].color");
    style.objects.clear();
    style.hidden.clear();
    const QJsonArray objects = value.toArray();
    for (qsizetype i = 0; i < objects.size(); ++i) {
        const QString w = where + QStringLiteral("[%1]").arg(i);
        if (!objects[i].isObject()) {
            r.fail(w, QStringLiteral("must be an object"));
        }
        const QJsonObject o = objects[i].toObject();
        render::ObjectStyle object;
        object.opacity = static_cast<float>(std::get<double>(
            r.setting(opacity, r.get(o, w, "opacity"), SessionReader::path(w, "opacity"))));
        const SettingValue c =
            r.setting(color, r.get(o, w, "color"), SessionReader::path(w, "color"));
        if (const auto* rgb = std::get_if<glm::vec3>(&c)) {
            object.color = *rgb;
        }
        if (const QJsonValue array = r.get(o, w, "array"); !array.isNull()) {
            object.array = r.string(o, w, "array").toStdString();
        }
        if (!r.boolean(o, w, "visible")) {
            style.hidden.push_back(static_cast<std::size_t>(i));
        }
        style.objects.push_back(std::move(object));
    }
}

}  // namespace

void insertSetting(QJsonObject& view, const Setting& s, const QJsonValue& value) {
    const KeyPath key = keyPath(s.key);
    insertAt(view, key.parents, key.name, value);
}

QJsonObject viewToJson(const DisplaySettings& settings) {
    const DisplaySettings& d = settings;
    QJsonObject view;
    for (const Setting& s : settingsSchema()) {
        if (!inView(s)) {
            continue;
        }
        const KeyPath key = keyPath(s.key);
        QJsonValue value = settingToJson(s, s.field.get(d));
        if (key.element >= 0) {
            QJsonArray elements = valueAt(view, key.parents, key.name).toArray();
            elements.append(value);  // the schema lists elements in order
            value = elements;
        }
        insertAt(view, key.parents, key.name, value);
    }
    insertAt(view, {QStringLiteral("vss")}, QStringLiteral("range"), depthRangeToJson(d));
    insertAt(view, {QStringLiteral("style")}, QStringLiteral("range"), colorRangeToJson(d));
    insertAt(view, {QStringLiteral("style")}, QStringLiteral("objects"), objectsToJson(d.style));
    return view;
}

void readView(const SessionReader& reader, const QJsonObject& view, DisplaySettings& settings) {
    const SessionReader& r = reader;
    DisplaySettings& d = settings;
    const QString top = QStringLiteral("view");
    for (const Setting& s : settingsSchema()) {
        if (!inView(s)) {
            continue;
        }
        const KeyPath key = keyPath(s.key);
        QJsonObject parent = view;
        QString where = top;
        for (const QString& p : key.parents) {
            parent = r.object(parent, where, p.toLatin1().constData());
            where = joined(where, p);
        }
        QString field = joined(where, key.name);
        QJsonValue value = parent.value(key.name);
        if (value.isUndefined()) {
            if (s.session == SessionForm::Optional) {
                continue;  // older sessions: the default
            }
            r.fail(field, QStringLiteral("is missing"));
        }
        if (key.element >= 0) {
            const qsizetype n = elementCount(key);
            if (!value.isArray() || value.toArray().size() != n) {
                r.fail(field, QStringLiteral("must be an array of %1 values").arg(n));
            }
            value = value.toArray()[key.element];
            field += QStringLiteral("[%1]").arg(key.element);
        }
        s.field.set(d, r.setting(s, value, field));
    }
    const QString vssWhere = joined(top, QStringLiteral("vss"));
    readDepthRange(r, r.object(view, top, "vss"), vssWhere, d);
    const QString styleWhere = joined(top, QStringLiteral("style"));
    const QJsonObject style = r.object(view, top, "style");
    readColorRange(r, style, styleWhere, d);
    // Optional (older sessions have none): the objects' styles.
    if (const QJsonValue objects = style.value(QLatin1String("objects")); !objects.isUndefined()) {
        readObjects(r, objects, joined(styleWhere, QStringLiteral("objects")), d.style);
    }
}

}  // namespace vv::app::detail
