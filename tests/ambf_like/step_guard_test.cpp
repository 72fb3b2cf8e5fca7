// The guard every step passes: a world that blows up (not finite, out of its bounds, faster than
// its scene allows) stops at that step with an error naming the body, the node, the step and the
// simulated time, and the limits come from the scene's size and step (StepGuard).

#include <BulletSoftBody/btSoftBody.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

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

TEST(StepGuard, ItsLimitsComeFromTheScenesSizeAndStep) {
  test_support::TempDir dir;
  // Two bodies 3 m apart: the scene is 3 m across, its bounds 30 m beyond each side.
  auto sim = test_support::simulate({dir.write(
      "scene.yaml", "bodies: [BODY base, BODY box]\n" + box("base", 0, 0) + box("box", 0.1, 3))});
  const auto& guard = sim->world->guard();
  EXPECT_NEAR(guard.bounds().min().z(), -30.0, 1e-9);
  EXPECT_NEAR(guard.bounds().max().z(), 33.0, 1e-9);
  EXPECT_NEAR(guard.bounds().max().x(), 30.0, 1e-9);
  // A tenth of 3 m per 1 ms step: 300 m/s, more than a fall across the bounds (48 m/s).
  EXPECT_NEAR(guard.speedLimit(), 300.0, 1e-9);
  ambf_like::WorldOptions slow;
  slow.step_size = 0.05;  // 6 m/s a step would allow: a fall across the bounds sets the limit
  auto coarse = test_support::simulate({dir.write("again.yaml", lonelyBox(3.0))}, slow);
  const double diagonal = coarse->world->guard().bounds().diagonal().norm();
  EXPECT_NEAR(coarse->world->guard().speedLimit(), std::sqrt(2 * 9.81 * diagonal), 1e-9);
}

TEST(StepGuard, ABodyFallingOutOfTheBoundsStopsTheRunWhenItLeaves) {
  test_support::TempDir dir;
  auto sim = test_support::simulate({dir.write("box.yaml", lonelyBox(0.0))});
  // A lone body: a 1 m scene, bounds 10 m below it, reached after sqrt(2 * 10 / g) = 1.43 s.
  try {
    sim->world->step(3000);
    FAIL() << "the box fell for 3 s and nothing stopped it";
  } catch (const ambf_like::SimulationDiverged& e) {
    EXPECT_EQ(e.body(), sim->world->body("box").qualifiedName());
    EXPECT_EQ(e.node(), -1);
    EXPECT_NEAR(e.time(), std::sqrt(2 * 10 / 9.81), 0.01);
    EXPECT_EQ(e.step(), sim->world->stepCount());
    EXPECT_THAT(e.what(), AllOf(HasSubstr("rigid body '" + e.body() + "'"),
                                HasSubstr("left the world's bounds"), HasSubstr("at step 14")));
  }
}

TEST(StepGuard, ANodeThrownFasterThanTheSceneAllowsIsNamedWithItsStepAndTime) {
  test_support::TempDir dir;
  auto sim = test_support::simulate(
      {dir.write("ball.yaml", "soft bodies: [BODY blob]\n" + test_support::softBallBody(0.01) +
                                  "  location: {position: {x: 0, y: 0, z: 1}}\n")});
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
  auto sim = test_support::simulate(
      {dir.write("ball.yaml", "soft bodies: [BODY blob]\n" + test_support::softBallBody(0.01) +
                                  "  location: {position: {x: 0, y: 0, z: 1}}\n")});
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
