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
  btAlignedObjectArray<btScalar> jacobian;
  jacobian.resize(6 + dofs);
  btAlignedObjectArray<btScalar> scratch_r;
  btAlignedObjectArray<btVector3> scratch_v;
  btAlignedObjectArray<btMatrix3x3> scratch_m;
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
