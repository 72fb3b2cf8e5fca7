#include "soft_body_sleep.hpp"

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletSoftBody/btSoftBody.h>

#include <algorithm>
#include <cmath>

namespace ambf_like::detail {

namespace {

Box boundsOf(const SoftBody& soft) {
  return {soft.bullet().m_bounds[0], soft.bullet().m_bounds[1]};
}

/// The speed of the body's fastest point inside its bounding box, bounded from above.
double fastestPointSpeed(const btRigidBody& body, const Box& box) {
  const double reach = 0.5 * (box.max - box.min).length();
  return body.getLinearVelocity().length() + body.getAngularVelocity().length() * reach;
}

/// Reports whether any contact point of a pair test lies within the query distance.
struct AnyPoint : btCollisionWorld::ContactResultCallback {
  bool found = false;
  btScalar addSingleResult(btManifoldPoint&, const btCollisionObjectWrapper*, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    found = true;
    return 0;
  }
};

/// True when the object can move at the next step: an awake dynamic rigid body, or a link of an
/// articulation other than its fixed base (a joint's command can come at any step).
bool canMove(const btCollisionObject& object) {
  if (const auto* link = btMultiBodyLinkCollider::upcast(&object)) {
    return link->m_link >= 0 || !link->m_multiBody->hasFixedBase();
  }
  const auto* rigid = btRigidBody::upcast(&object);
  return rigid != nullptr && rigid->getInvMass() > 0.0 && rigid->isActive();
}

/// True when the soft body touches something that can move: what holds it (a jaw) may let it go
/// or push it at any step, however slowly, so it must not sleep (Bullet's islands: a body sleeps
/// only with everything it touches).
bool touchesAMovableBody(const btSoftBody& body) {
  for (int c = 0; c < body.m_rcontacts.size(); ++c) {
    if (canMove(*body.m_rcontacts[c].m_cti.m_colObj)) return true;
  }
  return false;
}

void wake(SoftBody& soft) {
  soft.bullet().forceActivationState(ACTIVE_TAG);
}

}  // namespace

bool Box::overlaps(const Box& other, double gap) const {
  for (int k = 0; k < 3; ++k) {
    if (min[k] > other.max[k] + gap || other.min[k] > max[k] + gap) return false;
  }
  return true;
}

bool SoftBodySleeper::comesWithinWakeDistance(btCollisionObject& mover, const Box& bounds) const {
  btBoxShape shape((bounds.max - bounds.min) * 0.5);
  btCollisionObject probe;
  probe.setCollisionShape(&shape);
  probe.setWorldTransform(btTransform(btMatrix3x3::getIdentity(), (bounds.max + bounds.min) * 0.5));
  AnyPoint hit;
  hit.m_closestDistanceThreshold = settings_.wake_distance;
  world_.contactPairTest(&mover, &probe, hit);
  return hit.found;
}

bool SoftBodySleeper::approached(const SoftBody& sleeper,
                                 const std::vector<std::unique_ptr<SoftBody>>& soft,
                                 const std::vector<std::unique_ptr<RigidBody>>& rigid) const {
  const Box own = boundsOf(sleeper);
  for (const auto& body : rigid) {
    const btRigidBody& b = body->bullet();
    if (body->isStatic() || b.getCollisionShape()->getShapeType() == EMPTY_SHAPE_PROXYTYPE)
      continue;
    Box box;
    b.getAabb(box.min, box.max);
    if (own.overlaps(box, settings_.wake_distance) &&
        fastestPointSpeed(b, box) >= settings_.distance / settings_.time &&
        comesWithinWakeDistance(body->bullet(), own)) {
      return true;
    }
  }
  for (std::size_t i = 0; i < soft.size(); ++i) {
    if (soft[i].get() == &sleeper || soft[i]->isAsleep()) continue;
    if (!rest_[i].resting(settings_) && own.overlaps(boundsOf(*soft[i]), settings_.wake_distance)) {
      return true;
    }
  }
  return false;
}

void SoftBodySleeper::beforeStep(const std::vector<std::unique_ptr<SoftBody>>& soft,
                                 const std::vector<std::unique_ptr<RigidBody>>& rigid) {
  for (std::size_t i = 0; i < soft.size(); ++i) {
    SoftBody& body = *soft[i];
    if (!body.isAsleep()) continue;
    btSoftBody& b = body.bullet();
    b.m_rcontacts.resizeNoInitialize(std::min(b.m_rcontacts.size(), rest_[i].rigid_contacts));
    b.m_scontacts.resizeNoInitialize(std::min(b.m_scontacts.size(), rest_[i].soft_contacts));
    if (b.m_anchors.size() > 0 || approached(body, soft, rigid)) {
      wake(body);
      rest_[i].rested = 0.0;
    }
  }
}

void SoftBodySleeper::afterStep(const std::vector<std::unique_ptr<SoftBody>>& soft, double h) {
  const double reach2 = settings_.distance * settings_.distance;
  for (std::size_t i = 0; i < soft.size(); ++i) {
    if (soft[i]->isAsleep()) continue;
    btSoftBody& b = soft[i]->bullet();
    Rest& rest = rest_[i];
    bool stayed = rest.start.size() == static_cast<std::size_t>(b.m_nodes.size());
    for (int n = 0; stayed && n < b.m_nodes.size(); ++n) {
      stayed = (b.m_nodes[n].m_x - rest.start[static_cast<std::size_t>(n)]).length2() <= reach2;
    }
    if (!stayed) {
      rest.start.resize(static_cast<std::size_t>(b.m_nodes.size()));
      for (int n = 0; n < b.m_nodes.size(); ++n)
        rest.start[static_cast<std::size_t>(n)] = b.m_nodes[n].m_x;
      rest.rested = 0.0;
      continue;
    }
    rest.rested += h;
    // Not ISLAND_SLEEPING: Bullet's island manager wakes that whenever a dynamic body's bounds
    // overlap (a resting arm link's box spans the board), and then solves it unpredicted.
    if (rest.resting(settings_) && b.m_anchors.size() == 0 && !touchesAMovableBody(b)) {
      b.forceActivationState(DISABLE_SIMULATION);
      rest.rigid_contacts = b.m_rcontacts.size();
      rest.soft_contacts = b.m_scontacts.size();
    }
  }
}

}  // namespace ambf_like::detail
