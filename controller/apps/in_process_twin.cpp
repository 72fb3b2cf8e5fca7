#include "in_process_twin.hpp"

#include "twin/calibration_profile.hpp"
#include "twin/twin_platform.hpp"

namespace controller_app {

std::unique_ptr<bridge::RavenPlatform> makeInProcessTwin(const InProcessTwinSettings& settings) {
  twin::TwinOptions options;
  if (!settings.launch_file.empty()) options.launch_file = settings.launch_file;
  options.clock = settings.lock_step ? bridge::ClockKind::Simulated : bridge::ClockKind::Wall;
  if (settings.stand_in) options.stand_in = twin::CableActuationParams::physicalStandIn();
  if (!settings.calibration_file.empty()) {
    options.tracking = twin::CalibrationProfile::load(settings.calibration_file).tracking;
  }
  return std::make_unique<twin::TwinPlatform>(options);
}

ControllerCalibration loadControllerCalibration(const std::string& file) {
  return {twin::CalibrationProfile::load(file).iteration_overhead};
}

}  // namespace controller_app
