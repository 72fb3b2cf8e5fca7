#pragma once
// Where a recording of the Raven-II began, as a twin needs it to start there: per arm the joint
// setpoint the robot held and its actuators' state (motor angles, velocities, and the PID's
// integrators, which the first row's Tau gives away), and the way to put a twin there.

#include <array>

#include "recording/recording_io.hpp"
#include "twin/actuation.hpp"
#include "twin/twin_platform.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// The robot's state at a recording's first row.
struct RecordedStart {
  raven::PerArm<ArmJoints> setpoint;
  raven::PerArm<ArmStart> arms;
};

/// From the first row's signals of each arm (per raven::slot(arm)).
RecordedStart recordedStart(const raven::PerArm<recording::ArmSignals>& first_row);
/// From a recording's first row; throws recording::RecordingError naming the file when a column
/// is missing or the row's signals are not numbers.
RecordedStart recordedStart(const recording::RsRecording& rs);

/// Moves an enabled, homed twin to the recorded setpoints (move_jp), lets it settle, then places
/// its actuators exactly as the robot's were. Throws std::runtime_error if the move is refused.
void startAt(TwinPlatform& twin, const RecordedStart& start);

}  // namespace twin
