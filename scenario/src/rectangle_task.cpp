#include "scenario/rectangle_task.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "raven/arm_kinematics.hpp"
#include "recording/recording_io.hpp"
#include "scenario/scripted_session.hpp"
#include "twin/calibration_profile.hpp"

namespace scenario {

namespace {

/// Both sticks pushed the same way: (x, y) in the stick's own sense (y down when pushed forward).
recording::GamepadState bothSticks(double x, double y) {
  recording::GamepadState pad;
  pad.left_x = pad.right_x = x;
  pad.left_y = pad.right_y = y;
  return pad;
}

}  // namespace

std::vector<recording::GamepadState> rectangleInputs(const RectangleOptions& options,
                                                     const controller::MappingConstants& mapping) {
  if (!(options.width > 0.0 && options.depth > 0.0 && std::isfinite(options.width) &&
        std::isfinite(options.depth))) {
    throw std::invalid_argument("rectangle: width and depth must be positive and finite");
  }
  if (!(options.deflection > mapping.deadzone && options.deflection <= 1.0)) {
    throw std::invalid_argument("rectangle: the stick deflection must lie in (deadzone, 1]");
  }
  const double per_loop = options.deflection / mapping.divisor;  // M2: dx = x / DIV, dy = -y / DIV
  const double d = options.deflection;
  const std::array<std::pair<recording::GamepadState, double>, 4> edges{
      {{bothSticks(d, 0.0), options.width},
       {bothSticks(0.0, -d), options.depth},
       {bothSticks(-d, 0.0), options.width},
       {bothSticks(0.0, d), options.depth}}};
  std::vector<recording::GamepadState> inputs;
  for (const auto& [pad, length] : edges) {
    inputs.insert(inputs.end(), static_cast<std::size_t>(std::lround(length / per_loop)), pad);
    inputs.insert(inputs.end(), static_cast<std::size_t>(std::max(options.dwell, 0)),
                  recording::GamepadState{});
  }
  return inputs;
}

Eigen::Vector3d RectangleResult::extent(raven::Arm arm) const {
  const auto& path = wrist_path[raven::slot(arm)];
  if (path.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d low = path.front(), high = path.front();
  for (const auto& p : path) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return high - low;
}

nlohmann::json RectangleResult::json() const {
  nlohmann::json j{{"task", "rectangle"},         {"iterations", iterations},
                   {"refused_commands", refused}, {"clamped_iterations", clamped},
                   {"timed_out", timed_out},      {"rs_file", rs_file.string()},
                   {"ci_file", ci_file.string()}};
  for (raven::Arm arm : raven::kArms) {
    const Eigen::Vector3d e = extent(arm);
    j["extent_m"][std::string(raven::armName(arm))] = {e.x(), e.y(), e.z()};
  }
  timing.addTo(j);
  return j;
}

RectangleResult runRectangle(const RectangleOptions& options) {
  const controller::ControllerOptions controller_options;  // M2, the paper's constants
  const auto inputs = rectangleInputs(options, controller_options.mapping);
  twin::TwinOptions twin_options;
  if (options.actuation == common::ActuationKind::Motors)
    twin::CalibrationProfile::shipped().applyTo(twin_options);
  ScriptedSession session(twin_options, controller_options);
  session.makeReady(options.time_limit);
  twin::TwinPlatform& twin = session.twin();
  controller::DualPlatformController& controller = session.controller();

  std::unique_ptr<recording::RsWriter> rs;
  std::unique_ptr<recording::CiWriter> ci;
  if (!options.rs_file.empty()) rs = std::make_unique<recording::RsWriter>(options.rs_file);
  if (!options.ci_file.empty()) ci = std::make_unique<recording::CiWriter>(options.ci_file);
  const auto profile = raven::builtinProfile(controller_options.profile);
  const raven::PerArm<raven::ArmKinematics> kinematics{
      raven::ArmKinematics::of(profile, raven::Arm::Left),
      raven::ArmKinematics::of(profile, raven::Arm::Right)};

  RectangleResult result;
  auto recordPose = [&] {
    for (raven::Arm arm : raven::kArms) {
      const auto slot = raven::slot(arm);
      result.wrist_path[slot].push_back(kinematics[slot].wristPoint(twin.measuredJs(arm).position));
    }
  };
  recordPose();  // the homed pose the rectangle starts from
  RunProgress progress{twin.now(), 0, inputs.size()};
  for (const recording::GamepadState& pad : inputs) {
    if (twin.now() >= options.time_limit) break;
    const controller::IterationReport report = controller.manual(pad);
    result.refused += report.refused;
    result.clamped += report.clamped ? 1 : 0;
    if (ci) ci->write(pad);
    if (rs) rs->write(*twin.ravenState());
    recordPose();
    ++result.iterations;
    progress.sim_time = twin.now();
    progress.done = result.iterations;
    if (options.progress) options.progress(progress);
  }
  result.timed_out = result.iterations < inputs.size();
  result.timing = session.timing();
  if (rs) result.rs_file = rs->path();
  if (ci) result.ci_file = options.ci_file;
  return result;
}

}  // namespace scenario
