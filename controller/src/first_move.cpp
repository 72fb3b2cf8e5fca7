#include "controller/first_move.hpp"

#include <cmath>

namespace controller {

namespace {

bool standsStill(const raven::ArmPair& now, const raven::ArmPair& next) {
  constexpr double kStill = 1e-9;  // rad or m: a setpoint no increment moved
  for (std::size_t a = 0; a < 2; ++a) {
    if ((next[a] - now[a]).cwiseAbs().maxCoeff() > kStill) return false;
  }
  return true;
}

/// A stick past the deadzone radially is past it on any axis too (M1's wrist test).
bool asksForMotion(const recording::GamepadState& pad, double deadzone) {
  return pad.a || pad.x || pad.y || std::hypot(pad.left_x, pad.left_y) > deadzone ||
         std::hypot(pad.right_x, pad.right_y) > deadzone;
}

}  // namespace

std::optional<raven::ArmPair> firstMoveOf(const std::vector<raven::ArmPair>& setpoints,
                                          const std::vector<recording::GamepadState>& inputs,
                                          double deadzone) {
  if (inputs.empty() || asksForMotion(inputs.front(), deadzone)) return std::nullopt;
  for (std::size_t r = 1; r + 1 < setpoints.size(); ++r) {
    if (r - 1 >= inputs.size() || !(inputs[r - 1] == inputs.front())) return std::nullopt;
    if (standsStill(setpoints[r], setpoints[r + 1])) {
      return raven::ArmPair{setpoints[r][0] - setpoints[0][0], setpoints[r][1] - setpoints[0][1]};
    }
  }
  return std::nullopt;
}

}  // namespace controller
