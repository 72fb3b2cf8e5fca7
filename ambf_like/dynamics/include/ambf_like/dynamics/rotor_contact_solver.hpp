#pragma once
// Bullet's multibody solver, its rows on an articulation with motors moving the rotors too.

#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

namespace ambf_like::detail {

/// Bullet's multibody constraint solver, except that every row (contact, friction, limit) on
/// an articulation that carries rotors (carryRotors) acts on links and rotors together: the
/// row's response becomes impulseResponse's (M + A + h D)^-1 J^T instead of M^-1 J^T, and its
/// effective mass, right-hand side and softness follow. A tool pressed on the board then stops
/// its motors in the same solve, as a cable-driven arm's rotors stop with its links.
class RotorContactSolver : public btMultiBodyConstraintSolver {
 protected:
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int body_count,
                                        btPersistentManifold** manifolds, int manifold_count,
                                        btTypedConstraint** constraints, int constraint_count,
                                        const btContactSolverInfo& info,
                                        btIDebugDraw* debug) override;

 private:
  /// Re-derives one row's response on the bodies that carry rotors, and what follows from it.
  void throughRotors(btMultiBodySolverConstraint& row, const btContactSolverInfo& info);
  /// Replaces one side's response; returns how much its J W J^T grew.
  double replaceResponse(const btMultiBody& body, int jacobian_index);
};

}  // namespace ambf_like::detail
