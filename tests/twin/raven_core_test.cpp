// The robot's command layer: servo_jr accumulation and per-cycle clamps, refusals that move
// nothing, limits on every path, move_jp and homing, Cartesian servoing, the jaws.

#include "twin/raven_core.hpp"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <sstream>

#include "twin_fixtures.hpp"

namespace {

using bridge::Arm;
using bridge::ArmJoints;
using bridge::OperatingState;
using bridge::StateCommand;
using twin::RavenCore;

/// A core whose arms follow their setpoints exactly (a perfect robot).
struct Robot {
  RavenCore core{test_support::physicalProfile(),
                 bridge::ServoLimits{},
                 {test_support::physicalProfile().home, test_support::physicalProfile().home}};

  void cycle(int count = 1) {
    for (int i = 0; i < count; ++i) {
      core.cycle({core.setpoint(Arm::Left), core.setpoint(Arm::Right)});
    }
  }
  /// Cycles until the core is no longer busy (at most 20 s).
  void settle() {
    for (int i = 0; i < 20000 && core.status().is_busy; ++i) cycle();
  }
  /// Enabled and homed.
  void makeReady() {
    if (core.status().state == OperatingState::Disabled) {
      ASSERT_TRUE(core.apply(StateCommand::Enable));
    }
    ASSERT_TRUE(core.apply(StateCommand::Home));
    settle();
    ASSERT_TRUE(core.status().ready());
  }
  const ArmJoints& left() const { return core.setpoint(Arm::Left); }
};

/// What spdlog's default logger writes while it lives.
class LogCapture {
 public:
  LogCapture() : previous_(spdlog::default_logger()) {
    spdlog::set_default_logger(std::make_shared<spdlog::logger>(
        "capture", std::make_shared<spdlog::sinks::ostream_sink_st>(text_)));
  }
  ~LogCapture() { spdlog::set_default_logger(previous_); }
  std::string text() const { return text_.str(); }

 private:
  std::ostringstream text_;
  std::shared_ptr<spdlog::logger> previous_;
};

ArmJoints jointStep(int joint, double value) {
  ArmJoints q = ArmJoints::Zero();
  q(joint) = value;
  return q;
}

TEST(RavenCore, HomingMovesBothArmsToTheFirmwareHomeAndIsBusyMeanwhile) {
  Robot robot;
  ASSERT_TRUE(robot.core.apply(StateCommand::Enable));
  ASSERT_TRUE(robot.core.apply(StateCommand::Home));
  EXPECT_TRUE(robot.core.status().is_busy);
  robot.cycle(100);
  EXPECT_TRUE(robot.core.status().is_busy);
  EXPECT_FALSE(robot.core.status().is_homed);
  robot.settle();
  EXPECT_TRUE(robot.core.status().is_homed);
  for (Arm arm : raven::kArms) {
    EXPECT_LT((robot.core.setpoint(arm) - test_support::physicalProfile().robotHome())
                  .cwiseAbs()
                  .maxCoeff(),
              1e-12);
  }
}

TEST(RavenCore, ServoJrAccumulatesAndIsConsumedWithinThePerCycleClamp) {
  Robot robot;
  robot.makeReady();
  const ArmJoints start = robot.left();
  // Three increments of 0.004 rad on the shoulder arrive in one cycle: 0.012 rad pending.
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(robot.core.apply(bridge::ServoJr{Arm::Left, jointStep(raven::kShoulder, 0.004)}));
  }
  const ArmJoints insertion = jointStep(raven::kInsertion, 0.0003);
  ASSERT_TRUE(robot.core.apply(bridge::ServoJr{Arm::Left, insertion}));
  std::vector<double> shoulder_steps, insertion_steps;
  for (int c = 0; c < 8; ++c) {
    const ArmJoints before = robot.left();
    robot.cycle();
    shoulder_steps.push_back(robot.left()(raven::kShoulder) - before(raven::kShoulder));
    insertion_steps.push_back(robot.left()(raven::kInsertion) - before(raven::kInsertion));
  }
  // 0.012 rad at 0.0025 per cycle: 4 full cycles and 0.002; 0.0003 m at 0.00005: 6 cycles.
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(shoulder_steps[c], 0.0025, 1e-12);
  EXPECT_NEAR(shoulder_steps[4], 0.002, 1e-12);
  EXPECT_NEAR(shoulder_steps[5], 0.0, 1e-15);
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(insertion_steps[c], 0.00005, 1e-12);
  EXPECT_NEAR(insertion_steps[6], 0.0, 1e-15);
  EXPECT_NEAR(robot.left()(raven::kShoulder) - start(raven::kShoulder), 0.012, 1e-12);
  EXPECT_NEAR(robot.left()(raven::kInsertion) - start(raven::kInsertion), 0.0003, 1e-12);
  EXPECT_NEAR(robot.core.setpointVelocity(Arm::Left)(raven::kShoulder), 0.0, 1e-12);
}

TEST(RavenCore, MotionCommandsAreRefusedWhileDisabledPausedOrUnhomedAndMoveNothing) {
  Robot robot;
  const ArmJoints start = robot.left();
  const bridge::PlatformCommand commands[] = {
      bridge::ServoJr{Arm::Left, jointStep(raven::kShoulder, 0.001)},
      bridge::ServoJp{Arm::Left, start + jointStep(raven::kShoulder, 0.001)},
      bridge::MoveJp{Arm::Left, start + jointStep(raven::kShoulder, 0.1)},
      bridge::ServoJawJr{Arm::Left, 0.01},
  };
  auto expectRefused = [&](const std::string& word) {
    for (const auto& command : commands) {
      const auto result = robot.core.apply(command);
      EXPECT_FALSE(result) << describe(command);
      EXPECT_NE(result.note.find(word), std::string::npos) << result.note;
    }
    robot.cycle(50);
    EXPECT_EQ(robot.left(), start);
  };
  expectRefused("DISABLED");
  ASSERT_TRUE(robot.core.apply(StateCommand::Enable));
  expectRefused("not homed");
  robot.makeReady();
  const ArmJoints homed = robot.left();
  ASSERT_TRUE(robot.core.apply(StateCommand::Pause));
  for (const auto& command : commands) {
    const auto result = robot.core.apply(command);
    EXPECT_FALSE(result);
    EXPECT_NE(result.note.find("PAUSED"), std::string::npos) << result.note;
  }
  robot.cycle(50);
  EXPECT_EQ(robot.left(), homed);
}

TEST(RavenCore, NonFiniteValuesAreRefusedNamingTheJoint) {
  Robot robot;
  robot.makeReady();
  const ArmJoints start = robot.left();
  ArmJoints bad = ArmJoints::Zero();
  bad(raven::kWrist) = std::numeric_limits<double>::quiet_NaN();
  auto result = robot.core.apply(bridge::ServoJr{Arm::Left, bad});
  EXPECT_FALSE(result);
  EXPECT_NE(result.note.find("'wrist' is NaN or infinite"), std::string::npos) << result.note;
  bad(raven::kWrist) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(robot.core.apply(bridge::ServoJp{Arm::Left, start + bad}));
  EXPECT_FALSE(robot.core.apply(bridge::MoveJp{Arm::Left, start + bad}));
  EXPECT_FALSE(
      robot.core.apply(bridge::ServoJawJp{Arm::Left, std::numeric_limits<double>::quiet_NaN()}));
  Eigen::Isometry3d pose = robot.core.reportedPose(Arm::Left, start);
  pose.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(robot.core.apply(bridge::ServoCp{Arm::Left, pose}));
  robot.cycle(20);
  EXPECT_EQ(robot.left(), start);
}

TEST(RavenCore, AJumpBeyondTheClampsIsRefused) {
  Robot robot;
  robot.makeReady();
  const ArmJoints start = robot.left();
  const auto max_jump = bridge::ServoLimits{}.maxJump();
  // Just inside the window is taken, just beyond it is not: for servo_jp and servo_jr.
  EXPECT_TRUE(robot.core.apply(
      bridge::ServoJp{Arm::Left, start + jointStep(raven::kElbow, 0.99 * max_jump(1))}));
  EXPECT_TRUE(robot.core.apply(bridge::ServoJp{Arm::Left, start}));
  auto result = robot.core.apply(
      bridge::ServoJp{Arm::Left, start + jointStep(raven::kElbow, 1.01 * max_jump(1))});
  EXPECT_FALSE(result);
  EXPECT_NE(result.note.find("'elbow' would jump"), std::string::npos) << result.note;
  EXPECT_FALSE(robot.core.apply(
      bridge::ServoJr{Arm::Left, jointStep(raven::kInsertion, 1.01 * max_jump(2))}));
  // Increments that pile up past the window are refused too.
  const ArmJoints half = jointStep(raven::kRoll, 0.6 * max_jump(3));
  EXPECT_TRUE(robot.core.apply(bridge::ServoJr{Arm::Left, half}));
  EXPECT_FALSE(robot.core.apply(bridge::ServoJr{Arm::Left, half}));
  robot.cycle(100);
  EXPECT_NEAR(robot.left()(raven::kRoll) - start(raven::kRoll), half(raven::kRoll), 1e-12);
  EXPECT_EQ(robot.left()(raven::kElbow), start(raven::kElbow));
  EXPECT_EQ(robot.left()(raven::kInsertion), start(raven::kInsertion));
}

TEST(RavenCore, JointLimitsHoldOnEveryCommandPath) {
  Robot robot;
  robot.makeReady();
  const auto& limits = test_support::physicalProfile().limits;
  // Creep the insertion past its upper limit with increments, as a stuck stick would.
  for (int i = 0; i < 4000; ++i) {
    robot.core.apply(bridge::ServoJr{Arm::Left, jointStep(raven::kInsertion, 0.0001)});
    robot.cycle();
    ASSERT_LE(robot.left()(raven::kInsertion), limits.high(raven::kInsertion));
  }
  EXPECT_EQ(robot.left()(raven::kInsertion), limits.high(raven::kInsertion));
  // A move far outside every limit ends on the limits, and the log says so.
  LogCapture log;
  auto result = robot.core.apply(bridge::MoveJp{Arm::Left, ArmJoints::Constant(-100.0)});
  ASSERT_TRUE(result);
  EXPECT_NE(result.note.find("clamped shoulder"), std::string::npos) << result.note;
  EXPECT_NE(log.text().find("took move_jp left: clamped shoulder"), std::string::npos)
      << log.text();
  for (int i = 0; i < 20000 && robot.core.status().is_busy; ++i) {
    robot.cycle();
    ASSERT_TRUE((robot.left().array() >= limits.low.array()).all());
  }
  EXPECT_EQ(robot.left(), limits.low);
  // The jaws cannot open past their limits either.
  for (int i = 0; i < 200; ++i) {
    robot.core.apply(bridge::ServoJawJr{Arm::Left, 0.04});
    robot.cycle(20);
  }
  EXPECT_LE(robot.left()(raven::kJaw1), limits.high(raven::kJaw1));
  EXPECT_LE(robot.left()(raven::kJaw2), limits.high(raven::kJaw2));
}

TEST(RavenCore, MoveJpIsBusyUntilEveryJointArrivesTogetherWithinTheLimits) {
  Robot robot;
  robot.makeReady();
  const ArmJoints start = robot.left();
  const ArmJoints goal = start + (ArmJoints() << 0.3, -0.2, 0.05, 1.0, -0.5, 0.2, 0.1).finished();
  ASSERT_TRUE(robot.core.apply(bridge::MoveJp{Arm::Left, goal}));
  EXPECT_TRUE(robot.core.status().is_busy);
  const bridge::ServoLimits limits;
  int cycles = 0;
  ArmJoints velocity = ArmJoints::Zero();
  while (robot.core.status().is_busy && cycles < 20000) {
    robot.cycle();
    ++cycles;
    const ArmJoints v = robot.core.setpointVelocity(Arm::Left);
    // Never faster than the cycle clamp, never accelerating harder than A_MAX (+ rounding).
    ASSERT_TRUE((v.cwiseAbs().array() <= limits.moveVelocity().array() * (1 + 1e-9)).all());
    ASSERT_TRUE((((v - velocity).cwiseAbs() / limits.cycle).array() <=
                 limits.move_acceleration.array() * 1.001 + 1e-9)
                    .all());
    // On the straight line: every joint has covered the same fraction.
    const ArmJoints fraction = (robot.left() - start).cwiseQuotient(goal - start);
    ASSERT_LT(fraction.maxCoeff() - fraction.minCoeff(), 1e-9);
    velocity = v;
  }
  EXPECT_EQ(robot.left(), goal);
  // The insertion's 0.05 m at 0.02 m/s^2 sets the pace: a triangular profile of 2 sqrt(2.5) s.
  EXPECT_NEAR(cycles * limits.cycle, 2.0 * std::sqrt(2.5), 0.002);
}

TEST(RavenCore, AServoCommandPreemptsAMove) {
  Robot robot;
  robot.makeReady();
  const ArmJoints start = robot.left();
  ASSERT_TRUE(robot.core.apply(bridge::MoveJp{Arm::Left, start + jointStep(raven::kRoll, 1.0)}));
  robot.cycle(300);
  const ArmJoints there = robot.left();
  ASSERT_TRUE(robot.core.apply(bridge::ServoJr{Arm::Left, ArmJoints::Zero()}));
  EXPECT_FALSE(robot.core.status().is_busy);
  robot.cycle(100);
  EXPECT_EQ(robot.left(), there);
}

TEST(RavenCore, PauseStopsAMoveAndDisableDropsTheHoming) {
  Robot robot;
  robot.makeReady();
  ASSERT_TRUE(
      robot.core.apply(bridge::MoveJp{Arm::Left, robot.left() + jointStep(raven::kShoulder, 0.3)}));
  robot.cycle(200);
  ASSERT_TRUE(robot.core.apply(StateCommand::Pause));
  EXPECT_FALSE(robot.core.status().is_busy);
  const ArmJoints held = robot.left();
  robot.cycle(500);
  EXPECT_EQ(robot.left(), held);
  ASSERT_TRUE(robot.core.apply(StateCommand::Resume));
  robot.cycle(500);
  EXPECT_EQ(robot.left(), held) << "a resumed robot does not finish a paused move by itself";
  ASSERT_TRUE(robot.core.apply(StateCommand::Disable));
  EXPECT_FALSE(robot.core.status().is_homed);
}

TEST(RavenCore, ServoCpReachesThePoseInTheFirmwareFrameAndRefusesBigSteps) {
  Robot robot;
  robot.makeReady();
  const ArmJoints start = robot.left();
  Eigen::Isometry3d pose = robot.core.reportedPose(Arm::Left, start);
  pose.translation() += Eigen::Vector3d(0.008, -0.006, 0.004);  // 10.8 mm: within 15 mm
  ASSERT_TRUE(robot.core.apply(bridge::ServoCp{Arm::Left, pose}));
  robot.cycle(100);
  const Eigen::Isometry3d reached = robot.core.reportedPose(Arm::Left, robot.left());
  EXPECT_LT((reached.translation() - pose.translation()).norm(), 1e-9);
  EXPECT_TRUE(reached.linear().isApprox(pose.linear(), 1e-9));
  EXPECT_NEAR(robot.left()(raven::kJaw1) + robot.left()(raven::kJaw2),
              start(raven::kJaw1) + start(raven::kJaw2), 1e-9)
      << "the grasper opening is kept";

  Eigen::Isometry3d far = reached;
  far.translation().z() += 0.02;
  auto result = robot.core.apply(bridge::ServoCp{Arm::Left, far});
  EXPECT_FALSE(result);
  EXPECT_NE(result.note.find("tool would jump"), std::string::npos) << result.note;

  Eigen::Isometry3d sheared = reached;
  sheared.linear()(0, 1) += 0.1;
  EXPECT_FALSE(robot.core.apply(bridge::ServoCp{Arm::Left, sheared}));
}

TEST(RavenCore, ServoCrAddsTranslationAndPremultipliesRotation) {
  Robot robot;
  robot.makeReady();
  const Eigen::Isometry3d from =
      robot.core.reportedPose(Arm::Right, robot.core.setpoint(Arm::Right));
  Eigen::Isometry3d increment = Eigen::Isometry3d::Identity();
  increment.translation() = Eigen::Vector3d(-0.002, 0.001, 0.003);
  increment.linear() = Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  ASSERT_TRUE(robot.core.apply(bridge::ServoCr{Arm::Right, increment}));
  robot.cycle(100);
  const Eigen::Isometry3d to = robot.core.reportedPose(Arm::Right, robot.core.setpoint(Arm::Right));
  EXPECT_LT((to.translation() - from.translation() - increment.translation()).norm(), 1e-9);
  EXPECT_TRUE(to.linear().isApprox(increment.linear() * from.linear(), 1e-9));
}

TEST(RavenCore, JawCommandsSetTheOpeningAndKeepTheJawsDifference) {
  Robot robot;
  robot.makeReady();
  const ArmJoints start = robot.left();
  const double difference = start(raven::kJaw1) - start(raven::kJaw2);
  ASSERT_TRUE(robot.core.apply(bridge::ServoJawJp{Arm::Left, 1.6}));
  robot.cycle(40);
  EXPECT_NEAR(robot.left()(raven::kJaw1) + robot.left()(raven::kJaw2), 1.6, 1e-12);
  EXPECT_NEAR(robot.left()(raven::kJaw1) - robot.left()(raven::kJaw2), difference, 1e-12);
  ASSERT_TRUE(robot.core.apply(bridge::ServoJawJr{Arm::Left, -0.05}));
  robot.cycle(40);
  EXPECT_NEAR(robot.left()(raven::kJaw1) + robot.left()(raven::kJaw2), 1.55, 1e-12);
  for (int i : {0, 1, 2, 3, 4}) EXPECT_EQ(robot.left()(i), start(i));
}

TEST(RavenCore, AFaultHoldsAndRefusesUntilReEnabled) {
  Robot robot;
  robot.makeReady();
  ASSERT_TRUE(robot.core.apply(bridge::ServoJr{Arm::Left, jointStep(raven::kShoulder, 0.01)}));
  robot.cycle();
  robot.core.fault("test");
  const ArmJoints held = robot.left();
  robot.cycle(10);
  EXPECT_EQ(robot.left(), held);
  EXPECT_EQ(robot.core.status().state, OperatingState::Fault);
  EXPECT_FALSE(robot.core.apply(bridge::ServoJr{Arm::Left, jointStep(raven::kShoulder, 0.001)}));
  ASSERT_TRUE(robot.core.apply(StateCommand::Enable));
  EXPECT_TRUE(robot.core.apply(bridge::ServoJr{Arm::Left, jointStep(raven::kShoulder, 0.001)}));
}

}  // namespace
