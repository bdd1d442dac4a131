// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/StoredSettings.h"

#include <QSettings>
#include <QString>
#include <QVariant>
#include <QVariantList>
#include <cmath>
#include <limits>
#include <optional>

namespace vv::app {

namespace {

QString storeKey(const Setting& s) {
    return QStringLiteral("view/") +
           QString::fromUtf8(s.storedKey.data(), static_cast<qsizetype>(s.storedKey.size()));
}

std::optional<double> number(const QVariant& v) {
    bool ok = false;
    const double d = v.toDouble(&ok);
    return ok && std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
}

std::optional<int> wholeNumber(const QVariant& v) {
    const auto d = number(v);
    if (!d || *d != std::floor(*d) || *d < std::numeric_limits<int>::min() ||
        *d > std::numeric_limits<int>::max()) {
        return std::nullopt;
    }
    return static_cast<int>(*d);
}

/// What `v` holds as a value of `s`; nullopt when it is of the wrong kind.
/// (INI files give text for everything but lists: "true", "2.5".)
std::optional<SettingValue> fromVariant(const Setting& s, const QVariant& v) {
    switch (s.type) {
        case SettingType::Bool: {
            if (v.typeId() == QMetaType::Bool) {
                return v.toBool();
            }
            const QString t = v.toString().trimmed().toLower();
            if (t == QLatin1String("true") || t == QLatin1String("false")) {
                return t == QLatin1String("true");
            }
            return std::nullopt;
        }
        case SettingType::Int:
            if (const auto i = wholeNumber(v)) {
                return *i;
            }
            return std::nullopt;
        case SettingType::Real:
            if (const auto d = number(v)) {
                return *d;
            }
            return std::nullopt;
        case SettingType::Choice:
            if (s.storedAsIndex) {
                if (const auto i = wholeNumber(v)) {
                    return *i;
                }
                return std::nullopt;
            }
            if (const auto c = choiceFromName(s, v.toString().toStdString())) {
                return *c;
            }
            return std::nullopt;
        case SettingType::Color: {
            const QVariantList list = v.toList();
            if (list.size() != 3) {
                return std::nullopt;
            }
            glm::vec3 color{0.0F};
            for (int i = 0; i < 3; ++i) {
                const auto c = number(list[i]);
                if (!c) {
                    return std::nullopt;
                }
                color[i] = static_cast<float>(*c);
            }
            return color;
        }
        case SettingType::Text:
            return v.toString().toStdString();
    }
    return std::nullopt;
}

}  // namespace

QVariant settingToVariant(const Setting& s, const SettingValue& value, bool indexChoices) {
    if (std::holds_alternative<NoValue>(value)) {
        return {};
    }
    switch (s.type) {
        case SettingType::Bool:
            return std::get<bool>(value);
        case SettingType::Int:
            return std::get<int>(value);
        case SettingType::Real:
            return std::get<double>(value);
        case SettingType::Choice: {
            const int v = std::get<int>(value);
            if (indexChoices && s.storedAsIndex) {
                return v;
            }
            const std::string_view name = s.choices->name(v);
            return QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
        }
        case SettingType::Color: {
            const auto& c = std::get<glm::vec3>(value);
            return QVariantList{static_cast<double>(c.r), static_cast<double>(c.g),
                                static_cast<double>(c.b)};
        }
        case SettingType::Text:
            return QString::fromStdString(std::get<std::string>(value));
    }
    return {};
}

void writeStoredSettings(const DisplaySettings& settings, QSettings& store) {
    for (const Setting& s : settingsSchema()) {
        if (!s.storedKey.empty()) {
            store.setValue(storeKey(s), settingToVariant(s, s.field.get(settings), true));
        }
    }
}

void readStoredSettings(const QSettings& store, DisplaySettings& settings) {
    for (const Setting& s : settingsSchema()) {
        if (s.storedKey.empty()) {
            continue;
        }
        const QVariant stored = store.value(storeKey(s));
        if (!stored.isValid()) {
            continue;
        }
        const auto value = fromVariant(s, stored);
        if (value && problemWith(s, *value).empty()) {
            s.field.set(settings, *value);
        }
    }
}

}  // namespace vv::app
