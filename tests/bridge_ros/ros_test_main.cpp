// The ROS tests' main: one private rosmaster for the whole run, then ros::init against it.

#include <gtest/gtest.h>

#include "bridge/ros/ros_runtime.hpp"
#include "harness/ros_master.hpp"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  harness::RosMaster master;  // sets ROS_MASTER_URI before ros::init reads it
  bridge::ros1::initRos(argc, argv, "bridge_ros_tests");
  return RUN_ALL_TESTS();
}
