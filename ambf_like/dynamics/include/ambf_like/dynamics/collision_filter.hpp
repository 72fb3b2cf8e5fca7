#pragma once
// Broadphase filter implementing AMBF's collision groups and per-model `ignore inter-collision`.

#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>

#include <string>
#include <vector>

class btCollisionObject;

namespace ambf_like::detail {

/// What the filter knows about one collision object (set as its user pointer).
struct CollisionTag {
  std::string name;
  int model = 0;
  bool model_ignores_inter_collision = false;
  bool soft = false;
  std::vector<int> groups;  ///< sorted; empty collides with every group
  /// The object soft bodies meet instead of this body (a plane's box, see buildBodyShape); it
  /// shares this tag, so contacts with either read as the body's.
  const btCollisionObject* soft_proxy = nullptr;
  /// Bodies a joint keeps it from colliding with where Bullet does not: an articulation's
  /// static root, for the links jointed to it.
  std::vector<const CollisionTag*> jointed;
};

/// Two objects collide unless both are rigid bodies of a model that ignores inter-collision,
/// or both have groups and share none, or one is a soft body whose collision modes make nothing
/// of the other (no rigid-soft mode against a rigid object, no soft-soft mode in common with a
/// soft one); a body with a soft proxy meets soft bodies only through it, and the proxy
/// meets nothing else. Pairs joined by a joint are excluded by Bullet itself (constraints and
/// multibody links), and by the tags' `jointed` where it cannot (a link and its static root).
class CollisionFilter : public btOverlapFilterCallback {
 public:
  bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override;
};

}  // namespace ambf_like::detail
