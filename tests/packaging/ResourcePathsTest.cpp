// SPDX-License-Identifier: GPL-3.0-or-later
// The resource-location helper: data folders relative to the executable, in
// the installed layout, the build-tree layout and a macOS bundle.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "common/ResourcePaths.h"
#include "vv/Version.h"

namespace fs = std::filesystem;

namespace {

/// A fresh folder under the build tree's test-tmp, removed first.
fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(VV_TEST_TMP) / "resource-paths" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void touch(const fs::path& file) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << "x";
}

void setEnv(const char* name, const char* value) {
#if defined(_WIN32)
    _putenv_s(name, value);
#else
    ::setenv(name, value, 1);
#endif
}

void unsetEnv(const char* name) {
#if defined(_WIN32)
    _putenv_s(name, "");
#else
    ::unsetenv(name);
#endif
}

/// Sets an environment variable for one scope, restoring the old value.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) {
            old_ = old;
        }
        setEnv(name, value);
    }
    ~ScopedEnv() {
        if (old_) {
            setEnv(name_, old_->c_str());
        } else {
            unsetEnv(name_);
        }
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

  private:
    const char* name_;
    std::optional<std::string> old_;
};

}  // namespace

TEST(ResourcePaths, ExecutableDirIsTheFolderOfThisTest) {
    const fs::path dir = vv::app::executableDir();
    ASSERT_FALSE(dir.empty());
    EXPECT_TRUE(dir.is_absolute());
    EXPECT_TRUE(fs::is_regular_file(dir / "vv_packaging_tests") ||
                fs::is_regular_file(dir / "vv_packaging_tests.exe"))
        << dir;
}

TEST(ResourcePaths, InstalledLayoutFindsShareVesselview) {
    const fs::path prefix = freshDir("installed");
    touch(prefix / "share/vesselview/demo/vessel-tree.vtp");
    fs::create_directories(prefix / "bin");
    const auto found = vv::app::findData("demo/vessel-tree.vtp", prefix / "bin");
    ASSERT_TRUE(found.has_value());
    EXPECT_TRUE(fs::equivalent(*found, prefix / "share/vesselview/demo/vessel-tree.vtp"));
}

TEST(ResourcePaths, BuildTreeLayoutFindsResources) {
    const fs::path build = freshDir("build");
    touch(build / "resources/demo/vessel-tree.vtp");
    fs::create_directories(build / "app");
    const auto found = vv::app::findData("demo/vessel-tree.vtp", build / "app");
    ASSERT_TRUE(found.has_value());
    EXPECT_TRUE(fs::equivalent(*found, build / "resources/demo/vessel-tree.vtp"));
}

TEST(ResourcePaths, MacBundleLayoutFindsContentsResources) {
    const fs::path bundle = freshDir("VesselView.app");
    touch(bundle / "Contents/Resources/translations/vesselview_de.qm");
    fs::create_directories(bundle / "Contents/MacOS");
    const auto found = vv::app::findData("translations", bundle / "Contents/MacOS");
    ASSERT_TRUE(found.has_value());
    EXPECT_TRUE(fs::equivalent(*found, bundle / "Contents/Resources/translations"));
}

TEST(ResourcePaths, InstalledDataWinsOverABuildTreeBesideIt) {
    const fs::path root = freshDir("both");
    touch(root / "share/vesselview/demo/vessel-tree.vtp");
    touch(root / "resources/demo/vessel-tree.vtp");
    fs::create_directories(root / "bin");
    const auto found = vv::app::findData("demo/vessel-tree.vtp", root / "bin");
    ASSERT_TRUE(found.has_value());
    EXPECT_TRUE(fs::equivalent(*found, root / "share/vesselview/demo/vessel-tree.vtp"));
}

TEST(ResourcePaths, NothingFoundWithoutData) {
    const fs::path empty = freshDir("empty");
    fs::create_directories(empty / "bin");
    EXPECT_FALSE(vv::app::findData("demo/vessel-tree.vtp", empty / "bin").has_value());
    EXPECT_FALSE(vv::app::findData("translations", empty / "bin").has_value());
    EXPECT_TRUE(vv::app::dataDirCandidates({}).empty());
    EXPECT_FALSE(vv::app::findData("demo/vessel-tree.vtp", fs::path()).has_value());
}

TEST(ResourcePaths, CandidatesAreRelativeToTheExecutableOnly) {
    const fs::path exeDir = fs::path("/opt/somewhere/bin");
    const auto candidates = vv::app::dataDirCandidates(exeDir);
    ASSERT_EQ(candidates.size(), 3u);
    EXPECT_EQ(candidates[0], fs::path("/opt/somewhere/share/vesselview"));
    EXPECT_EQ(candidates[1], fs::path("/opt/somewhere/resources"));
    EXPECT_EQ(candidates[2], fs::path("/opt/somewhere/Resources"));
}

TEST(ResourcePaths, DemoFileFromTheEnvironmentWins) {
    const ScopedEnv env("VV_DEMO_FILE", "/data/my-tree.vtp");
    const auto demo = vv::app::findDemoFile();
    ASSERT_TRUE(demo.has_value());
    EXPECT_EQ(*demo, fs::path("/data/my-tree.vtp"));
}

TEST(ResourcePaths, DemoFileOfThisBuildTree) {
    // This test runs from <build>/tests/packaging: <build>/tests/resources does
    // not exist, so without VV_DEMO_FILE there is no demo for it.
    const ScopedEnv env("VV_DEMO_FILE", "");
    EXPECT_FALSE(vv::app::findDemoFile().has_value());
}

TEST(Version, HeaderMatchesTheProjectVersion) {
    EXPECT_EQ(vv::kVersion, std::string(VV_EXPECTED_VERSION));
    EXPECT_EQ(std::to_string(vv::kVersionMajor) + "." + std::to_string(vv::kVersionMinor) + "." +
                  std::to_string(vv::kVersionPatch),
              std::string(vv::kVersion));
}
