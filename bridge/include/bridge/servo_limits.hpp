#pragma once
// The Raven-II's real-time command limits, per 1 ms cycle
// (../shared/reference/raven2-ros-interface.md and raven2-kinematics.md).

#include "raven/arm.hpp"
#include "raven/control_cycle.hpp"

namespace bridge {

/// How far and how fast the robot lets a command move a joint.
struct ServoLimits {
  double cycle = raven::kControlCycle;  ///< the robot's control period (s)
  /// What one cycle consumes of pending servo motion: 0.0025 rad, 0.00005 m (insertion).
  raven::ArmJoints per_cycle =
      (raven::ArmJoints() << 0.0025, 0.0025, 0.00005, 0.0025, 0.0025, 0.0025, 0.0025).finished();
  /// A servo command may leave at most this many cycles of motion pending; a bigger jump is
  /// refused (so a bad stream cannot queue up seconds of motion).
  int jump_cycles = 20;
  /// The share of servo_jr increments that reach the control loop: the robot subscribes with a
  /// queue of one message, so one that arrives before its ROS thread took the last is lost now
  /// and then. The twin applies this expected share of every increment (1: all arrive); a
  /// calibration measures it.
  double servo_jr_delivered = 1.0;
  /// The largest tool-point step a servo_cp may ask for (m).
  double cartesian_step = 0.015;
  /// move_jp and homing accelerate at A_MAX = 1 rad/s^2 (the insertion at the same fraction of
  /// its cycle clamp, 0.02 m/s^2) up to the cycle clamp's speed.
  raven::ArmJoints move_acceleration =
      (raven::ArmJoints() << 1.0, 1.0, 0.02, 1.0, 1.0, 1.0, 1.0).finished();

  raven::ArmJoints maxJump() const { return per_cycle * jump_cycles; }
  raven::ArmJoints moveVelocity() const { return per_cycle / cycle; }
};

}  // namespace bridge
