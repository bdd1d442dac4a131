// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/SessionReader.h"

#include <QJsonArray>
#include <cmath>
#include <limits>

#include "common/StoredSettings.h"
#include "vv/core/Error.h"

namespace vv::app::detail {

QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size()));
}

QJsonValue settingToJson(const Setting& setting, const SettingValue& value) {
    return QJsonValue::fromVariant(settingToVariant(setting, value));
}

void SessionReader::fail(const QString& field, const QString& problem) const {
    throw FormatError(file_,
                      "session field '" + field.toStdString() + "' " + problem.toStdString());
}

QString SessionReader::path(const QString& where, const char* key) {
    return where.isEmpty() ? QLatin1String(key) : where + QLatin1Char('.') + QLatin1String(key);
}

QJsonValue SessionReader::get(const QJsonObject& o, const QString& where, const char* key) const {
    QJsonValue v = o.value(QLatin1String(key));
    if (v.isUndefined()) {
        fail(path(where, key), QStringLiteral("is missing"));
    }
    return v;
}

QJsonObject SessionReader::object(const QJsonObject& o, const QString& where,
                                  const char* key) const {
    const QJsonValue v = get(o, where, key);
    if (!v.isObject()) {
        fail(path(where, key), QStringLiteral("must be an object"));
    }
    return v.toObject();
}

double SessionReader::number(const QJsonObject& o, const QString& where, const char* key, double lo,
                             double hi) const {
    return checkNumber(get(o, where, key), path(where, key), lo, hi);
}

int SessionReader::integer(const QJsonObject& o, const QString& where, const char* key, int lo,
                           int hi) const {
    const double v = number(o, where, key, lo, hi);
    if (v != std::floor(v)) {
        fail(path(where, key), QStringLiteral("must be a whole number"));
    }
    return static_cast<int>(v);
}

float SessionReader::real(const QJsonObject& o, const QString& where, const char* key, double lo,
                          double hi) const {
    return static_cast<float>(number(o, where, key, lo, hi));
}

bool SessionReader::boolean(const QJsonObject& o, const QString& where, const char* key) const {
    const QJsonValue v = get(o, where, key);
    if (!v.isBool()) {
        fail(path(where, key), QStringLiteral("must be true or false"));
    }
    return v.toBool();
}

QString SessionReader::string(const QJsonObject& o, const QString& where, const char* key) const {
    const QJsonValue v = get(o, where, key);
    if (!v.isString()) {
        fail(path(where, key), QStringLiteral("must be a string"));
    }
    return v.toString();
}

std::vector<double> SessionReader::numbers(const QJsonValue& v, const QString& field, qsizetype n,
                                           double lo, double hi) const {
    if (!v.isArray() || v.toArray().size() != n) {
        fail(field, QStringLiteral("must be an array of %1 numbers").arg(n));
    }
    std::vector<double> out;
    const QJsonArray a = v.toArray();
    for (qsizetype i = 0; i < n; ++i) {
        out.push_back(checkNumber(a[i], field + QStringLiteral("[%1]").arg(i), lo, hi));
    }
    return out;
}

glm::vec3 SessionReader::vec3(const QJsonObject& o, const QString& where, const char* key,
                              double lo, double hi) const {
    const auto n = numbers(get(o, where, key), path(where, key), 3, lo, hi);
    return {static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])};
}

double SessionReader::checkNumber(const QJsonValue& v, const QString& field, double lo,
                                  double hi) const {
    if (!v.isDouble()) {
        fail(field, QStringLiteral("must be a number"));
    }
    const double d = v.toDouble();
    if (!std::isfinite(d) || d < lo || d > hi) {
        fail(field,
             QStringLiteral("must be a finite number in [%1, %2], not %3").arg(lo).arg(hi).arg(d));
    }
    return d;
}

SettingValue SessionReader::setting(const Setting& s, const QJsonValue& v,
                                    const QString& field) const {
    SettingValue value;
    if (v.isNull() && s.nullable) {
        return NoValue{};
    }
    switch (s.type) {
        case SettingType::Bool:
            if (!v.isBool()) {
                fail(field, QStringLiteral("must be true or false"));
            }
            value = v.toBool();
            break;
        case SettingType::Int: {
            if (!v.isDouble()) {
                fail(field, QStringLiteral("must be a whole number"));
            }
            const double d = v.toDouble();
            if (d != std::floor(d)) {
                fail(field, QStringLiteral("must be a whole number, not %1").arg(d));
            }
            if (d < std::numeric_limits<int>::min() || d > std::numeric_limits<int>::max()) {
                fail(field, QStringLiteral("must be %1, not %2").arg(text(validValues(s))).arg(d));
            }
            value = static_cast<int>(d);
            break;
        }
        case SettingType::Real:
            if (!v.isDouble()) {
                fail(field, QStringLiteral("must be a number"));
            }
            value = v.toDouble();
            break;
        case SettingType::Choice: {
            if (!v.isString()) {
                fail(field, QStringLiteral("must be a name (%1)").arg(text(choiceNames(s))));
            }
            const auto choice = choiceFromName(s, v.toString().toStdString());
            if (!choice) {
                fail(field, QStringLiteral("names none of %1: \"%2\"")
                                .arg(text(choiceNames(s)), v.toString()));
            }
            value = *choice;
            break;
        }
        case SettingType::Color: {
            const auto c = numbers(v, field, 3, 0.0, 1.0);
            value = glm::vec3(static_cast<float>(c[0]), static_cast<float>(c[1]),
                              static_cast<float>(c[2]));
            break;
        }
        case SettingType::Text:
            if (!v.isString()) {
                fail(field, QStringLiteral("must be a string"));
            }
            value = v.toString().toStdString();
            break;
    }
    if (const std::string problem = problemWith(s, value); !problem.empty()) {
        fail(field, text(problem));
    }
    return value;
}

}  // namespace vv::app::detail
