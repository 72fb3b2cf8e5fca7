// The paper's mappings against hand-computed cases: M2 and M1, the deadzone boundary, the IK
// choice, the wrist resets, grasping, and the released controller's deadzone quirk.

#include <gtest/gtest.h>

#include "controller/gamepad_mapping.hpp"
#include "twin_fixtures.hpp"

namespace {

using controller::ArmPair;
using controller::GamepadMapping;
using controller::GamepadState;
using controller::MappingScheme;
using raven::Arm;
using raven::ArmJoints;

/// The firmware's home: roll 0, jaws pi/4 each.
ArmPair home() {
  return {test_support::physicalProfile().robotHome(), test_support::physicalProfile().robotHome()};
}

Eigen::Vector3d wristPoint(Arm arm, const ArmJoints& q) {
  return raven::ArmKinematics::of(test_support::physicalProfile(), arm).wristPoint(q);
}

/// The wrist-point motion one pad reading causes on `arm`.
Eigen::Vector3d wristStep(GamepadMapping& m, const GamepadState& pad, Arm arm) {
  const auto before = m.targets();
  const auto result = m.apply(pad, home());
  const auto a = static_cast<std::size_t>(raven::index(arm));
  return wristPoint(arm, result.joints[a]) - wristPoint(arm, before[a]);
}

TEST(Mapping, M2MovesEachArmByItsStickInTheBaseFrame) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home());
  GamepadState pad;
  pad.left_x = 0.5;    // +x: 0.5 / 2000 = 0.25 mm
  pad.right_y = -0.8;  // pushed forward: +y by 0.4 mm
  const auto before = m.targets();
  const auto result = m.apply(pad, home());
  EXPECT_LT((wristPoint(Arm::Left, result.joints[0]) - wristPoint(Arm::Left, before[0]) -
             Eigen::Vector3d(0.00025, 0, 0))
                .norm(),
            1e-12);
  EXPECT_LT((wristPoint(Arm::Right, result.joints[1]) - wristPoint(Arm::Right, before[1]) -
             Eigen::Vector3d(0, 0.0004, 0))
                .norm(),
            1e-12);
  // Roll and wrist stay exactly where they were (C_W).
  for (const auto& q : result.joints) {
    EXPECT_EQ(q(raven::kRoll), test_support::physicalProfile().robotHome()(raven::kRoll));
    EXPECT_EQ(q(raven::kWrist), test_support::physicalProfile().robotHome()(raven::kWrist));
  }
}

TEST(Mapping, ABumperTurnsTheStickIntoZ) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home());
  GamepadState pad;
  pad.left_bumper = true;
  pad.left_x = 0.9;   // ignored while the bumper is held
  pad.left_y = -0.6;  // dz = -y / 2000 = +0.3 mm
  EXPECT_LT((wristStep(m, pad, Arm::Left) - Eigen::Vector3d(0, 0, 0.0003)).norm(), 1e-12);
}

TEST(Mapping, TheRadialDeadzoneBoundary) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home());
  auto moved = [&](double x, double y) {
    GamepadState pad;
    pad.left_x = x;
    pad.left_y = y;
    return wristStep(m, pad, Arm::Left).norm() > 1e-12;  // (re-solving IK wobbles by 1e-17)
  };
  EXPECT_FALSE(moved(0.15, 0.0)) << "exactly on the boundary is inside";
  EXPECT_TRUE(moved(0.1501, 0.0));
  EXPECT_FALSE(moved(0.1, 0.11));  // |(0.1, 0.11)| = 0.1487
  EXPECT_TRUE(moved(0.1, 0.12));   // 0.1562: past it, used raw (not rescaled)
  GamepadState pad;
  pad.left_x = 0.1;
  pad.left_y = 0.12;
  EXPECT_LT((wristStep(m, pad, Arm::Left) - Eigen::Vector3d(0.1 / 2000, -0.12 / 2000, 0)).norm(),
            1e-12);
}

TEST(Mapping, TheReleasedControllersDeadzoneReadsYTwice) {
  controller::MappingConstants c;
  c.deadzone_reads_y_twice = true;
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home(), c);
  GamepadState sideways;
  sideways.left_x = 1.0;
  sideways.left_y = 0.1;  // sqrt(2) * 0.1 = 0.141 < 0.15: nothing, as the recordings show
  EXPECT_LT(wristStep(m, sideways, Arm::Left).norm(), 1e-12);
  sideways.left_y = 0.11;  // 0.156: moves, by the raw values
  EXPECT_LT(
      (wristStep(m, sideways, Arm::Left) - Eigen::Vector3d(1.0 / 2000, -0.11 / 2000, 0)).norm(),
      1e-12);
}

TEST(Mapping, TriggersSetTheGraspAboutTheKeptJawDifference) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home());
  GamepadState pad;
  pad.left_trigger = 2.0;  // grasp = 1 - 2/4 = 0.5
  pad.right_trigger = 3.99609375;
  const auto q = m.apply(pad, home()).joints;
  EXPECT_DOUBLE_EQ(q[0](raven::kJaw1), 0.25);
  EXPECT_DOUBLE_EQ(q[0](raven::kJaw2), 0.25);
  EXPECT_NEAR(q[1](raven::kJaw1) + q[1](raven::kJaw2), 1.0 - 3.99609375 / 4.0, 1e-15);
}

TEST(Mapping, SchemeSelectionIsLevelTriggered) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home());
  GamepadState pad;
  pad.back = true;
  m.apply(pad, home());
  EXPECT_EQ(m.scheme(), MappingScheme::M1Left);
  pad = {};
  m.apply(pad, home());
  EXPECT_EQ(m.scheme(), MappingScheme::M1Left) << "kept until another selection";
  pad.start = true;
  m.apply(pad, home());
  EXPECT_EQ(m.scheme(), MappingScheme::M1Right);
  pad.back = true;
  m.apply(pad, home());
  EXPECT_EQ(m.scheme(), MappingScheme::M2);
}

TEST(Mapping, M1DrivesOneArmAndTurnsBothWristsWithTheRightStick) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M1Right, home());
  GamepadState pad;
  pad.left_x = -0.4;        // the right arm: -0.2 mm in x
  pad.right_x = 0.5;        // joint 4 of BOTH arms: -0.5 / 10 = -0.05 rad
  pad.right_y = 0.14;       // per-axis deadzone: ignored
  pad.right_trigger = 1.0;  // the right arm's grasp: 0.75
  pad.left_trigger = 4.0;   // M1 ignores it
  const auto before = m.targets();
  const auto q = m.apply(pad, home()).joints;
  EXPECT_LT((wristPoint(Arm::Right, q[1]) - wristPoint(Arm::Right, before[1]) -
             Eigen::Vector3d(-0.0002, 0, 0))
                .norm(),
            1e-12);
  EXPECT_LT((wristPoint(Arm::Left, q[0]) - wristPoint(Arm::Left, before[0])).norm(), 1e-12);
  for (const auto& arm : q) {
    EXPECT_NEAR(arm(raven::kRoll), -0.05, 1e-15);
    EXPECT_EQ(arm(raven::kWrist), 0.0);
  }
  EXPECT_NEAR(q[1](raven::kJaw1) + q[1](raven::kJaw2), 0.75, 1e-15);
  EXPECT_NEAR(q[0](raven::kJaw1) + q[0](raven::kJaw2), M_PI / 2, 1e-15) << "left grasp kept";
  // Joint 5 follows +RY / 10 once past the deadzone, and stops at +-pi/2.
  pad = {};
  pad.right_y = 1.0;
  for (int i = 0; i < 30; ++i) m.apply(pad, home());
  EXPECT_DOUBLE_EQ(m.targets()[0](raven::kWrist), M_PI / 2);
}

TEST(Mapping, XAndYResetTheWristsToHome) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M1Left, home());
  GamepadState turn;
  turn.right_x = 1.0;
  turn.right_y = 1.0;
  m.apply(turn, home());
  GamepadState reset_left;
  reset_left.x = true;
  const auto q = m.apply(reset_left, home()).joints;
  EXPECT_EQ(q[0](raven::kRoll), test_support::physicalProfile().home(raven::kRoll));
  EXPECT_EQ(q[0](raven::kWrist), test_support::physicalProfile().home(raven::kWrist));
  EXPECT_NEAR(q[1](raven::kRoll), -0.1, 1e-15) << "the right arm is not reset by X";
}

TEST(Mapping, ARereadsThePoseAndBSwitchesToFullIkKeepingTheToolOrientation) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home());
  ArmPair moved = home();
  moved[0](raven::kShoulder) += 0.1;
  GamepadState a;
  a.a = true;
  const auto q = m.apply(a, moved).joints;
  EXPECT_NEAR(q[0](raven::kShoulder), moved[0](raven::kShoulder), 1e-12) << "the pose was re-read";

  GamepadState b;
  b.b = true;
  m.apply(b, moved);
  EXPECT_EQ(m.ikMode(), controller::IkMode::Full);
  const auto kin = raven::ArmKinematics::of(test_support::physicalProfile(), Arm::Left);
  const Eigen::Isometry3d before = kin.toolPose(m.targets()[0]);
  GamepadState push;
  push.left_x = 1.0;
  const auto after = kin.toolPose(m.apply(push, moved).joints[0]);
  EXPECT_LT((after.translation() - before.translation() - Eigen::Vector3d(0.0005, 0, 0)).norm(),
            1e-9);
  EXPECT_TRUE(after.linear().isApprox(before.linear(), 1e-9));
}

TEST(Mapping, AClampedTargetIsReported) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M2, home());
  GamepadState down;
  down.left_bumper = true;
  down.left_y = 1.0;  // -z: away from the remote centre, until the insertion's limit
  bool clamped = false;
  for (int i = 0; i < 2000 && !clamped; ++i) clamped = m.apply(down, home()).clamped;
  EXPECT_TRUE(clamped);
  EXPECT_EQ(m.targets()[0](raven::kInsertion),
            test_support::physicalProfile().limits.low(raven::kInsertion));
}

}  // namespace
