#include "ambf_like/rigid_body.hpp"

#include <BulletDynamics/Dynamics/btRigidBody.h>

#include <cmath>

#include "ambf_like/bullet_conversions.hpp"

namespace ambf_like {

RigidBody::RigidBody(BodySpec spec, std::string qualified_name, std::unique_ptr<btRigidBody> body,
                     const Transform& com_in_body, std::size_t collision_vertices)
    : spec_(std::move(spec)),
      qualified_name_(std::move(qualified_name)),
      body_(std::move(body)),
      body_in_com_(com_in_body.inverse()),
      collision_vertices_(collision_vertices) {}

RigidBody::~RigidBody() = default;

Transform RigidBody::centerOfMassPose() const {
  return toEigen(body_->getCenterOfMassTransform());
}

Transform RigidBody::pose() const {
  return centerOfMassPose() * body_in_com_;
}

Vec3 RigidBody::linearVelocity() const {
  return toEigen(body_->getLinearVelocity());
}

Vec3 RigidBody::angularVelocity() const {
  return toEigen(body_->getAngularVelocity());
}

bool RigidBody::isFinite() const {
  // On Bullet's own values: the twin asks this of every body every cycle.
  const btTransform& pose = body_->getCenterOfMassTransform();
  const btMatrix3x3& basis = pose.getBasis();
  const btVector3 sum = pose.getOrigin() + basis[0] + basis[1] + basis[2] +
                        body_->getLinearVelocity() + body_->getAngularVelocity();
  return std::isfinite(sum.x()) && std::isfinite(sum.y()) && std::isfinite(sum.z());
}

bool RigidBody::isAsleep() const {
  // Bullet keeps static bodies in the sleeping state too; they are never stepped at all.
  return !isStatic() && body_->getActivationState() == ISLAND_SLEEPING;
}

}  // namespace ambf_like
