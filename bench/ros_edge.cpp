// The twin node over loopback ROS 1: how regularly it publishes at 1 kHz, and how long a
// servo_jr command takes to show in the robot's setpoint_js. C++17: it includes ROS headers.

#include <fmt/format.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <array>
#include <chrono>
#include <mutex>
#include <thread>

#include "bridge/enable_and_home.hpp"
#include "bridge/ros/raven_ros_client.hpp"
#include "bridge/ros/ros_runtime.hpp"
#include "harness/child_process.hpp"
#include "harness/ros_master.hpp"
#include "harness/temp_dir.hpp"
#include "sections.hpp"

namespace bench {

namespace {

const char* kSection = "ROS edge";
using Clock = std::chrono::steady_clock;

/// What arrives on the topics the benchmark listens to, stamped on arrival.
struct Listener {
  std::mutex mutex;
  std::vector<Clock::time_point> measured;      ///< arm1/measured_js arrivals
  Clock::time_point setpoint_at;                ///< last setpoint_js arrival
  raven::PerArm<std::vector<double>> setpoint;  ///< arm1's and arm2's latest setpoint_js

  void onMeasured(const sensor_msgs::JointState::ConstPtr&) {
    std::lock_guard<std::mutex> lock(mutex);
    measured.push_back(Clock::now());
  }
  void onSetpoint(int arm, const sensor_msgs::JointState::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    setpoint[static_cast<std::size_t>(arm)] = msg->position;
    setpoint_at = Clock::now();
  }
};

double seconds(Clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

/// True when any joint of either arm moved by more than 0.5 mrad (or 0.5 mm).
bool differs(const raven::PerArm<std::vector<double>>& a,
             const raven::PerArm<std::vector<double>>& b) {
  for (std::size_t arm = 0; arm < 2; ++arm) {
    if (a[arm].size() != b[arm].size()) return true;
    for (std::size_t i = 0; i < a[arm].size(); ++i) {
      if (std::abs(a[arm][i] - b[arm][i]) > 0.0005) return true;
    }
  }
  return false;
}

}  // namespace

void measureRosEdge(const BenchSettings& s, Report& report) {
  harness::TempDir dir;
  harness::RosMaster master;
  harness::ChildProcess node({(s.programs / "twin/ros/raven_twin_node").string()},
                             dir.path() / "node.log");
  int argc = 1;
  char name[] = "raven_bench";
  char* argv[] = {name, nullptr};
  bridge::ros1::initRos(argc, argv, "raven_bench", false);
  bridge::ros1::RavenRosClient client;
  bridge::enableAndHome(client, 30.0);

  Listener listener;
  ros::NodeHandle handle;
  const auto hints = ros::TransportHints().tcpNoDelay();
  auto measured_js = handle.subscribe<sensor_msgs::JointState>(
      "arm1/measured_js", 2000, &Listener::onMeasured, &listener, hints);
  auto setpoint1 = handle.subscribe<sensor_msgs::JointState>(
      "arm1/setpoint_js", 100,
      [&](const sensor_msgs::JointState::ConstPtr& m) { listener.onSetpoint(0, m); }, {}, hints);
  auto setpoint2 = handle.subscribe<sensor_msgs::JointState>(
      "arm2/setpoint_js", 100,
      [&](const sensor_msgs::JointState::ConstPtr& m) { listener.onSetpoint(1, m); }, {}, hints);
  ros::AsyncSpinner spinner(1);
  spinner.start();

  // Publish rate: 5 s of arm1/measured_js (the client keeps the robot alive meanwhile).
  client.advance(1.0);
  {
    std::lock_guard<std::mutex> lock(listener.mutex);
    listener.measured.clear();
  }
  client.advance(5.0);
  std::vector<Clock::time_point> arrivals;
  {
    std::lock_guard<std::mutex> lock(listener.mutex);
    arrivals = listener.measured;
  }
  std::vector<double> jitter_ms;
  for (std::size_t i = 1; i < arrivals.size(); ++i) {
    jitter_ms.push_back(1e3 * std::abs(seconds(arrivals[i] - arrivals[i - 1]) - 0.001));
  }
  const double rate =
      arrivals.size() > 1 ? (arrivals.size() - 1) / seconds(arrivals.back() - arrivals.front()) : 0;
  const auto how = fmt::format("arm1/measured_js arrivals over 5 s, {} messages", arrivals.size());
  report.add(atLeast(kSection, "twin node publish rate", Spread::of({rate}), "Hz", 990.0, how));
  report.add(measured(kSection, "arrival period jitter p99",
                      Spread::of({percentile(jitter_ms, 99)}), "ms", how));

  // Command to state: servo_jr on the left shoulder, until a setpoint_js shows it.
  std::vector<double> latency_ms;
  for (int k = 0; k < 100; ++k) {
    client.advance(0.02);
    raven::PerArm<std::vector<double>> before;
    {
      std::lock_guard<std::mutex> lock(listener.mutex);
      before = listener.setpoint;
    }
    raven::ArmJoints increment = raven::ArmJoints::Zero();
    increment[0] = k % 2 == 0 ? 0.002 : -0.002;
    const auto t0 = Clock::now();
    client.send(bridge::ServoJr{bridge::Arm::Left, increment});
    const auto deadline = t0 + std::chrono::milliseconds(200);
    while (Clock::now() < deadline) {
      {
        std::lock_guard<std::mutex> lock(listener.mutex);
        if (listener.setpoint_at > t0 && differs(listener.setpoint, before)) {
          latency_ms.push_back(1e3 * seconds(listener.setpoint_at - t0));
          break;
        }
      }
      std::this_thread::sleep_for(std::chrono::microseconds(50));
    }
  }
  const auto how_latency = fmt::format(
      "servo_jr published by RavenRosClient to the first setpoint_js showing it; {} of 100",
      latency_ms.size());
  for (double p : {50.0, 99.0, 100.0}) {
    report.add(measured(kSection,
                        p == 100.0 ? "command-to-state latency, max"
                                   : fmt::format("command-to-state latency, p{:.0f}", p),
                        Spread::of({percentile(latency_ms, p)}), "ms", how_latency));
  }
  spinner.stop();
  node.stop();
}

}  // namespace bench
