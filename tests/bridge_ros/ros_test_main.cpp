// The ROS tests' main: one private rosmaster for the whole run, then ros::init against it.

#include <gtest/gtest.h>

#include "bridge/ros/ros_runtime.hpp"
#include "harness/ros_master.hpp"
#include "ros_peers.hpp"

namespace {
harness::RosMaster* the_master = nullptr;
}  // namespace

harness::RosMaster& ros_test::master() {
  return *the_master;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  harness::RosMaster master;  // sets ROS_MASTER_URI before ros::init reads it
  the_master = &master;
  bridge::ros1::initRos(argc, argv, "bridge_ros_tests");
  return RUN_ALL_TESTS();
}
