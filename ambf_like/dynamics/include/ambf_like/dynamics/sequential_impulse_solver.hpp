#pragma once
// Bullet's sequential-impulse solver without its per-iteration pass over obsolete constraints.

#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>

namespace ambf_like::detail {

/// A Bullet sequential-impulse solver (btSequentialImpulseConstraintSolver, or its multibody
/// subclass) whose iterations skip calling each constraint's obsolete solver. Bullet makes that
/// call (and looks up both bodies) for every constraint in every iteration; it does something
/// only for hinges and cone twists built in their obsolete mode, which this library never
/// builds. Skipping it is 4 % of a Raven-II step; the rows solved and their order are Bullet's.
template <class Solver>
class SequentialImpulseSolver final : public Solver {
 protected:
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int body_count,
                                btPersistentManifold** manifolds, int manifold_count,
                                btTypedConstraint** constraints, int /*constraint_count*/,
                                const btContactSolverInfo& info, btIDebugDraw* debug) override {
    // The joints' rows were built in the setup; the constraints are passed only for their
    // obsolete solvers, so pass none.
    return Solver::solveSingleIteration(iteration, bodies, body_count, manifolds, manifold_count,
                                        constraints, 0, info, debug);
  }
};

}  // namespace ambf_like::detail
