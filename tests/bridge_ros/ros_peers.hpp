#pragma once
// Test peers of the twin node: the node itself as a child process, and a raw ROS peer that
// sends messages exactly as given (bad ones too) and steps the node in lock-step.

#include <raven_twin/Step.h>
#include <raven_twin/StepDone.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/String.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bridge/ros/command_topics.hpp"
#include "bridge/ros/raven_ros_client.hpp"
#include "harness/ros_master.hpp"
#include "test_files.hpp"

namespace ros_test {

/// raven_twin_node in its own namespace, logging to a temp file.
class TwinNode {
 public:
  /// `ns` like "/t3"; `args` are extra command-line flags (--lock-step, --actuation ideal, ...).
  TwinNode(const std::string& ns, const std::vector<std::string>& args);
  const std::string& ns() const { return ns_; }
  /// Stops the node (SIGINT) and returns what it logged.
  std::string stopAndReadLog();
  void kill() { process_->kill(); }

 private:
  std::string ns_;
  test_support::TempDir dir_;
  std::unique_ptr<harness::ChildProcess> process_;
};

/// A unique namespace per call: "/t1", "/t2", ...
std::string freshNamespace();

/// The private rosmaster of this test run (ros_test_main.cpp).
harness::RosMaster& master();

/// A twin node in a fresh namespace and a client of it.
struct Rig {
  explicit Rig(std::vector<std::string> node_args, bool lock_step = true,
               bridge::ros1::RosClientOptions options = {})
      : node(freshNamespace(), withLockStep(std::move(node_args), lock_step)),
        client(clientOptions(options, node.ns(), lock_step)) {}

  static std::vector<std::string> withLockStep(std::vector<std::string> args, bool lock_step) {
    if (lock_step) args.push_back("--lock-step");
    return args;
  }
  static bridge::ros1::RosClientOptions clientOptions(bridge::ros1::RosClientOptions o,
                                                      const std::string& ns, bool lock_step) {
    o.robot_namespace = ns;
    o.lock_step = lock_step;
    return o;
  }

  TwinNode node;
  bridge::ros1::RavenRosClient client;
};

/// A joint command with these positions and nothing else.
sensor_msgs::JointState jointCommand(std::vector<double> position);

/// Publishes raw messages on a robot's command topics and steps it (lock-step), collecting the
/// refusals the node reports.
class RawPeer {
 public:
  explicit RawPeer(const std::string& ns);

  template <typename Message>
  void send(bridge::ros1::CommandTopic topic, const Message& message) {
    auto& publisher = publishers_[topic];
    if (!publisher) {
      publisher = node_.advertise<Message>(std::string(bridge::ros1::topicName(topic)), 100);
      waitFor([&] { return publisher.getNumSubscribers() > 0; }, "a subscriber");
    }
    publisher.publish(message);
    order_.push_back(static_cast<std::uint8_t>(topic));
  }

  /// Asks for `cycles` cycles with every message sent since the last step applied first; waits
  /// for the answer and for `refusals` refusal reports (at most 5 s). Returns the reports.
  std::vector<std::string> step(std::uint32_t cycles, std::size_t refusals = 0);
  /// Names a command on `topic` in the next step without sending one (a lost or lying peer).
  void claim(bridge::ros1::CommandTopic topic) {
    order_.push_back(static_cast<std::uint8_t>(topic));
  }
  /// Names a command topic id that does not exist in the next step.
  void claimId(std::uint8_t id) { order_.push_back(id); }
  /// Why the node refused the last step ("" if it ran).
  const std::string& stepRefusal() const { return step_refused_; }

 private:
  template <typename Condition>
  void waitFor(Condition condition, const char* what) {
    const auto deadline = ros::WallTime::now() + ros::WallDuration(10.0);
    while (!condition()) {
      if (ros::WallTime::now() > deadline) throw std::runtime_error(std::string("no ") + what);
      queue_.callAvailable(ros::WallDuration(0.01));
    }
  }

  ros::CallbackQueue queue_;
  ros::NodeHandle node_;
  std::map<bridge::ros1::CommandTopic, ros::Publisher> publishers_;
  ros::Publisher step_;
  std::vector<ros::Subscriber> subscribers_;
  std::vector<std::uint8_t> order_;
  std::uint64_t seq_ = 1'000'000'000;  // apart from any client's step numbers
  std::uint64_t done_ = 0;
  std::string step_refused_;
  std::vector<std::string> refusals_;
};

}  // namespace ros_test
