#pragma once
// A recording's controller inputs replayed on the in-process twin with O3 in lock-step, exactly
// as `raven_controller --lock-step --replay-ci` replays them, kept in memory as an analysis trial.

#include <optional>
#include <vector>

#include "analysis/trial_set.hpp"
#include "calibration/setpoint_replay.hpp"
#include "controller/dual_platform_controller.hpp"
#include "recording/gamepad_state.hpp"
#include "twin/twin_platform.hpp"

namespace calibration {

/// What a replay needs besides the tracking response being tried.
struct ReplaySetup {
  std::vector<recording::GamepadState> inputs;  ///< one ci row per manual-loop iteration
  controller::ControllerOptions controller;     ///< rate, man_steps, scheme, deadzone quirk
  twin::TwinOptions twin;                       ///< model, actuation; always on the simulated clock
  double replay_delay = 1.0;                    ///< O3's wait after loading (s)
  /// Set: the twin starts where a recording began (moved there after homing, then its
  /// actuators placed in the recorded state); unset: at its home.
  std::optional<twin::RecordedStart> start;
  /// Set: the first move the recording's controller made (controller::firstMoveOf), which the
  /// replay's first iteration sends (DualPlatformController::sendFirstMove).
  std::optional<raven::ArmPair> first_move;
};

/// Builds, enables and homes a twin, replays every input row and returns one trial row per
/// input row (the state before each iteration, as the recorder writes it), in the physical
/// robot's conventions.
analysis::Trial replayOnTwin(const ReplaySetup& setup);
/// The same replay as the recorder writes it (every raven_state column).
recording::RsRecording recordReplay(const ReplaySetup& setup);

}  // namespace calibration
