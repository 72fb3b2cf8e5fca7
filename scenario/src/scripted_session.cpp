#include "scenario/scripted_session.hpp"

#include <stdexcept>
#include <string>

#include "bridge/enable_and_home.hpp"

namespace scenario {

ScriptedSession::ScriptedSession(const twin::TwinOptions& options,
                                 controller::ControllerOptions controller_options)
    : twin_(options),
      first_step_(twin_.world().stepCount()),
      controller_options_(std::move(controller_options)) {}

void ScriptedSession::makeReady(double time_limit) {
  try {
    bridge::enableAndHome(twin_, time_limit - twin_.now());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("the twin ") + e.what());
  }
  controller_.emplace(
      std::vector<controller::PlatformSlot>{{"twin", &twin_, controller::CommandStyle::ServoJr}},
      controller_options_);
  controller_->readPose();
}

RunTiming ScriptedSession::timing() const {
  const auto now = Clock::now();
  RunTiming t;
  t.sim_time = twin_.now();
  t.wall_time = std::chrono::duration<double>(now - wall_start_).count();
  t.loop_seconds = std::chrono::duration<double>(now - loop_start_).count();
  t.steps = twin_.world().stepCount() - first_step_;
  return t;
}

}  // namespace scenario
