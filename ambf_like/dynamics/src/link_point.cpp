#include "ambf_like/dynamics/link_point.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include <vector>

#include "ambf_like/dynamics/rotor_response.hpp"

namespace ambf_like::detail {

namespace {

/// Bullet's scratch for Jacobians and their responses, per thread.
struct Scratch {
  btAlignedObjectArray<btScalar> r;
  btAlignedObjectArray<btVector3> v;
  btAlignedObjectArray<btMatrix3x3> m;
  std::vector<btScalar> jacobian;
  std::vector<btScalar> response;
};

Scratch& scratch(const btMultiBody& body) {
  thread_local Scratch s;
  const auto size = static_cast<std::size_t>(6 + body.getNumDofs());
  s.jacobian.resize(size);
  s.response.resize(size);
  return s;
}

const btVector3 kAxes[3] = {btVector3(1, 0, 0), btVector3(0, 1, 0), btVector3(0, 0, 1)};

}  // namespace

btMultiBodyLinkCollider* movingLink(const btCollisionObject* object) {
  auto* link = const_cast<btMultiBodyLinkCollider*>(btMultiBodyLinkCollider::upcast(object));
  return link != nullptr && link->m_link >= 0 ? link : nullptr;
}

btVector3 linkPointVelocity(const btMultiBodyLinkCollider& link, const btVector3& point) {
  const btMultiBody& body = *link.m_multiBody;
  Scratch& s = scratch(body);
  const btScalar* velocity = body.getVelocityVector();
  btVector3 out(0, 0, 0);
  for (int k = 0; k < 3; ++k) {
    body.fillContactJacobianMultiDof(link.m_link, point, kAxes[k], s.jacobian.data(), s.r, s.v,
                                     s.m);
    for (std::size_t d = 0; d < s.jacobian.size(); ++d) out[k] += s.jacobian[d] * velocity[d];
  }
  return out;
}

void applyLinkImpulse(btMultiBodyLinkCollider& link, const btVector3& point,
                      const btVector3& impulse) {
  btMultiBody& body = *link.m_multiBody;
  Scratch& s = scratch(body);
  for (int k = 0; k < 3; ++k) {
    if (impulse[k] == 0.0) continue;
    body.fillContactJacobianMultiDof(link.m_link, point, kAxes[k], s.jacobian.data(), s.r, s.v,
                                     s.m);
    impulseResponse(body, s.jacobian.data(), s.response.data(), s.r, s.v);
    body.applyDeltaVeeMultiDof(s.response.data(), impulse[k]);
  }
}

}  // namespace ambf_like::detail
