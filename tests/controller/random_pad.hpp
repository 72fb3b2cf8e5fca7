#pragma once
// Random gamepad readings for the controller's property tests.

#include <random>

#include "raven/arm.hpp"
#include "recording/gamepad_state.hpp"

namespace test_support {

/// Random and adversarial pads: saturated sticks, triggers slammed, every button at random.
inline recording::GamepadState randomPad(std::mt19937_64& random, bool adversarial) {
  std::uniform_real_distribution<double> axis(-1.0, 1.0), trigger(0.0, 3.996);
  std::bernoulli_distribution coin(adversarial ? 0.5 : 0.05);
  auto stick = [&] {
    return adversarial ? (coin(random) ? 1.0 : -1.0) * (coin(random) ? 1.0 : 0.999) : axis(random);
  };
  recording::GamepadState p;
  p.left_x = stick();
  p.left_y = stick();
  p.right_x = stick();
  p.right_y = stick();
  p.left_trigger = adversarial ? (coin(random) ? 3.996 : 0.0) : trigger(random);
  p.right_trigger = adversarial ? (coin(random) ? 3.996 : 0.0) : trigger(random);
  p.left_bumper = coin(random);
  p.right_bumper = coin(random);
  p.a = coin(random);
  p.b = coin(random);
  p.x = coin(random);
  p.y = coin(random);
  p.back = coin(random);
  p.start = coin(random);
  return p;
}

/// Clears the one button that would leave M1 of `selected` (Start selects the right arm, Back the
/// left): every other input stays as drawn.
inline void keepM1(recording::GamepadState& pad, raven::Arm selected) {
  (selected == raven::Arm::Left ? pad.start : pad.back) = false;
}

}  // namespace test_support
