// An episode whose robot e-stops ends there: FAULT refuses every command until the robot is
// enabled again, so running on to the time limit would only record refusals.

#include <gtest/gtest.h>

#include "scenario/peg_transfer_env.hpp"
#include "twin/drive_train.hpp"

namespace {

TEST(EnvFault, AnEpisodeIsTruncatedWhenTheRobotFaults) {
  scenario::PegTransferEnv env;  // the default: the motor-level twin
  env.reset(1);
  const scenario::PegTransferStep first = env.step(env.expertAction());
  ASSERT_FALSE(first.faulted);
  ASSERT_FALSE(first.truncated);
  // The left roll's PID integrator wound far up (as a joint held against a stop would wind it):
  // its amplifier command passes the overdrive threshold and the robot e-stops.
  twin::ArmStart overdriven;
  overdriven.motor_position = twin::DriveTrain::raven2().toMotor(
      raven::Arm::Left, env.twin().measuredJs(raven::Arm::Left).position);
  overdriven.integrators(raven::kRoll) = 100.0;
  env.twin().place(raven::Arm::Left, overdriven);
  scenario::PegTransferStep step;
  int steps = 0;
  while (!step.truncated && ++steps < 500) step = env.step(env.expertAction());
  EXPECT_TRUE(step.faulted);
  EXPECT_TRUE(step.truncated);
  EXPECT_FALSE(step.terminated);
  EXPECT_LT(env.time(), 30.0);  // long before the time limit
}

}  // namespace
