#include "ambf_like/dynamics/multibody_weight.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace ambf_like::detail {

Eigen::VectorXd weightTorques(const btMultiBody& multibody, const btVector3& gravity) {
  const int dofs = multibody.getNumDofs();
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(dofs);
  const btScalar g = gravity.length();
  if (g == 0.0) return weight;
  const btVector3 down = gravity / g;
  // Scratch Bullet's Jacobians need, kept between calls (a transmission asks every step).
  thread_local btAlignedObjectArray<btScalar> jacobian;
  thread_local btAlignedObjectArray<btScalar> scratch_r;
  thread_local btAlignedObjectArray<btVector3> scratch_v;
  thread_local btAlignedObjectArray<btMatrix3x3> scratch_m;
  jacobian.resize(6 + dofs);
  for (int i = 0; i < multibody.getNumLinks(); ++i) {
    const btMultibodyLink& link = multibody.getLink(i);
    // A link's collider sits at its centre of mass.
    multibody.fillContactJacobianMultiDof(i, link.m_collider->getWorldTransform().getOrigin(), down,
                                          &jacobian[0], scratch_r, scratch_v, scratch_m);
    for (int d = 0; d < dofs; ++d) weight(d) -= link.m_mass * g * jacobian[6 + d];
  }
  return weight;
}

}  // namespace ambf_like::detail
