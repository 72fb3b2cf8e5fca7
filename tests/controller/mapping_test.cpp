// The paper's mappings against hand-computed cases from the reference's rules
// (../shared/reference/dual-platform-controller.md), each rule its own test: M2 and M1, the
// deadzone boundary, the IK choice, the wrist resets, grasping, the released controller's deadzone
// quirk; and a property test: under M1 no pad sequence ever changes the other arm's target.

#include <gtest/gtest.h>

#include <random>

#include "controller/gamepad_mapping.hpp"
#include "random_pad.hpp"
#include "twin_fixtures.hpp"

namespace {

using controller::ArmPair;
using controller::GamepadMapping;
using controller::MappingScheme;
using raven::Arm;
using raven::ArmJoints;
using recording::GamepadState;

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
  const auto a = raven::slot(arm);
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

/// The firmware's home with `arm`'s joint `joint` at `value`.
ArmPair homeWith(Arm arm, int joint, double value) {
  ArmPair q = home();
  q[raven::slot(arm)](joint) = value;
  return q;
}

MappingScheme m1(Arm arm) {
  return arm == Arm::Left ? MappingScheme::M1Left : MappingScheme::M1Right;
}

TEST(MappingM1, TheLeftStickMovesTheSelectedArmOnlyAndZWithTheLeftBumper) {
  for (Arm arm : raven::kArms) {
    GamepadMapping m(test_support::physicalProfile(), m1(arm), home());
    const Arm other = raven::other(arm);
    GamepadState pad;
    pad.left_x = -0.4;  // -0.2 mm in x
    pad.left_y = 0.6;   // -0.3 mm in y
    EXPECT_LT((wristStep(m, pad, arm) - Eigen::Vector3d(-0.0002, -0.0003, 0)).norm(), 1e-12);
    pad.left_bumper = true;  // now z: -y / 2000
    EXPECT_LT((wristStep(m, pad, arm) - Eigen::Vector3d(0, 0, -0.0003)).norm(), 1e-12);
    pad = {};
    pad.right_bumper = true;  // M1 has no use for RB
    pad.left_y = -1.0;
    EXPECT_EQ(wristStep(m, pad, other).norm(), 0.0) << "the other arm never moves";
  }
}

TEST(MappingM1, TheRightTriggerGraspsWithTheSelectedArmAndTheLeftTriggerIsIgnored) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M1Right, home());
  GamepadState pad;
  pad.right_trigger = 1.0;  // grasp = 1 - 1/4
  pad.left_trigger = 4.0;
  const auto q = m.apply(pad, home()).joints;
  EXPECT_NEAR(q[1](raven::kJaw1) + q[1](raven::kJaw2), 0.75, 1e-15);
  EXPECT_EQ(q[0], home()[0]) << "left grasp kept, bit for bit";
}

TEST(MappingM1, TheRightStickTurnsJoints4And5OfTheSelectedArmOnly) {
  for (Arm arm : raven::kArms) {
    GamepadMapping m(test_support::physicalProfile(), m1(arm), home());
    const auto a = raven::slot(arm);
    GamepadState pad;
    pad.right_x = 0.5;  // joint 4: -0.5 / 10
    pad.right_y = 0.3;  // joint 5: +0.3 / 10
    const auto q = m.apply(pad, home()).joints;
    EXPECT_NEAR(q[a](raven::kRoll), -0.05, 1e-15);
    EXPECT_NEAR(q[a](raven::kWrist), 0.03, 1e-15);
    EXPECT_EQ(q[1 - a], home()[1 - a]) << "the other arm's wrist never moves under M1";
  }
}

TEST(MappingM1, EachWristAxisHasItsOwnDeadzone) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M1Left, home());
  GamepadState pad;
  pad.right_x = 0.15;  // on the boundary: inside (|v| > 0.15 moves)
  pad.right_y = 0.14;  // radially 0.205, but each axis is tested alone
  auto q = m.apply(pad, home()).joints;
  EXPECT_EQ(q[0](raven::kRoll), 0.0);
  EXPECT_EQ(q[0](raven::kWrist), 0.0);
  pad.right_x = 0.1501;
  q = m.apply(pad, home()).joints;
  EXPECT_NEAR(q[0](raven::kRoll), -0.01501, 1e-15);
  EXPECT_EQ(q[0](raven::kWrist), 0.0);
}

TEST(MappingM1, ARollIncrementReachingPiIsSkippedNotClamped) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M1Left,
                   homeWith(Arm::Left, raven::kRoll, 3.1));
  GamepadState pad;
  pad.right_x = -1.0;  // +0.1: 3.2 is beyond pi, skipped
  EXPECT_EQ(m.apply(pad, home()).joints[0](raven::kRoll), 3.1);
  pad.right_x = -0.3;  // +0.03: 3.13 < pi, taken
  EXPECT_NEAR(m.apply(pad, home()).joints[0](raven::kRoll), 3.13, 1e-15);
  pad.right_x = -0.2;  // +0.02: 3.15 > pi, skipped (a clamp would give pi)
  EXPECT_NEAR(m.apply(pad, home()).joints[0](raven::kRoll), 3.13, 1e-15);
  GamepadMapping n(test_support::physicalProfile(), MappingScheme::M1Right,
                   homeWith(Arm::Right, raven::kRoll, -M_PI + 0.04));
  pad.right_x = 0.5;  // -0.05: beyond -pi, skipped on the negative side too
  EXPECT_EQ(n.apply(pad, home()).joints[1](raven::kRoll), -M_PI + 0.04);
}

TEST(MappingM1, AWristIncrementReachingHalfPiIsSkippedNotClamped) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M1Left,
                   homeWith(Arm::Left, raven::kWrist, 1.5));
  GamepadState pad;
  pad.right_y = 1.0;  // +0.1: 1.6 > pi/2, skipped
  for (int i = 0; i < 5; ++i) EXPECT_EQ(m.apply(pad, home()).joints[0](raven::kWrist), 1.5);
  pad.right_y = 0.5;  // +0.05: 1.55, taken
  EXPECT_NEAR(m.apply(pad, home()).joints[0](raven::kWrist), 1.55, 1e-15);
  pad.right_y = -1.0;  // and back down by 0.1
  EXPECT_NEAR(m.apply(pad, home()).joints[0](raven::kWrist), 1.45, 1e-15);
}

TEST(MappingM1, AlwaysPlacesTheWristPointEvenInFullIkMode) {
  GamepadMapping m(test_support::physicalProfile(), MappingScheme::M1Left, home());
  GamepadState b;
  b.b = true;
  m.apply(b, home());
  EXPECT_EQ(m.ikMode(), controller::IkMode::Full);
  GamepadState push;
  push.left_x = 1.0;
  push.right_x = 1.0;  // the roll turns: a full IK would have kept the tool's orientation
  const auto q = m.apply(push, home()).joints;
  EXPECT_NEAR(q[0](raven::kRoll), -0.1, 1e-15);
  EXPECT_LT((wristPoint(Arm::Left, q[0]) - wristPoint(Arm::Left, home()[0]) -
             Eigen::Vector3d(0.0005, 0, 0))
                .norm(),
            1e-12);
}

TEST(Mapping, XAndYResetTheWristsToHome) {
  const auto& profile = test_support::physicalProfile();
  GamepadMapping m(profile, MappingScheme::M1Left, home());
  GamepadState turn;
  turn.right_x = 1.0;
  turn.right_y = 1.0;
  EXPECT_NEAR(m.apply(turn, home()).joints[0](raven::kRoll), -0.1, 1e-15);
  GamepadState reset_left;
  reset_left.x = true;
  const auto q = m.apply(reset_left, home()).joints;
  EXPECT_EQ(q[0](raven::kRoll), profile.home(raven::kRoll));
  EXPECT_EQ(q[0](raven::kWrist), profile.home(raven::kWrist));
}

TEST(Mapping, AWristResetWaitsUntilItsArmIsDriven) {
  const auto& profile = test_support::physicalProfile();
  GamepadMapping m(profile, MappingScheme::M1Right, home());
  GamepadState turn;
  turn.right_x = 1.0;
  const ArmJoints turned = m.apply(turn, home()).joints[1];
  GamepadState y_under_m1_left;
  y_under_m1_left.back = true;  // M1 left
  y_under_m1_left.y = true;     // reset the right wrist
  EXPECT_EQ(m.apply(y_under_m1_left, home()).joints[1], turned) << "the right arm is not driven";
  GamepadState m2;
  m2.back = m2.start = true;
  const auto q = m.apply(m2, home()).joints;
  EXPECT_EQ(q[1](raven::kRoll), profile.home(raven::kRoll)) << "applied once the arm is driven";
  EXPECT_EQ(q[1](raven::kWrist), profile.home(raven::kWrist));
}

TEST(MappingM1Property, NoPadSequenceUnderM1EverChangesTheOtherArmsTarget) {
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> offset(-0.3, 0.3);
  for (Arm selected : raven::kArms) {
    const auto other = raven::slot(raven::other(selected));
    for (int sequence = 0; sequence < 20; ++sequence) {
      ArmPair start = home();  // both arms anywhere near home, wrists off home too
      for (auto& q : start) {
        for (int j : {raven::kShoulder, raven::kElbow, raven::kRoll, raven::kWrist}) {
          q(j) += offset(random);
        }
      }
      GamepadMapping m(test_support::physicalProfile(), m1(selected), start);
      GamepadState pad;
      for (int i = 0; i < 200; ++i) {
        if (i % 7 == 0) {
          pad = test_support::randomPad(random, /*adversarial=*/i % 2 == 0);
          test_support::keepM1(pad, selected);
        }
        // A re-reads the pose: a settled arm reports what it was commanded.
        const auto q = m.apply(pad, m.targets()).joints;
        ASSERT_EQ(q[other], start[other]) << "sequence " << sequence << ", iteration " << i;
      }
    }
  }
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
