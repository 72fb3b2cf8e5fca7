#pragma once
// A recording's controller inputs replayed on the in-process twin with O3 in lock-step, exactly
// as `raven_controller --lock-step --replay-ci` replays them, kept in memory as an analysis trial.

#include <optional>
#include <vector>

#include "analysis/trial_set.hpp"
#include "controller/dual_platform_controller.hpp"
#include "recording/gamepad_state.hpp"
#include "twin/twin_platform.hpp"

namespace calibration {

/// What a replay needs besides the tracking response being tried.
struct ReplaySetup {
  std::vector<recording::GamepadState> inputs;  ///< one ci row per manual-loop iteration
  controller::ControllerOptions controller;     ///< rate, man_steps, scheme, deadzone quirk
  twin::TwinOptions twin;                       ///< model, stand-in; always on the simulated clock
  double replay_delay = 1.0;                    ///< O3's wait after loading (s)
};

/// Builds, enables and homes a twin with `tracking` (none: the twin as it is), replays every
/// input row and returns one trial row per input row (the state before each iteration, as the
/// recorder writes it), in the physical robot's conventions.
analysis::Trial replayOnTwin(const ReplaySetup& setup,
                             const std::optional<twin::TrackingParams>& tracking);

}  // namespace calibration
