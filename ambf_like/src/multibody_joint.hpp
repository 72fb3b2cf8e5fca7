#pragma once
// A joint in reduced coordinates: one degree of freedom of an articulation.

#include "ambf_like/joint_spec.hpp"
#include "joint_dynamics.hpp"

class btMultiBody;
class btMultiBodyJointLimitConstraint;

namespace ambf_like::detail {

class Articulation;

/// Reads a multibody link's joint coordinate; its motor and effort go to the articulation,
/// which turns all of its joints' requests into torques at once (see JointSpaceServo).
class MultiBodyJoint final : public JointDynamics {
 public:
  /// `limit` is the joint's limit constraint, or null.
  MultiBodyJoint(JointType type, Articulation& articulation, btMultiBody& multibody, int link,
                 double coordinate_at_load, btMultiBodyJointLimitConstraint* limit);

  double coordinate() const override;
  double velocity() const override;
  double effort() const override;
  void actuate(const JointActuation& actuation, double dt) override;

 private:
  bool hasCoordinate() const { return type_ != JointType::Fixed; }
  void watchLimit(double dt);

  JointType type_;
  Articulation& articulation_;
  btMultiBody& multibody_;
  int link_;
  int dof_;
  double coordinate_at_load_;
  btMultiBodyJointLimitConstraint* limit_;
  bool limit_engaged_ = false;
  double last_step_ = 0.0;  ///< 0 until the first step
};

}  // namespace ambf_like::detail
