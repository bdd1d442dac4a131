// SPDX-License-Identifier: GPL-3.0-or-later
// The settings schema (app/common/SettingsSchema.h): its defaults are the
// engine's, its names are the ones sessions, QSettings and the command line
// have always used, and every consumer enforces the same range (no display,
// no GL).
#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QStringList>
#include <QTemporaryDir>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "common/Session.h"
#include "common/SettingsSchema.h"
#include "common/StoredSettings.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

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

TEST(SettingsSchema, DefaultsAreTheEnginesAndValid) {
    const app::DisplaySettings defaults;
    const render::VssSettings vss;
    EXPECT_EQ(std::get<double>(app::defaultValue(app::setting("vss.p"))), vss.solver.p);
    EXPECT_EQ(std::get<double>(app::defaultValue(app::setting("vss.tolerance"))),
              vss.solver.tolerance);
    EXPECT_EQ(std::get<int>(app::defaultValue(app::setting("vss.isoLines"))), vss.isoLines);
    EXPECT_EQ(std::get<double>(app::defaultValue(app::setting("ao.radius"))),
              static_cast<double>(render::AoSettings{}.radius));
    EXPECT_EQ(std::get<double>(app::defaultValue(app::setting("cue.fogStrength"))),
              static_cast<double>(render::VesselCueSettings{}.fogStrength));
    EXPECT_EQ(std::get<glm::vec3>(app::defaultValue(app::setting("style.vesselColor"))),
              render::MeshStyle{}.vesselColor);
    EXPECT_EQ(std::get<double>(app::defaultValue(app::setting("style.light[1]"))),
              static_cast<double>(render::LightAngles{}.elevation));
    EXPECT_EQ(std::get<glm::vec3>(app::defaultValue(app::setting("background"))),
              render::kDefaultBackground);
    for (const Setting& s : app::settingsSchema()) {
        EXPECT_EQ(app::problemWith(s, app::defaultValue(s)), "") << s.key << ": default invalid";
        EXPECT_NE(std::string(s.label), "") << s.key;
    }
}

TEST(SettingsSchema, KeepsEveryNameSessionsSettingsAndTheCommandLineUse) {
    std::set<std::string_view> keys;
    std::set<std::string_view> stored;
    std::set<std::string_view> options;
    for (const Setting& s : app::settingsSchema()) {
        EXPECT_TRUE(keys.insert(s.key).second) << "key twice: " << s.key;
        if (!s.storedKey.empty()) {
            EXPECT_TRUE(stored.insert(s.storedKey).second) << "QSettings key twice: " << s.key;
        }
        if (!s.cliOption.empty() && s.key != "style.light[1]") {  // --light AZ,EL: two settings
            EXPECT_TRUE(options.insert(s.cliOption).second) << "option twice: " << s.cliOption;
        }
    }
    for (const char* key :
         {"vss", "depthScale", "power", "solver", "tolerance", "step", "isoLines",
          "isoLineStrength", "lighting", "ao", "aoRadius", "colorMap", "bins", "vesselCue",
          "background", "vesselColor", "legends", "lightAzimuth", "lightElevation"}) {
        EXPECT_TRUE(stored.contains(key)) << "the QSettings key view/" << key << " is gone";
    }
    for (const char* option :
         {"--vss", "--scale", "--p", "--isolines", "--solver", "--tolerance", "--ao", "--aa",
          "--cue", "--legends", "--background", "--colormap", "--bins", "--array", "--light"}) {
        EXPECT_TRUE(options.contains(option)) << "the option " << option << " is gone";
    }
}

TEST(SettingsSchema, ValuesAreCheckedByTypeAndRange) {
    const Setting& p = app::setting("vss.p");
    EXPECT_EQ(app::problemWith(p, 0.25), "");
    EXPECT_NE(app::problemWith(p, 0.1).find("0.25..64"), std::string::npos);
    EXPECT_NE(app::problemWith(p, true), "");
    const Setting& bins = app::setting("style.bins");
    EXPECT_EQ(app::problemWith(bins, 0), "");
    EXPECT_EQ(app::problemWith(bins, 2), "");
    EXPECT_NE(app::problemWith(bins, 1), "");
    EXPECT_NE(app::problemWith(bins, 2.5).find("whole number"), std::string::npos);
    EXPECT_NE(app::problemWith(app::setting("background"), glm::vec3(0.5F, 1.5F, 0.0F)), "");
    EXPECT_NE(app::problemWith(app::setting("cue.cue"), 99), "");
    EXPECT_EQ(app::problemWith(app::setting("style.noDataColor"), app::NoValue{}), "");
    EXPECT_NE(app::problemWith(app::setting("style.vesselColor"), app::NoValue{}), "");
    EXPECT_THROW(static_cast<void>(app::setting("vss.nonsense")), InvalidArgumentError);
}

TEST(SettingsSchema, TextRoundTripsForEveryOption) {
    for (const Setting& s : app::settingsSchema()) {
        if (s.cliOption.empty()) {
            continue;
        }
        // Through the text and back into the field: the same value (a float
        // field's text is the float's), colours to 8 bits.
        const SettingValue v = app::defaultValue(s);
        const std::string text = app::settingText(s, v);
        app::DisplaySettings d;
        d.vss.solver.p = 64.0;  // anything else than the default
        s.field.set(d, app::parseSettingText(s, text));
        if (s.type == SettingType::Color) {
            const glm::vec3 back = std::get<glm::vec3>(s.field.get(d));
            const glm::vec3 want = std::get<glm::vec3>(v);
            EXPECT_LE(glm::length(back - want), 0.9F / 255.0F) << s.key << ": '" << text << "'";
        } else {
            EXPECT_EQ(s.field.get(d), v) << s.key << ": '" << text << "'";
        }
    }
    EXPECT_EQ(app::parseSettingText(app::setting("background"), "#ff8000"),
              SettingValue(glm::vec3(1.0F, 128.0F / 255.0F, 0.0F)));
    EXPECT_EQ(app::parseSettingText(app::setting("vss.scale"), "dmd"),
              SettingValue(static_cast<int>(colormaps::DepthScale::DarkMeansDeep)));
    EXPECT_THROW(static_cast<void>(app::parseSettingText(app::setting("vss.enabled"), "yes")),
                 InvalidArgumentError);
    EXPECT_THROW(static_cast<void>(app::parseSettingText(app::setting("vss.p"), "4,5")),
                 InvalidArgumentError);
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

TEST(SettingsSchema, StoredSettingsRoundTripAndKeepTheirFormats) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    QSettings store(dir.filePath(QStringLiteral("s.ini")), QSettings::IniFormat);
    app::DisplaySettings changed;
    changed.vss.solver.p = 5.0;
    changed.vss.scale = colormaps::DepthScale::DarkMeansDeep;
    changed.cue.cue = render::VesselCue::Fog;
    changed.style.light = {30.0F, -10.0F};
    changed.style.vesselColor = glm::vec3(0.25F, 0.5F, 0.75F);
    changed.legends = false;
    changed.style.array = "wss";  // belongs to the data: not stored
    app::writeStoredSettings(changed, store);
    EXPECT_EQ(store.value(QStringLiteral("view/depthScale")).toString(),
              QStringLiteral("dark-means-deep"));
    EXPECT_EQ(store.value(QStringLiteral("view/vesselCue")).toInt(),
              static_cast<int>(render::VesselCue::Fog));
    EXPECT_EQ(store.value(QStringLiteral("view/background")).toList().size(), 3);
    EXPECT_FALSE(store.contains(QStringLiteral("view/array")));
    app::DisplaySettings read;
    app::readStoredSettings(store, read);
    EXPECT_EQ(read.vss.solver.p, 5.0);
    EXPECT_EQ(read.vss.scale, colormaps::DepthScale::DarkMeansDeep);
    EXPECT_EQ(read.cue.cue, render::VesselCue::Fog);
    EXPECT_EQ(read.style.light, changed.style.light);
    EXPECT_EQ(read.style.vesselColor, changed.style.vesselColor);
    EXPECT_FALSE(read.legends);
    EXPECT_EQ(read.style.array, "");
}

TEST(SettingsSchema, ResetKeepsWhatBelongsToTheData) {
    app::DisplaySettings s;
    s.vss.solver.p = 7.0;
    s.vss.range = {vss::RangeMode::Fixed, 10.0, 20.0};
    s.style.array = "pressure";
    s.style.legendTitle = "P";
    s.style.range = std::make_pair(1.0F, 2.0F);
    s.style.light = {10.0F, 10.0F};
    app::resetToDefaults(s);
    EXPECT_EQ(s.vss.solver.p, render::VssSettings{}.solver.p);
    EXPECT_EQ(s.vss.range.mode, vss::RangeMode::Visible);
    EXPECT_EQ(s.style.light, render::LightAngles{});
    EXPECT_EQ(s.style.array, "pressure");
    EXPECT_EQ(s.style.legendTitle, "P");
    EXPECT_TRUE(s.style.range.has_value());
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

TEST(NumberText, ShortestRoundTripInTheCLocale) {
    EXPECT_EQ(vv::shortestText(0.5), "0.5");
    EXPECT_EQ(vv::shortestText(2.0), "2");
    EXPECT_EQ(vv::shortestText(0.1F), "0.1");
    EXPECT_EQ(vv::shortestText(static_cast<double>(0.1F)), "0.10000000149011612");
    EXPECT_EQ(vv::shortestText(std::nan("")), "nan");
    for (const double v : {1.0 / 3.0, 1e-300, 123456.789, -0.0625}) {
        EXPECT_EQ(vv::parseFiniteNumber(vv::shortestText(v)), v);
    }
    EXPECT_EQ(vv::readableText(2.0 / 3.0), "0.666667");
    EXPECT_FALSE(vv::parseFiniteNumber("1,5").has_value());
    EXPECT_FALSE(vv::parseFiniteNumber("inf").has_value());
    EXPECT_FALSE(vv::parseWholeNumber("2.5").has_value());
}

}  // namespace
}  // namespace vv::test

namespace vv::test {
namespace {

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
