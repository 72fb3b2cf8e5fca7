#pragma once
// How far a scripted move lets the robot's setpoint run ahead of an arm that contact holds back,
// so that pressing on something loads the arm with a bounded force instead of winding its
// amplifiers up to the robot's overdrive e-stop.

#include "raven/arm.hpp"

namespace controller {

/// Per joint (ArmJoints order) the bounds a scripted move keeps to; infinity: none.
struct FollowingLimit {
  /// The setpoint's lead over the measured joint (rad, m) past which the move stops advancing
  /// the joint's way (a proportional loop's torque grows with the lead alone).
  raven::ArmJoints lead;
  /// The control law's torque (raven_state's `tau`, N m at the gearbox) past which the
  /// setpoint is drawn back towards the measured joint: an integrator winds up under any lasting
  /// lead, so for a joint with one the torque itself is what must be bounded.
  raven::ArmJoints torque;
  /// How far to draw a setpoint back per N m of torque past that bound (rad or m per N m: the
  /// inverse of the position gain through the transmission, 1 / (KP x TR)).
  raven::ArmJoints give;
};

}  // namespace controller
