// Every joint type builds and behaves: springs oscillate at sqrt(k/m), limits hold, fixed and
// point-to-point joints keep their bodies together.

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <gtest/gtest.h>

#include <cmath>

#include "test_files.hpp"

namespace {

/// A static anchor and one child joined by `joint` (spliced into the JOINT block); the child is
/// a 1 kg box placed at `child_location`. `gravity` is the model's gravity.
std::unique_ptr<test_support::Simulation> anchorAndChild(const test_support::TempDir& dir,
                                                         const std::string& joint,
                                                         const std::string& child_location,
                                                         const std::string& gravity,
                                                         const std::string& inertia = "") {
  return test_support::simulate(
      {dir.write("m.yaml",
                 "bodies: [BODY anchor, BODY child]\njoints: [JOINT j]\n"
                 "gravity: " +
                     gravity +
                     "\n"
                     "BODY anchor: {mass: 0, collision shape: BOX, collision geometry: {x: 0.05, "
                     "y: 0.05, z: 0.05}}\n"
                     "BODY child:\n"
                     "  mass: 1\n"
                     "  collision shape: BOX\n"
                     "  collision geometry: {x: 0.05, y: 0.05, z: 0.05}\n"
                     "  damping: {linear: 0, angular: 0}\n" +
                     inertia + "  location: " + child_location +
                     "\n"
                     "JOINT j:\n  parent: BODY anchor\n  child: BODY child\n" +
                     joint)});
}

/// Mean period of the upward zero crossings of `reading` over `seconds`.
template <typename Reading>
double measuredPeriod(ambf_like::World& world, Reading reading, double seconds) {
  std::vector<double> crossings;
  double previous = reading();
  while (world.time() < seconds) {
    world.step();
    const double now = reading();
    if (previous < 0.0 && now >= 0.0) {
      crossings.push_back(world.time() - world.stepSize() * now / (now - previous));
    }
    previous = now;
  }
  if (crossings.size() < 3) return 0.0;
  return (crossings.back() - crossings.front()) / double(crossings.size() - 1);
}

const std::string kNoGravity = "{x: 0, y: 0, z: 0}";
const std::string kGravity = "{x: 0, y: 0, z: -9.81}";

TEST(JointTypes, LinearSpringOscillatesAtItsNaturalFrequency) {
  test_support::TempDir dir;
  auto sim = anchorAndChild(dir,
                            "  type: linear spring\n  parent pivot: {x: 0, y: 0, z: 0.5}\n"
                            "  stiffness: 100\n  damping: 0\n  equilibrium point: 0\n",
                            "{position: {x: 0, y: 0, z: 0.55}}", kNoGravity);
  auto& joint = sim->world->joint("j");
  EXPECT_NEAR(joint.position(), 0.05, 1e-9);
  const double period = measuredPeriod(
      *sim->world, [&] { return joint.position(); }, 3.0);
  EXPECT_NEAR(period, 2 * M_PI * std::sqrt(1.0 / 100.0), 0.02 * 2 * M_PI * 0.1);
}

TEST(JointTypes, TorsionSpringOscillatesAtItsNaturalFrequency) {
  test_support::TempDir dir;
  auto sim = anchorAndChild(dir,
                            "  type: torsion spring\n  parent pivot: {x: 0, y: 0, z: 0.5}\n"
                            "  stiffness: 1\n  damping: 0\n  equilibrium point: 0\n",
                            "{position: {x: 0, y: 0, z: 0.5}, orientation: {r: 0, p: 0, y: 0.2}}",
                            kNoGravity, "  inertia: {ix: 0.01, iy: 0.01, iz: 0.01}\n");
  auto& joint = sim->world->joint("j");
  EXPECT_NEAR(joint.position(), 0.2, 1e-9);
  const double period = measuredPeriod(
      *sim->world, [&] { return joint.position(); }, 3.0);
  EXPECT_NEAR(period, 2 * M_PI * std::sqrt(0.01 / 1.0), 0.02 * 2 * M_PI * 0.1);
}

TEST(JointTypes, FixedJointHoldsItsChildUnderGravity) {
  test_support::TempDir dir;
  auto sim = anchorAndChild(dir, "  type: fixed\n  parent pivot: {x: 0.3, y: 0, z: 0}\n",
                            "{position: {x: 0.3, y: 0, z: 0}}", kGravity);
  sim->world->step(2000);
  EXPECT_LT((sim->world->body("child").pose().translation() - ambf_like::Vec3(0.3, 0, 0)).norm(),
            1e-3);
}

TEST(JointTypes, PointToPointKeepsThePivotsTogether) {
  test_support::TempDir dir;
  auto sim = anchorAndChild(dir,
                            "  type: p2p\n  parent pivot: {x: 0, y: 0, z: 0}\n"
                            "  child pivot: {x: -0.2, y: 0, z: 0}\n",
                            "{position: {x: 0.2, y: 0, z: 0}}", kGravity);
  double worst = 0.0, lowest = 0.0;
  for (int i = 0; i < 2000; ++i) {
    sim->world->step();
    const auto pivot = sim->world->body("child").pose() * ambf_like::Vec3(-0.2, 0, 0);
    worst = std::max(worst, pivot.norm());
    lowest = std::min(lowest, sim->world->body("child").pose().translation().z());
  }
  EXPECT_LT(worst, 2e-3);
  EXPECT_LT(lowest, -0.19) << "it should swing down through the bottom of its arc";
}

TEST(JointTypes, SixDofStopsAtItsLimits) {
  test_support::TempDir dir;
  auto sim = anchorAndChild(
      dir,
      "  type: six dof\n  parent pivot: {x: 0, y: 0, z: 0.5}\n"
      "  joint limits: {linear: {low: {x: -0.01, y: -0.01, z: -0.02},"
      " high: {x: 0.01, y: 0.01, z: 0.02}},"
      " angular: {low: {x: -0.1, y: -0.1, z: -0.1}, high: {x: 0.1, y: 0.1, z: 0.1}}}\n",
      "{position: {x: 0, y: 0, z: 0.5}}", kGravity);
  sim->world->step(2000);
  EXPECT_NEAR(sim->world->body("child").pose().translation().z(), 0.5 - 0.02, 2e-3);
}

TEST(JointTypes, ConeTwistLimitsTheSwing) {
  test_support::TempDir dir;
  // The child hangs sideways from a cone-twist joint whose twist axis (x) points down; the cone
  // lets it swing 0.3 rad, so gravity cannot pull it further.
  auto sim = anchorAndChild(dir,
                            "  type: cone twist\n  parent pivot: {x: 0, y: 0, z: 0}\n"
                            "  parent axis: {x: 1, y: 0, z: 0}\n  child axis: {x: 1, y: 0, z: 0}\n"
                            "  child pivot: {x: -0.2, y: 0, z: 0}\n"
                            "  joint limits: {x: 0.3, y: 0.3, z: 0.3}\n",
                            "{position: {x: 0.2, y: 0, z: 0}}", kGravity);
  sim->world->step(3000);
  ASSERT_TRUE(sim->world->isFinite());
  const auto direction = (sim->world->body("child").pose().translation()).normalized();
  const double swing = std::acos(std::clamp(direction.x(), -1.0, 1.0));
  EXPECT_LT(swing, 0.3 + 0.05);
  EXPECT_GT(swing, 0.2) << "gravity should have pulled it to the cone";
}

TEST(JointTypes, SpringsAndMultiAxisJointsTakeNoCommands) {
  test_support::TempDir dir;
  auto sim =
      anchorAndChild(dir, "  type: linear spring\n", "{position: {x: 0, y: 0, z: 0}}", kNoGravity);
  EXPECT_FALSE(sim->world->joint("j").isControllable());
  EXPECT_THROW(sim->world->joint("j").commandPosition(0.1), std::invalid_argument);
}

TEST(JointTypes, SixDofAngularLimitsFollowTheRightHandRule) {
  test_support::TempDir dir;
  // The child may turn about z only between 0.1 and 0.3 rad; a torque drives it positive.
  auto sim =
      anchorAndChild(dir,
                     "  type: six dof\n  parent pivot: {x: 0, y: 0, z: 0.5}\n"
                     "  joint limits: {linear: {low: {x: 0, y: 0, z: 0}, high: {x: 0, y: 0, z: 0}},"
                     " angular: {low: {x: 0, y: 0, z: 0.1}, high: {x: 0, y: 0, z: 0.3}}}\n",
                     "{position: {x: 0, y: 0, z: 0.5}, orientation: {r: 0, p: 0, y: 0.2}}",
                     kNoGravity, "  inertia: {ix: 0.01, iy: 0.01, iz: 0.01}\n");
  auto& world = *sim->world;
  auto yaw = [&] { return Eigen::AngleAxisd(world.body("child").pose().linear()).angle(); };
  EXPECT_NEAR(yaw(), 0.2, 1e-9);
  for (int i = 0; i < 1000; ++i) {
    world.body("child").bullet().applyTorque(btVector3(0, 0, 0.05));
    world.step();
  }
  EXPECT_NEAR(yaw(), 0.3, 0.02) << "stopped by the upper limit";
}

TEST(JointTypes, SoftBodyWithClustersAndClusterCollisionSteps) {
  test_support::TempDir dir;
  auto sim = test_support::simulate({dir.write(
      "m.yaml",
      "bodies: [BODY ground]\nsoft bodies: [BODY blob]\n"
      "BODY ground: {mass: 0, collision shape: BOX, collision geometry: {x: 1, y: 1, z: 0.1},"
      " collision offset: {position: {x: 0, y: 0, z: -0.05}}}\n"
      "BODY blob: {mass: 0.1, mesh: " +
          test_support::icosphereMesh().string() +
          ", scale: 0.05, collision margin: 0.002, location: {position: {x: 0, y: 0, z: 0.2}},"
          " config: {clusters: 8, flags: 0x2, bending constraint: 2, kVC: 20}}\n")});
  sim->world->step(2000);
  ASSERT_TRUE(sim->world->isFinite());
  EXPECT_LT(sim->world->softBody("blob").centerOfMass().z(), 0.1) << "it should have fallen";
  EXPECT_GT(sim->world->softBody("blob").centerOfMass().z(), 0.0) << "and rest on the ground";
}

}  // namespace
