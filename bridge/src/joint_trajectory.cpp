#include "bridge/joint_trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bridge {

JointTrajectory::JointTrajectory(const raven::ArmJoints& start, const raven::ArmJoints& goal,
                                 const raven::ArmJoints& max_velocity,
                                 const raven::ArmJoints& max_acceleration)
    : start_(start), goal_(goal) {
  const raven::ArmJoints distance = (goal - start).cwiseAbs();
  if (distance.maxCoeff() == 0.0) return;
  // The joint with the least room per unit of s sets the path's speed and acceleration.
  s_velocity_ = std::numeric_limits<double>::infinity();
  s_acceleration_ = std::numeric_limits<double>::infinity();
  for (int i = 0; i < raven::kJointCount; ++i) {
    if (distance(i) == 0.0) continue;
    s_velocity_ = std::min(s_velocity_, max_velocity(i) / distance(i));
    s_acceleration_ = std::min(s_acceleration_, max_acceleration(i) / distance(i));
  }
  ramp_ = s_velocity_ / s_acceleration_;
  if (ramp_ * s_velocity_ >= 1.0) {  // never reaches full speed: a triangular profile
    ramp_ = std::sqrt(1.0 / s_acceleration_);
    s_velocity_ = s_acceleration_ * ramp_;
    duration_ = 2.0 * ramp_;
  } else {
    duration_ = 2.0 * ramp_ + (1.0 - ramp_ * s_velocity_) / s_velocity_;
  }
}

raven::ArmJoints JointTrajectory::at(double t) const {
  if (t >= duration_) return goal_;
  if (t <= 0.0) return start_;
  double s;
  if (t < ramp_) {
    s = 0.5 * s_acceleration_ * t * t;
  } else if (t <= duration_ - ramp_) {
    s = 0.5 * s_velocity_ * ramp_ + s_velocity_ * (t - ramp_);
  } else {
    const double left = duration_ - t;
    s = 1.0 - 0.5 * s_acceleration_ * left * left;
  }
  return start_ + s * (goal_ - start_);
}

}  // namespace bridge
