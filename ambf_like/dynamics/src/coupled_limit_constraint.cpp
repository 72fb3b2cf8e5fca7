#include "ambf_like/dynamics/coupled_limit_constraint.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ambf_like::detail {

namespace {

/// The island of a multibody: that of its base's collider, or else its first link's.
int islandOf(const btMultiBody& multibody) {
  if (const auto* base = multibody.getBaseCollider()) return base->getIslandTag();
  for (int i = 0; i < multibody.getNumLinks(); ++i) {
    if (const auto* collider = multibody.getLink(i).m_collider) return collider->getIslandTag();
  }
  return -1;
}

/// Besides the step's own travel, how near its bound (rad or m) the sum gets a row.
constexpr double kRowBand = 1e-4;

}  // namespace

CoupledLimitConstraint::CoupledLimitConstraint(btMultiBody& multibody, std::vector<Term> terms,
                                               double lower)
    : btMultiBodyConstraint(&multibody, &multibody, terms.front().link, terms.back().link, 1, true,
                            MULTIBODY_CONSTRAINT_LIMIT),
      terms_(std::move(terms)),
      lower_(lower) {
  setMaxAppliedImpulse(std::numeric_limits<double>::max());
}

void CoupledLimitConstraint::finalizeMultiDof() {
  allocateJacobiansMultiDof();
  for (const Term& term : terms_) {
    jacobianA(0)[6 + m_bodyA->getLink(term.link).m_dofOffset] = term.gain;
  }
  m_numDofsFinalized = m_jacSizeBoth;
}

int CoupledLimitConstraint::getIslandIdA() const {
  return islandOf(*m_bodyA);
}
int CoupledLimitConstraint::getIslandIdB() const {
  return islandOf(*m_bodyB);
}

double CoupledLimitConstraint::gap() const {
  double sum = 0.0;
  for (const Term& term : terms_) sum += term.gain * m_bodyA->getJointPos(term.link);
  return sum - lower_;
}

bool CoupledLimitConstraint::near(double dt, double band) const {
  double rate = 0.0;
  for (const Term& term : terms_) rate += term.gain * m_bodyA->getJointVel(term.link);
  return gap() <= 2.0 * dt * std::abs(rate) + band;
}

void CoupledLimitConstraint::createConstraintRows(btMultiBodyConstraintArray& rows,
                                                  btMultiBodyJacobianData& data,
                                                  const btContactSolverInfo& info) {
  if (m_numDofsFinalized != m_jacSizeBoth) finalizeMultiDof();
  const double dt = info.m_timeStep;
  internalSetAppliedImpulse(0, 0.0);
  if (!near(dt, kRowBand)) return;

  btMultiBodySolverConstraint& row = rows.expandNonInitializing();
  row.m_orgConstraint = this;
  row.m_orgDofIndex = 0;
  row.m_multiBodyA = m_bodyA;
  row.m_multiBodyB = m_bodyB;
  const btVector3 none(0, 0, 0);
  const double closing = fillMultiBodyConstraint(row, data, jacobianA(0), jacobianB(0), none, none,
                                                 none, none, 0.0, info, 0.0, m_maxAppliedImpulse);
  row.m_contactNormal1.setZero();
  row.m_contactNormal2.setZero();
  row.m_relpos1CrossNormal.setZero();
  row.m_relpos2CrossNormal.setZero();
  const double gap = this->gap();
  if (compliance_ > 0.0) {
    // A spring past the bound, solved implicitly (the soft constraint of Catto, undamped): the
    // impulse p solves (J M^-1 J^T + compliance / dt^2) p = -(closing + gap / dt), pushing only;
    // at rest past the bound it holds the sum where the force is -gap / compliance.
    const double softness = compliance_ / (dt * dt);
    row.m_jacDiagABInv = 1.0 / (1.0 / row.m_jacDiagABInv + softness);
    row.m_cfm = softness * row.m_jacDiagABInv;
    row.m_rhs = (-closing - gap / dt) * row.m_jacDiagABInv;
    row.m_rhsPenetration = 0.0;
    return;
  }
  // Apart: the sum may close by the gap in this step, no more (a speculative contact's row).
  // Past the bound: it stops, and the error is pushed out at the solver's error-reduction rate
  // (a shallow one as a separate push when the solver splits impulses, as Bullet's limits do).
  const bool split = info.m_splitImpulse && -gap <= info.m_splitImpulsePenetrationThreshold;
  const double velocity_error = -closing - std::max(gap, 0.0) / dt;
  const double position_error = std::max(-gap, 0.0) * (split ? info.m_erp2 : info.m_erp) / dt;
  row.m_rhs = (velocity_error + (split ? 0.0 : position_error)) * row.m_jacDiagABInv;
  row.m_rhsPenetration = (split ? position_error : 0.0) * row.m_jacDiagABInv;
}

}  // namespace ambf_like::detail
