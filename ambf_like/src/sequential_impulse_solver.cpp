#include "sequential_impulse_solver.hpp"

namespace ambf_like::detail {

btScalar SequentialImpulseSolver::solveSingleIteration(
    int iteration, btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int /*constraint_count*/,
    const btContactSolverInfo& info, btIDebugDraw* debug) {
  // The joints' rows were built in the setup; the constraints are passed only for their
  // obsolete solvers, so pass none.
  return btSequentialImpulseConstraintSolver::solveSingleIteration(
      iteration, bodies, body_count, manifolds, manifold_count, constraints, 0, info, debug);
}

}  // namespace ambf_like::detail
