#include "ambf_like/dynamics/rotor_contact_solver.hpp"

#include <initializer_list>

#include "ambf_like/dynamics/rotor_response.hpp"

namespace ambf_like::detail {

btScalar RotorContactSolver::solveGroupCacheFriendlySetup(
    btCollisionObject** bodies, int body_count, btPersistentManifold** manifolds,
    int manifold_count, btTypedConstraint** constraints, int constraint_count,
    const btContactSolverInfo& info, btIDebugDraw* debug) {
  const btScalar result = btMultiBodyConstraintSolver::solveGroupCacheFriendlySetup(
      bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, debug);
  // Without articulated warm starting (Bullet's default, kept here) the setup applied no
  // impulse yet, so the rows can still be changed before the iterations use them.
  for (btMultiBodyConstraintArray* rows :
       {&m_multiBodyNonContactConstraints, &m_multiBodyNormalContactConstraints,
        &m_multiBodyFrictionContactConstraints, &m_multiBodyTorsionalFrictionContactConstraints,
        &m_multiBodySpinningFrictionContactConstraints}) {
    for (int i = 0; i < rows->size(); ++i) throughRotors((*rows)[i], info);
  }
  return result;
}

double RotorContactSolver::replaceResponse(const btMultiBody& body, int jacobian_index) {
  const int size = body.getNumDofs() + 6;
  const btScalar* jacobian = &m_data.m_jacobians[jacobian_index];
  btScalar* response = &m_data.m_deltaVelocitiesUnitImpulse[jacobian_index];
  double before = 0.0, after = 0.0;
  for (int i = 0; i < size; ++i) before += jacobian[i] * response[i];
  impulseResponse(body, jacobian, response, m_data.scratch_r, m_data.scratch_v);
  for (int i = 0; i < size; ++i) after += jacobian[i] * response[i];
  return after - before;
}

void RotorContactSolver::throughRotors(btMultiBodySolverConstraint& row,
                                       const btContactSolverInfo& info) {
  double grown = 0.0;
  if (row.m_multiBodyA != nullptr && rotorsOf(*row.m_multiBodyA) != nullptr) {
    grown += replaceResponse(*row.m_multiBodyA, row.m_jacAindex);
  }
  if (row.m_multiBodyB != nullptr && rotorsOf(*row.m_multiBodyB) != nullptr) {
    grown += replaceResponse(*row.m_multiBodyB, row.m_jacBindex);
  }
  if (grown == 0.0 || row.m_jacDiagABInv == 0.0) return;
  // Bullet's m_jacDiagABInv is sor / (J W J^T + cfm), and a row's right-hand side and softness
  // are that times a speed and times a compliance: all three scale with it.
  const double relaxation = info.m_sor;
  const double scale = relaxation / (relaxation / row.m_jacDiagABInv + grown) / row.m_jacDiagABInv;
  row.m_jacDiagABInv *= scale;
  row.m_rhs *= scale;
  row.m_rhsPenetration *= scale;
  row.m_cfm *= scale;
}

}  // namespace ambf_like::detail
