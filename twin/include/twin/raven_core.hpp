#pragma once
// The Raven-II's real-time command layer, as the robot runs it every 1 ms: the operating state,
// servo goals consumed within the per-cycle clamps, planned moves and homing, joint limits. Every
// twin backend runs this same core, so the in-process twin and the twin over ROS answer the
// same commands identically.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "bridge/command_result.hpp"
#include "bridge/joint_trajectory.hpp"
#include "bridge/operating_state.hpp"
#include "bridge/platform_command.hpp"
#include "bridge/servo_limits.hpp"
#include "bridge/throttled_log.hpp"
#include "raven/arm_kinematics.hpp"
#include "raven/platform_profile.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

using raven::ArmPair;

/// Commands in, one joint setpoint per arm and cycle out.
class RavenCore {
 public:
  /// Starts DISABLED and unhomed, holding `measured`.
  RavenCore(raven::PlatformProfile profile, ServoLimits limits, const ArmPair& measured);

  /// Takes or refuses a command (refusals are logged). Motion needs ENABLED and homed.
  CommandResult apply(const PlatformCommand& command);
  /// One cycle: `measured` are the joints read at its start; every arm's setpoint moves toward
  /// its goal by at most the per-cycle clamp, or along its planned move.
  void cycle(const ArmPair& measured);
  /// Enters FAULT and holds.
  void fault(const std::string& why);

  const OperatingStatus& status() const { return machine_.status(); }
  std::uint64_t cycles() const { return cycles_; }
  double time() const { return static_cast<double>(cycles_) * limits_.cycle; }
  /// How many motion commands were taken (raven_state's last_seq).
  std::uint64_t commandsTaken() const { return commands_taken_; }

  const ArmJoints& setpoint(Arm arm) const { return arms_[slot(arm)].setpoint; }
  ArmJoints setpointVelocity(Arm arm) const;
  /// Where the arm is heading: the end of its move, or its pending servo goal.
  const ArmJoints& goal(Arm arm) const { return arms_[slot(arm)].goal; }
  /// The tool pose of `q` in the platform's reporting frame.
  Eigen::Isometry3d reportedPose(Arm arm, const ArmJoints& q) const;

  const raven::PlatformProfile& profile() const { return profile_; }
  const ServoLimits& limits() const { return limits_; }

 private:
  /// One arm's motion state.
  struct ArmMotion {
    ArmJoints setpoint, previous, goal;
    std::optional<JointTrajectory> move;
    double move_start = 0.0;
  };

  CommandResult applyState(StateCommand command);
  /// Joint commands must stay within the jump window; Cartesian ones are bounded by their
  /// tool step instead (`check_jump` false).
  CommandResult servoTo(Arm arm, const ArmJoints& goal, bool check_jump = true);
  CommandResult servoToPose(Arm arm, const Eigen::Isometry3d& pose);
  CommandResult moveTo(Arm arm, const ArmJoints& goal);
  /// Why motion commands are refused now, if they are.
  std::optional<std::string> motionRefusal() const;
  /// What a servo command builds on: the pending goal, or where a pre-empted move is now.
  ArmJoints servoBase(Arm arm) const;
  /// Saturates `q` to the limits; describes what it changed ("" if nothing).
  std::string clampToLimits(ArmJoints& q) const;
  void startMove(Arm arm, const ArmJoints& goal);
  void holdAll();
  CommandResult logged(const PlatformCommand& command, CommandResult result);

  raven::PlatformProfile profile_;
  ServoLimits limits_;
  raven::PerArm<raven::ArmKinematics> reporting_;
  OperatingStateMachine machine_;
  raven::PerArm<ArmMotion> arms_;
  ArmPair measured_;
  std::uint64_t cycles_ = 0;
  std::uint64_t commands_taken_ = 0;
  ThrottledLog log_;
};

}  // namespace twin
