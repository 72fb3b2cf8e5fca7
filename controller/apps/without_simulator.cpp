#include <stdexcept>

#include "in_process_twin.hpp"

namespace controller_app {

namespace {

std::runtime_error noSimulator(const std::string& what) {
  return std::runtime_error(what +
                            " needs the simulator, and this build has none (configured with "
                            "-DRAVEN_SIMULATOR=OFF): use --platform physical, or --twin-over-ros "
                            "with a raven_twin_node built elsewhere");
}

}  // namespace

std::unique_ptr<bridge::RavenPlatform> makeInProcessTwin(const InProcessTwinSettings&) {
  throw noSimulator("the in-process twin");
}

ControllerCalibration loadControllerCalibration(const std::string&) {
  throw noSimulator("--calibration");
}

}  // namespace controller_app
