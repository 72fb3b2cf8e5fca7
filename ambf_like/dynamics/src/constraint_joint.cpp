#include "ambf_like/dynamics/constraint_joint.hpp"

#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>
#include <BulletDynamics/ConstraintSolver/btHingeConstraint.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <limits>

#include "ambf_like/bullet_conversions.hpp"
#include "ambf_like/dynamics/joint_frames.hpp"

namespace ambf_like::detail {

ConstraintJoint::ConstraintJoint(const JointSpec& spec,
                                 std::unique_ptr<btTypedConstraint> constraint, btRigidBody& parent,
                                 btRigidBody& child, const Transform& frame_in_parent)
    : type_(spec.type),
      angular_(spec.isAngular()),
      constraint_(std::move(constraint)),
      feedback_(std::make_unique<btJointFeedback>()),
      parent_(parent),
      child_(child),
      frame_in_parent_(frame_in_parent) {
  if (spec.isSingleAxis()) {
    constraint_->setJointFeedback(feedback_.get());
    constraint_->enableFeedback(true);
  }
}

ConstraintJoint::~ConstraintJoint() = default;

double ConstraintJoint::coordinate() const {
  switch (type_) {
    case JointType::Revolute:
    case JointType::Continuous:
      return static_cast<btHingeConstraint&>(*constraint_).getHingeAngle();
    case JointType::Prismatic:
    case JointType::LinearSpring:
    case JointType::TorsionSpring: {
      auto& six = static_cast<btGeneric6DofSpring2Constraint&>(*constraint_);
      six.calculateTransforms();
      if (type_ == JointType::Prismatic) return six.getRelativePivotPosition(0);
      // Bullet's angular coordinate is minus the right-hand rotation (see constraint_factory).
      return type_ == JointType::LinearSpring ? six.getRelativePivotPosition(2) : -six.getAngle(2);
    }
    default:
      return 0.0;
  }
}

Vec3 ConstraintJoint::axisInWorld() const {
  const int column = constraintAxis(type_).x() > 0.5 ? 0 : 2;
  return toEigen(parent_.getCenterOfMassTransform().getBasis()) *
         frame_in_parent_.linear().col(column);
}

double ConstraintJoint::velocity() const {
  const Vec3 axis = axisInWorld();
  if (angular_) {
    return (toEigen(child_.getAngularVelocity()) - toEigen(parent_.getAngularVelocity())).dot(axis);
  }
  const Vec3 point = toEigen(parent_.getCenterOfMassTransform()) * frame_in_parent_.translation();
  auto pointVelocity = [&point](const btRigidBody& body) {
    const Vec3 r = point - toEigen(body.getCenterOfMassPosition());
    return Vec3(toEigen(body.getLinearVelocity()) + toEigen(body.getAngularVelocity()).cross(r));
  };
  return (pointVelocity(child_) - pointVelocity(parent_)).dot(axis);
}

double ConstraintJoint::axisInertia() const {
  const Vec3 axis = axisInWorld();
  const double mobility = angular_ ? axis.dot((toEigen(parent_.getInvInertiaTensorWorld()) +
                                               toEigen(child_.getInvInertiaTensorWorld())) *
                                              axis)
                                   : parent_.getInvMass() + child_.getInvMass();
  return mobility > 0.0 ? 1.0 / mobility : std::numeric_limits<double>::infinity();
}

double ConstraintJoint::effort() const {
  const Vec3 axis = axisInWorld();
  const Vec3 force = toEigen(feedback_->m_appliedForceBodyB);
  if (!angular_) return applied_effort_ + force.dot(axis);
  // Bullet reports the constraint's torque about the child's centre of mass; the pivot force's
  // moment is not the joint's doing, so take the torque about the pivot instead.
  const Vec3 pivot = toEigen(parent_.getCenterOfMassTransform()) * frame_in_parent_.translation();
  const Vec3 arm = pivot - toEigen(child_.getCenterOfMassPosition());
  const Vec3 torque = toEigen(feedback_->m_appliedTorqueBodyB) - arm.cross(force);
  return applied_effort_ + torque.dot(axis);
}

void ConstraintJoint::actuate(const JointActuation& actuation, double dt) {
  if (type_ == JointType::Prismatic) {
    auto& six = static_cast<btGeneric6DofSpring2Constraint&>(*constraint_);
    six.enableMotor(0, actuation.motor_on);
    six.setTargetVelocity(0, -actuation.motor_velocity);  // Bullet's motor runs opposite to its
                                                          // coordinate
    six.setMaxMotorForce(0, actuation.motor_max_impulse / dt);  // bounds the impulse at force*dt
  } else if (type_ == JointType::Revolute || type_ == JointType::Continuous) {
    static_cast<btHingeConstraint&>(*constraint_)
        .enableAngularMotor(actuation.motor_on, actuation.motor_velocity,
                            actuation.motor_max_impulse);
  }
  applied_effort_ = actuation.effort;
  if (actuation.effort == 0.0) return;
  const btVector3 generalized = toBt(axisInWorld() * actuation.effort);
  if (angular_) {
    parent_.applyTorque(-generalized);
    child_.applyTorque(generalized);
  } else {
    parent_.applyCentralForce(-generalized);
    child_.applyCentralForce(generalized);
  }
}

}  // namespace ambf_like::detail
