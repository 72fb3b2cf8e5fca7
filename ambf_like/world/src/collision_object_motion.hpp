#pragma once
// A collision object's motion as the broadphase, the contacts and island sleep read it, saved and
// put back (World::saveState).

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>

namespace ambf_like::detail {

/// What a btCollisionObject moves with, beyond a rigid body's velocities.
struct CollisionObjectMotion {
  btTransform pose, interpolation_pose;
  btVector3 interpolation_linear, interpolation_angular;
  int activation = 0;
  btScalar deactivation_time = 0, hit_fraction = 1;
};

inline CollisionObjectMotion motionOf(const btCollisionObject& o) {
  return {o.getWorldTransform(),
          o.getInterpolationWorldTransform(),
          o.getInterpolationLinearVelocity(),
          o.getInterpolationAngularVelocity(),
          o.getActivationState(),
          o.getDeactivationTime(),
          o.getHitFraction()};
}

/// Puts `m` back on `o`, its pose as a plain world transform (a rigid body's inertia tensor in
/// the world frame is the caller's).
inline void restoreMotion(btCollisionObject& o, const CollisionObjectMotion& m) {
  o.setWorldTransform(m.pose);
  o.setInterpolationWorldTransform(m.interpolation_pose);
  o.setInterpolationLinearVelocity(m.interpolation_linear);
  o.setInterpolationAngularVelocity(m.interpolation_angular);
  o.forceActivationState(m.activation);
  o.setDeactivationTime(m.deactivation_time);
  o.setHitFraction(m.hit_fraction);
}

}  // namespace ambf_like::detail
