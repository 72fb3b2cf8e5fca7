#pragma once
// Serves any RavenPlatform on the physical Raven-II's ROS topics (what the twin node runs): the
// CRTK command and state topics of /arm1, /arm2, grasp1, grasp2, `ravenstate` every cycle, and
// `raven_automove`; beside them, optionally, standard CRTK under a namespace of its own; and
// optionally in lock-step with a client on the simulated clock.

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "bridge/raven_platform.hpp"
#include "raven/platform_profile.hpp"

namespace bridge::ros1 {

/// The standard CRTK face: what a standard CRTK client (crtk_python_client, dVRK-style scripts)
/// expects, per arm under `<ros_namespace>/<arm name>/`: crtk_msgs/OperatingState published on
/// change and latched, PoseStamped poses, move_jp and move_cp with the busy flag, the jaw under
/// `jaw/`, query_cp / query_jp; no arm swap.
struct CrtkFaceOptions {
  std::string ros_namespace = "crtk";
  /// Left (gold) arm's name first: a dVRK user may call them "PSM1", "PSM2".
  raven::PerArm<std::string> arm_names{"arm1", "arm2"};
  /// The served platform's profile: its reporting chain for query_cp / query_jp and move_cp,
  /// its joint limits for telling when a move has arrived.
  raven::PlatformProfile profile;
};

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
  /// Serve standard CRTK too (none: the robot's own dialect only).
  std::optional<CrtkFaceOptions> crtk;
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
