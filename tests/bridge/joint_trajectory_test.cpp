// The move planner: starts and ends at rest on the goal, every joint on one straight line.

#include "bridge/joint_trajectory.hpp"

#include <gtest/gtest.h>

namespace {

using raven::ArmJoints;

TEST(JointTrajectory, TrapezoidReachesFullSpeedOnLongMoves) {
  const ArmJoints start = ArmJoints::Zero();
  ArmJoints goal = ArmJoints::Zero();
  goal(0) = 10.0;
  const bridge::JointTrajectory t(start, goal, ArmJoints::Constant(2.0), ArmJoints::Constant(1.0));
  // 2 s up to 2 rad/s (2 rad), 3 s cruising (6 rad), 2 s down (2 rad).
  EXPECT_NEAR(t.duration(), 7.0, 1e-12);
  EXPECT_NEAR(t.at(2.0)(0), 2.0, 1e-12);
  EXPECT_NEAR(t.at(5.0)(0), 8.0, 1e-12);
  EXPECT_EQ(t.at(7.0), goal);
  EXPECT_EQ(t.at(-1.0), start);
  EXPECT_NEAR((t.at(3.0 + 1e-6)(0) - t.at(3.0)(0)) / 1e-6, 2.0, 1e-6);
}

TEST(JointTrajectory, TheSlowestJointSetsThePaceAndAllArriveTogether) {
  const ArmJoints start = ArmJoints::Zero();
  const ArmJoints goal = (ArmJoints() << 1.0, -0.5, 0.01, 0, 0, 0, 0).finished();
  ArmJoints vmax = ArmJoints::Constant(1.0);
  ArmJoints amax = ArmJoints::Constant(1.0);
  vmax(2) = 0.001;  // the insertion is slow: 10 s at least
  amax(2) = 0.02;
  const bridge::JointTrajectory t(start, goal, vmax, amax);
  EXPECT_GT(t.duration(), 10.0);
  for (double time = 0.0; time < t.duration(); time += 0.1) {
    const ArmJoints q = t.at(time);
    EXPECT_NEAR(q(0) / goal(0), q(2) / goal(2), 1e-12);
    EXPECT_NEAR(q(1) / goal(1), q(2) / goal(2), 1e-12);
  }
}

TEST(JointTrajectory, ANullMoveTakesNoTime) {
  const ArmJoints q = ArmJoints::Constant(0.3);
  const bridge::JointTrajectory t(q, q, ArmJoints::Ones(), ArmJoints::Ones());
  EXPECT_EQ(t.duration(), 0.0);
  EXPECT_EQ(t.at(0.5), q);
}

}  // namespace
