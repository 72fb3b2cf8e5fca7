// A step that drives an arm into the board: the robot's position loop alone would e-stop once
// its setpoint led the blocked joint by the error its amplifiers refuse (twice the following
// limit: ../shared/reference/raven2-actuation.md §3-4); a step keeps the lead within the limit,
// so the arm presses with a bounded force and the robot stays enabled.

#include <gtest/gtest.h>

#include <cmath>

#include "scenario/env_action.hpp"
#include "scenario/observation_layout.hpp"
#include "scenario/peg_transfer.hpp"
#include "scenario/peg_transfer_env.hpp"
#include "scenario/scripted_session.hpp"

namespace {

using raven::Arm;

constexpr double kDeep = 0.23;  // m: the insertion's lower limit, the tool far into the board

/// Both arms' measured joints with the left insertion at kDeep.
controller::ArmPair intoTheBoard(const twin::TwinPlatform& twin) {
  controller::ArmPair q{twin.measuredJs(Arm::Left).position, twin.measuredJs(Arm::Right).position};
  q[0](raven::kInsertion) = kDeep;
  return q;
}

double insertionLead(const twin::TwinPlatform& twin) {
  return twin.setpointJs(Arm::Left).position(raven::kInsertion) -
         twin.measuredJs(Arm::Left).position(raven::kInsertion);
}

TEST(FollowingLimit, TheLimitsAreHalfTheErrorsThePositionLoopEStopsAt) {
  const raven::ArmJoints limit = scenario::followingLimit();
  EXPECT_NEAR(limit(raven::kShoulder), 0.5 * 20000 / 3695.8 / 0.30 * 0.0073423, 1e-12);
  EXPECT_NEAR(limit(raven::kInsertion), 0.00836, 1e-5);
  EXPECT_TRUE(std::isinf(limit(raven::kJaw1)));
}

TEST(FollowingLimit, WithoutItAnArmDrivenIntoTheBoardEStops) {
  scenario::ScriptedSession session(
      scenario::pegTransferTwin(scenario::PegTransferOptions{}, scenario::SceneVariation{}));
  session.makeReady(30.0);
  session.controller().moveTo(intoTheBoard(session.twin()));
  EXPECT_EQ(session.twin().operatingStatus().state, bridge::OperatingState::Fault);
}

TEST(FollowingLimit, AStepIntoTheBoardIsHeldBackAndTheRobotStaysEnabled) {
  scenario::PegTransferEnv env;  // the motor-level twin
  env.reset(1);
  Eigen::VectorXd action(14);
  const controller::ArmPair target = intoTheBoard(env.twin());
  action << target[0], target[1];
  double worst = 0.0;
  for (int step = 0; step < 50; ++step) {  // pressing on for a while
    const scenario::PegTransferStep s = env.step(action);
    ASSERT_FALSE(s.faulted) << "step " << step;
    worst = std::max(worst, std::abs(insertionLead(env.twin())));
  }
  // Blocked well short of the target, the lead stays at the limit (plus one command's share).
  EXPECT_GT(env.twin().measuredJs(Arm::Left).position(raven::kInsertion), kDeep + 0.02);
  EXPECT_LT(worst, scenario::followingLimit()(raven::kInsertion) + 0.001);
  EXPECT_GT(worst, 0.5 * scenario::followingLimit()(raven::kInsertion));
}

TEST(FollowingLimit, AJointHeldBackHoldsOnlyItself) {
  scenario::PegTransferEnv env;  // the motor-level twin
  env.reset(1);
  controller::ArmPair target = intoTheBoard(env.twin());
  Eigen::VectorXd action(14);
  action << target[0], target[1];
  for (int step = 0; step < 50; ++step) ASSERT_FALSE(env.step(action).faulted) << "step " << step;
  // Still pressing the left tool into the board, and now turning the right shoulder and opening
  // the left jaws: those reach their targets, the insertion stays held.
  target[1](raven::kShoulder) += 0.05;
  target[0](raven::kJaw2) += 0.1;
  action << target[0], target[1];
  const scenario::PegTransferStep s = env.step(action);
  ASSERT_FALSE(s.faulted);
  const auto targets = [&](Arm arm) {
    return s.observation.segment<raven::kJointCount>(
        scenario::observation::item(scenario::observation::kTargets, raven::slot(arm)).start);
  };
  EXPECT_DOUBLE_EQ(targets(Arm::Right)(raven::kShoulder), target[1](raven::kShoulder));
  EXPECT_DOUBLE_EQ(targets(Arm::Left)(raven::kJaw2), target[0](raven::kJaw2));
  EXPECT_GT(targets(Arm::Left)(raven::kInsertion), kDeep + 0.02)
      << "the held insertion's target ran on";
  EXPECT_LT(std::abs(insertionLead(env.twin())),
            scenario::followingLimit()(raven::kInsertion) + 0.001);
}

}  // namespace
