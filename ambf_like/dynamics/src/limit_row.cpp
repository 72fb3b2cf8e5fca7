#include "ambf_like/dynamics/limit_row.hpp"

#include <algorithm>
#include <cmath>

namespace ambf_like::detail {

bool withinReach(double gap, double rate, double dt, double band) {
  return gap <= 2.0 * dt * std::abs(rate) + band;
}

btMultiBodySolverConstraint& openLimitRow(btMultiBodyConstraintArray& rows,
                                          btMultiBodyConstraint& owner, int index) {
  btMultiBodySolverConstraint& row = rows.expandNonInitializing();
  row.m_orgConstraint = &owner;
  row.m_orgDofIndex = index;
  row.m_multiBodyA = owner.getMultiBodyA();
  row.m_multiBodyB = owner.getMultiBodyB();
  row.m_contactNormal1.setZero();
  row.m_contactNormal2.setZero();
  row.m_relpos1CrossNormal.setZero();
  row.m_relpos2CrossNormal.setZero();
  return row;
}

void aimLimitRow(btMultiBodySolverConstraint& row, double closing, double gap,
                 const btContactSolverInfo& info) {
  const double dt = info.m_timeStep;
  const bool split = info.m_splitImpulse && gap <= info.m_splitImpulsePenetrationThreshold;
  const double velocity_error = -closing - std::max(gap, 0.0) / dt;
  const double position_error = std::max(-gap, 0.0) * (split ? info.m_erp2 : info.m_erp) / dt;
  row.m_rhs = (velocity_error + (split ? 0.0 : position_error)) * row.m_jacDiagABInv;
  row.m_rhsPenetration = (split ? position_error : 0.0) * row.m_jacDiagABInv;
}

}  // namespace ambf_like::detail
