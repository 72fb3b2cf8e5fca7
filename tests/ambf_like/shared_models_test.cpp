// Every model in ../shared/data/ambf loads and steps 2000 steps without a NaN; AMBF's scenes end
// where they ended before the speed work of issue 26.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

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

/// A body's position after 20 s of 1 ms steps of one of AMBF's scenes (the bench's runs).
struct FinalPosition {
  const char* body;
  double x, y, z;
};

/// Steps `world` + `models` (its settings changed by `settings`) for 20 s and compares every
/// rigid body's final position with `expected` within `tolerance` (m), printing what it found
/// when they differ.
void expectFinalPositions(const std::filesystem::path& world,
                          const std::vector<std::filesystem::path>& models,
                          const std::vector<FinalPosition>& expected, double tolerance = 1e-6,
                          const test_support::WorldSettings& settings = {}) {
  auto scene = ambf_like::loadModelFiles(models, world);
  if (settings) settings(scene.spec.world);
  ambf_like::MeshLibrary meshes;
  ambf_like::World sim(scene.spec, meshes);
  sim.step(20000);
  ASSERT_TRUE(sim.isFinite());
  std::ostringstream found;
  found.precision(9);
  for (std::size_t b = 0; b < sim.bodyCount(); ++b) {
    const ambf_like::Vec3 p = sim.body(b).pose().translation();
    found << std::fixed << "{\"" << sim.body(b).name() << "\", " << p.x() << ", " << p.y() << ", "
          << p.z() << "},\n";
  }
  ASSERT_EQ(sim.bodyCount(), expected.size()) << found.str();
  for (std::size_t b = 0; b < expected.size(); ++b) {
    const ambf_like::Vec3 p = sim.body(b).pose().translation();
    EXPECT_EQ(sim.body(b).name(), expected[b].body);
    EXPECT_LT((p - ambf_like::Vec3(expected[b].x, expected[b].y, expected[b].z)).norm(), tolerance)
        << expected[b].body << "; found:\n"
        << found.str();
  }
}

// Positions taken once the packed link solve and the articulations' damping were in, neither of
// which touches a scene of rigid bodies in maximal coordinates: what commit 3ba261f did, before
// the speed work. The Raven in maximal coordinates, as then (its default is now reduced: see
// RavenInReducedCoordinatesMovesAsWithConstraints). world.yaml's floor file is missing from
// ../shared/data: the puzzles fall (as far as their damping lets them).
TEST_F(SharedModels, AmbfsRigidScenesEndWhereTheyEndedBeforeTheSpeedWork) {
  const auto descriptions = data_ / "ambf/ambf_models/descriptions";
  expectFinalPositions(descriptions / "world/raven_world.yaml",
                       {descriptions / "multi-bodies/robots/blender-raven2.yaml"},
                       {
                           {"0_link", 0.000013793, 0.000000000, -0.000006405},
                           {"base_link_L", -0.000000000, 0.680000000, 0.000000000},
                           {"link1_L", 0.000000000, 0.680000000, 0.000000000},
                           {"link2_L", -0.000000000, 0.680000000, 0.000000000},
                           {"link3_L", -0.000000414, 0.680000312, 0.000000029},
                           {"instrument_shaft_L", -0.000000414, 0.680000312, 0.000000029},
                           {"wrist_L", -0.000000414, 0.680000312, 0.000000029},
                           {"grasper1_L", -0.009794932, 0.687082478, -0.000954087},
                           {"grasper2_L", -0.009794932, 0.687082478, -0.000954087},
                           {"base_link_R", 0.000000000, -0.703000000, -0.000000000},
                           {"link1_R", 0.000000000, -0.703000000, 0.000000000},
                           {"link2_R", 0.000000000, -0.703000000, -0.000000000},
                           {"link3_R", -0.000003540, -0.703002673, 0.000000250},
                           {"instrument_shaft_R", -0.000003540, -0.703002673, 0.000000250},
                           {"wrist_R", -0.000003540, -0.703002673, 0.000000250},
                           {"grasper1_R", -0.009799523, -0.710084059, -0.000944578},
                           {"grasper2_R", -0.009799523, -0.710084059, -0.000944578},
                       },
                       1e-6, test_support::maximalArticulation);
  expectFinalPositions(descriptions / "world/world.yaml",
                       {descriptions / "multi-bodies/puzzles/peg_and_base.yaml"},
                       {
                           {"PegBase", -0.608000000, -0.525800000, -262.972868942},
                           {"Torus", 0.000000000, 0.000000000, -262.736668942},
                       });
  expectFinalPositions(descriptions / "world/world.yaml",
                       {descriptions / "multi-bodies/puzzles/puzzle2.yaml"},
                       {
                           {"Ball_A", 1.186000000, -0.554000000, -1522.125880860},
                           {"Ball_B", 1.090000000, -0.013000000, -1522.218880860},
                           {"Box_A", 0.962000000, -1.126000000, -1522.225880860},
                           {"Box_B", 0.682000000, -0.521000000, -1522.201880860},
                           {"Cylinder_A", 1.435000000, -0.018000000, -1522.222880860},
                           {"Cylinder_B", 0.683000000, -0.004000000, -1522.203880860},
                           {"Mold_A", -0.827331051, -0.071189187, -1522.449593691},
                           {"HandleBaseLeft", -0.920944200, -0.831621827, -1521.453232419},
                           {"HandleLidLeft", -0.785692633, -0.498087520, -1520.950075504},
                           {"HandleBaseRight", -0.810685738, 0.753373831, -1523.432418074},
                           {"HandleLidRight", -0.660638297, 1.256320397, -1523.116094633},
                           {"MoldHinge", -1.584701572, 0.316194323, -1522.182931149},
                           {"TopPlate", -1.688605060, 0.433940817, -1522.095017390},
                           {"Triangle_A", 0.992000000, 1.161000000, -1522.222880860},
                           {"Triangle_B", 0.681000000, 0.542000000, -1522.202880860},
                           {"LightCone", -0.874000000, 0.051000000, 0.434911381},
                           {"LightCube", -0.874000000, 0.051000000, 0.751930972},
                           {"LightCylinder", -0.874000000, 0.051000000, 1.215000000},
                           {"LightSphere", -0.874000000, 0.051000000, 1.040970287},
                       });
}

// On AMBF's floor (its PLANE now Bullet's half-space, as AMBF makes it). Taken after that change;
// against the 1 km box before it, resting heights differ by the floor's 1 mm collision margin
// (which Bullet's convex-plane contact leaves out) and the puzzle pieces that slide on landing
// end up to 16 mm apart. Pieces that land and slide also carry the compiler's rounding forward:
// the Clang sanitizer build ends 1.3 um from GCC's, hence 0.1 mm here. Every body stays awake,
// as it did then (RigidBodySleep off).
TEST_F(SharedModels, AmbfsPuzzlesOnItsFloorEndWhereTheyEnded) {
  constexpr double kLandedTolerance = 1e-4;
  const auto descriptions = data_ / "ambf/ambf_models/descriptions";
  const auto floor = test_support::exampleFile("ambf_checkered_floor.yaml");
  expectFinalPositions(descriptions / "world/world.yaml",
                       {descriptions / "multi-bodies/puzzles/peg_and_base.yaml", floor},
                       {
                           {"PegBase", -0.607748790, -0.525800000, -1.475582534},
                           {"Torus", -0.000050507, 0.000943096, -1.464669253},
                           {"Plane", 0.000000000, 0.000000000, -1.500000000},
                       },
                       kLandedTolerance, test_support::noRigidBodySleep);
  expectFinalPositions(descriptions / "world/world.yaml",
                       {descriptions / "multi-bodies/puzzles/puzzle2.yaml", floor},
                       {
                           {"Ball_A", 1.186000000, -0.554000000, -1.351000000},
                           {"Ball_B", 1.090000000, -0.013000000, -1.300500000},
                           {"Box_A", 0.960877476, -1.122369374, -1.307000769},
                           {"Box_B", 0.697702432, -0.519503800, -1.284500068},
                           {"Cylinder_A", 1.435298310, -0.018000000, -1.307000020},
                           {"Cylinder_B", 0.688939318, -0.004000000, -1.284500411},
                           {"Mold_A", -0.838514170, -0.015248912, -1.373316854},
                           {"HandleBaseLeft", -0.894775632, -1.270811382, -1.359334896},
                           {"HandleLidLeft", -0.897930587, -1.623057888, -0.850793404},
                           {"HandleBaseRight", -0.872015596, 1.267118713, -1.349326373},
                           {"HandleLidRight", -0.868813220, 1.623778679, -0.851019936},
                           {"MoldHinge", -1.687478284, -0.007636035, -1.101349022},
                           {"TopPlate", -1.642858477, -0.008036527, -0.927002602},
                           {"Triangle_A", 0.991781418, 1.160955274, -1.305197571},
                           {"Triangle_B", 0.679598913, 0.542101163, -1.282646446},
                           {"LightCone", -0.874000000, 0.051000000, 0.434911381},
                           {"LightCube", -0.874000000, 0.051000000, 0.751930972},
                           {"LightCylinder", -0.874000000, 0.051000000, 1.215000000},
                           {"LightSphere", -0.874000000, 0.051000000, 1.040970287},
                           {"Plane", 0.000000000, 0.000000000, -1.500000000},
                       },
                       kLandedTolerance, test_support::noRigidBodySleep);
}

// With the default RigidBodySleep the puzzles' free pieces fall, land and sleep where they came
// to rest: at the awake run's heights within 0.1 mm. Across the floor the awake run's pieces keep
// creeping (Bullet's resting contacts on a level floor: 0.3-1 mm/s, turning at random), so
// there the two runs part by that creep, up to 5 mm over the 18 s after landing.
TEST_F(SharedModels, AmbfsPuzzlesSleepWhereTheyCameToRest) {
  const auto descriptions = data_ / "ambf/ambf_models/descriptions";
  const auto floor = test_support::exampleFile("ambf_checkered_floor.yaml");
  // The free pieces: peg_and_base's torus (its base is static); puzzle2's two balls, boxes,
  // cylinders and triangles (its mould's jointed pieces never sleep).
  const std::vector<std::pair<const char*, std::size_t>> puzzles{{"puzzles/peg_and_base.yaml", 1},
                                                                 {"puzzles/puzzle2.yaml", 8}};
  for (const auto& [puzzle, free_pieces] : puzzles) {
    SCOPED_TRACE(puzzle);
    auto scene =
        ambf_like::loadModelFiles({models() / puzzle, floor}, descriptions / "world/world.yaml");
    ambf_like::MeshLibrary meshes;
    ambf_like::World sleeping(scene.spec, meshes);
    test_support::noRigidBodySleep(scene.spec.world);
    ambf_like::World awake(scene.spec, meshes);
    sleeping.step(20000);
    awake.step(20000);
    std::size_t asleep = 0;
    for (std::size_t b = 0; b < sleeping.bodyCount(); ++b) {
      const auto& body = sleeping.body(b);
      SCOPED_TRACE(body.name());
      const ambf_like::Vec3 gap = body.pose().translation() - awake.body(b).pose().translation();
      EXPECT_LT(std::abs(gap.z()), 1e-4);
      EXPECT_LT(gap.head<2>().norm(), 5e-3);
      asleep += body.isAsleep() ? 1 : 0;
      EXPECT_FALSE(awake.body(b).isAsleep());
    }
    EXPECT_EQ(asleep, free_pieces);
  }
}

// The cloth after 20 s: its centre of mass and every 77th node. Taken with AMBF's order of its
// links (shuffled after the bending links are made), which the speed work brought in; the
// packed link solve itself changes no bit (PackedLinkSolver's own test).
TEST_F(SharedModels, AmbfsClothEndsInTheShapeItHadBeforeTheSpeedWork) {
  const auto descriptions = data_ / "ambf/ambf_models/descriptions";
  const auto scene = ambf_like::loadModelFiles({descriptions / "multi-bodies/sb/cloth.yaml"},
                                               descriptions / "world/world.yaml");
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(scene.spec, meshes);
  world.step(20000);
  ASSERT_TRUE(world.isFinite());
  const auto& cloth = world.softBody("cloth");
  std::vector<ambf_like::Vec3> found{cloth.centerOfMass()};
  for (std::size_t node = 0; node < cloth.nodeCount(); node += 77) {
    found.push_back(cloth.nodePosition(node));
  }
  std::ostringstream printed;
  printed.precision(6);
  for (const auto& p : found) {
    printed << std::fixed << "{" << p.x() << ", " << p.y() << ", " << p.z() << "}, ";
  }
  const std::vector<ambf_like::Vec3> expected{ambf_like::Vec3{-0.389235, 1.999863, -1.523543},
                                              ambf_like::Vec3{-0.389723, 2.000000, -0.677088},
                                              ambf_like::Vec3{-0.385091, 1.799094, -1.324086},
                                              ambf_like::Vec3{-0.384593, 2.256578, -1.964861},
                                              ambf_like::Vec3{-0.550860, 2.067269, -1.251832},
                                              ambf_like::Vec3{-0.195680, 2.238119, -2.238623},
                                              ambf_like::Vec3{-0.389852, 1.770305, -1.527866}};
  ASSERT_EQ(found.size(), expected.size()) << printed.str();
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_LT((found[i] - expected[i]).norm(), 1e-3) << i << "; found: " << printed.str();
  }
}

// AMBF's Raven in reduced coordinates: its two arms become articulations (the 0.1 kg 0_link,
// welded between the two static bases by fixed joints, stays a rigid body), and under the same
// position commands every joint ends where the constraint formulation puts it. Reduced is what
// the default (Articulation::Automatic) makes of it.
TEST_F(SharedModels, RavenInReducedCoordinatesMovesAsWithConstraints) {
  const auto descriptions = data_ / "ambf/ambf_models/descriptions";
  const auto scene =
      ambf_like::loadModelFiles({descriptions / "multi-bodies/robots/blender-raven2.yaml"},
                                descriptions / "world/raven_world.yaml");
  ambf_like::MeshLibrary meshes;
  auto make = [&](ambf_like::Articulation articulation) {
    ambf_like::SceneSpec spec = scene.spec;
    spec.world.articulation = articulation;
    return std::make_unique<ambf_like::World>(spec, meshes);
  };
  auto reduced = make(ambf_like::Articulation::Reduced);
  auto maximal = make(ambf_like::Articulation::Maximal);
  EXPECT_EQ(reduced->articulationCount(), 2u);
  EXPECT_EQ(make(ambf_like::Articulation::Automatic)->articulationCount(), 2u);
  ASSERT_EQ(reduced->warnings().size(), 1u);
  EXPECT_THAT(reduced->warnings()[0], HasSubstr("'0_link'"));
  // Each commandable joint a tenth of its range (or 0.1 rad / 10 mm) from where it starts.
  for (auto* world : {reduced.get(), maximal.get()}) {
    for (std::size_t j = 0; j < world->jointCount(); ++j) {
      auto& joint = world->joint(j);
      if (!joint.isControllable()) continue;
      const bool prismatic = joint.spec().type == ambf_like::JointType::Prismatic;
      joint.commandPosition(joint.position() + (prismatic ? 0.01 : 0.1));
    }
  }
  double worst_gap = 0.0;
  std::string worst;
  for (int step = 0; step < 2000; ++step) {
    reduced->step();
    maximal->step();
  }
  for (std::size_t j = 0; j < reduced->jointCount(); ++j) {
    const auto& joint = reduced->joint(j);
    EXPECT_EQ(joint.name(), maximal->joint(j).name());
    const double gap = std::abs(joint.position() - maximal->joint(j).position());
    if (gap > worst_gap) {
      worst_gap = gap;
      worst = joint.name();
    }
  }
  RecordProperty("worst_joint_gap", std::to_string(worst_gap) + " (" + worst + ")");
  EXPECT_LT(worst_gap, 1e-3) << worst;
}

}  // namespace
