// The twin node under faults around it: its rosmaster killed and restarted, lock-step steps
// that cannot be answered, a sender's text that would flood or forge its log.

#include <crtk_msgs/StringStamped.h>
#include <crtk_msgs/operating_state.h>
#include <gtest/gtest.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <chrono>
#include <functional>

#include "bridge/ros/low_latency.hpp"
#include "harness/ros_master.hpp"
#include "ros_peers.hpp"

namespace {

using bridge::ros1::CommandTopic;
using Clock = std::chrono::steady_clock;

/// Spins `queue` until `condition` holds; false if `seconds` of wall time pass first.
bool spinUntil(ros::CallbackQueue& queue, const std::function<bool()>& condition, double seconds) {
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  while (!condition()) {
    if (Clock::now() > deadline) return false;
    queue.callAvailable(ros::WallDuration(0.01));
  }
  return true;
}

TEST(NodeFaults, TheNodeRegistersAgainWhenItsMasterRestartsAndKeepsItsConnections) {
  ros_test::TwinNode node(ros_test::freshNamespace(), {});  // wall clock, as on a robot
  ros::CallbackQueue queue;
  ros::NodeHandle handle(node.ns());
  handle.setCallbackQueue(&queue);
  int before_restart = 0;
  auto early = handle.subscribe<sensor_msgs::JointState>(
      "arm1/measured_js", 10, [&](const sensor_msgs::JointState::ConstPtr&) { ++before_restart; },
      {}, bridge::ros1::lowLatency());
  ASSERT_TRUE(spinUntil(
      queue, [&] { return before_restart > 0; }, 20.0))
      << "no measured_js";

  ros_test::master().restart();

  // The connection made with the old master stays.
  const int seen = before_restart;
  EXPECT_TRUE(spinUntil(
      queue, [&] { return before_restart > seen + 100; }, 10.0));
  // A peer that comes after the restart finds the node's state topics...
  int after_restart = 0;
  std::string state;
  auto late = handle.subscribe<sensor_msgs::JointState>(
      "arm2/measured_js", 10, [&](const sensor_msgs::JointState::ConstPtr&) { ++after_restart; },
      {}, bridge::ros1::lowLatency());
  auto status = handle.subscribe<crtk_msgs::operating_state>(
      "operating_state", 10,
      [&](const crtk_msgs::operating_state::ConstPtr& m) { state = m->state; }, {},
      bridge::ros1::lowLatency());
  EXPECT_TRUE(spinUntil(
      queue, [&] { return after_restart > 0 && !state.empty(); }, 10.0))
      << "a subscriber that came after the restart gets nothing";
  EXPECT_EQ(state, "DISABLED");
  // ... and its command topics: a new publisher's enable is obeyed.
  auto command = handle.advertise<crtk_msgs::StringStamped>("state_command", 10);
  ASSERT_TRUE(spinUntil(
      queue, [&] { return command.getNumSubscribers() > 0; }, 10.0))
      << "the node's state_command is not registered with the new master";
  crtk_msgs::StringStamped enable;
  enable.string = "enable";
  command.publish(enable);
  EXPECT_TRUE(spinUntil(
      queue, [&] { return state == "ENABLED"; }, 10.0))
      << state;
  const std::string log = node.stopAndReadLog();
  EXPECT_NE(log.find("restarted"), std::string::npos) << log;
}

TEST(NodeFaults, ALockStepStepWhoseCommandsNeverCameIsRefusedAndLaterStepsRun) {
  ros_test::TwinNode node(ros_test::freshNamespace(), {"--lock-step", "--command-wait", "0.2"});
  ros_test::RawPeer peer(node.ns());
  const auto started = Clock::now();
  peer.claim(CommandTopic::Arm1ServoJp);  // named, never sent
  const auto refusals = peer.step(5, 1);
  const double took = std::chrono::duration<double>(Clock::now() - started).count();
  EXPECT_NE(peer.stepRefusal().find("did not all arrive within 0.2"), std::string::npos)
      << peer.stepRefusal();
  EXPECT_NE(peer.stepRefusal().find("1 on arm1/servo_jp"), std::string::npos) << peer.stepRefusal();
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_NE(refusals[0].find("did not all arrive"), std::string::npos) << refusals[0];
  EXPECT_LT(took, 2.0) << "the refusal must come within the command wait";
  // The steps after it are not held up.
  peer.step(5);
  EXPECT_EQ(peer.stepRefusal(), "");
  // A step longer than one step may be, and one naming a topic that does not exist.
  peer.step(bridge::ros1::kMostCyclesPerStep + 1, 1);
  EXPECT_NE(peer.stepRefusal().find("more than the 60000"), std::string::npos)
      << peer.stepRefusal();
  peer.claimId(200);
  peer.step(1, 1);
  EXPECT_NE(peer.stepRefusal().find("id 200"), std::string::npos) << peer.stepRefusal();
  peer.step(1);
  EXPECT_EQ(peer.stepRefusal(), "");
}

TEST(NodeFaults, ASendersTextIsLoggedEscapedAndCutShort) {
  ros_test::TwinNode node(ros_test::freshNamespace(), {"--lock-step"});
  ros_test::RawPeer peer(node.ns());
  crtk_msgs::StringStamped forged;
  forged.string = "fly\n[error] forged line\n" + std::string(1'000'000, 'x');
  peer.send(CommandTopic::StateCommand, forged);
  const auto refusals = peer.step(1, 1);
  ASSERT_EQ(refusals.size(), 1u);
  EXPECT_LT(refusals[0].size(), 300u) << "the refusal echoes the whole text";
  EXPECT_NE(refusals[0].find("fly\\n[error] forged line\\n"), std::string::npos) << refusals[0];
  const std::string log = node.stopAndReadLog();
  EXPECT_EQ(log.find("\n[error] forged line"), std::string::npos) << "a forged log line";
  EXPECT_LT(log.size(), 20'000u) << "the node logged the sender's megabyte";
}

}  // namespace
