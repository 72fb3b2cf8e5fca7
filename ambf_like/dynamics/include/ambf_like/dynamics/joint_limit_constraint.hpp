#pragma once
// One joint's limits as speculative rows: a joint reaching its bound stops on it.

#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>

namespace ambf_like::detail {

/// Bullet's joint limit (row 0 the lower bound, row 1 the upper, bounds in Bullet's coordinate),
/// with each row made while its bound is within the step's reach rather than once it is passed:
/// Bullet's own rows ask nothing while a gap remains, so a joint arriving at v passed its bound
/// by up to v dt before being pushed back.
class JointLimitConstraint final : public btMultiBodyJointLimitConstraint {
 public:
  using btMultiBodyJointLimitConstraint::btMultiBodyJointLimitConstraint;

  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
};

}  // namespace ambf_like::detail
