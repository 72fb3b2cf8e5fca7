#pragma once
// What a grasper's jaws push on (measured_cf), as values: per jaw, the contact normal and friction
// forces on the objects they touch, and the sum as one wrench. No simulator needed to read them.

#include <Eigen/Core>
#include <array>

namespace bridge {

/// The forces one jaw put on the objects it touched in the last step (N, the twin's world
/// frame). The bodies of the jaw's own arm (the other jaw, the wrist) are not objects.
struct JawForces {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d friction = Eigen::Vector3d::Zero();
  int contacts = 0;
};

/// A grasper's measured_cf: both jaws' forces on what they hold, and their sum as a wrench
/// about the jaw axis point (force N, torque N m; the twin's world frame).
struct GrasperForces {
  double time = 0.0;
  std::array<JawForces, 2> jaws;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

}  // namespace bridge
