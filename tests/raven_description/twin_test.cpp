// Our Raven-II twin: the committed model is what the generator writes, its body poses agree
// with the kinematics (and so do AMBF's meshes placed on its links), it tracks joint commands
// under gravity, and the peg-transfer scene rests and stops a ring thrown at its board.

#include <BulletSoftBody/btSoftBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>

#include "ambf_like/scene_loader.hpp"
#include "raven/arm_kinematics.hpp"
#include "raven/design/peg_scene_design.hpp"
#include "test_files.hpp"
#include "twin/drive_train.hpp"
#include "twin/gravity_compensation.hpp"
#include "twin/twin_arms.hpp"
#include "twin_fixtures.hpp"
#include "viewer/visual_skin.hpp"

namespace {

using Eigen::Vector3d;
using raven::Arm;
using raven::ArmJoints;

const std::filesystem::path kModels = RAVEN_MODELS_DIR;

/// A World with a launch file loaded, and the Raven arm layer over it.
struct Twin {
  explicit Twin(const std::filesystem::path& launch)
      : scene(ambf_like::loadLaunchFile(launch, {})),
        world(scene.spec, meshes),
        arms(world, twin::ArmBindings::ourRaven()) {}
  ambf_like::LoadedScene scene;
  ambf_like::MeshLibrary meshes;
  ambf_like::World world;
  twin::TwinArms arms;

  Vector3d wristPoint(Arm arm) {
    return world.body("/raven2/" + std::string(raven::armName(arm)) + "/wrist_link")
        .pose()
        .translation();
  }
  Vector3d toolPoint(Arm arm) {
    return world.body("/raven2/" + std::string(raven::armName(arm)) + "/jaw1_link")
        .pose()
        .translation();
  }
};

/// A measurement for RecordProperty, in three significant figures (std::to_string rounds
/// micrometres to zero).
std::string measured(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// AMBF's meshes on our links: written by raven_fit_visuals, not by the model generator.
const std::filesystem::path kVisualSkin = "raven2/ambf_visuals.yaml";

std::set<std::filesystem::path> filesUnder(const std::filesystem::path& dir) {
  std::set<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    const auto file = std::filesystem::relative(entry.path(), dir);
    if (entry.is_regular_file() && file != kVisualSkin) out.insert(file);
  }
  return out;
}

TEST(Twin, CommittedModelsAreWhatTheGeneratorWrites) {
  test_support::TempDir dir;
  const std::string command =
      std::string(RAVEN_MODEL_GENERATOR) + " --out " + dir.path().string() + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const auto generated = filesUnder(dir.path());
  ASSERT_EQ(generated, filesUnder(kModels)) << "run: cmake --build build --target raven_models";
  for (const auto& file : generated) {
    EXPECT_EQ(test_support::readFile(dir.path() / file), test_support::readFile(kModels / file))
        << file << " is stale: cmake --build build --target raven_models";
  }
}

TEST(Twin, ReadsTheHomeJointsAndSitsOnTheKinematicFramesAtLoad) {
  Twin twin(kModels / "raven2/launch.yaml");
  for (Arm arm : raven::kArms) {
    EXPECT_LT(
        (twin.arms.measured(arm) - test_support::physicalProfile().home).cwiseAbs().maxCoeff(),
        1e-9);
    const auto kin = raven::ArmKinematics::of(test_support::physicalProfile(), arm);
    EXPECT_LT((twin.wristPoint(arm) - kin.wristPoint(test_support::physicalProfile().home)).norm(),
              1e-9);
    EXPECT_LT(
        (twin.toolPoint(arm) - kin.toolPose(test_support::physicalProfile().home).translation())
            .norm(),
        1e-9);
  }
}

/// Steps until `arm` is at rest near `target` (every joint within 2e-4 rad, the insertion within
/// 2e-5 m), at most 8 s: the servos run at up to 3 rad/s and a roll may turn 4 pi.
void settle(Twin& twin, Arm arm, const ArmJoints& target) {
  ArmJoints tolerance = ArmJoints::Constant(2e-4);
  tolerance(raven::kInsertion) = 2e-5;
  for (int chunk = 0; chunk < 160; ++chunk) {
    twin.world.step(50);
    const ArmJoints error = (twin.arms.measured(arm) - target).cwiseAbs();
    if ((error.array() < tolerance.array()).all() &&
        twin.arms.velocities(arm).cwiseAbs().maxCoeff() < 1e-4) {
      return;
    }
  }
}

// One arm at a time, the other held at home: about 3 % of random pairs of poses make the two
// arms' carriages or rails meet above the midline, and then neither reaches its pose (as on the
// real robot). With the other arm at home no pose of the moving arm touches it.
TEST(Twin, SettledPosesMatchTheKinematicsWithinATenthOfAMillimetre) {
  Twin twin(kModels / "raven2/launch.yaml");
  std::mt19937_64 random(2024);
  const auto& limits = test_support::physicalProfile().limits;
  for (Arm arm : raven::kArms) {
    const Arm other = raven::other(arm);
    const auto kin = raven::ArmKinematics::of(test_support::physicalProfile(), arm);
    double worst_wrist = 0.0, worst_tool = 0.0;
    std::size_t contacts = 0;
    for (int sample = 0; sample < 1000; ++sample) {
      ArmJoints q;
      for (int i = 0; i < raven::kJointCount; ++i) {
        q(i) = std::uniform_real_distribution<double>(limits.low(i), limits.high(i))(random);
      }
      twin.arms.command(arm, q);
      twin.arms.command(other, test_support::physicalProfile().home);
      settle(twin, arm, q);
      for (const auto& c : twin.world.contacts()) contacts += c.distance < 0.0;
      worst_wrist = std::max(worst_wrist, (twin.wristPoint(arm) - kin.wristPoint(q)).norm());
      worst_tool =
          std::max(worst_tool, (twin.toolPoint(arm) - kin.toolPose(q).translation()).norm());
    }
    const std::string side(raven::armName(arm));
    RecordProperty(side + "_worst_wrist_point_error_m", measured(worst_wrist));
    RecordProperty(side + "_worst_tool_point_error_m", measured(worst_tool));
    EXPECT_EQ(contacts, 0u) << side;
    EXPECT_LT(worst_wrist, 1e-4) << side;
    EXPECT_LT(worst_tool, 1e-4) << side;
  }
  EXPECT_TRUE(twin.world.isFinite());
}

// The robot's firmware holds its first three links with a model of their weight (masses and
// centres of mass from grav_comp.cpp, raven2-actuation.md §3), and a fitted correction of a few
// tens of percent is all the recordings ask beyond it: the twin's links must weigh on their joints
// what that model says, or motors driving them would sag where the robot holds. The firmware puts
// the instrument's weight at frame 3's origin (the carriage); ours hangs along the shaft, which
// moves the shoulder's and elbow's loads by at most that weight times how far it hangs.
TEST(Twin, HeldStillItsLinksWeighOnTheirJointsAsTheRobotsFirmwareExpects) {
  Twin twin(kModels / "raven2/launch.yaml");
  const twin::DriveTrain drive = twin::DriveTrain::raven2();
  const double world_over_firmware_g = 9.81 / 9.8;  // world.yaml's g over grav_comp.cpp's
  const auto& profile = test_support::physicalProfile();
  std::mt19937_64 random(64);
  for (Arm arm : raven::kArms) {
    const Arm other = raven::other(arm);
    const std::string prefix = "/raven2/" + std::string(raven::armName(arm)) + "/";
    // The instrument's moment about the carriage (N m): sum of m g |r| over its bodies.
    auto hanging = [&] {
      const Vector3d carriage = twin.world.body(prefix + "carriage").pose().translation();
      double moment = 0.0;
      for (const char* b : {"shaft", "wrist_link", "jaw1_link", "jaw2_link"}) {
        const auto& body = twin.world.body(prefix + b);
        moment += body.mass() * 9.81 * (body.centerOfMassPose().translation() - carriage).norm();
      }
      return moment;
    };
    double worst = 0.0;
    for (int sample = 0; sample < 12; ++sample) {
      ArmJoints q = profile.home;
      for (int i = 0; sample > 0 && i < 3; ++i) {
        q(i) = std::uniform_real_distribution<double>(profile.limits.low(i),
                                                      profile.limits.high(i))(random);
      }
      twin.arms.command(arm, q);
      twin.arms.command(other, profile.home);
      settle(twin, arm, q);
      ArmJoints held = ArmJoints::Zero();
      constexpr int kSteps = 200;
      for (int s = 0; s < kSteps; ++s) {
        twin.world.step();
        held += twin.arms.efforts(arm) / kSteps;
      }
      // The firmware's Tau is at the gearbox output: the joint load is Tau x transmission /
      // gearbox.
      const ArmJoints firmware = twin::gravityCompensation(arm, twin.arms.measured(arm), drive)
                                     .cwiseProduct(drive.transmission)
                                     .cwiseQuotient(drive.gearbox) *
                                 world_over_firmware_g;
      const double instrument_moment = hanging();
      for (int i = 0; i < 3; ++i) {
        // 1 % of the load, or 2 mN m (2 mN on the insertion) where it nearly vanishes; the
        // insertion carries the whole link-3 weight either way.
        const double where_it_hangs = i == raven::kInsertion ? 0.0 : instrument_moment;
        EXPECT_NEAR(held(i), firmware(i), 0.01 * std::abs(firmware(i)) + 2e-3 + where_it_hangs)
            << raven::armName(arm) << " joint " << i << " at " << q.head<3>().transpose();
        worst = std::max(worst, std::abs(held(i) - firmware(i)));
      }
    }
    RecordProperty(std::string(raven::armName(arm)) + "_worst_gravity_load_error", measured(worst));
  }
}

TEST(Twin, AmbfsGrasperAndWristMeshesSitOnTheKinematicsInThreePoses) {
  // The skin places AMBF's meshes through AMBF's own joint geometry (raven_fit_visuals): a
  // grasper mesh's frame is on its jaw axis at its pivot, a wrist mesh's on the wrist axis where
  // the shaft crosses it. Where those land against our forward kinematics is the check.
  const auto skin = viewer::VisualSkin::load(kModels / kVisualSkin);
  Twin twin(kModels / "raven2/launch.yaml");
  ArmJoints reach = test_support::physicalProfile().home, tilted = reach;
  reach << 0.35, 1.2, 0.47, 0.6, -0.5, 0.4, 0.2;
  tilted << 0.9, 1.9, 0.33, -1.0, 0.7, 0.1, 0.5;
  for (Arm arm : raven::kArms) {
    const auto kin = raven::ArmKinematics::of(test_support::physicalProfile(), arm);
    const std::string prefix = "/raven2/" + std::string(raven::armName(arm)) + "/";
    double worst_pivot = 0.0, worst_wrist = 0.0;
    for (const ArmJoints& q : {test_support::physicalProfile().home, reach, tilted}) {
      twin.arms.command(arm, q);
      twin.arms.command(raven::other(arm), test_support::physicalProfile().home);
      settle(twin, arm, q);
      const ArmJoints reached = twin.arms.measured(arm);
      for (const char* jaw : {"jaw1_link", "jaw2_link"}) {
        const Vector3d pivot = twin.world.body(prefix + jaw).pose() *
                               skin.bodies.at(prefix + jaw).offset.translation();
        worst_pivot = std::max(worst_pivot, (pivot - kin.toolPose(reached).translation()).norm());
      }
      const Vector3d wrist = twin.world.body(prefix + "wrist_link").pose() *
                             skin.bodies.at(prefix + "wrist_link").offset.translation();
      worst_wrist = std::max(worst_wrist, (wrist - kin.wristPoint(reached)).norm());
    }
    const std::string side(raven::armName(arm));
    RecordProperty(side + "_grasper_mesh_pivot_to_tool_point_m", measured(worst_pivot));
    RecordProperty(side + "_wrist_mesh_to_wrist_point_m", measured(worst_wrist));
    EXPECT_LT(worst_pivot, 2e-3) << side;
    EXPECT_LT(worst_wrist, 2e-3) << side;
  }
}

TEST(Twin, CommittedVisualSkinIsWhatTheFitWrites) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: AMBF's Raven model is not here";
  test_support::TempDir dir;
  const std::string command = std::string(RAVEN_FIT_VISUALS) + " --models " +
                              (kModels / "raven2").string() + " --ambf-model " +
                              (shared /
                               "ambf/ambf_models/descriptions/multi-bodies/robots/"
                               "blender-raven2.yaml")
                                  .string() +
                              " --out " + (dir.path() / "skin.yaml").string() + " > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  // The same bodies and meshes, the same offsets to the printed digits (the last may differ with
  // the compiler's floating-point contractions).
  const auto fitted = viewer::VisualSkin::load(dir.path() / "skin.yaml");
  const auto committed = viewer::VisualSkin::load(kModels / kVisualSkin);
  ASSERT_EQ(fitted.bodies.size(), committed.bodies.size());
  for (const auto& [body, piece] : committed.bodies) {
    ASSERT_TRUE(fitted.bodies.count(body)) << body;
    const auto& fresh = fitted.bodies.at(body);
    EXPECT_EQ(fresh.mesh, piece.mesh) << body;
    EXPECT_LT((fresh.offset.translation() - piece.offset.translation()).norm(), 1e-8) << body;
    EXPECT_LT(
        Eigen::AngleAxisd(fresh.offset.rotation().transpose() * piece.offset.rotation()).angle(),
        1e-7)
        << body << ": stale, run build/twin/raven_fit_visuals from the repository root";
  }
}

TEST(Twin, FollowsAJointStepAtTheVelocityCapsUnderGravity) {
  Twin twin(kModels / "raven2/launch.yaml");
  // The controller's caps (per second): 5 deg, 5 deg, 0.02 m, then 15 deg for the rest.
  const double deg = M_PI / 180.0;
  const ArmJoints cap =
      (ArmJoints() << 5 * deg, 5 * deg, 0.02, 15 * deg, 15 * deg, 15 * deg, 15 * deg).finished();
  ArmJoints step = (ArmJoints() << 0.05, -0.05, 0.01, 0.2, 0.2, -0.2, 0.2).finished();
  const ArmJoints start = test_support::physicalProfile().home;
  const ArmJoints goal = start + step;
  const double duration = (step.cwiseAbs().array() / cap.array()).maxCoeff();
  for (double t = 0.0; t < duration; t += twin.world.stepSize()) {
    const double s = t / duration;
    for (Arm arm : raven::kArms) twin.arms.command(arm, start + s * step);
    twin.world.step();
  }
  for (Arm arm : raven::kArms) twin.arms.command(arm, goal);
  twin.world.step(300);
  for (Arm arm : raven::kArms) {
    const ArmJoints error = (twin.arms.measured(arm) - goal).cwiseAbs();
    const std::string side(raven::armName(arm));
    RecordProperty(side + "_insertion_error_m", measured(error(raven::kInsertion)));
    RecordProperty(side + "_worst_revolute_error_rad",
                   measured(std::max(error.head<2>().maxCoeff(), error.tail<4>().maxCoeff())));
    EXPECT_LT(error(raven::kInsertion), 0.05e-3) << raven::armName(arm);
    for (int i : {0, 1, 3, 4, 5, 6})
      EXPECT_LT(error(i), 1e-3) << raven::armName(arm) << " joint " << i;
  }
}

TEST(Twin, ArmLayerRefusesNonFiniteCommandsWithoutMoving) {
  Twin twin(kModels / "raven2/launch.yaml");
  ArmJoints bad = test_support::physicalProfile().home;
  bad(raven::kWrist) = std::nan("");
  twin.arms.command(Arm::Left, test_support::physicalProfile().home);
  EXPECT_THROW(twin.arms.command(Arm::Left, bad), std::invalid_argument);
  EXPECT_DOUBLE_EQ(twin.world.joint("/raven2/left/shoulder").target(),
                   test_support::physicalProfile().home(0));
}

/// The vertices of one of our collision meshes (an OBJ's `v` lines), in its body's frame.
std::vector<Vector3d> objVertices(const std::filesystem::path& file) {
  std::vector<Vector3d> vertices;
  std::istringstream lines(test_support::readFile(file));
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string tag;
    Vector3d v;
    if (words >> tag && tag == "v" && words >> v.x() >> v.y() >> v.z()) vertices.push_back(v);
  }
  return vertices;
}

/// How far (m) jaw2's body reaches into jaw1's beyond jaw1's gripping face (the plane of its
/// frame's x and z axes; jaw1's body lies on one side of it), with `arm`'s jaws at `opening`
/// (jaw1 + jaw2) and the pair turned by `twist`: <= 0 where they only touch or stand apart.
double jawOverlap(Twin& twin, Arm arm, double opening, double twist) {
  const std::string side(raven::armName(arm));
  ArmJoints q = test_support::physicalProfile().home;
  q(raven::kJaw1) = 0.5 * opening + twist;
  q(raven::kJaw2) = 0.5 * opening - twist;
  twin.arms.command(arm, q);
  twin.arms.place(arm, q, ArmJoints::Zero());
  twin.world.step(1);  // the bodies' poses follow the joints in a step (1 ms: under 1 nm here)
  const auto jaw1 = twin.world.body("/raven2/" + side + "/jaw1_link").pose();
  const auto jaw2 = twin.world.body("/raven2/" + side + "/jaw2_link").pose();
  const auto meshes = kModels / "raven2/meshes";
  double jaw1_side = 0.0;
  for (const Vector3d& v : objVertices(meshes / ("jaw1_" + side + ".obj"))) jaw1_side += v.y();
  double overlap = -1.0;
  for (const Vector3d& v : objVertices(meshes / ("jaw2_" + side + ".obj"))) {
    const Vector3d in_jaw1 = jaw1.inverse() * (jaw2 * v);
    overlap = std::max(overlap, std::copysign(1.0, jaw1_side) * in_jaw1.y());
  }
  return overlap;
}

TEST(Twin, OurJawsFacesMeetAtOpeningZero) {
  // Where the twin's jaw stop sits (ArmBindings::ourRaven().jaws_meet): derived from the
  // model's own jaws, whatever the pair's twist.
  Twin twin(kModels / "raven2/launch.yaml");
  ASSERT_EQ(twin::ArmBindings::ourRaven().jaws_meet, 0.0);
  for (Arm arm : raven::kArms) {
    for (double twist : {0.0, 0.3, -0.5}) {
      EXPECT_LT(jawOverlap(twin, arm, 0.0, twist), 1e-8) << raven::armName(arm) << " " << twist;
      // 0.02 rad further closed, the 11 mm jaws' tips pass 0.2 mm into each other.
      EXPECT_GT(jawOverlap(twin, arm, -0.02, twist), 1.5e-4) << raven::armName(arm) << twist;
    }
  }
}

TEST(Twin, PegTransferSceneRestsTenSecondsWithEveryPegOnItsPost) {
  Twin twin(kModels / "peg_transfer/launch.yaml");
  for (Arm arm : raven::kArms) twin.arms.command(arm, test_support::physicalProfile().home);
  ASSERT_EQ(twin.world.softBodyCount(), 6u);
  twin.world.step(1000);
  std::vector<Vector3d> settled;
  for (std::size_t p = 0; p < 6; ++p) settled.push_back(twin.world.softBody(p).centerOfMass());
  twin.world.step(9000);
  ASSERT_TRUE(twin.world.isFinite());
  // Tall rings (centre line 8 mm, tube 2 x 5 mm half-axes) on the start row of posts.
  const double board_top = -0.205, hole = 0.006, post = 0.0025;
  const std::array<Eigen::Vector2d, 6> posts{Eigen::Vector2d(0.266, 0.058),
                                             {0.300, 0.058},
                                             {0.334, 0.058},
                                             {-0.266, 0.058},
                                             {-0.300, 0.058},
                                             {-0.334, 0.058}};
  double worst_drift = 0.0;
  for (std::size_t p = 0; p < 6; ++p) {
    const auto& peg = twin.world.softBody(p);
    const Vector3d centre = peg.centerOfMass();
    worst_drift = std::max(worst_drift, (centre - settled[p]).norm());
    EXPECT_LT((centre - settled[p]).norm(), 1e-3) << peg.name() << " drifted";
    EXPECT_LT((centre.head<2>() - posts[p]).norm(), hole - post) << peg.name() << " left its post";
    Eigen::AlignedBox3d box;
    for (const auto& v : peg.nodePositions()) box.extend(v);
    EXPECT_GT(box.min().z(), board_top - 1e-3) << peg.name() << " sank into the board";
    EXPECT_NEAR(box.sizes().x(), 0.020, 0.2 * 0.020) << peg.name() << " lost its shape";
    EXPECT_NEAR(box.sizes().z(), 0.010, 0.2 * 0.010) << peg.name() << " lost its height";
  }
  std::printf("worst peg drift from 1 s to 10 s: %.1f um\n", worst_drift * 1e6);
}

TEST(Twin, AmbfsOwnRavenIsDrivableThroughTheSameArmLayer) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: AMBF's Raven model is not here";
  ambf_like::LoadOptions options;
  const auto scene =
      ambf_like::loadLaunchFile(shared / "ambf/ambf_controller/raven2/launch.yaml", {}, options);
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(scene.spec, meshes);
  twin::TwinArms arms(world, twin::ArmBindings::ambfRaven());
  const auto ambf = raven::builtinProfile("ambf");
  ArmJoints target = ambf.home;
  target(raven::kShoulder) += 0.1;
  target(raven::kInsertion) += 0.02;
  for (Arm arm : raven::kArms) arms.command(arm, target);
  world.step(3000);
  for (Arm arm : raven::kArms) {
    const ArmJoints error = (arms.measured(arm) - target).cwiseAbs();
    EXPECT_LT(error.head<3>().maxCoeff(), 5e-3) << raven::armName(arm) << ": " << error.transpose();
  }
  EXPECT_DOUBLE_EQ(world.joint("wrist_R-grasper1_R").target(), -target(raven::kJaw1));
}

TEST(Twin, ARingThrownAtTheBoardFasterThanARingSnapsStaysOnIt) {
  // Bullet tests a soft body's node against a solid once a step and pushes one past the solid's
  // mid-plane out by its far side: the board and the table under it (depth d) stop a node moving
  // under d / 2 per step. A ring snapping free of a post reached 6 m/s, which passed the 10 mm
  // board alone.
  const raven::design::PegSceneDesign design;
  Twin twin(kModels / "peg_transfer/launch.yaml");
  const double solid = design.board_size.z() + design.table_depth;
  const double speed = 0.8 * (solid / 2) / twin.world.stepSize();
  ASSERT_GT(speed, 6.0);
  for (Arm arm : raven::kArms) twin.arms.command(arm, test_support::physicalProfile().home);
  twin.world.step(500);
  ambf_like::SoftBody& ring = twin.world.softBody(0);
  ring.bullet().setVelocity(btVector3(0.0, 0.0, -speed));
  double lowest = ring.centerOfMass().z();
  for (int step = 0; step < 300; ++step) {
    twin.world.step(1);
    for (const auto& p : ring.nodePositions()) lowest = std::min(lowest, p.z());
  }
  EXPECT_GT(lowest, design.board_top - 0.002) << "thrown down at " << speed << " m/s";
  EXPECT_GT(ring.centerOfMass().z(), design.board_top) << "the ring came to rest on the board";
}

TEST(Twin, ARingDroppedOffTheBoardsEdgeComesToRestOnTheFloor) {
  // A ring let go beyond the board's front edge falls to the floor, a table's height lower, and
  // rests there instead of falling until the world's guard ends the run.
  const raven::design::PegSceneDesign design;
  Twin twin(kModels / "peg_transfer/launch.yaml");
  for (Arm arm : raven::kArms) twin.arms.command(arm, test_support::physicalProfile().home);
  twin.world.step(500);
  ambf_like::SoftBody& ring = twin.world.softBody(0);
  const double front_edge = design.board_centre.y() - design.board_size.y() / 2;
  const double beyond = front_edge - 2.0 * design.ring_major_radius - ring.centerOfMass().y();
  ring.bullet().translate(btVector3(0.0, beyond, 0.02));
  twin.world.step(1500);
  const double floor = design.board_top - design.floor_below_board;
  double lowest = ring.centerOfMass().z();
  for (const auto& p : ring.nodePositions()) lowest = std::min(lowest, p.z());
  EXPECT_NEAR(lowest, floor, 0.002) << "the ring's lowest node against the floor";
  EXPECT_LT(ring.centerOfMass().y(), front_edge) << "the ring fell in front of the board";
}

TEST(Twin, TheBoardsBoundsHoldTheBoardAndNotTheFloor) {
  // Bullet tests a pair of bodies whose bounds overlap: the floor as a part of the board's compound
  // stretched the board's bounds to its 4 m, every arm link overlapped them, and the dense scene
  // ran 7x slower. The floor is a static body of its own, collided with and never drawn.
  const raven::design::PegSceneDesign design;
  Twin twin(kModels / "peg_transfer/launch.yaml");
  const auto extent = [&](std::string_view name) {
    btVector3 low, high;
    twin.world.body(name).bullet().getAabb(low, high);
    return high - low;
  };
  const btVector3 board = extent("peg_board");
  EXPECT_LT(board.x(), design.board_size.x() + 0.01);
  EXPECT_LT(board.y(), design.board_size.y() + 0.01);
  const btVector3 floor = extent("floor");
  EXPECT_GT(floor.x(), design.floor_size.x() - 0.01);
  EXPECT_FALSE(twin.world.body("floor").spec().visible);
  EXPECT_TRUE(twin.world.body("peg_board").spec().visible);
  EXPECT_EQ(twin.world.body("floor").spec().mass, 0.0);
}

}  // namespace
