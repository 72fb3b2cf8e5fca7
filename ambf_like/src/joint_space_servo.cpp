#include "joint_space_servo.hpp"

#include <algorithm>

namespace ambf_like::detail {

namespace {

/// Gauss-Seidel sweeps over the motors (a Raven arm has 7; unsaturated, 3-4 sweeps converge).
constexpr int kSweeps = 8;

}  // namespace

JointSpaceServo::JointSpaceServo(int dofs)
    : inverse_inertia_(Eigen::MatrixXd::Identity(dofs, dofs)),
      free_acceleration_(Eigen::VectorXd::Zero(dofs)),
      effort_(Eigen::VectorXd::Zero(dofs)),
      motor_velocity_(Eigen::VectorXd::Zero(dofs)),
      motor_impulse_(Eigen::VectorXd::Zero(dofs)),
      motor_torque_(Eigen::VectorXd::Zero(dofs)),
      torque_(Eigen::VectorXd::Zero(dofs)),
      velocity_before_(Eigen::VectorXd::Zero(dofs)) {}

void JointSpaceServo::setInverseInertia(const Eigen::MatrixXd& inverse_inertia) {
  inverse_inertia_ = inverse_inertia;
}

void JointSpaceServo::request(int dof, const JointActuation& actuation) {
  effort_(dof) = actuation.effort;
  motor_velocity_(dof) = actuation.motor_velocity;
  motor_impulse_(dof) = actuation.motor_on ? actuation.motor_max_impulse : 0.0;
}

const Eigen::VectorXd& JointSpaceServo::torques(
    const Eigen::VectorXd& velocity,
    double
        dt) {  // Velocity change the motors must add to what the efforts and the free motion give.
  const Eigen::VectorXd coasting =
      velocity + dt * (free_acceleration_ + inverse_inertia_ * effort_);
  solveMotors(motor_velocity_ - coasting, dt);
  torque_ = effort_ + motor_torque_;
  velocity_before_ = velocity;
  step_ = dt;
  return torque_;
}

void JointSpaceServo::observeFreeMotion(const Eigen::VectorXd& velocity) {
  free_acceleration_ = (velocity - velocity_before_) / step_ - inverse_inertia_ * torque_;
}

void JointSpaceServo::solveMotors(const Eigen::VectorXd& velocity_change, double dt) {
  const Eigen::Index n = velocity_change.size();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (motor_impulse_(i) == 0.0) motor_torque_(i) = 0.0;  // warm start from the last step
  }
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    for (Eigen::Index i = 0; i < n; ++i) {
      if (motor_impulse_(i) == 0.0) continue;
      const double residual = velocity_change(i) / dt - inverse_inertia_.row(i).dot(motor_torque_);
      const double cap = motor_impulse_(i) / dt;
      motor_torque_(i) =
          std::clamp(motor_torque_(i) + residual / inverse_inertia_(i, i), -cap, cap);
    }
  }
}

}  // namespace ambf_like::detail
