#include "ambf_like/constraint_actuator.hpp"

#include <BulletSoftBody/btSoftBody.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
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
  if (body.bullet().getBroadphaseHandle() == nullptr) {
    throw std::invalid_argument("actuator '" + spec_.name + "': '" + body.qualifiedName() +
                                "' is a link of an articulation (reduced coordinates); give its "
                                "world 'articulation: maximal' to attach it");
  }
  // The attachment point is a point of the body: a far or non-finite one would fling it.
  constexpr double kFarthestOffset = 10.0;  // m
  if (!offset.allFinite() || offset.norm() > kFarthestOffset) {
    throw std::invalid_argument("actuator '" + spec_.name +
                                "': the offset must be finite and within 10 m of the body");
  }
  release();
  const btVector3 point = toBt(body.pose() * offset);
  btRigidBody& a = parent_.bullet();
  btRigidBody& b = body.bullet();
  b.activate(true);  // a resting free body may be asleep (RigidBodySleep)
  constraint_ = std::make_unique<btPoint2PointConstraint>(
      a, b, a.getCenterOfMassTransform().inverse() * point,
      b.getCenterOfMassTransform().inverse() * point);
  constraint_->m_setting.m_tau = static_cast<btScalar>(spec_.tau);
  constraint_->m_setting.m_impulseClamp = static_cast<btScalar>(spec_.max_impulse);
  world_.addConstraint(constraint_.get(), /*disableCollisionsBetweenLinkedBodies=*/true);
  held_ = &body;
}

void ConstraintActuator::actuate(SoftBody& body, const std::vector<int>& nodes) {
  btSoftBody& soft = body.bullet();
  for (int node : nodes) {
    if (node < 0 || node >= soft.m_nodes.size()) {
      throw std::invalid_argument("actuator '" + spec_.name + "': " + body.qualifiedName() +
                                  " has no node " + std::to_string(node));
    }
  }
  if (held_soft_ != &body) release();
  held_soft_ = &body;
  for (int node : nodes) {
    if (std::find(anchored_.begin(), anchored_.end(), node) != anchored_.end()) continue;
    soft.appendAnchor(node, &parent_.bullet(), /*disableCollisionBetweenLinkedBodies=*/false, 1.0);
    anchored_.push_back(node);
  }
}

void ConstraintActuator::release() {
  if (constraint_) {
    world_.removeConstraint(constraint_.get());
    constraint_.reset();
    held_ = nullptr;
  }
  if (held_soft_) {
    // btSoftBody::removeAnchor only knows the deformable world's anchors: drop ours by hand.
    btSoftBody& soft = held_soft_->bullet();
    for (int i = soft.m_anchors.size() - 1; i >= 0; --i) {
      btSoftBody::Anchor& anchor = soft.m_anchors[i];
      if (anchor.m_body != &parent_.bullet()) continue;
      anchor.m_node->m_battach = 0;
      soft.m_anchors.removeAtIndex(i);
    }
    held_soft_ = nullptr;
    anchored_.clear();
  }
}

ConstraintActuator::Hold ConstraintActuator::hold() const {
  Hold out{held_, held_soft_, anchored_};
  if (constraint_) {
    out.pivot_in_parent = toEigen(constraint_->getPivotInA());
    out.pivot_in_body = toEigen(constraint_->getPivotInB());
  }
  return out;
}

bool ConstraintActuator::Hold::sameAs(const Hold& other) const {
  return rigid == other.rigid && soft == other.soft && nodes == other.nodes &&
         pivot_in_parent == other.pivot_in_parent && pivot_in_body == other.pivot_in_body;
}

std::string ConstraintActuator::heldBody() const {
  if (held_soft_) return held_soft_->qualifiedName();
  return held_ ? held_->qualifiedName() : std::string();
}

}  // namespace ambf_like
