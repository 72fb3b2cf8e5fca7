#include "dynamics_world.hpp"

#include <BulletDynamics/Dynamics/btRigidBody.h>

namespace ambf_like::detail {

// Bullet calls this after predicting motion and before collision detection, so the switch
// below also decides whether this step's AABBs are swept.
void DynamicsWorld::createPredictiveContacts(btScalar time_step) {
  bool any_ccd = false;
  for (int i = 0; i < m_nonStaticRigidBodies.size() && !any_ccd; ++i) {
    any_ccd = m_nonStaticRigidBodies[i]->getCcdSquareMotionThreshold() > 0.0;
  }
  getDispatchInfo().m_useContinuous = any_ccd;
  if (any_ccd) btSoftRigidDynamicsWorld::createPredictiveContacts(time_step);
}

}  // namespace ambf_like::detail
