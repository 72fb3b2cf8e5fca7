#pragma once
// The one interface every Raven-II backend implements (the in-process twin, the physical robot
// over ROS, the twin over ROS): CRTK-shaped commands and queries, and the platform's clock.

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "bridge/command_result.hpp"
#include "bridge/grasper_forces.hpp"
#include "bridge/operating_state.hpp"
#include "bridge/platform_command.hpp"
#include "bridge/raven_state.hpp"

namespace bridge {

/// Which clock a platform runs on: the wall clock (real time: a live gamepad, the real robot)
/// or a simulated clock that only moves when advance() is called (deterministic, as fast as the
/// CPU allows).
enum class ClockKind { Wall, Simulated };

/// One arm's joints at one time (measured_js / setpoint_js), SI units.
struct JointSample {
  double time = 0.0;
  ArmJoints position = ArmJoints::Zero();
  ArmJoints velocity = ArmJoints::Zero();
  ArmJoints effort = ArmJoints::Zero();
};

/// One arm's tool pose at one time (measured_cp / setpoint_cp) in the platform's reporting
/// frame (the physical robot's: each arm's base frame, metres).
struct PoseSample {
  double time = 0.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

/// A Raven-II: two arms, one operating state, one clock.
class RavenPlatform {
 public:
  virtual ~RavenPlatform() = default;

  /// Takes or refuses one command; a refused command moves nothing and says why.
  virtual CommandResult send(const PlatformCommand& command) = 0;
  virtual OperatingStatus operatingStatus() const = 0;

  virtual JointSample measuredJs(Arm arm) const = 0;
  virtual JointSample setpointJs(Arm arm) const = 0;
  virtual PoseSample measuredCp(Arm arm) const = 0;
  virtual PoseSample setpointCp(Arm arm) const = 0;
  /// measured_cf: what the grasper's jaws push on, when the platform can tell (the physical
  /// Raven-II has no force sensing: none).
  virtual std::optional<GrasperForces> measuredCf(Arm /*arm*/) const { return std::nullopt; }
  /// The latest raven_state sample, when the platform has one.
  virtual std::optional<RavenStateSnapshot> ravenState() const = 0;

  virtual ClockKind clockKind() const = 0;
  /// The platform's time (s).
  virtual double now() const = 0;
  /// Lets `seconds` of platform time pass. Simulated clock: runs that many 1 ms robot cycles
  /// now (fractions carry over). Wall clock: returns when the wall clock reaches the previous
  /// deadline plus `seconds` (no drift), at once if that has passed.
  virtual void advance(double seconds) = 0;
};

}  // namespace bridge
