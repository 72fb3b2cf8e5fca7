// The in-process twin behind RavenPlatform: it follows servo streams, reports raven_state in the
// robot's units and layout, holds when the controller goes silent, and repeats itself exactly.
// The motor-level actuation adds the robot's lag, friction band and quantised encoders.

#include "twin/twin_platform.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "bridge/enable_and_home.hpp"
#include "test_files.hpp"
#include "twin/calibration_profile.hpp"
#include "twin/gravity_compensation.hpp"
#include "twin/motor_controller.hpp"
#include "twin_fixtures.hpp"

namespace {

using bridge::Arm;
using bridge::ArmJoints;
using bridge::StateCommand;
using test_support::makeReady;
using twin::TwinPlatform;

/// How far from its setpoint (motor rad) a PD motor can rest: where its torque KP e, plus the
/// gravity the compensation misses and the constant offset, stays within Coulomb friction, its
/// load-dependent part and what a stretched cable holds (raven2-actuation.md §3 for the law;
/// the mechanics from the shipped calibration).
double restBand(const twin::MotorMechanics& m, const twin::MotorGains& gains, double gravity, int i,
                double coupled = 0.0) {
  const double held = m.coulomb(i) + m.cable_friction(i) + std::abs(m.offset(i)) +
                      std::abs(m.gravity_error(i) * gravity) +
                      m.load_friction(i) * std::abs(gravity) + coupled;
  return held / (gains.kp(i) * (1.0 - m.load_friction(i)));
}

/// Per motor, what the other motors' torques `tau` put on its joint through the cables, in its
/// own torque: the tool cables pull on the insertion, the elbow's and insertion's on the
/// shoulder (joint loads are coupling^T tau / gearbox; motor i drives joint i).
ArmJoints coupledLoads(const twin::DriveTrain& drive, Arm arm, const ArmJoints& tau) {
  const auto c = drive.coupling(arm);
  const ArmJoints at_motor = tau.cwiseQuotient(drive.gearbox);
  ArmJoints loads;
  for (int i = 0; i < raven::kJointCount; ++i) {
    const double others = c.col(i).dot(at_motor) - c(i, i) * at_motor(i);
    loads(i) = std::abs(others) * drive.gearbox(i) / c(i, i);
  }
  return loads;
}

twin::TwinOptions withMotors() {
  twin::TwinOptions options;
  options.motors = twin::CalibrationProfile::shipped().mechanics;
  return options;
}

/// A smooth 500 Hz servo_jr stream on both arms: `count` increments, one every 2 ms.
ArmJoints streamIncrement(int k) {
  const double s = std::sin(0.01 * k);
  return (ArmJoints() << 1.5e-4 * s, -1.0e-4 * s, 2.0e-5 * s, 4e-4 * s, 3e-4 * s, 2e-4 * s,
          -1e-4 * s)
      .finished();
}
void stream(bridge::RavenPlatform& platform, int count) {
  for (int k = 0; k < count; ++k) {
    for (Arm arm : raven::kArms) {
      ASSERT_TRUE(platform.send(bridge::ServoJr{arm, streamIncrement(k)}));
    }
    platform.advance(0.002);
  }
}

TEST(TwinPlatform, FollowsAServoJrStreamOnTheSimulatedClock) {
  TwinPlatform twin;
  EXPECT_EQ(twin.clockKind(), bridge::ClockKind::Simulated);
  makeReady(twin);
  const double t0 = twin.now();
  const ArmJoints start = twin.setpointJs(Arm::Left).position;
  stream(twin, 500);
  EXPECT_NEAR(twin.now() - t0, 1.0, 1e-9);
  ArmJoints expected = start;
  for (int k = 0; k < 500; ++k) expected += streamIncrement(k);
  EXPECT_LT((twin.setpointJs(Arm::Left).position - expected).cwiseAbs().maxCoeff(), 1e-12);
  // In motion the servos trail the setpoint by about a cycle (the roll moves at 0.2 rad/s);
  // at rest they sit on it (the joint-space servo halves the error every step, under load too).
  for (Arm arm : raven::kArms) {
    const ArmJoints error =
        (twin.measuredJs(arm).position - twin.setpointJs(arm).position).cwiseAbs();
    EXPECT_LT(error.maxCoeff(), 3e-4) << error.transpose();
  }
  twin.advance(0.05);
  for (Arm arm : raven::kArms) {
    const ArmJoints error =
        (twin.measuredJs(arm).position - twin.setpointJs(arm).position).cwiseAbs();
    EXPECT_LT(error.maxCoeff(), 1e-9) << error.transpose();
  }
}

TEST(TwinPlatform, NoJointOfTheMotorTwinPassesItsHardStopPoweredOrNot) {
  // Every joint of each arm pushed toward its upper, then its lower limit by legal servo_jr
  // increments at 1 kHz, 0.3 rad/s and 3 cm/s (the robot clamps each setpoint to its limits),
  // then an e-stop with the arms resting on their stops: the amplifiers go off and gravity takes
  // the arms.
  TwinPlatform twin(withMotors());
  makeReady(twin);
  const auto& limits = test_support::physicalProfile().limits;
  const auto drive = twin::DriveTrain::raven2();
  ArmJoints furthest_past = ArmJoints::Constant(-1.0);
  auto watch = [&] {
    for (Arm arm : raven::kArms) {
      const ArmJoints q = twin.measuredJs(arm).position;
      furthest_past = furthest_past.cwiseMax(q - limits.high).cwiseMax(limits.low - q);
    }
  };
  // One arm at a time: pushed to their upper limits together, the two arms' elbow links meet
  // (and that contact winds the motors up to the e-stop, as on the robot).
  for (Arm pushed : raven::kArms) {
    for (const double sign : {1.0, -1.0}) {
      ArmJoints increment = ArmJoints::Constant(sign * 3e-4);
      increment(raven::kInsertion) = sign * 3e-5;
      for (int k = 0; k < 6000; ++k) {
        ASSERT_TRUE(twin.send(bridge::ServoJr{pushed, increment}));
        twin.advance(0.001);
        watch();
      }
    }
  }
  ASSERT_EQ(twin.operatingStatus().state, bridge::OperatingState::Enabled);
  twin::ArmStart overdriven;
  overdriven.motor_position = drive.toMotor(Arm::Left, twin.measuredJs(Arm::Left).position);
  overdriven.integrators(raven::kRoll) = 100.0;
  twin.place(Arm::Left, overdriven);
  for (int k = 0; k < 3000; ++k) {
    twin.advance(0.001);
    watch();
  }
  EXPECT_EQ(twin.operatingStatus().state, bridge::OperatingState::Fault);
  // A reading lands at most two counts of its own motor past a stop, and a count of each motor
  // its angle also reads through the cables (a jaw's combines its motor's count, 0.18 mrad,
  // with half the wrist's; the elbow's, 0.15 of the shoulder's).
  const double count = 1.0 / drive.countsPerMotorRadian();
  for (int j = 0; j < raven::kJointCount; ++j) {
    double reach = 2.0 * count / drive.transmission(j);
    for (int i = 0; i < raven::kJointCount; ++i) {
      if (i != j) reach += std::abs(drive.toJoints(Arm::Left, count * ArmJoints::Unit(i))(j));
    }
    EXPECT_LE(furthest_past(j), reach + 1e-12) << raven::kJointNames[static_cast<std::size_t>(j)];
  }
  // Enabled again with the integrator that tripped it emptied (the firmware never empties it:
  // the real robot would trip again at once), the amplifiers take commands.
  EXPECT_TRUE(twin.send(bridge::StateCommand::Enable));
  overdriven.motor_position = drive.toMotor(Arm::Left, twin.measuredJs(Arm::Left).position);
  overdriven.integrators.setZero();
  twin.place(Arm::Left, overdriven);
  twin.advance(0.01);
  EXPECT_EQ(twin.operatingStatus().state, bridge::OperatingState::Enabled);
  EXPECT_NE(twin.ravenState()->dac_val[0], 0) << "the amplifiers take commands again";
}

TEST(TwinPlatform, RavenStateIsInDegreesAndMicronsInTheRobotsLayout) {
  TwinPlatform twin;
  makeReady(twin);
  twin.advance(0.1);
  const auto state = twin.ravenState();
  ASSERT_TRUE(state);
  EXPECT_EQ(state->runlevel, bridge::kPedalDown);
  EXPECT_EQ(state->sublevel, 1);
  EXPECT_EQ(state->type, (std::array<std::int32_t, 2>{24, 10}));
  EXPECT_DOUBLE_EQ(state->dt, 0.001);
  EXPECT_NEAR(state->time, twin.now(), 1e-12);
  // Homed: shoulder 30 deg, elbow 90 deg, insertion 0.4 m = 22.918 "deg", roll 0, jaws 45 deg.
  for (int base : {0, 8}) {
    EXPECT_NEAR(state->jpos[base + 0], 30.0, 0.01);
    EXPECT_NEAR(state->jpos[base + 1], 90.0, 0.01);
    EXPECT_NEAR(state->jpos[base + 2], 22.918, 0.001);
    EXPECT_EQ(state->jpos[base + 3], 0.0f) << "index 3 is not connected";
    EXPECT_NEAR(state->jpos[base + 4], 0.0, 0.01);
    EXPECT_NEAR(state->jpos[base + 6], 45.0, 0.01);
    EXPECT_NEAR(state->jpos[base + 7], 45.0, 0.01);
    EXPECT_NEAR(state->jpos_d[base + 2], 22.918, 0.001);
    EXPECT_NEAR(state->grasp_d[static_cast<std::size_t>(base / 8)], 90.0, 0.01);
  }
  const auto drive = twin::DriveTrain::raven2();
  for (Arm arm : raven::kArms) {
    const auto measured = twin.measuredJs(arm).position;
    for (int i = 0; i < raven::kJointCount; ++i) {
      const auto k = static_cast<std::size_t>(bridge::ravenStateIndex(arm, i));
      EXPECT_NEAR(state->jpos[k], measured(i) * 180.0 / M_PI, 1e-3);
      EXPECT_NEAR(state->mpos[k], drive.toMotor(arm, measured)(i) * 180.0 / M_PI, 0.05);
    }
    // pos: the tool point in microns, in the firmware's frame, as measured_cp reports it.
    const auto pose = twin.measuredCp(arm).pose;
    const auto a = raven::slot(arm);
    for (std::size_t r = 0; r < 3; ++r) {
      EXPECT_NEAR(state->pos[a * 3 + r], pose.translation()(static_cast<int>(r)) * 1e6, 1.0);
      EXPECT_NEAR(state->ori[a * 9 + r * 3 + 1], pose.linear()(static_cast<int>(r), 1), 1e-6);
    }
  }
}

TEST(TwinPlatform, RunlevelFollowsTheOperatingState) {
  TwinPlatform twin;
  EXPECT_EQ(twin.ravenState()->runlevel, bridge::kEStop);
  ASSERT_TRUE(twin.send(StateCommand::Enable));
  EXPECT_EQ(twin.ravenState()->runlevel, bridge::kInit);
  EXPECT_EQ(twin.ravenState()->sublevel, 0);
  makeReady(twin);
  ASSERT_TRUE(twin.send(StateCommand::Pause));
  EXPECT_EQ(twin.ravenState()->runlevel, bridge::kPedalUp);
}

TEST(TwinPlatform, SameCommandsGiveTheSameTrajectoryEveryTime) {
  auto run = [] {
    TwinPlatform twin(withMotors());
    makeReady(twin);
    stream(twin, 200);
    return std::make_pair(twin.measuredJs(Arm::Left).position,
                          twin.measuredJs(Arm::Right).velocity);
  };
  const auto first = run();
  const auto second = run();
  EXPECT_EQ(first.first, second.first);
  EXPECT_EQ(first.second, second.second);
}

TEST(TwinPlatform, TheMotorsLagSettleWithinTheirFrictionBandAndReadWholeCounts) {
  TwinPlatform twin(withMotors());
  makeReady(twin);
  const auto drive = twin::DriveTrain::raven2();
  const auto mechanics = twin::CalibrationProfile::shipped().mechanics[0];
  const auto gains = twin::MotorGains::raven2(Arm::Left);
  ArmJoints goal = twin.setpointJs(Arm::Left).position;
  goal(raven::kShoulder) += 0.02;
  ASSERT_TRUE(twin.send(bridge::ServoJp{Arm::Left, goal}));
  twin.advance(0.01);
  EXPECT_GT(goal(0) - twin.measuredJs(Arm::Left).position(0), 0.002)
      << "the motors should lag behind a step";
  twin.advance(1.0);
  // The PD has no integrator on the shoulder: friction holds the motor anywhere within its rest
  // band, one encoder count more for the reading.
  const ArmJoints settled = twin.measuredJs(Arm::Left).position;
  const double gravity = twin::gravityCompensation(Arm::Left, settled, drive)(0);
  const double band =
      (restBand(mechanics, gains, gravity, 0) + 1.0 / drive.countsPerMotorRadian()) /
      drive.transmission(0);
  EXPECT_LE(std::abs(settled(0) - goal(0)), band);
  EXPECT_GT(settled(0) - (goal(0) - 0.02), 0.5 * 0.02) << "the shoulder did not move";
  // Every motor reading is a whole number of encoder counts.
  const ArmJoints motor = drive.toMotor(Arm::Left, settled);
  for (int i = 0; i < raven::kJointCount; ++i) {
    const double counts = motor(i) * drive.countsPerMotorRadian();
    EXPECT_NEAR(counts, std::round(counts), 1e-6)
        << raven::kJointNames[static_cast<std::size_t>(i)];
  }
  // raven_state carries what the control software computed: Tau and its DAC command agree.
  const auto state = twin.ravenState();
  ASSERT_TRUE(state);
  const auto dac = twin::DacConversion::raven2(Arm::Left);
  EXPECT_NEAR(state->dac_val[0], state->tau[0] * dac.counts_per_torque(0), 1.0);
  EXPECT_NE(state->tau[0], 0.0f);
}

TEST(TwinPlatform, TheArmsHoldWhenTheControllerGoesSilent) {
  TwinPlatform twin(withMotors());
  makeReady(twin);
  stream(twin, 250);
  twin.advance(0.5);  // the last increments are consumed
  const auto held_setpoint = twin.setpointJs(Arm::Left).position;
  // A PD motor rests anywhere within its rest band; the tool motors' integrators creep them in
  // (kp / ki = 1 s) from wherever they stopped. Nothing runs away.
  const auto drive = twin::DriveTrain::raven2();
  const auto mechanics = twin::CalibrationProfile::shipped().mechanics[0];
  const auto gains = twin::MotorGains::raven2(Arm::Left);
  auto motorError = [&] {
    const auto state = twin.ravenState();
    ArmJoints e;
    for (int i = 0; i < raven::kJointCount; ++i) {
      const auto k = static_cast<std::size_t>(bridge::ravenStateIndex(Arm::Left, i));
      e(i) = std::abs(state->mpos_d[k] - state->mpos[k]) * M_PI / 180.0;
    }
    return e;
  };
  const ArmJoints error_then = motorError();
  for (int k = 0; k < 100; ++k) {
    twin.advance(0.01);
    const ArmJoints gravity =
        twin::gravityCompensation(Arm::Left, twin.measuredJs(Arm::Left).position, drive);
    const ArmJoints error = motorError();
    const auto state = twin.ravenState();
    ArmJoints tau;
    for (int i = 0; i < raven::kJointCount; ++i) {
      tau(i) = state->tau[static_cast<std::size_t>(bridge::ravenStateIndex(Arm::Left, i))];
    }
    const ArmJoints coupled = coupledLoads(drive, Arm::Left, tau);
    for (int i = 0; i < raven::kJointCount; ++i) {
      const double rest = restBand(mechanics, gains, gravity(i), i, coupled(i));
      const double band = (gains.ki(i) > 0.0 ? std::max(rest, error_then(i)) : rest) +
                          2.0 / drive.countsPerMotorRadian();
      ASSERT_LE(error(i), band) << raven::kJointNames[static_cast<std::size_t>(i)] << " at "
                                << twin.now();
    }
  }
  EXPECT_LE(motorError().maxCoeff(), error_then.maxCoeff() + 1e-9)
      << "moving away from the setpoint";
  EXPECT_EQ(twin.setpointJs(Arm::Left).position, held_setpoint);
  EXPECT_EQ(twin.operatingStatus().state, bridge::OperatingState::Enabled);
}

TEST(TwinPlatform, AmbfsOwnRavenIsDrivenThroughTheSamePlatformWithTheAmbfProfile) {
  const auto shared = test_support::sharedDataDir();
  if (shared.empty()) GTEST_SKIP() << "../shared/data is absent: AMBF's Raven-II model is needed";
  twin::TwinOptions options;
  options.launch_file = shared / "ambf/ambf_controller/raven2/launch.yaml";
  options.bindings = twin::ArmBindings::ambfRaven();
  options.profile = "ambf";
  TwinPlatform twin(options);
  makeReady(twin);
  const auto ambf = raven::builtinProfile("ambf");
  for (Arm arm : raven::kArms) {
    EXPECT_LT((twin.setpointJs(arm).position - ambf.home).cwiseAbs().maxCoeff(), 1e-12);
  }
  ArmJoints step = ArmJoints::Zero();
  step(raven::kInsertion) = 0.0001;  // the cycle clamp's pace: 0.05 m/s
  for (int k = 0; k < 50; ++k) {
    ASSERT_TRUE(twin.send(bridge::ServoJr{Arm::Right, step}));
    twin.advance(0.002);
  }
  EXPECT_NEAR(twin.setpointJs(Arm::Right).position(raven::kInsertion),
              ambf.home(raven::kInsertion) + 0.005, 1e-12);
  twin.advance(1.5);  // AMBF's own joint controllers settle in about half a second
  EXPECT_NEAR(twin.measuredJs(Arm::Right).position(raven::kInsertion),
              ambf.home(raven::kInsertion) + 0.005, 1e-4);
}

TEST(TwinPlatform, AdvanceRefusesNegativeOrNonFiniteTime) {
  TwinPlatform twin;
  EXPECT_THROW(twin.advance(-0.001), std::invalid_argument);
  EXPECT_THROW(twin.advance(std::nan("")), std::invalid_argument);
  EXPECT_EQ(twin.now(), 0.0);
}

TEST(TwinPlatform, InvalidMechanicsAreRefusedNamingArmAndField) {
  twin::TwinOptions options = withMotors();
  options.motors->at(1).inertia(raven::kWrist) = 0.0;
  try {
    TwinPlatform twin(options);
    ADD_FAILURE() << "built with a zero inertia";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("right arm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("inertia of wrist"), std::string::npos) << e.what();
  }
}

TEST(EnableAndHome, BringsTheTwinToReadyOrSaysWhereItStopped) {
  twin::TwinPlatform slow;
  try {
    bridge::enableAndHome(slow, 0.05);  // homing takes seconds
    ADD_FAILURE() << "ready after 0.05 s";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("within 0.05"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(state "), std::string::npos) << e.what();
  }
  EXPECT_LT(slow.now(), 0.07);

  twin::TwinPlatform twin;
  bridge::enableAndHome(twin, 60.0);
  EXPECT_TRUE(twin.operatingStatus().ready());
  const double homed_at = twin.now();
  bridge::enableAndHome(twin, 60.0);  // already ready: no time passes
  EXPECT_EQ(twin.now(), homed_at);

  twin::TwinPlatform interrupted;
  EXPECT_THROW(bridge::enableAndHome(interrupted, 60.0, [] { return false; }), std::runtime_error);
  EXPECT_EQ(interrupted.now(), 0.0);
}

}  // namespace
