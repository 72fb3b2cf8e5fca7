#include "bridge/ros/ros_runtime.hpp"

#include <ros/ros.h>

#include <csignal>

namespace bridge::ros1 {

void initRos(int& argc, char** argv, const std::string& node_name, bool ros_handles_sigint) {
  ::ros::init(argc, argv, node_name, ros_handles_sigint ? 0 : ::ros::init_options::NoSigintHandler);
  // roscpp handles SIGINT only; a scheduler or `kill` sends SIGTERM.
  if (ros_handles_sigint) std::signal(SIGTERM, [](int) { ::ros::requestShutdown(); });
}

bool rosOk() {
  return ::ros::ok();
}

std::string masterUri() {
  return ::ros::master::getURI();
}

}  // namespace bridge::ros1
