#pragma once
// Serves any RavenPlatform on the physical Raven-II's ROS topics (what the twin node runs): the
// CRTK command and state topics of /arm1, /arm2, grasp1, grasp2, `ravenstate` every cycle, and
// `raven_automove`; optionally in lock-step with a client on the simulated clock.

#include <functional>
#include <memory>
#include <string>

#include "bridge/raven_platform.hpp"

namespace bridge::ros1 {

/// How the server runs.
struct RosServerOptions {
  /// Off: one 1 ms cycle per loop on the platform's (wall) clock, commands applied as they
  /// arrive. On: cycles run only when a client's raven_twin/step asks, with the commands it
  /// names applied first, in its order (deterministic over ROS).
  bool lock_step = false;
  /// Reproduce upstream's swap: the green arm's joints on arm1/measured_js, the gold arm's on
  /// arm2/measured_js.
  bool arm_swap = true;
  /// Lock-step: how long (wall seconds) a step waits for the commands it names. ROS delivers
  /// each topic in order but not the topics among themselves, so a command sent just before its
  /// step may arrive just after it; one that has not come within this wait never will, and the
  /// step is refused (answered with the reason) instead of holding every later step.
  double command_wait = 1.0;
  /// Called after every 1 ms cycle, on the serving thread (the twin node serves its world's
  /// sensors and actuators from here).
  std::function<void()> after_cycle;
};

/// The robot's side of the ROS interface, over a platform. Refused commands are logged and
/// their reasons published on raven_twin/refusals.
class RavenRosServer {
 public:
  /// Advertises and subscribes under `ros_namespace` ("" for the robot's own names). Needs
  /// initRos().
  RavenRosServer(RavenPlatform& platform, const std::string& ros_namespace,
                 RosServerOptions options);
  ~RavenRosServer();

  /// Serves until ROS shuts down or `stop_after` seconds of platform time have run (0: no end).
  void spin(double stop_after = 0.0);
  /// One turn of the loop: wall mode runs one cycle; lock-step mode waits up to `wait` (wall
  /// seconds) for traffic and runs whatever steps are complete.
  void spinOnce(double wait = 0.01);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bridge::ros1
