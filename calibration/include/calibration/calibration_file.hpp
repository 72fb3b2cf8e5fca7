#pragma once
// Writes the calibration profile raven_calibrate produces: the fitted mechanics of each arm's
// motors and their uncertainty, the recording controller's measured iteration overhead, and a
// `fit` section saying what it was fitted on and how well it did (twin::CalibrationProfile
// reads it back).

#include <filesystem>
#include <string>
#include <vector>

#include "twin/calibration_profile.hpp"

namespace calibration {

/// Provenance written beside the parameters (free text lines, one per entry).
struct FitProvenance {
  std::string inputs;                 ///< the ci file, if replays were scored
  std::vector<std::string> physical;  ///< the physical trials fitted on
  std::vector<std::string> notes;     ///< scores, options
};

/// Writes `profile` and `provenance` as YAML; throws std::runtime_error when it cannot.
void writeCalibration(const std::filesystem::path& file, const twin::CalibrationProfile& profile,
                      const FitProvenance& provenance);

}  // namespace calibration
