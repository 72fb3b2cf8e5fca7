#include "scenario/scripted_session.hpp"

#include <stdexcept>

namespace scenario {

ScriptedSession::ScriptedSession(const bridge::TwinOptions& options,
                                 controller::ControllerOptions controller_options)
    : twin_(options),
      first_step_(twin_.world().stepCount()),
      controller_options_(std::move(controller_options)) {}

void ScriptedSession::makeReady(double time_limit) {
  twin_.send(bridge::StateCommand::Enable);
  twin_.send(bridge::StateCommand::Home);
  while (!twin_.operatingStatus().ready() && twin_.now() < time_limit) twin_.advance(0.01);
  if (!twin_.operatingStatus().ready()) {
    throw std::runtime_error("the twin did not finish homing within the time limit");
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
