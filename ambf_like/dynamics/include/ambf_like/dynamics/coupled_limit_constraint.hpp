#pragma once
// Bullet's side of a CoupledStop: one one-sided row on a weighted sum of an articulation's
// joint coordinates.

#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

#include <vector>

namespace ambf_like::detail {

/// Keeps sum_i gain_i q_i >= lower on one multibody (q in Bullet's coordinates, from the load
/// pose), as btMultiBodyJointLimitConstraint keeps one joint within its bounds: a row is made
/// only while the sum is within the step's reach of its bound, and it may push, never pull.
class CoupledLimitConstraint final : public btMultiBodyConstraint {
 public:
  struct Term {
    int link;  ///< the multibody link whose joint's coordinate it is
    double gain;
  };
  CoupledLimitConstraint(btMultiBody& multibody, std::vector<Term> terms, double lower);

  void finalizeMultiDof() override;
  int getIslandIdA() const override;
  int getIslandIdB() const override;
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(class btIDebugDraw*) override {}

  /// sum_i gain_i q_i - lower: how far the coordinates are from the stop (< 0: past it).
  double gap() const;
  /// The rate of the weighted sum (per second).
  double rate() const;

 private:
  std::vector<Term> terms_;
  double lower_;
};

}  // namespace ambf_like::detail
