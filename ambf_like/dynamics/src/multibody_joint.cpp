#include "ambf_like/dynamics/multibody_joint.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>

#include <limits>

#include "ambf_like/dynamics/joint_space_servo.hpp"
#include "ambf_like/dynamics/limit_row.hpp"

namespace ambf_like::detail {

namespace {

/// A MultiBodyJoint's memory.
struct LimitMemory final : JointDynamicsMemory {
  bool limit_engaged = false;
  double last_step = 0.0;
  double lower_impulse = 0.0, upper_impulse = 0.0;
};

}  // namespace

MultiBodyJoint::MultiBodyJoint(JointType type, JointSpaceServo& servo,
                               btMultiBodyDynamicsWorld& world, btMultiBody& multibody, int link,
                               double coordinate_at_load, btMultiBodyJointLimitConstraint* limit)
    : type_(type),
      servo_(servo),
      world_(world),
      multibody_(multibody),
      link_(link),
      dof_(multibody.getLink(link).m_dofOffset),
      coordinate_at_load_(coordinate_at_load),
      limit_(limit) {}

double MultiBodyJoint::coordinate() const {
  return hasCoordinate() ? coordinate_at_load_ + multibody_.getJointPos(link_) : 0.0;
}

double MultiBodyJoint::velocity() const {
  return hasCoordinate() ? multibody_.getJointVel(link_) : 0.0;
}

double MultiBodyJoint::axisInertia() const {
  const Eigen::MatrixXd& mobility = servo_.inverseInertia();
  const bool known = hasCoordinate() && dof_ < mobility.rows() && mobility(dof_, dof_) > 0.0;
  return known ? 1.0 / mobility(dof_, dof_) : std::numeric_limits<double>::infinity();
}

double MultiBodyJoint::effort() const {
  if (!hasCoordinate()) return 0.0;
  double limit_effort = 0.0;
  if (limit_ && last_step_ > 0.0) {
    // Row 0 pushes the coordinate up from its lower bound, row 1 down from its upper one.
    limit_effort = (limit_->getAppliedImpulse(0) - limit_->getAppliedImpulse(1)) / last_step_;
  }
  return servo_.appliedTorque(dof_) + limit_effort;
}

void MultiBodyJoint::actuate(const JointActuation& actuation, double dt) {
  if (!hasCoordinate()) return;
  servo_.request(dof_, actuation);
  if (limit_) watchLimit(dt);
  last_step_ = dt;
}

JointDynamics::ServoDof MultiBodyJoint::servoDof() const {
  if (!hasCoordinate()) return {};
  return {&servo_, dof_, &multibody_};
}

bool MultiBodyJoint::place(double coordinate, double velocity) {
  if (!hasCoordinate()) return false;
  multibody_.setJointPos(link_, coordinate - coordinate_at_load_);
  multibody_.setJointVel(link_, velocity);
  btAlignedObjectArray<btQuaternion> rotations;
  btAlignedObjectArray<btVector3> offsets;
  multibody_.updateCollisionObjectWorldTransforms(rotations, offsets);
  servo_.forgetPrediction();
  return true;
}

std::shared_ptr<const JointDynamicsMemory> MultiBodyJoint::memory() const {
  auto memory = std::make_shared<LimitMemory>();
  memory->limit_engaged = limit_engaged_;
  memory->last_step = last_step_;
  if (limit_) {
    memory->lower_impulse = limit_->getAppliedImpulse(0);
    memory->upper_impulse = limit_->getAppliedImpulse(1);
  }
  return memory;
}

void MultiBodyJoint::recall(const JointDynamicsMemory* memory) {
  const auto& saved = dynamic_cast<const LimitMemory&>(*memory);
  limit_engaged_ = saved.limit_engaged;
  last_step_ = saved.last_step;
  if (limit_) {
    limit_->internalSetAppliedImpulse(0, saved.lower_impulse);
    limit_->internalSetAppliedImpulse(1, saved.upper_impulse);
  }
}

void MultiBodyJoint::watchLimit(double dt) {
  // The solver writes a row's impulse only in steps it has the row (near the bound).
  limit_->internalSetAppliedImpulse(0, 0.0);
  limit_->internalSetAppliedImpulse(1, 0.0);
  const double q = multibody_.getJointPos(link_);
  const double v = velocity();
  const bool near = withinReach(q - limit_->getLowerBound(), v, dt, kLimitWatchBand) ||
                    withinReach(limit_->getUpperBound() - q, v, dt, kLimitWatchBand);
  if (near != limit_engaged_) {
    // Added near a bound, removed far from it (see kLimitWatchBand).
    if (near) {
      world_.addMultiBodyConstraint(limit_);
    } else {
      world_.removeMultiBodyConstraint(limit_);
    }
    limit_engaged_ = near;
  }
}

}  // namespace ambf_like::detail
