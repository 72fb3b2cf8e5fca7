#pragma once
// A calibration profile (raven_calibrate writes it, --calibration reads it): the twin's tracking
// response, and the timing of the controller that made the physical recordings it was fitted
// to, so replays of such recordings take as long per iteration as they did on the robot.

#include <filesystem>

#include "twin/tracking_response.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

struct CalibrationProfile {
  TrackingParams tracking;
  /// Platform time a manual-loop iteration of the recording controller took besides its command
  /// steps (its pad read, IK and recorder), in seconds.
  double iteration_overhead = 0.0;

  /// Reads `tracking: {latency_cycles, bandwidth_hz, damping_ratio[, friction_deadband,
  /// max_velocity, max_acceleration]}`, `replay: {iteration_overhead}` and ignores `fit` (what the
  /// values were fitted on). Throws common::LoadError naming file, line and key.
  static CalibrationProfile load(const std::filesystem::path& file);
};

}  // namespace twin
