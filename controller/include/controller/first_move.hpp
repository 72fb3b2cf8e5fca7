#pragma once
// What the first move of a recorded session shows of its controller's open-loop state. The
// paper's controller sends increments from joints it keeps itself (the roll, wrist and jaw
// difference it holds, the jaws it last commanded), not from where the robot stood, so a
// recording's first row does not show them; the robot's setpoints do once the first manual
// iteration has been delivered, since nothing but those increments moves them.

#include <optional>
#include <vector>

#include "raven/arm.hpp"
#include "recording/gamepad_state.hpp"

namespace controller {

/// From a recording's joint setpoints (per row, both arms) and the inputs its controller read
/// (one per row): the setpoints at the first row r >= 1 at which every joint of both arms stands
/// still into the next row, less those of the first row. Unset when they never do, or when an
/// input before r differs from the first or could move an arm itself (a stick past `deadzone`,
/// radially or on an axis; A re-reads the pose; X or Y sends a wrist home): then the first move
/// cannot be told from the moves asked for.
std::optional<raven::ArmPair> firstMoveOf(const std::vector<raven::ArmPair>& setpoints,
                                          const std::vector<recording::GamepadState>& inputs,
                                          double deadzone);

}  // namespace controller
