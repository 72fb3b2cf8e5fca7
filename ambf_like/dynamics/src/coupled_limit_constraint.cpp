#include "ambf_like/dynamics/coupled_limit_constraint.hpp"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include <limits>

#include "ambf_like/dynamics/limit_row.hpp"

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

double CoupledLimitConstraint::rate() const {
  double rate = 0.0;
  for (const Term& term : terms_) rate += term.gain * m_bodyA->getJointVel(term.link);
  return rate;
}

bool CoupledLimitConstraint::near(double dt, double band) const {
  return withinReach(gap(), rate(), dt, band);
}

void CoupledLimitConstraint::createConstraintRows(btMultiBodyConstraintArray& rows,
                                                  btMultiBodyJacobianData& data,
                                                  const btContactSolverInfo& info) {
  if (m_numDofsFinalized != m_jacSizeBoth) finalizeMultiDof();
  const double dt = info.m_timeStep;
  internalSetAppliedImpulse(0, 0.0);
  const double gap = this->gap();
  if (!withinReach(gap, rate(), dt, kLimitRowBand)) return;

  btMultiBodySolverConstraint& row = openLimitRow(rows, *this, 0);
  const btVector3 none(0, 0, 0);
  const double closing = fillMultiBodyConstraint(row, data, jacobianA(0), jacobianB(0), none, none,
                                                 none, none, 0.0, info, 0.0, m_maxAppliedImpulse);
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
  aimLimitRow(row, closing, gap, info);
}

}  // namespace ambf_like::detail
