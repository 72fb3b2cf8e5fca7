#pragma once
// A joint in maximal coordinates: a Bullet constraint between two rigid bodies.

#include <memory>

#include "ambf_like/dynamics/joint_dynamics.hpp"
#include "ambf_like/joint_spec.hpp"

class btRigidBody;
class btTypedConstraint;
struct btJointFeedback;

namespace ambf_like::detail {

/// Reads a hinge or six-DoF constraint's coordinate and drives its motor, as AMBF does.
class ConstraintJoint final : public JointDynamics {
 public:
  /// `frame_in_parent` is the constraint frame in the parent's centre-of-mass frame.
  ConstraintJoint(const JointSpec& spec, std::unique_ptr<btTypedConstraint> constraint,
                  btRigidBody& parent, btRigidBody& child, const Transform& frame_in_parent);
  ~ConstraintJoint() override;

  double coordinate() const override;
  double velocity() const override;
  /// Of the two bodies alone (what else they are joined to only adds to it).
  double axisInertia() const override;
  double effort() const override;
  void actuate(const JointActuation& actuation, double dt) override;

  btTypedConstraint& constraint() { return *constraint_; }

 private:
  Vec3 axisInWorld() const;

  JointType type_;
  bool angular_;
  std::unique_ptr<btTypedConstraint> constraint_;
  std::unique_ptr<btJointFeedback> feedback_;
  btRigidBody& parent_;
  btRigidBody& child_;
  Transform frame_in_parent_;
  double applied_effort_ = 0.0;
};

}  // namespace ambf_like::detail
