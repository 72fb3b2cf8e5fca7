// The environment's actions become joint targets as documented, and a period-controlled move
// lasts exactly its steps: cut short on the way, or arrived and held.

#include "scenario/env_action.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "raven/platform_profile.hpp"
#include "scenario/scripted_session.hpp"

namespace {

using scenario::EnvAction;

struct Arms {
  raven::PlatformProfile profile = raven::builtinProfile("physical");
  std::array<raven::ArmKinematics, 2> kinematics{
      raven::ArmKinematics::of(profile, raven::Arm::Left),
      raven::ArmKinematics::of(profile, raven::Arm::Right)};
  controller::ArmPair home{profile.home, profile.home};
};

TEST(EnvAction, ToolDeltasMoveTheToolTipWithTheWristLocked) {
  const Arms a;
  Eigen::VectorXd action(8);
  action << 0.003, -0.002, 0.001, 0.8, 0.0, 0.0, 0.0, 1.2;
  const auto targets =
      scenario::targetsOf(EnvAction::ToolDeltas, action, a.home, a.kinematics, a.profile.home);
  const Eigen::Vector3d moved = a.kinematics[0].toolPose(targets[0]).translation() -
                                a.kinematics[0].toolPose(a.home[0]).translation();
  EXPECT_NEAR((moved - Eigen::Vector3d(0.003, -0.002, 0.001)).norm(), 0.0, 2e-5) << moved;
  EXPECT_EQ(targets[0](raven::kRoll), a.home[0](raven::kRoll));  // the wrist locked
  EXPECT_EQ(targets[0](raven::kWrist), a.home[0](raven::kWrist));
  EXPECT_NEAR(targets[0](raven::kJaw1) + targets[0](raven::kJaw2), 0.8, 1e-12);
  EXPECT_NEAR(targets[0](raven::kJaw1) - targets[0](raven::kJaw2),
              a.home[0](raven::kJaw1) - a.home[0](raven::kJaw2), 1e-12);
  EXPECT_LT((targets[1].head<5>() - a.home[1].head<5>()).norm(), 1e-9);  // none asked
  // A displacement beyond kMaxToolDelta is clipped to it.
  action << 0.05, 0, 0, 0.8, 0, 0, 0, 1.2;
  const auto clipped =
      scenario::targetsOf(EnvAction::ToolDeltas, action, a.home, a.kinematics, a.profile.home);
  EXPECT_NEAR((a.kinematics[0].toolPose(clipped[0]).translation() -
               a.kinematics[0].toolPose(a.home[0]).translation())
                  .norm(),
              scenario::kMaxToolDelta, 2e-5);
}

TEST(EnvAction, JointActionsRoundTripAndBadOnesAreNamed) {
  const Arms a;
  controller::ArmPair goal = a.home;
  goal[0](raven::kShoulder) += 0.05;
  goal[1](raven::kInsertion) -= 0.01;
  for (EnvAction kind : {EnvAction::Joints, EnvAction::JointDeltas}) {
    const Eigen::VectorXd action = scenario::actionFor(kind, goal, a.home, a.kinematics);
    const auto back = scenario::targetsOf(kind, action, a.home, a.kinematics, a.profile.home);
    EXPECT_LT((back[0] - goal[0]).norm() + (back[1] - goal[1]).norm(), 1e-12);
  }
  Eigen::VectorXd bad = Eigen::VectorXd::Zero(14);
  bad(9) = NAN;
  EXPECT_THROW(
      {
        try {
          scenario::targetsOf(EnvAction::JointDeltas, bad, a.home, a.kinematics, a.profile.home);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("action[9]"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
  EXPECT_THROW(scenario::targetsOf(EnvAction::ToolDeltas, Eigen::VectorXd::Zero(14), a.home,
                                   a.kinematics, a.profile.home),
               std::invalid_argument);
  EXPECT_THROW(scenario::envActionNamed("cartesian"), std::invalid_argument);
}

TEST(EnvAction, APeriodMoveLastsExactlyItsSteps) {
  scenario::ScriptedSession session(twin::TwinOptions{});
  session.makeReady(60.0);
  auto& control = session.controller();
  const controller::ArmPair start = control.commanded();
  controller::ArmPair far = start;
  far[0](raven::kShoulder) += 0.2;  // 0.2 rad at 5 deg/s: 2.3 s, far more than 25 steps
  double t0 = session.twin().now();
  auto report = control.moveFor(far, 25);
  EXPECT_EQ(report.steps, 25);
  EXPECT_NEAR(session.twin().now() - t0, 25 * control.period(), 1e-9);
  const double reached = control.commanded()[0](raven::kShoulder) - start[0](raven::kShoulder);
  EXPECT_GT(reached, 0.0);
  EXPECT_LT(reached, 0.2 * 25.0 / 100.0);  // cut short on the way
  controller::ArmPair near = control.commanded();
  near[0](raven::kShoulder) += 0.001;
  t0 = session.twin().now();
  report = control.moveFor(near, 25);  // arrives in ten steps, then holds
  EXPECT_NEAR(session.twin().now() - t0, 25 * control.period(), 1e-9);
  EXPECT_EQ(control.commanded()[0], near[0]);
}

}  // namespace
