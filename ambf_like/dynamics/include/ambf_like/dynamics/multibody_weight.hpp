#pragma once
// What gravity puts on an articulation's joints.

#include <Eigen/Core>

class btMultiBody;
class btVector3;

namespace ambf_like::detail {

/// The joint torques (N m, or N on a prismatic joint) that hold `multibody`'s links still
/// against `gravity` at their pose now: minus the sum over links of J_i^T m_i g, J_i the
/// Jacobian of link i's centre of mass.
Eigen::VectorXd weightTorques(const btMultiBody& multibody, const btVector3& gravity);

}  // namespace ambf_like::detail
