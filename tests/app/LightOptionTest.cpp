// SPDX-License-Identifier: GPL-3.0-or-later
// `--light AZ,EL`, the render option of the key light's direction.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "CliRun.h"
#include "cli/Cli.h"
#include "cli/RenderOptions.h"

namespace {

/// Parses `--light value` alone; the values it gave.
vv::cli::RenderOptionValues parsedLight(const std::string& value) {
    const std::vector<std::string> args{"--light", value};
    std::size_t i = 0;
    vv::cli::RenderOptionValues values;
    EXPECT_TRUE(vv::cli::parseRenderOption(args, i, values, "render"));
    EXPECT_EQ(i, 1U);
    return values;
}

TEST(LightOption, GoodValuesBecomeTheLightAngles) {
    auto v = parsedLight("-30,20");
    EXPECT_FLOAT_EQ(v.light.azimuth, -30.0F);
    EXPECT_FLOAT_EQ(v.light.elevation, 20.0F);
    v = parsedLight("180,-90");
    EXPECT_FLOAT_EQ(v.light.azimuth, 180.0F);
    EXPECT_FLOAT_EQ(v.light.elevation, -90.0F);
    v = parsedLight("12.5,0");
    EXPECT_FLOAT_EQ(v.light.azimuth, 12.5F);
    // The default is the renderer's default light; offscreenOptions passes it on.
    EXPECT_EQ(vv::cli::RenderOptionValues{}.light, vv::render::LightAngles{});
    vv::scene::Scene scene;
    vv::cli::RenderOptionValues values;
    values.light = {45.0F, 10.0F};
    values.array = "";
    EXPECT_EQ(vv::cli::offscreenOptions(values, scene, "x.vtp").display.style.light, values.light);
}

TEST(LightOption, BadValuesAreUsageErrorsNamingTheOption) {
    for (const std::string bad :
         {"30", "30,", ",20", "a,b", "181,0", "0,91", "0,-90.5", "nan,0", "1,2,3", ""}) {
        try {
            static_cast<void>(vv::cli::parseLightAngles(bad));
            ADD_FAILURE() << "'" << bad << "' was accepted";
        } catch (const vv::cli::UsageError& e) {
            EXPECT_NE(std::string(e.what()).find("--light"), std::string::npos) << e.what();
        }
    }
    // Through the command line: exit code 2 (usage) and the message on stderr.
    const auto result = vv::test::runCli({"render", "in.vtp", "--light", "0,100", "-o", "x.png"});
    EXPECT_EQ(result.code, 2);
    EXPECT_NE(result.err.find("--light"), std::string::npos) << result.err;
}

}  // namespace
