#pragma once
// Bullet's soft-rigid world, doing continuous collision work only when a body asks for it.

#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>

namespace ambf_like::detail {

/// btSoftRigidDynamicsWorld that sweeps AABBs and creates predictive contacts only while some
/// body has a CCD motion threshold. Bullet otherwise predicts every moving body's next pose and
/// widens its AABB to cover it each step; no body this library builds sets a threshold (at 1 ms
/// a body at 1 m/s moves 1 mm, inside the contact margins), and that work was 6 % of a Raven-II
/// step.
class DynamicsWorld final : public btSoftRigidDynamicsWorld {
 public:
  using btSoftRigidDynamicsWorld::btSoftRigidDynamicsWorld;

 protected:
  void createPredictiveContacts(btScalar time_step) override;
};

}  // namespace ambf_like::detail
