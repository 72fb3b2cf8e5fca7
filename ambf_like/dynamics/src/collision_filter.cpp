#include "ambf_like/dynamics/collision_filter.hpp"

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletSoftBody/btSoftBody.h>

#include <algorithm>

namespace ambf_like::detail {

namespace {

const btCollisionObject* objectOf(const btBroadphaseProxy* proxy) {
  return static_cast<const btCollisionObject*>(proxy->m_clientObject);
}

const CollisionTag* tagOf(const btBroadphaseProxy* proxy) {
  const auto* object = objectOf(proxy);
  return object ? static_cast<const CollisionTag*>(object->getUserPointer()) : nullptr;
}

/// Whether `object` (tagged `tag`) may meet an object that is soft or not (`other_soft`).
bool meetsSoftness(const btCollisionObject* object, const CollisionTag& tag, bool other_soft) {
  if (tag.soft_proxy == nullptr) return true;
  const bool is_proxy = object == tag.soft_proxy;
  return is_proxy == other_soft;
}

/// Whether Bullet's collision handlers of a soft body with `modes` (btSoftBody::fCollision bits)
/// can make anything of a pair with `other`: against a rigid object they switch on the soft
/// body's rigid-soft modes, against another soft body on the soft-soft modes both have. A pair
/// that makes nothing still costs its narrow phase (a GImpact mesh walks its triangles for it).
bool softModesMeet(int modes, const btCollisionObject* other) {
  using Collision = btSoftBody::fCollision;
  if (const btSoftBody* soft = btSoftBody::upcast(other)) {
    return (modes & soft->m_cfg.collisions & Collision::SVSmask) != 0;
  }
  return (modes & (Collision::RVSmask | Collision::RVDFmask)) != 0;
}

/// Whether `a` is a soft body whose modes make nothing of a pair with `b`.
bool softPairIsVoid(const btCollisionObject* a, const btCollisionObject* b) {
  const btSoftBody* soft = btSoftBody::upcast(a);
  return soft != nullptr && !softModesMeet(soft->m_cfg.collisions, b);
}

bool shareGroup(const std::vector<int>& a, const std::vector<int>& b) {
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i == *j) return true;
    (*i < *j) ? ++i : ++j;
  }
  return false;
}

}  // namespace

bool CollisionFilter::needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const {
  // Bullet's own group/mask test (keeps static-static pairs out).
  if ((a->m_collisionFilterGroup & b->m_collisionFilterMask) == 0 ||
      (b->m_collisionFilterGroup & a->m_collisionFilterMask) == 0) {
    return false;
  }
  if (softPairIsVoid(objectOf(a), objectOf(b)) || softPairIsVoid(objectOf(b), objectOf(a))) {
    return false;
  }
  const CollisionTag* ta = tagOf(a);
  const CollisionTag* tb = tagOf(b);
  if (ta == nullptr || tb == nullptr) return true;
  if (!meetsSoftness(objectOf(a), *ta, tb->soft) || !meetsSoftness(objectOf(b), *tb, ta->soft)) {
    return false;
  }
  if (std::find(ta->jointed.begin(), ta->jointed.end(), tb) != ta->jointed.end() ||
      std::find(tb->jointed.begin(), tb->jointed.end(), ta) != tb->jointed.end()) {
    return false;
  }
  if (ta->model == tb->model && ta->model_ignores_inter_collision && !ta->soft && !tb->soft) {
    return false;
  }
  if (ta->groups.empty() || tb->groups.empty()) return true;
  return shareGroup(ta->groups, tb->groups);
}

}  // namespace ambf_like::detail
