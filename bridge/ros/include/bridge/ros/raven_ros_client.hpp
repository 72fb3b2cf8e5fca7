#pragma once
// The RavenPlatform that drives a Raven-II over its ROS 1 topics: the physical robot, or this
// project's twin node (the same topics). Works unchanged against both. ROS stays behind this
// header (ROS 1's message headers need C++17; the rest of the project is C++20).

#include <memory>
#include <string>

#include "bridge/raven_platform.hpp"
#include "bridge/servo_limits.hpp"

namespace bridge::ros1 {

/// How the client reaches the robot.
struct RosClientOptions {
  /// The robot's namespace ("" for the real robot's defaults: /arm1, /ravenstate, ...).
  std::string robot_namespace;
  /// Off: the wall clock (a real robot, or a twin node running in real time). On: the twin
  /// node's simulated clock, advanced in lock-step (raven_twin/step); deterministic.
  bool lock_step = false;
  /// The robot publishes the green arm on arm1/measured_js and the gold arm on arm2 (upstream's
  /// swap); the client undoes it. Off for a robot (or twin node) without the swap.
  bool arm_swap = true;
  double connect_timeout = 10.0;  ///< wall s to find the robot's topics
  /// Wall s without measured_js (wall clock) or without a step's answer (lock-step) after which
  /// the robot counts as lost: the client reports FAULT and refuses commands.
  double robot_timeout = 0.5;
  ServoLimits limits;
  /// The robot's platform profile (its joint limits bound the client's planned moves).
  std::string profile = "physical";
};

/// A Raven-II reached over ROS. Measurements are taken in during advance(); commands are
/// checked (finite, within one command's jump window) and published at once; what the robot
/// refuses on its side the client cannot see. move_jp is planned here and streamed as servo_jp
/// (the robot has no move_jp topic).
class RavenRosClient final : public RavenPlatform {
 public:
  /// Needs initRos(). Waits for the robot's topics; throws std::runtime_error naming what is
  /// missing after connect_timeout.
  explicit RavenRosClient(RosClientOptions options = {});
  ~RavenRosClient() override;

  CommandResult send(const PlatformCommand& command) override;
  OperatingStatus operatingStatus() const override;
  JointSample measuredJs(Arm arm) const override;
  JointSample setpointJs(Arm arm) const override;
  PoseSample measuredCp(Arm arm) const override;
  PoseSample setpointCp(Arm arm) const override;
  std::optional<RavenStateSnapshot> ravenState() const override;
  /// The grasper's forces when the robot publishes them (the twin node's graspN/jaw_forces and
  /// measured_cf of the same cycle); none from a physical Raven-II.
  std::optional<GrasperForces> measuredCf(Arm arm) const override;
  ClockKind clockKind() const override;
  double now() const override;
  void advance(double seconds) override;

  /// Why the client gave the robot up ("" while it has not).
  const std::string& lostReason() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bridge::ros1
