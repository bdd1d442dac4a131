// SPDX-License-Identifier: GPL-3.0-or-later
// The surface index built on a thread of its own answers as the one built
// at once, to queries from several threads that arrive before it is done.
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "PreparedSurface.h"
#include "SurfaceIndex.h"
#include "TubeOptions.h"
#include "vv/demo/TubePhantom.h"

namespace vv::analysis::detail {
namespace {

TEST(SurfaceIndex, BuiltInTheBackgroundAnswersAsBuiltAtOnce) {
    const auto tube =
        demo::makeTubePhantom(test::tubeOptions(demo::TubeShape::Cylinder, 5.0, 200'000));
    const PreparedSurface s = prepareSurface(tube.mesh, std::nullopt, {}, 3'000'000);
    const SurfaceIndex now(s);
    const SurfaceIndex later(s, SurfaceIndex::Build::InBackground);
    // Points along the axis and off it; each thread asks its own half.
    std::vector<glm::dvec3> probes;
    for (int i = 0; i < 64; ++i) {
        probes.emplace_back(0.3 * (i % 7), -0.2 * (i % 5), 1.5 * i);
    }
    std::vector<double> expected;
    for (const glm::dvec3& p : probes) {
        expected.push_back(now.nearest(p).distance);
    }
    std::vector<double> got(probes.size(), -1.0);
    {
        std::jthread other([&] {
            for (std::size_t i = 1; i < probes.size(); i += 2) {
                got[i] = later.nearest(probes[i]).distance;
            }
        });
        for (std::size_t i = 0; i < probes.size(); i += 2) {
            got[i] = later.nearest(probes[i]).distance;
        }
    }
    for (std::size_t i = 0; i < probes.size(); ++i) {
        EXPECT_EQ(got[i], expected[i]) << i;
        EXPECT_GT(expected[i], 0.0);
    }
    const auto hit = later.firstHit({0.0, 0.0, 50.0}, {1.0, 0.0, 0.0});
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->x, 5.0, 0.05);
}

}  // namespace
}  // namespace vv::analysis::detail
