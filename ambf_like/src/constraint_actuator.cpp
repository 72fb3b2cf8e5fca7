#include "ambf_like/constraint_actuator.hpp"

#include <btBulletDynamicsCommon.h>

#include <stdexcept>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like {

ConstraintActuator::ConstraintActuator(ActuatorSpec spec, std::string qualified_name,
                                       RigidBody& parent, bool parent_in_world,
                                       btDiscreteDynamicsWorld& world)
    : spec_(std::move(spec)),
      qualified_name_(std::move(qualified_name)),
      parent_(parent),
      world_(world) {
  if (!parent_in_world) {
    throw std::invalid_argument("actuator '" + spec_.name + "': its parent '" + parent.name() +
                                "' is a link of an articulation (reduced coordinates); give its "
                                "model's world 'articulation: maximal' to attach bodies to it");
  }
}

ConstraintActuator::~ConstraintActuator() {
  release();
}

Vec3 ConstraintActuator::pointInWorld() const {
  return parent_.pose() * spec_.location.translation();
}

void ConstraintActuator::actuate(RigidBody& body, const Vec3& offset) {
  if (&body == &parent_) {
    throw std::invalid_argument("actuator '" + spec_.name + "' cannot attach its own parent");
  }
  if (body.isStatic()) {
    throw std::invalid_argument("actuator '" + spec_.name + "': '" + body.qualifiedName() +
                                "' is static; only a dynamic body can be attached");
  }
  release();
  const btVector3 point = toBt(body.pose() * offset);
  btRigidBody& a = parent_.bullet();
  btRigidBody& b = body.bullet();
  constraint_ = std::make_unique<btPoint2PointConstraint>(
      a, b, a.getCenterOfMassTransform().inverse() * point,
      b.getCenterOfMassTransform().inverse() * point);
  constraint_->m_setting.m_tau = static_cast<btScalar>(spec_.tau);
  constraint_->m_setting.m_impulseClamp = static_cast<btScalar>(spec_.max_impulse);
  world_.addConstraint(constraint_.get(), /*disableCollisionsBetweenLinkedBodies=*/true);
  held_ = &body;
}

void ConstraintActuator::release() {
  if (!constraint_) return;
  world_.removeConstraint(constraint_.get());
  constraint_.reset();
  held_ = nullptr;
}

std::string ConstraintActuator::heldBody() const {
  return held_ ? held_->qualifiedName() : std::string();
}

}  // namespace ambf_like
