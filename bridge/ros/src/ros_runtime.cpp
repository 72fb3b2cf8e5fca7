#include "bridge/ros/ros_runtime.hpp"

#include <ros/ros.h>

namespace bridge::ros1 {

void initRos(int& argc, char** argv, const std::string& node_name, bool ros_handles_sigint) {
  ::ros::init(argc, argv, node_name, ros_handles_sigint ? 0 : ::ros::init_options::NoSigintHandler);
}

bool rosOk() {
  return ::ros::ok();
}

std::string masterUri() {
  return ::ros::master::getURI();
}

}  // namespace bridge::ros1
