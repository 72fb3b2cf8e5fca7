#include "controller/held_wrist.hpp"

#include <cmath>

namespace controller {

namespace {

/// Roll, wrist and jaw1 - jaw2 of `q`.
Eigen::Vector3d wristValues(const raven::ArmJoints& q) {
  return {q(raven::kRoll), q(raven::kWrist), q(raven::kJaw1) - q(raven::kJaw2)};
}

bool standsStill(const raven::ArmPair& now, const raven::ArmPair& next) {
  constexpr double kStill = 1e-9;  // rad: a setpoint no increment moved
  for (std::size_t a = 0; a < 2; ++a) {
    if ((wristValues(next[a]) - wristValues(now[a])).cwiseAbs().maxCoeff() > kStill) return false;
  }
  return true;
}

bool mayTurnWrist(const recording::GamepadState& pad, double deadzone) {
  return pad.a || pad.x || pad.y || std::abs(pad.right_x) > deadzone ||
         std::abs(pad.right_y) > deadzone;
}

}  // namespace

std::optional<raven::ArmPair> heldWristChange(const std::vector<raven::ArmPair>& setpoints,
                                              const std::vector<recording::GamepadState>& inputs,
                                              double deadzone) {
  for (std::size_t r = 1; r + 1 < setpoints.size(); ++r) {
    if (r - 1 >= inputs.size() || mayTurnWrist(inputs[r - 1], deadzone)) return std::nullopt;
    if (standsStill(setpoints[r], setpoints[r + 1])) {
      return raven::ArmPair{setpoints[r][0] - setpoints[0][0], setpoints[r][1] - setpoints[0][1]};
    }
  }
  return std::nullopt;
}

}  // namespace controller
