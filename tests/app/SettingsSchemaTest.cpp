// SPDX-License-Identifier: GPL-3.0-or-later
// The settings schema (app/common/SettingsSchema.h) and QSettings through it
// (StoredSettings.h), linked on their own (vv_app_settings): the schema's
// defaults are the engine's, its names are the ones sessions, QSettings and
// the command line have always used, its values are checked by type and range
// (no display, no GL). Sessions: SettingsSessionTest.cpp.
#include <gtest/gtest.h>

#include <QSettings>
#include <QTemporaryDir>
#include <cmath>
#include <set>
#include <string>

#include "common/SettingsSchema.h"
#include "common/StoredSettings.h"
#include "vv/core/Error.h"
#include "vv/core/NumberText.h"

namespace vv::test {
namespace {

using app::Setting;
using app::SettingType;
using app::SettingValue;

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
