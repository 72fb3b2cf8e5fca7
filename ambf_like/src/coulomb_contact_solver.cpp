#include "coulomb_contact_solver.hpp"

#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletSoftBody/btSoftBody.h>

namespace ambf_like::detail {

void CoulombContactSolver::useCoulombContacts(btSoftBody& body) {
  auto& sequence = body.m_cfg.m_psequence;
  for (int i = sequence.size() - 1; i >= 0; --i) {
    if (sequence[i] == btSoftBody::ePSolver::RContacts) sequence.removeAtIndex(i);
  }
  coulomb_.insert(&body);
}

void CoulombContactSolver::forget(const btSoftBody& body) {
  coulomb_.erase(&body);
}

void CoulombContactSolver::solveConstraints(btScalar solver_dt) {
  btDefaultSoftBodySolver::solveConstraints(solver_dt);
  impulses_.clear();
  for (int i = 0; i < m_softBodySet.size(); ++i) {
    btSoftBody& body = *m_softBodySet[i];
    if (body.isActive() && coulomb_.count(&body) != 0) solveContacts(body);
  }
}

void CoulombContactSolver::solveContacts(btSoftBody& body) {
  const btScalar dt = body.m_sst.sdt;
  const btScalar kdf = body.m_cfg.kDF;
  for (int i = 0; i < body.m_rcontacts.size(); ++i) {
    const btSoftBody::RContact& contact = body.m_rcontacts[i];
    btSoftBody::Node& node = *contact.m_node;
    const btCollisionObject* object = contact.m_cti.m_colObj;
    if (node.m_im <= 0.0 || !object->hasContactResponse()) continue;
    // Articulation links are refused when the world is built: only rigid bodies get here.
    btRigidBody* rigid = const_cast<btRigidBody*>(btRigidBody::upcast(object));
    const btVector3 arm = node.m_x - object->getWorldTransform().getOrigin();
    const btVector3 surface_velocity =
        rigid != nullptr ? rigid->getVelocityInLocalPoint(arm) : btVector3(0, 0, 0);
    const btVector3& normal = contact.m_cti.m_normal;
    // The contact plane was found before the rigid body moved this step: move it along.
    const btScalar depth =
        -(normal.dot(node.m_x) + contact.m_cti.m_offset - normal.dot(surface_velocity) * dt);
    if (depth <= 0.0) continue;

    const btScalar mass = 1.0 / node.m_im;
    const btVector3 normal_dv = normal * (depth / dt);
    btVector3 relative = node.m_v - surface_velocity;
    const btVector3 slip = relative - normal * normal.dot(relative);
    const btScalar slip_speed = slip.length();
    const btScalar normal_impulse = mass * normal_dv.length();
    const btScalar limit = kdf * object->getFriction() * normal_impulse;
    btVector3 friction_dv(0, 0, 0);
    if (slip_speed > 0.0) {
      friction_dv = mass * slip_speed <= limit ? -slip : slip * (-limit / (mass * slip_speed));
    }
    node.m_x += normal * depth + friction_dv * dt;
    node.m_v += normal_dv + friction_dv;
    const btVector3 impulse = (normal_dv + friction_dv) * mass;
    if (rigid != nullptr && rigid->getInvMass() > 0.0) rigid->applyImpulse(-impulse, arm);
    impulses_.push_back({&body, object, node.m_x, normal, normal_dv * mass, friction_dv * mass});
  }
}

}  // namespace ambf_like::detail
