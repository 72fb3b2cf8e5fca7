#pragma once
// A straight joint-space move with a trapezoidal speed profile on which every joint starts and
// arrives together: what move_jp and homing follow.

#include "raven/arm.hpp"

namespace bridge {

/// q(t) = start + s(t) (goal - start), s rising 0 -> 1 as fast as every joint's speed and
/// acceleration limits allow.
class JointTrajectory {
 public:
  JointTrajectory(const raven::ArmJoints& start, const raven::ArmJoints& goal,
                  const raven::ArmJoints& max_velocity, const raven::ArmJoints& max_acceleration);

  /// The position `t` seconds after the start (the goal once t >= duration()).
  raven::ArmJoints at(double t) const;
  double duration() const { return duration_; }
  const raven::ArmJoints& goal() const { return goal_; }

 private:
  raven::ArmJoints start_, goal_;
  double s_velocity_ = 0.0;      ///< peak ds/dt
  double s_acceleration_ = 0.0;  ///< ds/dt^2
  double ramp_ = 0.0;            ///< time spent accelerating (and again decelerating)
  double duration_ = 0.0;
};

}  // namespace bridge
