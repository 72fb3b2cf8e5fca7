#include "in_process_twin.hpp"

#include "twin/calibration_profile.hpp"
#include "twin/twin_platform.hpp"

namespace controller_app {

struct TwinTracking {
  twin::TrackingParams params;
};

std::unique_ptr<bridge::RavenPlatform> makeInProcessTwin(const InProcessTwinSettings& settings) {
  twin::TwinOptions options;
  if (!settings.launch_file.empty()) options.launch_file = settings.launch_file;
  options.clock = settings.lock_step ? bridge::ClockKind::Simulated : bridge::ClockKind::Wall;
  if (settings.stand_in) options.stand_in = twin::CableActuationParams::physicalStandIn();
  if (settings.calibration) options.tracking = settings.calibration->twin_tracking->params;
  return std::make_unique<twin::TwinPlatform>(options);
}

ControllerCalibration loadControllerCalibration(const std::string& file) {
  auto profile = twin::CalibrationProfile::load(file);
  return {profile.iteration_overhead,
          std::make_shared<const TwinTracking>(TwinTracking{profile.tracking})};
}

}  // namespace controller_app
