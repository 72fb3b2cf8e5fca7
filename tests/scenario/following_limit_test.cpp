// A step that drives an arm into the board: the robot's position loop alone would e-stop once
// its setpoint led the blocked joint by the error its amplifiers refuse (twice the following
// limit: ../shared/reference/raven2-actuation.md §3-4); a step keeps the lead within the limit,
// so the arm presses with a bounded force and the robot stays enabled.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "scenario/env_action.hpp"
#include "scenario/observation_layout.hpp"
#include "scenario/peg_transfer.hpp"
#include "scenario/peg_transfer_env.hpp"
#include "scenario/scripted_session.hpp"
#include "twin/twin_arms.hpp"

namespace {

using raven::Arm;

constexpr double kDeep = 0.23;  // m: the insertion's lower limit, the tool far into the board

/// Both arms' measured joints with the left jaws commanded 0.1 rad past each other's faces (an
/// opening of -0.2 rad: a grasp closed hard on nothing).
controller::ArmPair jawsPastEachOther(const twin::TwinPlatform& twin) {
  controller::ArmPair q{twin.measuredJs(Arm::Left).position, twin.measuredJs(Arm::Right).position};
  q[0](raven::kJaw1) = q[0](raven::kJaw2) = -0.1;
  return q;
}

double jaw1Torque(const twin::TwinPlatform& twin) {
  return twin.ravenState()
      ->tau[static_cast<std::size_t>(bridge::ravenStateIndex(Arm::Left, raven::kJaw1))];
}

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

TEST(FollowingLimit, TheLimitsAreHalfOfWhatTheControlLawEStopsAt) {
  const controller::FollowingLimit limit = scenario::followingLimit();
  // raven2-actuation.md §2.1 and §4: TR = 63.095 / 5.675 x 12.25 (shoulder), 10.905 / 5.005 x
  // 26/7 x 100/90 (jaws); 2730 / (0.0603 x 12.25) and 5461 / (0.0538 x 26/7) counts per N m.
  const double shoulder_tr = 63.095 / 5.675 * 12.25,
               jaw_tr = 10.905 / 5.005 * 26.0 / 7.0 * 100 / 90;
  const double arm_counts = 2730 / (0.0603 * 12.25), tool_counts = 5461 / (0.0538 * 26.0 / 7.0);
  EXPECT_NEAR(limit.lead(raven::kShoulder), 0.5 * 20000 / arm_counts / 0.30 / shoulder_tr, 1e-12);
  EXPECT_NEAR(limit.lead(raven::kInsertion), 0.00836, 1e-5);
  EXPECT_TRUE(std::isinf(limit.lead(raven::kJaw1)));
  EXPECT_NEAR(limit.torque(raven::kJaw1), 0.5 * 20000 / tool_counts, 1e-12);
  EXPECT_NEAR(limit.give(raven::kJaw1), 1.0 / (0.05 * jaw_tr), 1e-12);
  EXPECT_TRUE(std::isinf(limit.torque(raven::kInsertion)));
  EXPECT_TRUE(std::isinf(limit.torque(raven::kJaw2))) << "GRASP2 is never checked";
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
  EXPECT_LT(worst, scenario::followingLimit().lead(raven::kInsertion) + 0.001);
  EXPECT_GT(worst, 0.5 * scenario::followingLimit().lead(raven::kInsertion));
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
            scenario::followingLimit().lead(raven::kInsertion) + 0.001);
}

TEST(FollowingLimit, WithoutItJawsClosedOnEachOtherWindUpToTheEStop) {
  scenario::ScriptedSession session(
      scenario::pegTransferTwin(scenario::PegTransferOptions{}, scenario::SceneVariation{}));
  session.makeReady(30.0);
  controller::DualPlatformController& controller = session.controller();
  controller.moveTo(jawsPastEachOther(session.twin()));
  // jaw 1's integrator winds up by KI x 0.9 motor rad a second, to the overdrive in about 15 s.
  for (int k = 0;
       k < 20000 && session.twin().operatingStatus().state != bridge::OperatingState::Fault; ++k) {
    controller.idle();
  }
  EXPECT_EQ(session.twin().operatingStatus().state, bridge::OperatingState::Fault);
}

TEST(FollowingLimit, JawsClosedOnEachOtherSqueezeAtTheTorqueLimitAndTheRobotStaysEnabled) {
  scenario::PegTransferEnvOptions options;  // the motor-level twin
  options.control = scenario::EnvControl::Period;
  options.period = 0.5;
  scenario::PegTransferEnv env(options);
  env.reset(1);
  const controller::ArmPair target = jawsPastEachOther(env.twin());
  Eigen::VectorXd action(14);
  action << target[0], target[1];
  double worst = 0.0;
  for (int step = 0; step < 80; ++step) {  // 40 s: past where the unguarded jaws e-stop
    ASSERT_FALSE(env.step(action).faulted) << "step " << step;
    worst = std::max(worst, std::abs(jaw1Torque(env.twin())));
  }
  const double limit = scenario::followingLimit().torque(raven::kJaw1);
  std::printf("jaw 1's torque at most %.3f N m (limit %.3f)\n", worst, limit);
  EXPECT_LT(worst, limit + 0.01);
  EXPECT_GT(worst, limit - 0.01) << "it squeezes at the limit";
  // Still squeezing: the jaws stay shut on each other (on the stop where their faces meet, or
  // past it by the faces' give), jaw 1's motor closing them at the limit (its integrator holds
  // the torque; the setpoint has come back to the jaw).
  const ambf_like::CoupledStop* faces = env.twin().arms().jawStop(Arm::Left);
  ASSERT_NE(faces, nullptr);
  EXPECT_LT(faces->gap(), 1e-3);
  EXPECT_LT(jaw1Torque(env.twin()), -(limit - 0.01));
}

}  // namespace
