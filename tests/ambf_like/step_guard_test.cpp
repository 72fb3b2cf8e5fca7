// The guard every step passes: a world that blows up (not finite, out of its bounds, faster than
// its scene allows) stops at that step with an error naming the body, the node, the step and the
// simulated time, and the limits come from the scene's size and step (StepGuard).

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "test_files.hpp"

namespace {

using testing::AllOf;
using testing::HasSubstr;

/// ADF text of a 10 cm box `name` of `mass` (0: static) at z = `height` (m).
std::string box(const std::string& name, double mass, double height) {
  return "BODY " + name + ":\n  name: " + name + "\n  mass: " + std::to_string(mass) +
         "\n  collision shape: BOX\n  collision geometry: {x: 0.1, y: 0.1, z: 0.1}\n"
         "  damping: {linear: 0, angular: 0}\n"
         "  location: {position: {x: 0, y: 0, z: " +
         std::to_string(height) + "}}\n";
}

/// A box at z = `height` (m), alone: nothing holds it up.
std::string lonelyBox(double height) {
  return "bodies: [BODY box]\n" + box("box", 0.1, height);
}

/// A soft ball (Bullet's links, no material) 1 m up, alone.
std::unique_ptr<test_support::Simulation> softBall(test_support::TempDir& dir) {
  return test_support::simulate(
      {dir.write("ball.yaml", "soft bodies: [BODY blob]\n" + test_support::softBallBody(0.01) +
                                  "  location: {position: {x: 0, y: 0, z: 1}}\n")});
}

TEST(StepGuard, ItsLimitsComeFromTheScenesSizeAndStep) {
  test_support::TempDir dir;
  // Two bodies 3 m apart: the scene is 3 m across, its bounds 30 m beyond each side.
  auto sim = test_support::simulate({dir.write(
      "scene.yaml", "bodies: [BODY base, BODY box]\n" + box("base", 0, 0) + box("box", 0.1, 3))});
  const auto& guard = sim->world->guard();
  // A tenth of 3 m per 1 ms step: 300 m/s, more than a fall across the scene and its margins
  // (sqrt(2 g 63 m) = 35 m/s).
  EXPECT_NEAR(guard.speedLimit(), 300.0, 1e-9);
  EXPECT_NEAR(guard.bounds().max().z(), 33.0, 1e-9);
  EXPECT_NEAR(guard.bounds().max().x(), 30.0, 1e-9);
  EXPECT_NEAR(guard.bounds().min().x(), -30.0, 1e-9);
  // Downwards, as far as a fall goes before it reaches 300 m/s: v^2 / 2 g.
  EXPECT_NEAR(guard.bounds().min().z(), -30.0 - 300.0 * 300.0 / (2 * 9.81), 1e-6);
  ambf_like::WorldOptions slow;
  slow.step_size = 0.05;  // 6 m/s a step would allow: the fall across the scene sets the limit
  auto coarse =
      test_support::simulate({dir.write("again.yaml", "bodies: [BODY base, BODY box]\n" +
                                                          box("base", 0, 0) + box("box", 0.1, 3))},
                             {}, slow);
  EXPECT_NEAR(coarse->world->guard().speedLimit(), std::sqrt(2 * 9.81 * 63), 1e-9);
}

TEST(StepGuard, ABodyFallingOffTheSceneIsStoppedWhenItIsFasterThanTheSceneAllows) {
  test_support::TempDir dir;
  auto sim = test_support::simulate({dir.write("box.yaml", lonelyBox(0.0))});
  // A lone body: a 1 m scene, 100 m/s at 1 ms, reached falling after 100 / g = 10.2 s (AMBF
  // lets a body fall as long as it likes: the bounds below reach that far).
  try {
    sim->world->step(12000);
    FAIL() << "the box fell for 12 s and nothing stopped it";
  } catch (const ambf_like::SimulationDiverged& e) {
    EXPECT_EQ(e.body(), sim->world->body("box").qualifiedName());
    EXPECT_EQ(e.node(), -1);
    EXPECT_NEAR(e.time(), 100 / 9.81, 0.002);
    EXPECT_EQ(e.step(), sim->world->stepCount());
    EXPECT_THAT(e.what(), AllOf(HasSubstr("rigid body '" + e.body() + "' moves at 100"),
                                HasSubstr("faster than the scene allows (100 m/s)")));
  }
}

TEST(StepGuard, ABodyFlungSidewaysIsStoppedWhenItLeavesTheBounds) {
  test_support::TempDir dir;
  auto sim = test_support::simulate({dir.write("box.yaml", lonelyBox(0.0))});
  // 60 m/s sideways, under the 100 m/s limit: it leaves the bounds 10 m away after 1/6 s.
  sim->world->body("box").bullet().setLinearVelocity(btVector3(60, 0, 0));
  try {
    sim->world->step(1000);
    FAIL() << "the box flew 60 m and nothing stopped it";
  } catch (const ambf_like::SimulationDiverged& e) {
    EXPECT_NEAR(e.time(), 10.0 / 60.0, 0.002);
    EXPECT_THAT(e.what(), AllOf(HasSubstr("rigid body '" + e.body() + "'"),
                                HasSubstr("left the world's bounds: at (10.0")));
  }
}

TEST(StepGuard, ANodeThrownFasterThanTheSceneAllowsIsNamedWithItsStepAndTime) {
  test_support::TempDir dir;
  auto sim = softBall(dir);
  sim->world->step(10);
  auto& blob = sim->world->softBody("blob");
  for (int i = 0; i < blob.bullet().m_nodes.size(); ++i) {  // thrown faster than a 1 m scene allows
    blob.bullet().m_nodes[i].m_v = btVector3(0, 0, 2e3);
  }
  try {
    sim->world->step();
    FAIL() << "a node at 2 km/s went unnoticed";
  } catch (const ambf_like::SimulationDiverged& e) {
    EXPECT_EQ(e.body(), blob.qualifiedName());
    std::cout << e.what() << "\n";
    EXPECT_EQ(e.node(), 0);
    EXPECT_EQ(e.step(), 11u);
    EXPECT_NEAR(e.time(), 0.011, 1e-12);
    EXPECT_THAT(e.what(),
                AllOf(HasSubstr("at step 11 (t = 0.0110 s)"),
                      HasSubstr("soft body '" + blob.qualifiedName() + "' node 0 moves at"),
                      HasSubstr("faster than the scene allows (100 m/s)")));
  }
}

TEST(StepGuard, ANodeThatIsNotFiniteIsNamed) {
  test_support::TempDir dir;
  auto sim = softBall(dir);
  sim->world->softBody("blob").bullet().m_nodes[3].m_x.setX(NAN);
  EXPECT_THROW(
      {
        try {
          sim->world->step();
        } catch (const ambf_like::SimulationDiverged& e) {
          EXPECT_THAT(e.what(), AllOf(HasSubstr("node"), HasSubstr("is not finite")));
          throw;
        }
      },
      ambf_like::SimulationDiverged);
}

}  // namespace
