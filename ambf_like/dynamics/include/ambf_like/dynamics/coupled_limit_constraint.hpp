#pragma once
// Bullet's side of a CoupledStop: one one-sided row on a weighted sum of an articulation's
// joint coordinates.

#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

#include <vector>

namespace ambf_like::detail {

/// Keeps sum_i gain_i q_i >= lower on one multibody (q in Bullet's coordinates, from the load
/// pose), as JointLimitConstraint keeps one joint within its bounds: a row is made
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

  /// Moves the bound by `delta` (rad or m).
  void shiftLower(double delta) { lower_ += delta; }
  /// How far past its bound the sum goes per unit of the force holding it there (rad per N m,
  /// or m per N): a spring there; 0, the default, is rigid.
  void setCompliance(double compliance) { compliance_ = compliance; }
  /// sum_i gain_i q_i - lower: how far the coordinates are from the stop (< 0: past it).
  double gap() const;
  /// d/dt of the sum.
  double rate() const;
  /// Whether the sum is within `band` (rad or m) of its bound beyond two steps of `dt` at its
  /// present rate.
  bool near(double dt, double band) const;

 private:
  std::vector<Term> terms_;
  double lower_;
  double compliance_ = 0.0;
};

}  // namespace ambf_like::detail
