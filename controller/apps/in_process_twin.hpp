#pragma once
// raven_controller's in-process twin, which only a build with the simulator has
// (RAVEN_SIMULATOR, on by default): in_process_twin.cpp builds it, without_simulator.cpp says
// how to get it. Everything else in the program runs on the physical robot's side alone.

#include <memory>
#include <string>

#include "bridge/raven_platform.hpp"
#include "common/actuation_flag.hpp"
#include "common/video_flags.hpp"
#include "recording/recording_io.hpp"

namespace controller_app {

/// The twin's part of a calibration profile (its motors, its commands' delivery), known to
/// in_process_twin.cpp.
struct TwinActuation;

/// A raven_calibrate profile, read once: what the controller uses, and what the twin does.
struct ControllerCalibration {
  double iteration_overhead = 0.0;  ///< s per manual iteration, as the recording controller's
  std::shared_ptr<const TwinActuation> twin_actuation;
};

/// What the command line asks of the in-process twin.
struct InProcessTwinSettings {
  std::string launch_file;  ///< empty: our Raven-II alone
  bool lock_step = false;   ///< simulated clock
  common::ActuationKind actuation = common::ActuationKind::Motors;
  /// From --calibration; null: the shipped calibration's actuation.
  const ControllerCalibration* calibration = nullptr;
  common::VideoFlags video;  ///< of the twin; no file: none
  /// An rs recording (--start-from, read once): the twin is enabled, homed and put where it
  /// began; null: at home.
  const recording::RsRecording* start_from = nullptr;
};

/// The in-process twin; throws std::runtime_error in a build without the simulator.
std::unique_ptr<bridge::RavenPlatform> makeInProcessTwin(const InProcessTwinSettings& settings);

/// Reads a raven_calibrate profile; throws std::runtime_error in a build without the simulator.
ControllerCalibration loadControllerCalibration(const std::string& file);

}  // namespace controller_app
