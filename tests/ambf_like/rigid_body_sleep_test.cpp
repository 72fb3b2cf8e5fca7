// Resting free rigid bodies sleep where they came to rest, what touches them wakes them, and the
// setting reads from the world file with its errors named.

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ambf_like/scene_loader.hpp"
#include "test_files.hpp"

namespace {

using test_support::TempDir;
using testing::HasSubstr;

/// A 4 cm, 100 g box 5 cm above the ground plane, and the soft ball far to its side.
std::filesystem::path writeBoxAndBall(const TempDir& dir) {
  return dir.write("scene.yaml",
                   "bodies: [BODY ground, BODY box]\nsoft bodies: [BODY blob]\n" +
                       test_support::groundPlaneBody() +
                       "BODY box:\n  name: box\n  mass: 0.1\n  collision shape: BOX\n"
                       "  collision geometry: {x: 0.04, y: 0.04, z: 0.04}\n"
                       "  location: {position: {x: 0, y: 0, z: 0.07}}\n" +
                       test_support::softBallBody(0.002) +
                       "  location: {position: {x: 1, y: 0, z: 0.053}}\n"
                       "  config: {kDF: 0.8, kVC: 20, piterations: 4, bending constraint: 2}\n");
}

TEST(RigidBodySleep, AFreeBoxSleepsWhereItCameToRest) {
  TempDir dir;
  auto sleeping = test_support::simulate({writeBoxAndBall(dir)});
  auto awake = test_support::simulate({writeBoxAndBall(dir)}, test_support::noRigidBodySleep);
  const auto& box = sleeping->world->body("box");
  EXPECT_FALSE(box.isAsleep());
  sleeping->world->step(4000);
  awake->world->step(4000);
  EXPECT_TRUE(box.isAsleep()) << "it rested from about 0.1 s, for Bullet's 2 s";
  EXPECT_FALSE(awake->world->body("box").isAsleep());
  const ambf_like::Vec3 asleep = box.pose().translation();
  // The awake box's resting contact creeps by some 20 um over those seconds.
  EXPECT_LT((asleep - awake->world->body("box").pose().translation()).norm(), 1e-4);
  EXPECT_NEAR(asleep.z(), 0.02, 1e-3) << "on the ground";
  sleeping->world->step(1000);
  EXPECT_EQ(box.pose().translation(), asleep) << "a sleeper does not move at all";
}

TEST(RigidBodySleep, ASoftBodyLandingOnASleepingBoxWakesItAndRestsOnIt) {
  TempDir dir;
  // The ball stays awake (soft-body sleep off) for the test to move it.
  auto sim = test_support::simulate({writeBoxAndBall(dir)}, test_support::noSoftBodySleep);
  auto& world = *sim->world;
  world.step(4000);
  ASSERT_TRUE(world.body("box").isAsleep());
  // The ball, moved over the box, falls onto it.
  auto& ball = world.softBody("blob");
  ball.bullet().translate(btVector3(-1.0, 0.0, 0.1));
  ball.bullet().setVelocity(btVector3(0, 0, -0.5));
  const ambf_like::Vec3 asleep = world.body("box").pose().translation();
  double lowest = 1.0;  // of the ball's nodes while it lands on the box
  for (int step = 0; step < 300; ++step) {
    world.step();
    for (const auto& node : ball.nodePositions()) lowest = std::min(lowest, node.z());
  }
  EXPECT_FALSE(world.body("box").isAsleep());
  EXPECT_GT((world.body("box").pose().translation() - asleep).norm(), 0.0) << "it felt the ball";
  EXPECT_GT(lowest, 0.035) << "the ball lands on the box's top (4 cm), not through it";
}

TEST(RigidBodySleep, TheSettingIsReadFromTheWorldFileAndABadSpeedIsNamed) {
  TempDir dir;
  const auto model = writeBoxAndBall(dir);
  const auto world_file = dir.write(
      "world.yaml", "ambf_like:\n  rigid body sleep: {linear speed: 0.001, angular speed: 0.01}\n");
  const auto scene = ambf_like::loadModelFiles({model}, world_file);
  EXPECT_TRUE(scene.spec.world.rigid_body_sleep.enabled);
  EXPECT_EQ(scene.spec.world.rigid_body_sleep.linear_speed, 0.001);
  EXPECT_EQ(scene.spec.world.rigid_body_sleep.angular_speed, 0.01);
  const auto bad = dir.write("bad.yaml", "ambf_like:\n  rigid body sleep: {linear speed: -1}\n");
  const auto message = test_support::loadErrorOf([&] { ambf_like::loadModelFiles({model}, bad); });
  EXPECT_THAT(message, HasSubstr("bad.yaml:2"));
  EXPECT_THAT(message, HasSubstr("linear speed"));
}

}  // namespace
