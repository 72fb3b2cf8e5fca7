#pragma once
// A calibration profile (raven_calibrate writes it; the twins load the shipped one unless told
// otherwise): the mechanics behind each arm's motors, how certain the fit is of them, and the
// timing of the controller that made the recordings, so replays of such recordings take as long
// per iteration as they did on the robot. Its file is read and written here, one spelling of
// each key.

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "twin/motor_dynamics.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

struct TwinOptions;

/// What a profile was fitted on, written beside its values as its `fit` section (free text, one
/// line per entry).
struct FitProvenance {
  std::string inputs;                 ///< the ci file, if replays were scored
  std::vector<std::string> physical;  ///< the physical trials fitted on
  std::vector<std::string> notes;     ///< scores, options
};

/// The fitted actuation of the twin's motors and the timing of the recording controller.
struct CalibrationProfile {
  ArmsMechanics mechanics;
  /// Per arm: the standard deviation of each fitted value, in the fit's sense (the change that
  /// moves the model's signals by the robot's own spread); 0 where it was not fitted.
  ArmsMechanics uncertainty;
  /// The share of servo_jr increments the robot's subscriber delivers (ServoLimits).
  double servo_jr_delivered = 1.0;
  /// Platform time a manual-loop iteration of the recording controller took besides its command
  /// steps (its pad read, IK and recorder), in seconds.
  double iteration_overhead = 0.0;

  /// Reads `actuation: {left|right: {inertia, coulomb, load_friction, viscous, offset,
  /// gravity_error}}` (7 values each; offset optional, 0 when absent), `uncertainty` (the same
  /// shape, optional), `commands: {servo_jr_delivered}` (optional), `replay: {iteration_overhead}`,
  /// and ignores `fit` (what the values were fitted on). Throws common::LoadError naming file, line
  /// and key.
  static CalibrationProfile load(const std::filesystem::path& file);
  /// Writes the profile in the layout load() reads, with `provenance` as its `fit` section;
  /// throws std::runtime_error when it cannot.
  void save(const std::filesystem::path& file, const FitProvenance& provenance) const;
  /// Makes `options` a twin of the calibrated robot: its motors and its command delivery
  /// (defined with the twin, twin/src/calibration_apply.cpp).
  void applyTo(TwinOptions& options) const;
  /// twin/config/raven2_calibration.yaml: the fit to the paper's physical recordings.
  static std::filesystem::path shippedFile();
  static CalibrationProfile shipped() { return load(shippedFile()); }
};

}  // namespace twin
