// A learning step on the motor-level twin ends with the arm where its targets are: the Raven-II's
// shoulder, elbow and insertion have no integrator, so a move alone leaves them short of its last
// command (still on their way, then held off by friction and the weight the firmware misjudges),
// and the step waits and makes the shortfall up within its bound, as the scripted operator does
// before it closes the jaws. On ideal servos, which arrive with their command, it adds nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "raven/arm_kinematics.hpp"
#include "scenario/env_action.hpp"
#include "scenario/peg_transfer.hpp"
#include "scenario/scripted_session.hpp"

namespace {

using raven::Arm;

/// A session on `actuation`, its steps waiting for the arm or not.
std::unique_ptr<scenario::ScriptedSession> session(common::ActuationKind actuation, bool arrival) {
  scenario::PegTransferOptions run;
  run.actuation = actuation;
  controller::ControllerOptions control;
  control.following_limit = scenario::followingLimit();
  if (arrival) control.arrival = scenario::arrival();
  auto out = std::make_unique<scenario::ScriptedSession>(
      scenario::pegTransferTwin(run, scenario::SceneVariation{}), control);
  out->makeReady(30.0);
  return out;
}

/// The homed pose with the left tool moved in free space, above the board.
controller::ArmPair moved(scenario::ScriptedSession& s) {
  controller::ArmPair q = s.controller().commanded();
  q[0](raven::kShoulder) += 0.04;
  q[0](raven::kElbow) -= 0.04;
  q[0](raven::kInsertion) -= 0.004;
  return q;
}

const raven::ArmKinematics& leftArm() {
  static const raven::ArmKinematics left =
      raven::ArmKinematics::of(raven::builtinProfile("physical"), Arm::Left);
  return left;
}

/// How far the left wrist's axis (where the shoulder, elbow and insertion put the tool) is from
/// where its targets put it (m).
double wristShortfall(scenario::ScriptedSession& s) {
  return (leftArm().wristPoint(s.controller().commanded()[0]) -
          leftArm().wristPoint(s.twin().measuredJs(Arm::Left).position))
      .norm();
}

/// How far the left setpoints' shoulder, elbow and insertion put the wrist past the targets (m).
double madeUp(scenario::ScriptedSession& s) {
  const raven::ArmJoints targets = s.controller().commanded()[0];
  raven::ArmJoints setpoint = s.twin().setpointJs(Arm::Left).position;
  setpoint.tail<4>() = targets.tail<4>();
  return (leftArm().wristPoint(setpoint) - leftArm().wristPoint(targets)).norm();
}

TEST(Arrival, AMoveAloneEndsShortOfItsTargetsAndAStepEndsAtThem) {
  auto alone = session(common::ActuationKind::Motors, false);
  const int periods_alone = alone->controller().moveTo(moved(*alone)).steps;
  const double short_alone = wristShortfall(*alone);
  auto step = session(common::ActuationKind::Motors, true);
  const controller::IterationReport report = step->controller().moveTo(moved(*step));
  const double short_step = wristShortfall(*step);
  std::printf(
      "the wrist %.3f mm from its targets after a move (%d periods), %.3f mm after a step "
      "(%d)\n",
      short_alone * 1e3, periods_alone, short_step * 1e3, report.steps);
  EXPECT_GT(short_alone, 0.0002) << "the motors arrive with their command";
  // Each joint within its tolerance: 0.3 mrad, 0.3 mrad, 0.1 mm at 0.33 m, about 0.2 mm.
  EXPECT_LT(short_step, 0.0002);
  EXPECT_LE(madeUp(*step), scenario::arrival().most_make_up + 1e-9);
  EXPECT_LE(report.steps, periods_alone + std::lround(scenario::arrival().most_wait /
                                                      step->controller().period()));
}

TEST(Arrival, AnArmPressedOnTheBoardIsPushedOnNoFurtherThanTheMakeUpsBound) {
  auto step = session(common::ActuationKind::Motors, true);
  controller::ArmPair target = step->controller().commanded();
  // Down onto the board (the insertion's lower limit lies far into it; the following limit holds
  // the insertion's setpoint 8.4 mm below the tool), then 3 mm below where the board stops it.
  target[0](raven::kInsertion) = 0.23;
  for (int k = 0; k < 20; ++k) step->controller().moveTo(target);
  target[0](raven::kInsertion) =
      step->twin().measuredJs(Arm::Left).position(raven::kInsertion) - 0.003;
  for (int k = 0; k < 5; ++k) step->controller().moveTo(target);
  EXPECT_NE(step->twin().operatingStatus().state, bridge::OperatingState::Fault);
  EXPECT_GT(madeUp(*step), 0.5 * scenario::arrival().most_make_up) << "it made the shortfall up";
  EXPECT_LE(madeUp(*step), scenario::arrival().most_make_up + 1e-9);
}

TEST(Arrival, OnIdealServosAStepIsTheMoveAlone) {
  auto alone = session(common::ActuationKind::Ideal, false);
  auto step = session(common::ActuationKind::Ideal, true);
  const int periods_alone = alone->controller().moveTo(moved(*alone)).steps;
  EXPECT_EQ(step->controller().moveTo(moved(*step)).steps, periods_alone);
  EXPECT_EQ(step->twin().measuredJs(Arm::Left).position,
            alone->twin().measuredJs(Arm::Left).position);
}

}  // namespace
