// SPDX-License-Identifier: GPL-3.0-or-later
// Which arrays are labels (scene/ArrayLabels.h): the rule, on the demo's
// segment_id, on arbitrary ids, and on float arrays of whole numbers.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "vv/demo/DemoTree.h"
#include "vv/scene/ArrayLabels.h"

namespace {

using vv::scene::Scene;

Scene withArray(const std::string& name, const std::vector<float>& values, bool integer) {
    Scene scene;
    vv::scene::Mesh mesh;
    mesh.positions.resize(values.size());
    vv::scene::DataArray array;
    array.name = name;
    array.values = values;
    array.integer = integer;
    mesh.pointArrays.push_back(array);
    scene.meshes.push_back(mesh);
    return scene;
}

TEST(ArrayLabelsTest, TheDemosSegmentIdsAreLabelsItsPressureIsNot) {
    vv::demo::DemoTreeOptions options;
    options.generations = 3;
    Scene scene;
    scene.meshes.push_back(vv::demo::generateDemoMesh(options));
    EXPECT_TRUE(vv::scene::looksCategorical(scene, "segment_id"));
    EXPECT_TRUE(vv::scene::looksCategorical(scene, "generation"));
    EXPECT_FALSE(vv::scene::looksCategorical(scene, "pressure"));
    EXPECT_FALSE(vv::scene::looksCategorical(scene, "wss"));
    const auto labels = vv::scene::distinctLabels(scene, "segment_id");
    ASSERT_TRUE(labels.has_value());
    EXPECT_EQ(labels->front().value, 0);
}

TEST(ArrayLabelsTest, ArbitraryIdsAreLabelsInAscendingOrder) {
    const Scene scene = withArray("branch", {200, 0, 17, 5, 5, 0, 200}, false);
    EXPECT_TRUE(vv::scene::looksCategorical(scene, "branch"));
    const auto labels = vv::scene::distinctLabels(scene, "branch");
    ASSERT_TRUE(labels.has_value());
    std::vector<std::int64_t> values;
    for (const auto& l : *labels) {
        values.push_back(l.value);
    }
    EXPECT_EQ(values, (std::vector<std::int64_t>{0, 5, 17, 200}));
}

TEST(ArrayLabelsTest, ManyWholeNumbersOrFractionsStayContinuous) {
    std::vector<float> many;
    for (int i = 0; i < 100; ++i) {
        many.push_back(static_cast<float>(80 + i));  // a pressure rounded to mmHg
    }
    EXPECT_FALSE(vv::scene::looksCategorical(withArray("pressure", many, false), "pressure"));
    // 12 whole numbers in a float array without a label-like name: continuous
    // (more than 8); with one, labels (the name breaks the tie).
    std::vector<float> twelve(many.begin(), many.begin() + 12);
    EXPECT_FALSE(vv::scene::looksCategorical(withArray("value", twelve, false), "value"));
    EXPECT_TRUE(vv::scene::looksCategorical(withArray("group", twelve, false), "group"));
    EXPECT_FALSE(vv::scene::looksCategorical(withArray("f", {0.5F, 1.0F}, false), "f"));
    EXPECT_TRUE(vv::scene::labelLikeName("segment_id"));
    EXPECT_TRUE(vv::scene::labelLikeName("BranchId"));
    EXPECT_FALSE(vv::scene::labelLikeName("pressure"));
}

TEST(ArrayLabelsTest, NamesComeFromTheMeshes) {
    Scene scene = withArray("segment_id", {1, 2, 3}, true);
    scene.meshes[0].labelNames["segment_id"] = {{2, "Left iliac"}};
    const auto labels = vv::scene::distinctLabels(scene, "segment_id");
    ASSERT_TRUE(labels.has_value());
    EXPECT_EQ((*labels)[1].name, "Left iliac");
    EXPECT_EQ(vv::scene::labelText((*labels)[0]), "Label 1");
}

}  // namespace
