#include "ambf_like/joint.hpp"

#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>
#include <BulletDynamics/ConstraintSolver/btHingeConstraint.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ambf_like/bullet_conversions.hpp"
#include "joint_frames.hpp"

namespace ambf_like {

namespace {

double wrapToPi(double angle) {
  return std::remainder(angle, 2.0 * M_PI);
}

bool isAngular(JointType type) {
  return type == JointType::Revolute || type == JointType::Continuous ||
         type == JointType::TorsionSpring;
}

const char* typeName(JointType type) {
  switch (type) {
    case JointType::Revolute:
      return "revolute";
    case JointType::Continuous:
      return "continuous";
    case JointType::Prismatic:
      return "prismatic";
    case JointType::Fixed:
      return "fixed";
    case JointType::P2P:
      return "p2p";
    case JointType::LinearSpring:
      return "linear spring";
    case JointType::TorsionSpring:
      return "torsion spring";
    case JointType::ConeTwist:
      return "cone twist";
    case JointType::SixDof:
      return "six dof";
    case JointType::SixDofSpring:
      return "six dof spring";
  }
  return "?";
}

}  // namespace

Joint::Joint(JointSpec spec, std::unique_ptr<btTypedConstraint> constraint, btRigidBody& parent,
             btRigidBody& child, const Transform& frame_in_parent)
    : spec_(std::move(spec)),
      constraint_(std::move(constraint)),
      feedback_(std::make_unique<btJointFeedback>()),
      parent_(parent),
      child_(child),
      frame_in_parent_(frame_in_parent),
      pid_(spec_.controller) {
  if (spec_.isSingleAxis()) {
    constraint_->setJointFeedback(feedback_.get());
    constraint_->enableFeedback(true);
  }
  last_raw_ = rawCoordinate();
  position_ = last_raw_;
}

Joint::~Joint() = default;

bool Joint::isControllable() const {
  const bool commandable_type = spec_.type == JointType::Revolute ||
                                spec_.type == JointType::Continuous ||
                                spec_.type == JointType::Prismatic;
  return commandable_type && !spec_.passive && spec_.enable_motor;
}

double Joint::rawCoordinate() const {
  switch (spec_.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      return static_cast<btHingeConstraint&>(*constraint_).getHingeAngle();
    case JointType::Prismatic:
    case JointType::LinearSpring:
    case JointType::TorsionSpring: {
      auto& six = static_cast<btGeneric6DofSpring2Constraint&>(*constraint_);
      six.calculateTransforms();
      if (spec_.type == JointType::Prismatic) return six.getRelativePivotPosition(0);
      // Bullet's angular coordinate is minus the right-hand rotation (see constraint_factory).
      return spec_.type == JointType::LinearSpring ? six.getRelativePivotPosition(2)
                                                   : -six.getAngle(2);
    }
    default:
      return 0.0;
  }
}

void Joint::updateCoordinate() {
  const double raw = rawCoordinate();
  if (isAngular(spec_.type)) {
    position_ += wrapToPi(raw - last_raw_);
  } else {
    position_ = raw;
  }
  last_raw_ = raw;
}

Vec3 Joint::axisInWorld() const {
  const int column = detail::constraintAxis(spec_.type).x() > 0.5 ? 0 : 2;
  return toEigen(parent_.getCenterOfMassTransform().getBasis()) *
         frame_in_parent_.linear().col(column);
}

double Joint::velocity() const {
  if (!spec_.isSingleAxis()) return 0.0;
  const Vec3 axis = axisInWorld();
  if (isAngular(spec_.type)) {
    return (toEigen(child_.getAngularVelocity()) - toEigen(parent_.getAngularVelocity())).dot(axis);
  }
  const Vec3 point = toEigen(parent_.getCenterOfMassTransform()) * frame_in_parent_.translation();
  auto pointVelocity = [&point](const btRigidBody& body) {
    const Vec3 r = point - toEigen(body.getCenterOfMassPosition());
    return Vec3(toEigen(body.getLinearVelocity()) + toEigen(body.getAngularVelocity()).cross(r));
  };
  return (pointVelocity(child_) - pointVelocity(parent_)).dot(axis);
}

double Joint::effort() const {
  if (!spec_.isSingleAxis()) return 0.0;
  const Vec3 axis = axisInWorld();
  const Vec3 force = toEigen(feedback_->m_appliedForceBodyB);
  if (!isAngular(spec_.type)) return actuator_effort_ + force.dot(axis);
  // Bullet reports the constraint's torque about the child's centre of mass; the pivot force's
  // moment is not the joint's doing, so take the torque about the pivot instead.
  const Vec3 pivot = toEigen(parent_.getCenterOfMassTransform()) * frame_in_parent_.translation();
  const Vec3 arm = pivot - toEigen(child_.getCenterOfMassPosition());
  const Vec3 torque = toEigen(feedback_->m_appliedTorqueBodyB) - arm.cross(force);
  return actuator_effort_ + torque.dot(axis);
}

void Joint::requireCommandable(const char* what, double value) const {
  if (!isControllable()) {
    throw std::invalid_argument(
        "joint '" + spec_.name + "' (" + typeName(spec_.type) + (spec_.passive ? ", passive" : "") +
        (spec_.enable_motor ? "" : ", motor disabled") + ") takes no commands");
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument("joint '" + spec_.name + "': " + what + " command " +
                                std::to_string(value) + " is not a finite number; ignored");
  }
}

void Joint::setDrive(JointDrive drive, double target) {
  if (drive != drive_) pid_.reset();
  drive_ = drive;
  target_ = target;
}

double Joint::commandPosition(double position) {
  requireCommandable("position", position);
  if (spec_.limits) position = std::clamp(position, spec_.limits->low, spec_.limits->high);
  setDrive(JointDrive::Position, position);
  return position;
}

void Joint::commandVelocity(double velocity) {
  requireCommandable("velocity", velocity);
  setDrive(JointDrive::Velocity, velocity);
}

void Joint::commandEffort(double effort) {
  requireCommandable("effort", effort);
  setDrive(JointDrive::Effort, effort);
}

void Joint::release() {
  setDrive(JointDrive::Free, 0.0);
}

void Joint::driveMotor(bool on, double velocity, double max_impulse, double dt) {
  if (spec_.max_velocity)
    velocity = std::clamp(velocity, -*spec_.max_velocity, *spec_.max_velocity);
  if (spec_.type == JointType::Prismatic) {
    auto& six = static_cast<btGeneric6DofSpring2Constraint&>(*constraint_);
    six.enableMotor(0, on);
    six.setTargetVelocity(0, -velocity);        // Bullet's motor runs opposite to its coordinate
    six.setMaxMotorForce(0, max_impulse / dt);  // bounds the impulse at force * dt
  } else if (spec_.type == JointType::Revolute || spec_.type == JointType::Continuous) {
    static_cast<btHingeConstraint&>(*constraint_).enableAngularMotor(on, velocity, max_impulse);
  }
}

void Joint::applyEffort(double effort) {
  actuator_effort_ = effort;
  if (effort == 0.0) return;
  const btVector3 generalized = toBt(axisInWorld() * effort);
  if (isAngular(spec_.type)) {
    parent_.applyTorque(-generalized);
    child_.applyTorque(generalized);
  } else {
    parent_.applyCentralForce(-generalized);
    child_.applyCentralForce(generalized);
  }
}

double Joint::drivenEffort(double dt) {
  switch (drive_) {
    case JointDrive::Free:
      driveMotor(false, 0.0, 0.0, dt);
      return 0.0;
    case JointDrive::Position: {
      const double error = target_ - position_;
      const double output = pid_.update(error, dt);
      switch (spec_.output) {
        case ControlOutput::Effort:
          driveMotor(false, 0.0, 0.0, dt);
          return output;
        case ControlOutput::Velocity:
          driveMotor(true, output, spec_.max_motor_impulse, dt);
          return 0.0;
        case ControlOutput::Position:
          // Close half the error each step (the deadbeat e/dt is only marginally stable in
          // Bullet's iterative solver: a slider then oscillates step to step), no faster than
          // `max velocity` (driveMotor caps it): without a cap a large jump asks for hundreds of
          // rad/s and the torque-limited joint overshoots wildly.
          driveMotor(true, error / (2.0 * dt), spec_.max_motor_impulse, dt);
          return 0.0;
      }
      return 0.0;
    }
    case JointDrive::Velocity:
      driveMotor(true, target_, spec_.max_motor_impulse, dt);
      return 0.0;
    case JointDrive::Effort:
      driveMotor(false, 0.0, 0.0, dt);
      return target_;
  }
  return 0.0;
}

void Joint::applyControl(double dt) {
  const bool springs_damp_themselves =
      spec_.type == JointType::LinearSpring || spec_.type == JointType::TorsionSpring;
  if (!spec_.isSingleAxis() || springs_damp_themselves) return;
  double effort = isControllable() ? drivenEffort(dt) : 0.0;
  if (spec_.damping > 0.0) effort -= spec_.damping * velocity();
  applyEffort(effort);
}

}  // namespace ambf_like
