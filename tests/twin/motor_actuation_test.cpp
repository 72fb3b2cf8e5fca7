// The motor-level actuation's parts against the firmware's equations and textbook mechanics:
// the cable coupling and its inverse, the DAC conversion and clip, the motors under torque and
// friction, and an arm placed where a recording began.

#include <gtest/gtest.h>

#include <cmath>

#include "arm_contacts.hpp"
#include "twin/arm_drive.hpp"
#include "twin/drive_train.hpp"
#include "twin/gravity_compensation.hpp"
#include "twin/motor_controller.hpp"
#include "twin/motor_dynamics.hpp"

namespace {

using raven::Arm;
using raven::ArmJoints;

ArmJoints home() {
  return (ArmJoints() << M_PI / 6, M_PI / 2, 0.4, 0.1, -0.2, M_PI / 4, M_PI / 3).finished();
}

TEST(DriveTrain, TheCouplingAndItsInverseAgreeOnBothArms) {
  const auto drive = twin::DriveTrain::raven2();
  for (Arm arm : raven::kArms) {
    const ArmJoints m = drive.toMotor(arm, home());
    EXPECT_LT((drive.toJoints(arm, m) - home()).cwiseAbs().maxCoeff(), 1e-12);
    // Inserting drags the tool cables: the tool motors turn with the insertion motor alone.
    ArmJoints deeper = home();
    deeper(raven::kInsertion) += 0.01;
    const ArmJoints dm = drive.toMotor(arm, deeper) - m;
    const double drag = dm(raven::kInsertion) * drive.tool_drag;
    const double sign = twin::DriveTrain::toolSign(arm);
    EXPECT_NEAR(dm(raven::kRoll), sign * drag, 1e-9);
    EXPECT_NEAR(dm(raven::kJaw1), -sign * drag, 1e-9) << "jaw 1's cable runs the other way";
  }
  // The firmware's ratios (raven2-actuation.md §2.1).
  EXPECT_NEAR(drive.transmission(raven::kShoulder), 136.196, 1e-3);
  EXPECT_NEAR(drive.transmission(raven::kElbow), 121.522, 1e-3);
  EXPECT_NEAR(drive.transmission(raven::kInsertion), 2158.59, 1e-2);
  EXPECT_NEAR(1.0 / drive.tool_drag, 2.9087, 1e-4);
}

TEST(MotorController, TheDacIsTauOverTheAmplifiersAndTheClipHoldsExceptOnGrasp2) {
  const auto drive = twin::DriveTrain::raven2();
  const auto dac = twin::DacConversion::raven2(Arm::Left);
  EXPECT_NEAR(dac.counts_per_torque(raven::kShoulder), -3695.8, 0.1) << "gold: negative";
  EXPECT_NEAR(twin::DacConversion::raven2(Arm::Right).counts_per_torque(raven::kShoulder), 3695.8,
              0.1);
  EXPECT_NEAR(dac.counts_per_torque(raven::kRoll), 27328.0, 1.0);
  EXPECT_LT(dac.counts_per_torque(raven::kJaw1), 0.0) << "grasp 1 opposes";
  twin::MotorController law(Arm::Left, drive);
  const ArmJoints m = drive.toMotor(Arm::Left, home());
  // Small errors: Tau is KP e (+ gravity), the DAC its truncated count.
  ArmJoints set = m;
  set(raven::kShoulder) += 0.1;
  auto out = law.cycle(set, m, ArmJoints::Zero(), home());
  const ArmJoints gravity = twin::gravityCompensation(Arm::Left, home(), drive);
  EXPECT_NEAR(out.torque(raven::kShoulder), 0.3 * 0.1 + gravity(raven::kShoulder), 1e-12);
  EXPECT_EQ(out.gravity, gravity) << "the compensation's part, as the motors are stepped with";
  EXPECT_EQ(out.dac[0], static_cast<int>(std::trunc(out.torque(0) * dac.counts_per_torque(0))));
  EXPECT_FALSE(out.overdrive);
  // 2 motor rad of error on the shoulder: 0.6 N m, 2217 counts, under the 2500 clip; 3 rad: over.
  set(raven::kShoulder) = m(raven::kShoulder) + 3.0;
  out = law.cycle(set, m, ArmJoints::Zero(), home());
  EXPECT_EQ(out.dac[0], -2500) << "clipped to DAC_max (gold: negative counts)";
  EXPECT_NEAR(out.applied(0), -2500 / dac.counts_per_torque(0), 1e-12);
  // Jaw 2 is never clipped; past 20000 counts anywhere else the amplifiers are zeroed.
  twin::MotorController jaws(Arm::Left, drive);
  set = m;
  set(raven::kJaw2) += 0.1;  // 0.005 N m: 137 counts
  EXPECT_EQ(jaws.cycle(set, m, ArmJoints::Zero(), home()).dac[raven::kJaw2], 136);
  set = m;
  set(raven::kRoll) += 10.0;  // 0.9 N m: 24595 counts
  out = twin::MotorController(Arm::Left, drive).cycle(set, m, ArmJoints::Zero(), home());
  ASSERT_TRUE(out.overdrive);
  EXPECT_EQ(out.overdrive->motor, raven::kRoll) << "the e-stop names the motor that tripped it";
  EXPECT_NEAR(out.overdrive->counts,
              std::trunc(out.torque(raven::kRoll) * dac.counts_per_torque(raven::kRoll)), 0.5);
  for (int c : out.dac) EXPECT_EQ(c, 0);
}

twin::MotorMechanics frictionless(double inertia) {
  twin::MotorMechanics m;
  m.inertia.setConstant(inertia);
  return m;
}

TEST(MotorAxes, AConstantTorqueAcceleratesTheInertia) {
  twin::MotorAxes axes(frictionless(2e-4));
  ArmJoints torque = ArmJoints::Zero();
  torque(0) = 0.01;
  for (int k = 0; k < 100; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_NEAR(axes.velocity()(0), 0.01 * 0.1 / 2e-4, 1e-9);                // a t
  EXPECT_NEAR(axes.position()(0), 0.5 * 0.01 * 0.01 / 2e-4, 0.01 * 0.25);  // a t^2 / 2, O(h)
  EXPECT_EQ(axes.velocity()(1), 0.0);
}

TEST(MotorAxes, FrictionHoldsBelowItsLevelAndDragsAboveIt) {
  twin::MotorMechanics m = frictionless(2e-4);
  m.coulomb.setConstant(0.05);
  m.viscous.setConstant(0.002);
  m.load_friction.setConstant(0.5);
  twin::MotorAxes axes(m);
  ArmJoints torque = ArmJoints::Zero();
  torque(0) = 0.09;  // below 0.05 + 0.5 * 0.09 = 0.095: stuck
  torque(1) = 0.3;   // above 0.05 + 0.15 = 0.2: terminal speed (0.3 - 0.2) / 0.002 = 50 rad/s
  for (int k = 0; k < 3000; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_EQ(axes.velocity()(0), 0.0);
  EXPECT_EQ(axes.position()(0), 0.0);
  EXPECT_NEAR(axes.velocity()(1), 50.0, 1e-6);
}

TEST(MotorAxes, AnOffsetMakesFrictionAsymmetric) {
  // Coulomb 0.05 with offset -0.03: moving up takes 0.02, moving down 0.08.
  twin::MotorMechanics m = frictionless(2e-4);
  m.coulomb.setConstant(0.05);
  m.offset.setConstant(-0.03);
  twin::MotorAxes axes(m);
  const ArmJoints torque =
      (ArmJoints() << 0.019, 0.021, -0.079, -0.081, 0.0, -0.02, 0.0).finished();
  for (int k = 0; k < 100; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_EQ(axes.velocity()(0), 0.0) << "up, below 0.02";
  EXPECT_NEAR(axes.velocity()(1), 0.001 * 0.1 / 2e-4, 1e-9) << "up, 0.001 above it";
  EXPECT_EQ(axes.velocity()(2), 0.0) << "down, below 0.08";
  EXPECT_NEAR(axes.velocity()(3), -0.001 * 0.1 / 2e-4, 1e-9) << "down, 0.001 above it";
  EXPECT_EQ(axes.velocity()(4), 0.0) << "at rest with no torque: the offset is within friction";
}

TEST(MotorAxes, TheGravityTheCompensationMissesPullsTheMotor) {
  twin::MotorMechanics m = frictionless(2e-4);
  m.gravity_error(0) = 0.5;  // the arm weighs 1.5 times the firmware's estimate
  twin::MotorAxes axes(m);
  ArmJoints load = ArmJoints::Zero();
  load(0) = 0.02;
  // The firmware adds its estimate (0.02): the motor feels -0.01 net.
  for (int k = 0; k < 10; ++k) axes.step(load, load, 0.001);
  EXPECT_NEAR(axes.velocity()(0), -0.01 * 0.01 / 2e-4, 1e-9);
}

/// A motor with Coulomb friction 0.04 of its own and 0.08 beyond a cable that carries it all
/// once stretched by 0.5 motor rad (stiffness 0.16 N m per rad), and some viscous friction.
twin::MotorMechanics cabled() {
  twin::MotorMechanics m = frictionless(2e-4);
  m.coulomb.setConstant(0.04);
  m.viscous.setConstant(0.002);
  m.cable_friction.head<3>().setConstant(0.08);
  m.cable_travel.head<3>().setConstant(0.5);
  return m;
}

TEST(MotorAxes, ACableStretchesUntilItCarriesThePushAndThenTheLinkSlides) {
  twin::MotorAxes axes(cabled());
  // Joint 0 pushed with 0.08: beyond its own 0.04, not beyond 0.04 + 0.08. It turns until the
  // cable's 0.16 N m per rad takes up what its own friction does not: it swings about 0.25 rad
  // (where the pull is 0.08 - 0.04) by up to 0.25, damped, and rests where the pull is within
  // 0.08 -/+ 0.04, from 0.25 rad on, short of the full 0.5.
  // Joint 1 pushed with 0.2: past both, it slides at (0.2 - 0.04 - 0.08) / 0.002 = 40 rad/s.
  const ArmJoints torque = (ArmJoints() << 0.08, 0.2, 0.0, 0.0, 0.0, 0.0, 0.0).finished();
  for (int k = 0; k < 4000; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_EQ(axes.velocity()(0), 0.0);
  EXPECT_GE(axes.position()(0), 0.25);
  EXPECT_LT(axes.position()(0), 0.5);
  EXPECT_NEAR(axes.velocity()(1), 40.0, 1e-6);
}

TEST(MotorAxes, AfterAReversalTheMotorTurnsUnderLessThanItSlidesUnder) {
  // Slid up and held with 0.1, the cable carries the link's friction (0.08) and pulls the motor
  // back by it. Eased to 0.02 the motor turns back (0.08 - 0.02 is past its own 0.04) and rests
  // where the cable's pull is within 0.02 -/+ 0.04: at least 0.125 rad of 0.16 N m per rad
  // back, less the viscous damping's share of the swing past it. From a slack cable 0.02 does
  // not move it. Going on down takes 0.04 + 0.08 = 0.12 once the cable is stretched down.
  twin::MotorAxes axes(cabled());
  ArmJoints torque = ArmJoints::Zero();
  torque(0) = 0.2;
  for (int k = 0; k < 500; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  torque(0) = 0.1;
  for (int k = 0; k < 1000; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  ASSERT_EQ(axes.velocity()(0), 0.0) << "held within 0.08 -/+ 0.04";
  const double held = axes.position()(0);
  torque(0) = 0.02;
  for (int k = 0; k < 2000; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_EQ(axes.velocity()(0), 0.0);
  EXPECT_LT(axes.position()(0), held - 0.1);
  EXPECT_GT(axes.position()(0), held - 0.25);
  twin::MotorAxes slack(cabled());
  for (int k = 0; k < 100; ++k) slack.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_EQ(slack.position()(0), 0.0) << "0.02 is within a slack cable's motor's own 0.04";
  torque(0) = -0.119;  // down, short of 0.12: it stops once the cable is stretched down
  for (int k = 0; k < 4000; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_EQ(axes.velocity()(0), 0.0);
  torque(0) = -0.14;  // past it: slides at (0.14 - 0.12) / 0.002 = 10 rad/s
  for (int k = 0; k < 4000; ++k) axes.step(torque, ArmJoints::Zero(), 0.001);
  EXPECT_NEAR(axes.velocity()(0), -10.0, 1e-6);
}

TEST(MotorAxes, ARigidCablesFrictionActsAsTheMotorsOwn) {
  // No travel: the friction beyond the cable stops the motor at once, as its own would.
  twin::MotorMechanics rigid = cabled();
  rigid.cable_travel.setZero();
  twin::MotorMechanics own = cabled();
  own.cable_friction.setZero();
  own.coulomb.head<3>().setConstant(0.04 + 0.08);
  twin::MotorAxes a(rigid), b(own);
  const ArmJoints torque = (ArmJoints() << 0.119, 0.121, -0.2, 0.0, 0.0, 0.0, 0.0).finished();
  for (int k = 0; k < 1000; ++k) {
    a.step(torque, ArmJoints::Zero(), 0.001);
    b.step(torque, ArmJoints::Zero(), 0.001);
  }
  EXPECT_EQ(a.velocity()(0), 0.0);
  EXPECT_EQ(a.position(), b.position());
  EXPECT_EQ(a.velocity(), b.velocity());
}

TEST(ArmDrive, PlacedAtARecordedStateItsFirstCycleGivesThatStatesTorque) {
  const auto drive = twin::DriveTrain::raven2();
  twin::MotorMechanics m = frictionless(2e-4);
  twin::ArmDrive arm(Arm::Right, drive, m, 0.001, home());
  twin::ArmStart start;
  start.motor_position = drive.toMotor(Arm::Right, home());
  const ArmJoints setpoint = home() + ArmJoints::Constant(0.001);
  const ArmJoints wanted =
      (ArmJoints() << -0.02, 0.05, 0.01, 0.004, -0.003, 0.002, 0.001).finished();
  const ArmJoints motor_setpoint =
      drive.toMotor(Arm::Right, setpoint, drive.quantise(start.motor_position)(raven::kInsertion));
  start.integrators = arm.controller().integratorsGiving(
      wanted, motor_setpoint - drive.quantise(start.motor_position), ArmJoints::Zero(),
      drive.toJoints(Arm::Right, drive.quantise(start.motor_position)));
  arm.place(start);
  const auto& r = arm.cycle(setpoint);
  // The integrator gains one cycle of error: KI e h, at most 0.05 * 0.1 * 0.001.
  for (int i = raven::kRoll; i < raven::kJointCount; ++i) {
    EXPECT_NEAR(r.torque(i), wanted(i), 1e-5) << raven::kJointNames[static_cast<std::size_t>(i)];
  }
  EXPECT_TRUE(r.motor_velocity.isZero());
}

}  // namespace

namespace {

using test_support::countInJoint;

TEST(ArmDrive, AJointDrivenPastItsHardStopRestsOnItAndSoDoItsMotors) {
  const auto drive = twin::DriveTrain::raven2();
  raven::JointLimits stops{ArmJoints::Constant(-10.0), ArmJoints::Constant(10.0)};
  stops.low(raven::kShoulder) = 0.0;
  stops.high(raven::kShoulder) = M_PI / 2;
  ArmJoints start = home();
  start(raven::kShoulder) = M_PI / 2 - 0.01;
  twin::ArmDrive arm(Arm::Left, drive, frictionless(2e-4), 0.001, start, {stops, {}});
  ArmJoints setpoint = start;
  // 0.05 rad past the stop, from 0.01 rad before it: the PD asks up to 2.4 N m, the amplifiers
  // give their clip (0.68 N m), short of the overdrive that would e-stop the robot (5.4 N m).
  setpoint(raven::kShoulder) = M_PI / 2 + 0.05;
  double highest = 0.0;
  for (int k = 0; k < 1500; ++k) highest = std::max(highest, arm.cycle(setpoint).position(0));
  EXPECT_LE(highest, M_PI / 2 + countInJoint(drive, raven::kShoulder));
  EXPECT_NEAR(arm.readings().position(raven::kShoulder), M_PI / 2,
              countInJoint(drive, raven::kShoulder));
  EXPECT_EQ(arm.readings().motor_velocity(raven::kShoulder), 0.0) << "resting on the stop";
  EXPECT_TRUE(arm.fault().empty());
  EXPECT_GT(arm.readings().torque(raven::kShoulder), 1.0) << "its motor keeps pushing";
}

TEST(ArmDrive, JawsClosedPastEachOtherRestWhereTheirFacesMeetAndWindTheirMotorsUp) {
  // The motors alone (the calibration's model) with the jaws' stop at opening 0: commanded
  // 0.1 rad each past it, the jaws rest with their faces together, twisted or not, and both
  // motors keep pushing them closed (their integrators wind up on the error that stays).
  const auto drive = twin::DriveTrain::raven2();
  ArmJoints start = home();
  start(raven::kJaw1) = start(raven::kJaw2) = 0.05;
  twin::ArmDrive arm(Arm::Left, drive, frictionless(2e-4), 0.001, start, {{}, 0.0});
  ArmJoints setpoint = start;
  setpoint(raven::kJaw1) = setpoint(raven::kJaw2) = -0.1;
  double tightest = 1.0;
  for (int k = 0; k < 1000; ++k) {
    const ArmJoints q = arm.cycle(setpoint).position;
    tightest = std::min(tightest, q(raven::kJaw1) + q(raven::kJaw2));
  }
  // Readings are of quantised motor angles: two counts of each jaw.
  const double counts = 2.0 * countInJoint(drive, raven::kJaw1);
  EXPECT_GT(tightest, -2.0 * counts);
  const ArmJoints tau_then = arm.readings().torque;
  for (int k = 0; k < 500; ++k) arm.cycle(setpoint);
  const ArmJoints& q = arm.readings().position;
  EXPECT_NEAR(q(raven::kJaw1) + q(raven::kJaw2), 0.0, 2.0 * counts) << "resting on each other";
  const ArmJoints growth = arm.readings().torque - tau_then;
  const twin::MotorGains gains = twin::MotorGains::raven2(Arm::Left);
  for (int jaw : {raven::kJaw1, raven::kJaw2}) {
    // Over 0.5 s each motor's Tau grows by KI times its (steady) error: the error is the
    // jaw's 0.1 rad or more past the faces, through its cables.
    const double error = arm.readings().motor_setpoint(jaw) - arm.readings().motor_position(jaw);
    EXPECT_NEAR(growth(jaw), gains.ki(jaw) * error * 0.5, 0.05 * std::abs(gains.ki(jaw) * error))
        << raven::kJointNames[static_cast<std::size_t>(jaw)];
  }
}

TEST(ArmDrive, JawsWithFittedFacesRestWhereTheseMeet) {
  // The calibration's faces move the pair's stop: 0.010 + 0.005 rad past the model's zero.
  const auto drive = twin::DriveTrain::raven2();
  ArmJoints start = home();
  start(raven::kJaw1) = start(raven::kJaw2) = 0.05;
  twin::MotorMechanics mechanics = frictionless(2e-4);
  mechanics.face(raven::kJaw1) = 0.010;
  mechanics.face(raven::kJaw2) = 0.005;
  twin::ArmDrive arm(Arm::Left, drive, mechanics, 0.001, start, {{}, 0.0});
  ArmJoints setpoint = start;
  setpoint(raven::kJaw1) = setpoint(raven::kJaw2) = -0.1;
  for (int k = 0; k < 1500; ++k) arm.cycle(setpoint);
  const ArmJoints& q = arm.readings().position;
  EXPECT_NEAR(q(raven::kJaw1) + q(raven::kJaw2), 0.015, 4.0 * countInJoint(drive, raven::kJaw1));
}

TEST(ArmDrive, JawsOnFacesThatGiveArePressedPastThemByTheLoadTimesTheCompliance) {
  // Faces that give 0.1 rad each per N m (the pair 0.2): jaws closed 0.02 rad each past where
  // they meet come to rest there once the integrators have wound, each jaw's joint pressed
  // open with 0.04 / 0.2 = 0.2 N m, which the motors' Tau carries through the cables (joint
  // loads are C^T Tau / gearbox). No Coulomb friction; viscous friction, which a PI loop on an
  // inertia needs to be stable at all (Routh: viscous x KP > inertia x KI), and no more.
  const auto drive = twin::DriveTrain::raven2();
  ArmJoints start = home();
  start(raven::kJaw1) = start(raven::kJaw2) = 0.05;
  twin::MotorMechanics mechanics = frictionless(1e-5);
  mechanics.viscous.setConstant(1e-4);
  mechanics.face_compliance(raven::kJaw1) = mechanics.face_compliance(raven::kJaw2) = 0.1;
  twin::ArmDrive arm(Arm::Left, drive, mechanics, 0.001, start, {{}, 0.0});
  ArmJoints setpoint = start;
  setpoint(raven::kJaw1) = setpoint(raven::kJaw2) = -0.02;
  for (int k = 0; k < 60000; ++k) arm.cycle(setpoint);
  const auto& r = arm.readings();
  const double sum = r.position(raven::kJaw1) + r.position(raven::kJaw2);
  EXPECT_NEAR(sum, -0.04, 4.0 * countInJoint(drive, raven::kJaw1));
  const ArmJoints load =
      drive.coupling(Arm::Left).transpose() * r.torque.cwiseQuotient(drive.gearbox);
  for (int jaw : {raven::kJaw1, raven::kJaw2}) {
    EXPECT_NEAR(-load(jaw), -sum / 0.2, 0.05 * 0.2) << "jaw " << jaw;
  }
}

TEST(ArmDrive, AfterTheSoftEStopTheAmplifiersStayOffUntilTheFaultIsCleared) {
  const auto drive = twin::DriveTrain::raven2();
  twin::ArmDrive arm(Arm::Right, drive, frictionless(2e-4), 0.001, home());
  twin::ArmStart start;
  start.motor_position = drive.toMotor(Arm::Right, home());
  start.integrators(raven::kRoll) = 100.0;  // KI 0.05: Tau 5 N m, 137k counts, past 20000
  arm.place(start);
  arm.cycle(home());
  ASSERT_FALSE(arm.fault().empty());
  for (int k = 0; k < 5; ++k) {
    const auto& r = arm.cycle(home());
    EXPECT_GT(std::abs(r.torque(raven::kRoll)), 1.0) << "the law still computes its torque";
    for (int c : r.dac) EXPECT_EQ(c, 0) << "but the amplifiers get nothing";
  }
  arm.clearFault();
  start.integrators(raven::kRoll) = 0.02;  // Tau 0.001 N m: 27 counts
  arm.place(start);
  EXPECT_NE(arm.cycle(home()).dac[raven::kRoll], 0) << "enabled again: powered";
  EXPECT_TRUE(arm.fault().empty());
}

}  // namespace
