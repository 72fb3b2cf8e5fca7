#pragma once
// Bullet's default soft-body solver, with Coulomb friction for the soft bodies that ask for it.

#include <BulletSoftBody/btDefaultSoftBodySolver.h>

#include <unordered_set>
#include <vector>

class btCollisionObject;

namespace ambf_like::detail {

/// The impulse one soft-body node exchanged with a rigid body in the last step.
struct NodeContactImpulse {
  const btSoftBody* soft = nullptr;
  const btCollisionObject* rigid = nullptr;
  btVector3 position;  ///< the node, after the step
  btVector3 normal;    ///< the rigid surface's normal, pointing to the node
  btVector3 normal_impulse;
  btVector3 friction_impulse;  ///< on the node, tangential
};

/// btDefaultSoftBodySolver that, for the soft bodies registered with it, replaces Bullet's
/// rigid-contact projection (ePSolver::RContacts: a node within the margin sticks whenever
/// kDF x friction >= 1, however lightly it is pressed) by one Coulomb contact pass after the
/// body's own constraints: each node found inside a rigid body is pushed back onto its surface,
/// which is the normal impulse J_n = m dx / dt the body's elasticity pressed it in with; its
/// tangential velocity relative to the surface is then removed if that takes no more than
/// mu J_n (stick), else reduced by mu J_n (slip), mu = kDF x the rigid body's friction. The
/// opposite impulses go to the rigid body, so a grasp is held, and felt, by its squeeze.
class CoulombContactSolver final : public btDefaultSoftBodySolver {
 public:
  /// `body` gets Coulomb contacts: Bullet's own rigid-contact projection is taken out of it.
  void useCoulombContacts(btSoftBody& body);
  void forget(const btSoftBody& body);
  void solveConstraints(btScalar solver_dt) override;
  /// The Coulomb contacts' impulses of the last step.
  const std::vector<NodeContactImpulse>& lastImpulses() const { return impulses_; }

 private:
  void solveContacts(btSoftBody& body);

  std::unordered_set<const btSoftBody*> coulomb_;
  std::vector<NodeContactImpulse> impulses_;
};

}  // namespace ambf_like::detail
