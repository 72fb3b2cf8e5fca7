// What a recording shows of the wrist values its controller held (controller::heldWristChange),
// on hand-made setpoints, and the mapping keeping them: only increments move the robot's
// setpoints, so the first move, once delivered, shows how far the held values sat from them.

#include "controller/held_wrist.hpp"

#include <gtest/gtest.h>

#include "controller/gamepad_mapping.hpp"
#include "twin_fixtures.hpp"

namespace {

using raven::ArmJoints;
using raven::ArmPair;
using recording::GamepadState;

constexpr double kDeadzone = 0.15;

ArmPair start() {
  const ArmJoints home = test_support::physicalProfile().robotHome();
  return {home, home};
}

/// The setpoints of a first move that turns the right roll by -0.06 rad and the left jaw
/// difference by +0.1 in two rows, then stands still (the jaws' sum and the shoulder go on).
std::vector<ArmPair> firstMove() {
  std::vector<ArmPair> rows{start()};
  for (double share : {0.5, 1.0, 1.0, 1.0}) {
    ArmPair q = start();
    q[1](raven::kRoll) -= 0.06 * share;
    q[0](raven::kJaw1) += 0.05 * share;
    q[0](raven::kJaw2) -= 0.05 * share;
    q[0](raven::kShoulder) += 0.01 * static_cast<double>(rows.size());
    q[1](raven::kJaw1) -= 0.02 * static_cast<double>(rows.size());
    q[1](raven::kJaw2) -= 0.02 * static_cast<double>(rows.size());
    rows.push_back(q);
  }
  return rows;
}

TEST(HeldWrist, IsWhereTheFirstMoveLeftTheSetpoints) {
  const auto change =
      controller::heldWristChange(firstMove(), std::vector<GamepadState>(5), kDeadzone);
  ASSERT_TRUE(change.has_value());
  EXPECT_NEAR((*change)[1](raven::kRoll), -0.06, 1e-12);
  EXPECT_NEAR((*change)[0](raven::kJaw1) - (*change)[0](raven::kJaw2), 0.1, 1e-12);
  EXPECT_NEAR((*change)[0](raven::kWrist), 0.0, 1e-12);
}

TEST(HeldWrist, IsUnknownWhereAnInputCouldHaveTurnedTheWrist) {
  for (auto press :
       {+[](GamepadState& p) { p.x = true; }, +[](GamepadState& p) { p.y = true; },
        +[](GamepadState& p) { p.a = true; }, +[](GamepadState& p) { p.right_y = 0.2; }}) {
    std::vector<GamepadState> inputs(5);
    press(inputs[1]);
    EXPECT_FALSE(controller::heldWristChange(firstMove(), inputs, kDeadzone).has_value());
  }
}

TEST(HeldWrist, IsUnknownWhileTheSetpointsNeverStandStill) {
  auto rows = firstMove();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    rows[r][0](raven::kWrist) += 0.001 * static_cast<double>(r);
  }
  EXPECT_FALSE(
      controller::heldWristChange(rows, std::vector<GamepadState>(5), kDeadzone).has_value());
}

TEST(HeldWrist, TheMappingHoldsTheShiftedValuesAndGraspsAboutThem) {
  controller::GamepadMapping mapping(test_support::physicalProfile(), controller::MappingScheme::M2,
                                     start());
  ArmPair change{ArmJoints::Zero(), ArmJoints::Zero()};
  change[1](raven::kRoll) = -0.06;
  change[1](raven::kJaw1) = 0.05;
  mapping.shiftHeldWrist(change);
  GamepadState pad;
  pad.right_trigger = 2.0;  // grasp 0.5 rad
  const auto result = mapping.apply(pad, start());
  const ArmJoints& right = result.joints[1];
  EXPECT_NEAR(right(raven::kRoll), start()[1](raven::kRoll) - 0.06, 1e-9);
  EXPECT_NEAR(right(raven::kJaw1) + right(raven::kJaw2), 0.5, 1e-9);
  const double difference = start()[1](raven::kJaw1) - start()[1](raven::kJaw2) + 0.05;
  EXPECT_NEAR(right(raven::kJaw1) - right(raven::kJaw2), difference, 1e-9);
  EXPECT_NEAR(result.joints[0](raven::kRoll), start()[0](raven::kRoll), 1e-9) << "the other arm";
}

}  // namespace
