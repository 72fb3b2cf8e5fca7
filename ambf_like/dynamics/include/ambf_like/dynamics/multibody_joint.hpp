#pragma once
// A joint in reduced coordinates: one degree of freedom of an articulation.

#include "ambf_like/dynamics/joint_dynamics.hpp"
#include "ambf_like/joint_spec.hpp"

class btMultiBody;
class btMultiBodyDynamicsWorld;
class btMultiBodyJointLimitConstraint;

namespace ambf_like::detail {

class JointSpaceServo;

/// Reads a multibody link's joint coordinate; its motor and effort go to the articulation's
/// servo, which turns all of its joints' requests into torques at once (see JointSpaceServo).
class MultiBodyJoint final : public JointDynamics {
 public:
  /// `limit` is the joint's limit constraint, or null; the joint puts it into `world` only near
  /// a bound.
  MultiBodyJoint(JointType type, JointSpaceServo& servo, btMultiBodyDynamicsWorld& world,
                 btMultiBody& multibody, int link, double coordinate_at_load,
                 btMultiBodyJointLimitConstraint* limit);

  double coordinate() const override;
  double velocity() const override;
  /// From the articulation's joint-space inverse inertia: the links with every other joint free.
  double axisInertia() const override;
  double effort() const override;
  void actuate(const JointActuation& actuation, double dt) override;
  ServoDof servoDof() const override;
  /// Sets the coordinate and its speed; the links' colliders move with it at once, their
  /// bodies (mirrors) after the next step.
  bool place(double coordinate, double velocity) override;
  /// Whether its limit is in the world, and the limit's last impulses; World::restoreState puts
  /// the limits back into the world in their saved order.
  std::shared_ptr<const JointDynamicsMemory> memory() const override;
  void recall(const JointDynamicsMemory* memory) override;

 private:
  bool hasCoordinate() const { return type_ != JointType::Fixed; }
  void watchLimit(double dt);

  JointType type_;
  JointSpaceServo& servo_;
  btMultiBodyDynamicsWorld& world_;
  btMultiBody& multibody_;
  int link_;
  int dof_;
  double coordinate_at_load_;
  btMultiBodyJointLimitConstraint* limit_;
  bool limit_engaged_ = false;
  double last_step_ = 0.0;  ///< 0 until the first step
};

}  // namespace ambf_like::detail
