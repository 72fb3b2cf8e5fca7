#pragma once
// The motors of one articulation, solved together in joint space.

#include <Eigen/Dense>
#include <vector>

#include "ambf_like/dynamics/joint_dynamics.hpp"

namespace ambf_like::detail {

/// Turns an articulation's motor requests (reach this joint speed this step, within this
/// impulse) into joint torques, as Bullet's constraint motors do but exactly and without solver
/// rows: with the joint-space inverse inertia M^-1 and the free acceleration a (gravity,
/// Coriolis, contacts, limits) the step's velocity change is dt (a + M^-1 tau), and the motor
/// torques solve that for the targets: directly (a Cholesky factor of the motors' block of
/// M^-1), and by projected Gauss-Seidel from there when a bound is hit.
/// `a` is measured each step: the velocity change of the free motion (before contacts and
/// limits act) beyond what the torques explain.
class JointSpaceServo {
 public:
  explicit JointSpaceServo(int dofs);

  /// Sets the joint-space inverse inertia (refreshed as the articulation moves).
  void setInverseInertia(const Eigen::MatrixXd& inverse_inertia);
  /// Records one joint's request for the coming step.
  void request(int dof, const JointActuation& actuation);
  /// The torques for the coming step, given the joints' velocities now.
  const Eigen::VectorXd& torques(const Eigen::Ref<const Eigen::VectorXd>& velocity, double dt);
  /// The joints' velocities once the step's free motion has been applied.
  void observeFreeMotion(const Eigen::Ref<const Eigen::VectorXd>& velocity);
  /// Torque given to `dof` for the last step (motor plus effort).
  double appliedTorque(int dof) const { return torque_(dof); }

 private:
  void solveMotors(double dt);
  void boundMotors(double dt);

  Eigen::MatrixXd inverse_inertia_;
  Eigen::VectorXd free_acceleration_;
  Eigen::VectorXd effort_;
  Eigen::VectorXd motor_velocity_;
  Eigen::VectorXd motor_impulse_;  ///< bound per step (N m s or N s); 0: no motor
  Eigen::VectorXd motor_torque_;
  Eigen::VectorXd torque_;
  std::vector<Eigen::Index> motors_;    ///< dofs with a motor on this step
  std::vector<Eigen::Index> factored_;  ///< the motors `factor_` is of
  Eigen::LLT<Eigen::MatrixXd> factor_;
  Eigen::VectorXd motor_solution_;   ///< scratch: the motors' torques, unbounded
  Eigen::VectorXd velocity_change_;  ///< what the motors must add to the coasting velocities
  Eigen::VectorXd velocity_before_;  ///< at the start of the step under way
  double step_ = 0.0;
};

}  // namespace ambf_like::detail
