#include "bridge/enable_and_home.hpp"

#include <stdexcept>
#include <string>

namespace bridge {

void enableAndHome(RavenPlatform& robot, double timeout, const std::function<bool()>& keep_going) {
  if (robot.operatingStatus().ready()) return;
  if (robot.operatingStatus().state != OperatingState::Enabled) robot.send(StateCommand::Enable);
  robot.send(StateCommand::Home);
  const double deadline = robot.now() + timeout;
  while (!robot.operatingStatus().ready() && robot.now() < deadline &&
         (!keep_going || keep_going())) {
    robot.advance(0.01);
  }
  if (!robot.operatingStatus().ready()) {
    throw std::runtime_error("did not become enabled and homed within " + std::to_string(timeout) +
                             " s (state " + std::string(wireName(robot.operatingStatus().state)) +
                             ")");
  }
}

}  // namespace bridge
