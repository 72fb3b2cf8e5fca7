#include "ambf_like/dynamics/joint_limit_constraint.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>

#include "ambf_like/dynamics/limit_row.hpp"

namespace ambf_like::detail {

void JointLimitConstraint::createConstraintRows(btMultiBodyConstraintArray& rows,
                                                btMultiBodyJacobianData& data,
                                                const btContactSolverInfo& info) {
  if (m_numDofsFinalized != m_jacSizeBoth) finalizeMultiDof();
  const double q = m_bodyA->getJointPos(m_linkA);
  const double rate = m_bodyA->getJointVel(m_linkA);
  const double gaps[2] = {q - m_lowerBound, m_upperBound - q};
  for (int bound = 0; bound < 2; ++bound) {
    setPosition(bound, gaps[bound]);
    if (!withinReach(gaps[bound], rate, info.m_timeStep, kLimitRowBand)) continue;
    btMultiBodySolverConstraint& row = openLimitRow(rows, *this, bound);
    const btVector3 none(0, 0, 0);
    const double closing =
        fillMultiBodyConstraint(row, data, jacobianA(bound), jacobianB(bound), none, none, none,
                                none, 0.0, info, 0.0, m_maxAppliedImpulse);
    aimLimitRow(row, closing, gaps[bound], info);
  }
}

}  // namespace ambf_like::detail
