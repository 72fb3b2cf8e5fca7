// raven_controller with --platform both: one instance sends the same commands to the twin
// (in-process) and to a "physical" Raven-II over ROS (here a twin node, with the motor-level
// actuation), records both, and reports their live divergence.

#include <gtest/gtest.h>

#include "recording/recording_io.hpp"
#include "ros_peers.hpp"

namespace {

TEST(ControllerOverRos, BothPlatformsGetTheSameCommandsAndTheirDivergenceIsReported) {
  ros_test::TwinNode robot(ros_test::freshNamespace(), {});
  test_support::TempDir dir;
  std::string ci =
      "Left Joystick X,Left Joystick Y,Left Trigger,Left Bumper,Right Joystick X,"
      "Right Joystick Y,Right Trigger,Right Bumper,A Button,B Button,X Button,"
      "Y Button,Back Button,Start Button\n";
  for (int i = 0; i < 40; ++i) ci += "0.8,0.0,0.0,0.0,0.0,-0.6,2.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0\n";
  const auto inputs = dir.write("inputs_ci.csv", ci);
  harness::ChildProcess controller(
      {RAVEN_CONTROLLER, "--platform", "both", "--physical-ns", robot.ns(), "--no-gamepad",
       "--no-keyboard", "--replay-ci", inputs.string(), "--record", "yes", "--name", "both",
       "--out", (dir.path() / "out").string()},
      dir.path() / "controller.log");
  ASSERT_EQ(controller.wait(120.0), 0) << test_support::readFile(dir.path() / "controller.log");
  const std::string log = test_support::readFile(dir.path() / "controller.log");
  EXPECT_NE(log.find("largest twin vs physical joint divergence"), std::string::npos) << log;
  std::map<std::string, std::size_t> rows;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path() / "out")) {
    const std::string name = entry.path().filename().string();
    if (name.find("_physical_rs.csv") != std::string::npos) {
      rows["physical"] = recording::readRs(entry.path()).rows.size();
    } else if (name.find("_twin_rs.csv") != std::string::npos) {
      rows["twin"] = recording::readRs(entry.path()).rows.size();
    } else if (name.find("_ci.csv") != std::string::npos) {
      rows["ci"] = recording::readCi(entry.path()).size();
    }
  }
  EXPECT_EQ(rows["physical"], 40u);
  EXPECT_EQ(rows["twin"], 40u);
  EXPECT_EQ(rows["ci"], 40u);
}

}  // namespace
