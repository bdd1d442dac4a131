// SPDX-License-Identifier: GPL-3.0-or-later
// vesselview-cli artefacts, through vv::cli::run.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/Cli.h"

namespace vv::cli {
namespace {

struct Outcome {
    int code;
    std::string out;
    std::string err;
};

Outcome runCli(const std::vector<std::string>& args) {
    std::ostringstream out;
    std::ostringstream err;
    const int code = run(args, out, err);
    return {code, out.str(), err.str()};
}

TEST(ArtefactsCliTest, PrintsOneRowPerMesh) {
    const Outcome o = runCli({"artefacts", "--size", "160x90", "--triangles", "20000"});
    ASSERT_EQ(o.code, kOk) << o.err;
    EXPECT_NE(o.out.find("View close, 160x90, p = 2"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| demo (smooth control) | 300884 | "), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| 1.00 |"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("| demo decimated to 20000 | "), std::string::npos) << o.out;
}

TEST(ArtefactsCliTest, RejectsBadOptions) {
    EXPECT_EQ(runCli({"artefacts", "--view", "sideways"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--p", "0"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--triangles", "2"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--bogus"}).code, kUsage);
    EXPECT_EQ(runCli({"artefacts", "--mesh", "/nonexistent/tree.stl", "--triangles", "none",
                      "--size", "32x32"})
                  .code,
              kInvalidInput);
}

}  // namespace
}  // namespace vv::cli
