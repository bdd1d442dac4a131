// SPDX-License-Identifier: GPL-3.0-or-later
// The settings schema (app/common/SettingsSchema.h) through sessions
// (app/common/Session.h): every consumer (the command line, sessions,
// QSettings) enforces the same range, and the newer optional settings load
// from older sessions as their defaults (no display, no GL).
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QStringList>
#include <QTemporaryDir>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "common/Session.h"
#include "common/SettingsSchema.h"
#include "common/StoredSettings.h"
#include "vv/core/Error.h"

namespace vv::test {
namespace {

using app::Setting;
using app::SettingType;
using app::SettingValue;

std::filesystem::path sessionFile() {
    return std::filesystem::path(VV_TEST_TMP) / "settings-schema" / "s.vvs";
}

bool numeric(const Setting& s) {
    return s.type == SettingType::Int || s.type == SettingType::Real;
}

/// A value of `s` just beyond its maximum (a whole step for Int).
SettingValue aboveMax(const Setting& s) {
    if (s.type == SettingType::Int) {
        return static_cast<int>(s.max) + 1;
    }
    return s.max + std::max(1.0, std::abs(s.max)) * 0.01;
}

SettingValue atMax(const Setting& s) {
    if (s.type == SettingType::Int) {
        return static_cast<int>(s.max);
    }
    return s.max;
}

QJsonValue json(const Setting& s, const SettingValue& v) {
    return s.type == SettingType::Int ? QJsonValue(std::get<int>(v))
                                      : QJsonValue(std::get<double>(v));
}

/// The session JSON of the defaults with view.<key> replaced by `value`.
QByteArray sessionWith(const Setting& s, const QJsonValue& value) {
    app::Session session;
    session.files = {QStringLiteral("/data/a.vtp")};
    QJsonObject root = QJsonDocument::fromJson(app::sessionToJson(session, sessionFile())).object();
    QStringList path = QString::fromUtf8(s.key.data(), static_cast<qsizetype>(s.key.size()))
                           .prepend(QStringLiteral("view."))
                           .split(QLatin1Char('.'));
    int element = -1;
    if (const qsizetype bracket = path.back().indexOf(QLatin1Char('[')); bracket >= 0) {
        element = path.back().mid(bracket + 1, 1).toInt();
        path.back() = path.back().left(bracket);
    }
    // Rebuild the objects along the path with the new value.
    std::vector<QJsonObject> objects{root};
    for (qsizetype i = 0; i + 1 < path.size(); ++i) {
        objects.push_back(objects.back().value(path[i]).toObject());
    }
    QJsonValue leaf = value;
    if (element >= 0) {
        QJsonArray array = objects.back().value(path.back()).toArray();
        array[element] = value;
        leaf = array;
    }
    objects.back().insert(path.back(), leaf);
    for (qsizetype i = path.size() - 2; i >= 0; --i) {
        objects[static_cast<std::size_t>(i)].insert(path[i],
                                                    objects[static_cast<std::size_t>(i) + 1]);
    }
    return QJsonDocument(objects.front()).toJson();
}

// One range for every consumer: the command line, sessions and QSettings all
// refuse a value just beyond a setting's maximum and take its maximum.
TEST(SettingsSchema, EveryConsumerEnforcesTheSameRange) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    std::filesystem::create_directories(sessionFile().parent_path());
    int checked = 0;
    for (const Setting& s : app::settingsSchema()) {
        if (!numeric(s) || s.field.set == nullptr) {
            continue;
        }
        SCOPED_TRACE(std::string(s.key));
        const SettingValue above = aboveMax(s);
        const SettingValue max = atMax(s);
        // The command line.
        if (!s.cliOption.empty()) {
            EXPECT_THROW(static_cast<void>(app::parseSettingText(s, app::settingText(s, above))),
                         InvalidArgumentError);
            EXPECT_EQ(app::parseSettingText(s, app::settingText(s, max)), max);
        }
        // Sessions: refused naming the key; the maximum loads.
        if (s.session == app::SessionForm::Required || s.session == app::SessionForm::Optional) {
            try {
                static_cast<void>(
                    app::sessionFromJson(sessionWith(s, json(s, above)), sessionFile()));
                ADD_FAILURE() << "the session took a value above the maximum";
            } catch (const FormatError& e) {
                EXPECT_NE(std::string(e.what()).find("view." + std::string(s.key)),
                          std::string::npos)
                    << e.what();
            }
            const app::Session loaded =
                app::sessionFromJson(sessionWith(s, json(s, max)), sessionFile());
            EXPECT_EQ(app::settingText(s, s.field.get(loaded)), app::settingText(s, max));
        }
        // QSettings: ignored beyond the range; the maximum is taken.
        if (!s.storedKey.empty()) {
            QSettings store(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
            const QString key =
                QStringLiteral("view/") + QString::fromUtf8(s.storedKey.data(), s.storedKey.size());
            app::DisplaySettings settings;
            store.setValue(key, json(s, above).toVariant());
            app::readStoredSettings(store, settings);
            EXPECT_EQ(s.field.get(settings), app::defaultValue(s));
            store.setValue(key, json(s, max).toVariant());
            app::readStoredSettings(store, settings);
            EXPECT_EQ(app::settingText(s, s.field.get(settings)), app::settingText(s, max));
        }
        ++checked;
    }
    EXPECT_GT(checked, 15);
}

TEST(SettingsSchema, SessionsHoldTheNoDataColourAndLegendTitleOptionally) {
    app::Session s;
    s.files = {QStringLiteral("/data/a.vtp")};
    s.style.noDataColor = glm::vec3(1.0F, 0.0F, 1.0F);
    s.style.legendTitle = "Wall shear stress";
    const app::Session back =
        app::sessionFromJson(app::sessionToJson(s, sessionFile()), sessionFile());
    EXPECT_EQ(back.style.noDataColor, s.style.noDataColor);
    EXPECT_EQ(back.style.legendTitle, s.style.legendTitle);
    // Older sessions have neither: the defaults.
    QJsonObject root = QJsonDocument::fromJson(app::sessionToJson(s, sessionFile())).object();
    QJsonObject view = root.value(QStringLiteral("view")).toObject();
    QJsonObject style = view.value(QStringLiteral("style")).toObject();
    style.remove(QStringLiteral("noDataColor"));
    style.remove(QStringLiteral("legendTitle"));
    view.insert(QStringLiteral("style"), style);
    root.insert(QStringLiteral("view"), view);
    const app::Session old = app::sessionFromJson(QJsonDocument(root).toJson(), sessionFile());
    EXPECT_FALSE(old.style.noDataColor.has_value());
    EXPECT_EQ(old.style.legendTitle, "");
}

// Label arrays: "Values" (auto / continuous / categories) is a setting of
// the command line and of sessions (older sessions: automatic).
TEST(SettingsSchema, ArrayValuesAreAnOptionAndPersistInSessions) {
    const Setting* option = app::settingForOption("--values");
    ASSERT_NE(option, nullptr);
    EXPECT_EQ(std::get<int>(app::parseSettingText(*option, "categories")),
              static_cast<int>(render::ArrayValues::Categories));
    EXPECT_EQ(std::get<int>(app::parseSettingText(*option, "labels")),
              static_cast<int>(render::ArrayValues::Categories));
    EXPECT_THROW(static_cast<void>(app::parseSettingText(*option, "gradient")),
                 InvalidArgumentError);
    app::Session s;
    s.files = {QStringLiteral("/data/a.vtp")};
    s.style.values = render::ArrayValues::Continuous;
    const app::Session back =
        app::sessionFromJson(app::sessionToJson(s, sessionFile()), sessionFile());
    EXPECT_EQ(back.style.values, render::ArrayValues::Continuous);
    QJsonObject root = QJsonDocument::fromJson(app::sessionToJson(s, sessionFile())).object();
    QJsonObject view = root.value(QStringLiteral("view")).toObject();
    QJsonObject style = view.value(QStringLiteral("style")).toObject();
    ASSERT_TRUE(style.contains(QStringLiteral("values")));
    style.remove(QStringLiteral("values"));
    view.insert(QStringLiteral("style"), style);
    root.insert(QStringLiteral("view"), view);
    const app::Session old = app::sessionFromJson(QJsonDocument(root).toJson(), sessionFile());
    EXPECT_EQ(old.style.values, render::ArrayValues::Auto);
}

}  // namespace
}  // namespace vv::test
