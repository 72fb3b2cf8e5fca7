#include "recording/gamepad_state.hpp"

namespace recording {

const std::array<std::string_view, GamepadState::kCiColumns>& GamepadState::ciColumnNames() {
  static constexpr std::array<std::string_view, kCiColumns> kNames{
      "Left Joystick X",  "Left Joystick Y", "Left Trigger", "Left Bumper", "Right Joystick X",
      "Right Joystick Y", "Right Trigger",   "Right Bumper", "A Button",    "B Button",
      "X Button",         "Y Button",        "Back Button",  "Start Button"};
  return kNames;
}

std::array<double, GamepadState::kCiColumns> GamepadState::toCiRow() const {
  auto bit = [](bool pressed) { return pressed ? 1.0 : 0.0; };
  return {left_x,  left_y,        left_trigger,      bit(left_bumper), right_x,
          right_y, right_trigger, bit(right_bumper), bit(a),           bit(b),
          bit(x),  bit(y),        bit(back),         bit(start)};
}

GamepadState GamepadState::fromCiRow(const std::array<double, kCiColumns>& r) {
  auto pressed = [](double v) { return v > 0.5; };
  GamepadState s;
  s.left_x = r[0];
  s.left_y = r[1];
  s.left_trigger = r[2];
  s.left_bumper = pressed(r[3]);
  s.right_x = r[4];
  s.right_y = r[5];
  s.right_trigger = r[6];
  s.right_bumper = pressed(r[7]);
  s.a = pressed(r[8]);
  s.b = pressed(r[9]);
  s.x = pressed(r[10]);
  s.y = pressed(r[11]);
  s.back = pressed(r[12]);
  s.start = pressed(r[13]);
  return s;
}

}  // namespace recording
