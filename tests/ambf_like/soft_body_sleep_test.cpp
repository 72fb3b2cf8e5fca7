// Resting soft bodies sleep, keep still and keep their contacts; moving bodies that come near
// wake them in time, bodies that only share a bounding box with them do not.

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_files.hpp"

namespace {

using test_support::TempDir;

/// Writes scene.yaml: the soft ball resting on the ground plane (it starts just above it), plus
/// `extra` bodies.
std::filesystem::path writeBallOnGround(const TempDir& dir, const std::string& extra_names = "",
                                        const std::string& extra = "") {
  return dir.write("scene.yaml",
                   "bodies: [BODY ground" + extra_names + "]\nsoft bodies: [BODY blob]\n" +
                       test_support::groundPlaneBody() + test_support::softBallBody(0.002) +
                       "  location: {position: {x: 0, y: 0, z: 0.053}}\n"
                       "  config: {kDF: 0.8, kVC: 20, piterations: 4, bending constraint: 2}\n" +
                       extra);
}

std::unique_ptr<test_support::Simulation> ballOnGround(
    const TempDir& dir, const std::string& extra_names = "", const std::string& extra = "",
    const test_support::WorldSettings& settings = {}) {
  return test_support::simulate({writeBallOnGround(dir, extra_names, extra)}, settings);
}

/// ADF text of a dynamic box `name` with its own gravity along z, at `location` (an ADF
/// location map's contents).
std::string boxBody(const std::string& name, double mass, const std::string& size, double gravity_z,
                    const std::string& location) {
  return "BODY " + name + ":\n  name: " + name + "\n  mass: " + std::to_string(mass) +
         "\n  collision shape: BOX\n  collision geometry: " + size +
         "\n  gravity: {x: 0, y: 0, z: " + std::to_string(gravity_z) + "}\n  location: {" +
         location + "}\n";
}

/// Steps until the body sleeps; returns the simulated time it took (or -1 after `limit` s).
double stepUntilAsleep(ambf_like::World& world, const ambf_like::SoftBody& body, double limit) {
  while (world.time() < limit) {
    world.step();
    if (body.isAsleep()) return world.time();
  }
  return -1.0;
}

TEST(SoftBodySleep, ARestingBodyFallsAsleepAndThenStaysExactlyWhereItWas) {
  TempDir dir;
  auto sim = ballOnGround(dir);
  auto& world = *sim->world;
  const auto& ball = world.softBody("blob");
  const double fell_asleep = stepUntilAsleep(world, ball, 5.0);
  ASSERT_GT(fell_asleep, 0.5) << "it cannot have rested for the 0.5 s window yet";
  const auto asleep = ball.nodePositions();
  const auto contacts = world.contacts().size();
  EXPECT_GT(contacts, 0u) << "a sleeper reports the contacts it rests on";
  world.step(2000);
  EXPECT_TRUE(ball.isAsleep());
  EXPECT_EQ(ball.nodePositions(), asleep);
  EXPECT_EQ(world.contacts().size(), contacts) << "contacts must not pile up while it sleeps";
}

TEST(SoftBodySleep, TheWorldFileAndTheWorldSpecCanTurnItOff) {
  TempDir dir;
  auto sim = ballOnGround(dir, "", "", test_support::noSoftBodySleep);
  // With sleep on, this ball sleeps after about 2.7 s (the first test).
  EXPECT_LT(stepUntilAsleep(*sim->world, sim->world->softBody("blob"), 5.0), 0.0);

  dir.write("world.yaml", "ambf_like: {soft body sleep: {enabled: false}}\n");
  const auto launch = dir.write("launch.yaml",
                                "world config: world.yaml\nmultibody configs:\n"
                                "  - scene.yaml\n");
  writeBallOnGround(dir);
  const auto scene = ambf_like::loadLaunchFile(launch, {});
  EXPECT_FALSE(scene.spec.world.soft_body_sleep.enabled);
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(scene.spec, meshes);
  EXPECT_LT(stepUntilAsleep(world, world.softBody("blob"), 5.0), 0.0);
}

TEST(SoftBodySleep, TheWorldFileSetsTheThresholdsAndRefusesBadOnes) {
  TempDir dir;
  dir.write("m.yaml", "bodies: [BODY b]\nBODY b: {mass: 0}\n");
  const auto launch =
      dir.write("launch.yaml", "world config: world.yaml\nmultibody configs:\n  - m.yaml\n");
  dir.write("world.yaml",
            "ambf_like: {soft body sleep: {distance: 0.002, time: 1.5, wake distance: 0.02}}\n");
  const auto sleep = ambf_like::loadLaunchFile(launch, {}).spec.world.soft_body_sleep;
  EXPECT_TRUE(sleep.enabled);
  EXPECT_EQ(sleep.distance, 0.002);
  EXPECT_EQ(sleep.time, 1.5);
  EXPECT_EQ(sleep.wake_distance, 0.02);
  dir.write("world.yaml", "ambf_like: {soft body sleep: {distance: 0}}\n");
  EXPECT_THAT(test_support::loadErrorOf([&] { ambf_like::loadLaunchFile(launch, {}); }),
              testing::AllOf(testing::HasSubstr("soft body sleep/distance"),
                             testing::HasSubstr("must be positive")));
  dir.write("world.yaml", "ambf_like: {soft body sleep: {speed: 0.1}}\n");  // unknown key
  EXPECT_THAT(
      test_support::loadErrorOf([&] { ambf_like::loadLaunchFile(launch, {}, {.strict = true}); }),
      testing::HasSubstr("speed"));
}

TEST(SoftBodySleep, ABodyFallingOntoASleeperWakesItBeforeArrivingAndRestsOnIt) {
  TempDir dir;
  // A light box sinks towards the ball under a weak gravity of its own, so the ball is asleep
  // (after about 2.7 s of settling) before the box arrives (4.7 s) and meets it slowly.
  auto sim = ballOnGround(dir, ", BODY lid",
                          boxBody("lid", 0.01, "{x: 0.06, y: 0.06, z: 0.01}", -0.02,
                                  "position: {x: 0, y: 0, z: 0.33}"));
  auto& world = *sim->world;
  const auto& ball = world.softBody("blob");
  const auto& lid = world.body("lid");
  ASSERT_GT(stepUntilAsleep(world, ball, 4.0), 0.0);
  const auto asleep = ball.nodePositions();
  double top = -1.0;
  for (const auto& p : asleep) top = std::max(top, p.z());
  while (ball.isAsleep() && world.time() < 8.0) world.step();
  ASSERT_FALSE(ball.isAsleep()) << "the lid never woke the ball";
  const double gap = lid.pose().translation().z() - 0.005 - top;
  EXPECT_GT(gap, 0.002) << "woken only once the lid was touching it";
  // The wake distance (10 mm) counts from the ball's bounds: its nodes plus its 2 mm margin.
  EXPECT_LE(gap, 0.01 + 0.002 + 0.0005) << "woken farther away than the wake distance";
  world.step(3000);
  EXPECT_GT(lid.pose().translation().z(), 0.06) << "the lid went through the ball";
  EXPECT_TRUE(ball.isFinite());
}

TEST(SoftBodySleep, AMovingBodyWhoseBoxOnlyOverlapsTheSleepersLetsItSleep) {
  TempDir dir;
  // A 1 m rod tilted 45 degrees: its bounding box takes in the ball, the rod itself passes
  // 0.5 m away from it (a long arm link above a peg is the case that matters).
  auto sim = ballOnGround(dir, ", BODY rod",
                          boxBody("rod", 0.1, "{x: 1.0, y: 0.01, z: 0.01}", 0.0,
                                  "position: {x: 0.4, y: 0, z: 0.4}, "
                                  "orientation: {r: 0, p: 0.785398, y: 0}"));
  auto& world = *sim->world;
  const auto& ball = world.softBody("blob");
  ASSERT_GT(stepUntilAsleep(world, ball, 4.0), 0.0);
  auto& rod = world.body("rod").bullet();
  rod.activate(true);  // the resting rod is asleep too (RigidBodySleep): pushed from outside
  rod.setLinearVelocity(btVector3(0, 0.02, 0));
  btVector3 low, high;
  rod.getAabb(low, high);
  ASSERT_LT(low.x(), 0.06);
  ASSERT_LT(low.z(), 0.1);
  for (int i = 0; i < 1000; ++i) {
    world.step();
    ASSERT_TRUE(ball.isAsleep()) << "woken at step " << i;
  }
  EXPECT_GT(world.body("rod").linearVelocity().norm(), 0.019) << "the rod must have been moving";
}

TEST(SoftBodySleep, AnAnchorWakesASleeperAndKeepsItAwake) {
  TempDir dir;
  auto sim = ballOnGround(dir);
  auto& world = *sim->world;
  auto& ball = world.softBody("blob");
  ASSERT_GT(stepUntilAsleep(world, ball, 5.0), 0.0);
  ball.bullet().appendAnchor(0, &world.body("ground").bullet());
  world.step();
  EXPECT_FALSE(ball.isAsleep());
  world.step(2000);
  EXPECT_FALSE(ball.isAsleep()) << "a held body must keep being simulated";
}

}  // namespace
