// What a recording's first move shows of its controller's open-loop state
// (controller::firstMoveOf), on hand-made setpoints, and a controller sending it: only the
// controller's increments move the robot's setpoints, so the first move, once delivered, is
// what the controller's own joints (held wrist values, last jaws) asked of the robot.

#include "controller/first_move.hpp"

#include <gtest/gtest.h>

#include "controller/dual_platform_controller.hpp"
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

/// Setpoints whose first move turns the right roll by -0.06 rad and opens the left jaws by
/// 0.1 rad between them over two rows, then stand still.
std::vector<ArmPair> firstMove() {
  std::vector<ArmPair> rows{start()};
  for (double share : {0.5, 1.0, 1.0, 1.0}) {
    ArmPair q = start();
    q[1](raven::kRoll) -= 0.06 * share;
    q[0](raven::kJaw1) += 0.05 * share;
    q[0](raven::kJaw2) -= 0.05 * share;
    rows.push_back(q);
  }
  return rows;
}

TEST(FirstMove, IsWhereTheSetpointsFirstStandStill) {
  const auto change = controller::firstMoveOf(firstMove(), std::vector<GamepadState>(5), kDeadzone);
  ASSERT_TRUE(change.has_value());
  EXPECT_NEAR((*change)[1](raven::kRoll), -0.06, 1e-12);
  EXPECT_NEAR((*change)[0](raven::kJaw1) - (*change)[0](raven::kJaw2), 0.1, 1e-12);
  EXPECT_NEAR((*change)[0](raven::kWrist), 0.0, 1e-12);
}

TEST(FirstMove, IsUnknownWhereTheInputsAskedForMotion) {
  for (auto ask : {+[](GamepadState& p) { p.x = true; }, +[](GamepadState& p) { p.y = true; },
                   +[](GamepadState& p) { p.a = true; }, +[](GamepadState& p) { p.right_y = 0.2; },
                   +[](GamepadState& p) { p.left_x = 0.12, p.left_y = 0.12; }}) {
    std::vector<GamepadState> first(5), later(5);
    ask(first[0]);
    ask(later[1]);
    EXPECT_FALSE(controller::firstMoveOf(firstMove(), first, kDeadzone).has_value());
    EXPECT_FALSE(controller::firstMoveOf(firstMove(), later, kDeadzone).has_value());
  }
}

TEST(FirstMove, IsUnknownWhileTheSetpointsNeverStandStill) {
  auto rows = firstMove();
  for (std::size_t r = 0; r < rows.size(); ++r) {
    rows[r][0](raven::kShoulder) += 0.001 * static_cast<double>(r);
  }
  EXPECT_FALSE(controller::firstMoveOf(rows, std::vector<GamepadState>(5), kDeadzone).has_value());
}

TEST(FirstMove, TheControllerSendsItThenGoesOnFromItsTargets) {
  auto twin = test_support::readyTwin();
  controller::DualPlatformController control(
      {{"twin", twin.get(), controller::CommandStyle::ServoJr}}, {});
  control.readPose();
  const ArmPair before{twin->setpointJs(raven::Arm::Left).position,
                       twin->setpointJs(raven::Arm::Right).position};
  ArmPair change{ArmJoints::Zero(), ArmJoints::Zero()};
  change[1](raven::kRoll) = -0.06;
  change[0](raven::kJaw1) = 0.02;
  GamepadState pad;  // grasp 1 rad: the mapping's jaws move too, and are replaced by the change
  control.sendFirstMove(change);
  control.manual(pad);
  control.manual(pad);  // the same pad: nothing more to send
  twin->advance(0.5);
  for (std::size_t a = 0; a < 2; ++a) {
    const ArmJoints after =
        twin->setpointJs(a == 0 ? raven::Arm::Left : raven::Arm::Right).position;
    EXPECT_LT((after - before[a] - change[a]).cwiseAbs().maxCoeff(), 1e-3) << "arm " << a;
  }
}

}  // namespace
