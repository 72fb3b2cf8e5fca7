#pragma once
// One reading of a gamepad on the paper's scale, and its 14-column `ci` row.

#include <array>
#include <string_view>

namespace recording {

/// Sticks in [-1, 1] with Y pointing down when pushed forward (evdev's and SDL's sense),
/// triggers on the paper's scale (an Xbox One trigger reads 0 .. 3.996), buttons pressed or not.
struct GamepadState {
  double left_x = 0.0, left_y = 0.0, left_trigger = 0.0;
  bool left_bumper = false;
  double right_x = 0.0, right_y = 0.0, right_trigger = 0.0;
  bool right_bumper = false;
  bool a = false, b = false, x = false, y = false, back = false, start = false;

  static constexpr std::size_t kCiColumns = 14;
  /// The ci header's column names, in order.
  static const std::array<std::string_view, kCiColumns>& ciColumnNames();
  /// LX, LY, LT, LB, RX, RY, RT, RB, A, B, X, Y, Back, Start; buttons as 0 or 1.
  std::array<double, kCiColumns> toCiRow() const;
  /// Buttons count as pressed when their value is above 0.5.
  static GamepadState fromCiRow(const std::array<double, kCiColumns>& row);

  bool operator==(const GamepadState& o) const { return toCiRow() == o.toCiRow(); }
};

}  // namespace recording
