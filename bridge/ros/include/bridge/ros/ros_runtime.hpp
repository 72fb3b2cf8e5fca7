#pragma once
// ROS 1 start-up and state for programs that do not include ROS headers themselves.

#include <string>

namespace bridge::ros1 {

/// ros::init: takes ROS remappings (name:=value, __ns:=...) out of argv. Call once, first.
/// `ros_handles_sigint` true: SIGINT and SIGTERM both shut ROS down (rosOk() turns false); false:
/// the program keeps its own handling of both.
void initRos(int& argc, char** argv, const std::string& node_name, bool ros_handles_sigint = true);
/// False once ROS is shutting down (Ctrl-C, rosnode kill).
bool rosOk();
/// The master this process talks to.
std::string masterUri();

}  // namespace bridge::ros1
