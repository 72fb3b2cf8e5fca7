#pragma once
// The twin and the controller a scripted scenario drives: the twin built, then enabled and
// homed by the robot's own homing, the controller reading the pose from there; and the run's
// clocks (build, loop) for its report.

#include <chrono>
#include <optional>

#include "controller/dual_platform_controller.hpp"
#include "scenario/run_timing.hpp"
#include "twin/twin_platform.hpp"

namespace scenario {

/// One twin under one controller, on the simulated clock.
class ScriptedSession {
 public:
  /// Builds the twin. Throws common::LoadError for bad model files.
  explicit ScriptedSession(const twin::TwinOptions& options,
                           controller::ControllerOptions controller_options = {});
  ScriptedSession(const ScriptedSession&) = delete;
  ScriptedSession& operator=(const ScriptedSession&) = delete;

  /// Enables and homes the twin, then starts the controller from the homed pose. Throws
  /// std::runtime_error when homing has not finished by `time_limit` simulated seconds.
  void makeReady(double time_limit);

  twin::TwinPlatform& twin() { return twin_; }
  /// Valid after makeReady().
  controller::DualPlatformController& controller() { return *controller_; }
  /// The clocks so far.
  RunTiming timing() const;

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point wall_start_ = Clock::now();
  twin::TwinPlatform twin_;
  Clock::time_point loop_start_ = Clock::now();
  std::uint64_t first_step_ = 0;
  controller::ControllerOptions controller_options_;
  std::optional<controller::DualPlatformController> controller_;
};

}  // namespace scenario
