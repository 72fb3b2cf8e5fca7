#pragma once
// How far the wrist values (roll, wrist, the jaws' difference) a running paper controller held
// sat from the robot's setpoints when a recording began. The controller keeps them open loop,
// not where the robot stood, so a recording's first row does not show them; its setpoints do
// once the first manual iteration has been delivered, since nothing but the controller's
// increments moves those setpoints.

#include <optional>
#include <vector>

#include "raven/arm.hpp"
#include "recording/gamepad_state.hpp"

namespace controller {

/// From a recording's joint setpoints (per row, both arms) and the inputs its controller read
/// (one per row): the setpoints at the first row after the first at which every arm's roll,
/// wrist and jaw difference stand still into the next row, less those of the first row. Unset
/// when they never do, or when an input before it could have turned the wrist itself (A
/// re-reads the pose, X or Y sends the wrist home, M1's right stick past `deadzone` on either
/// axis turns it): then the held values cannot be told from the moves.
std::optional<raven::ArmPair> heldWristChange(const std::vector<raven::ArmPair>& setpoints,
                                              const std::vector<recording::GamepadState>& inputs,
                                              double deadzone);

}  // namespace controller
