// Every model in ../shared/data/ambf loads and steps 2000 steps without a NaN.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ambf_like/scene_loader.hpp"
#include "test_files.hpp"

namespace {

using testing::HasSubstr;

class SharedModels : public testing::Test {
 protected:
  void SetUp() override {
    data_ = test_support::sharedDataDir();
    if (data_.empty()) GTEST_SKIP() << "../shared/data is absent: AMBF's model files are not here";
  }
  std::filesystem::path models() const {
    return data_ / "ambf/ambf_models/descriptions/multi-bodies";
  }
  std::filesystem::path ravenLaunch() const {
    return data_ / "ambf/ambf_controller/raven2/launch.yaml";
  }
  static void stepsWithoutNan(const ambf_like::LoadedScene& scene) {
    ambf_like::MeshLibrary meshes;
    ambf_like::World world(scene.spec, meshes);
    for (int i = 0; i < 2000; ++i) {
      world.step();
      ASSERT_TRUE(world.isFinite()) << "NaN after step " << i;
    }
  }
  std::filesystem::path data_;
};

TEST_F(SharedModels, RavenReportsItsTwoMissingBaseMeshesAsErrorsUnderStrict) {
  const auto message = test_support::loadErrorOf(
      [&] { ambf_like::loadLaunchFile(ravenLaunch(), {}, {.strict = true}); });
  EXPECT_THAT(message, HasSubstr("body 'base_link_L': mesh file 'base_link_L.STL' not found"));
  EXPECT_THAT(message, HasSubstr("body 'base_link_R': mesh file 'base_link_R.STL' not found"));
  EXPECT_THAT(message, HasSubstr("raven_2/low_res/base_link_L.STL"));
  EXPECT_THAT(message, HasSubstr("blender-raven2.yaml:37: BODY base_link_L/mesh"));
}

TEST_F(SharedModels, RavenWithItsRealMeshesLoadsAsAmbfLoadsItWithWarnings) {
  const auto scene = ambf_like::loadLaunchFile(ravenLaunch(), {});
  std::string warnings;
  for (const auto& w : scene.warnings) warnings += w.str() + "\n";
  EXPECT_THAT(warnings, HasSubstr("base_link_L.STL"));
  EXPECT_THAT(warnings, HasSubstr("base_link_R.STL"));
  EXPECT_THAT(warnings, HasSubstr("continuing without it"));
  const auto& raven = scene.spec.models.at(0);
  EXPECT_EQ(raven.bodies.size(), 17u);
  EXPECT_EQ(raven.joints.size(), 16u);
  EXPECT_EQ(raven.gravity, ambf_like::Vec3::Zero());
  stepsWithoutNan(scene);
}

TEST_F(SharedModels, EveryDescriptionAndLaunchFileLoadsAndStepsWithDefaultFlags) {
  std::size_t loaded = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(data_ / "ambf")) {
    const auto& path = entry.path();
    if (path.extension() != ".yaml") continue;
    const auto name = path.filename().string();
    const bool launch = name == "launch.yaml";
    const bool model = path.string().find("multi-bodies") != std::string::npos;
    if (!launch && !model) continue;  // worlds, colours, input devices: read through launches
    SCOPED_TRACE(path.string());
    const auto scene =
        launch ? ambf_like::loadLaunchFile(path, {}) : ambf_like::loadModelFiles({path});
    stepsWithoutNan(scene);
    ++loaded;
  }
  EXPECT_GE(loaded, 6u) << "AMBF's launch files, the Raven, the puzzles and the cloth";
}

TEST_F(SharedModels, PegAndBase) {
  stepsWithoutNan(ambf_like::loadModelFiles({models() / "puzzles/peg_and_base.yaml"}));
}

TEST_F(SharedModels, Puzzle2) {
  const auto scene = ambf_like::loadModelFiles({models() / "puzzles/puzzle2.yaml"});
  EXPECT_EQ(scene.spec.models.at(0).joints.size(), 9u);
  stepsWithoutNan(scene);
}

TEST_F(SharedModels, SoftCloth) {
  const auto scene = ambf_like::loadModelFiles({models() / "sb/cloth.yaml"});
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(scene.spec, meshes);
  auto& cloth = world.softBody("cloth");
  ASSERT_GT(cloth.nodeCount(), 100u);
  const auto pinned = cloth.nodePosition(0);
  for (int i = 0; i < 2000; ++i) {
    world.step();
    ASSERT_TRUE(world.isFinite()) << "NaN after step " << i;
  }
  EXPECT_TRUE(cloth.nodePosition(0).isApprox(pinned, 1e-12)) << "fixed node 0 moved";
  EXPECT_LT(cloth.centerOfMass().z(), -0.01) << "the cloth should hang from its fixed node";
}

}  // namespace
