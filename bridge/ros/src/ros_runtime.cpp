#include "bridge/ros/ros_runtime.hpp"

#include <ros/ros.h>

namespace bridge::ros1 {

void initRos(int& argc, char** argv, const std::string& node_name) {
  ::ros::init(argc, argv, node_name);
}

bool rosOk() {
  return ::ros::ok();
}

std::string masterUri() {
  return ::ros::master::getURI();
}

}  // namespace bridge::ros1
