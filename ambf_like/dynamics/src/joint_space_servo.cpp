#include "ambf_like/dynamics/joint_space_servo.hpp"

#include <algorithm>
#include <cmath>

namespace ambf_like::detail {

namespace {

/// Gauss-Seidel sweeps over the motors once a bound is hit, from the unbounded solution.
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
      velocity_change_(Eigen::VectorXd::Zero(dofs)),
      velocity_before_(Eigen::VectorXd::Zero(dofs)) {}

void JointSpaceServo::setInverseInertia(const Eigen::MatrixXd& inverse_inertia) {
  inverse_inertia_ = inverse_inertia;
  factored_.clear();
}

void JointSpaceServo::request(int dof, const JointActuation& actuation) {
  effort_(dof) = actuation.effort;
  motor_velocity_(dof) = actuation.motor_velocity;
  motor_impulse_(dof) = actuation.motor_on ? actuation.motor_max_impulse : 0.0;
}

const Eigen::VectorXd& JointSpaceServo::torques(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                                                double dt) {
  // What the motors must add to where the joints coast: velocity + dt (a + M^-1 effort).
  velocity_change_.noalias() = motor_velocity_ - velocity - dt * free_acceleration_;
  velocity_change_.noalias() -= dt * inverse_inertia_ * effort_;
  solveMotors(dt);
  torque_ = effort_ + motor_torque_;
  velocity_before_ = velocity;
  step_ = dt;
  return torque_;
}

void JointSpaceServo::observeFreeMotion(const Eigen::Ref<const Eigen::VectorXd>& velocity) {
  free_acceleration_.noalias() = (velocity - velocity_before_) / step_;
  free_acceleration_.noalias() -= inverse_inertia_ * torque_;
}

void JointSpaceServo::solveMotors(double dt) {
  motors_.clear();
  for (Eigen::Index i = 0; i < motor_impulse_.size(); ++i) {
    if (motor_impulse_(i) > 0.0) motors_.push_back(i);
  }
  motor_torque_.setZero();
  if (motors_.empty()) return;
  if (motors_ != factored_) {
    factor_.compute(inverse_inertia_(motors_, motors_));
    factored_ = motors_;
  }
  motor_solution_ = velocity_change_(motors_) / dt;
  factor_.solveInPlace(motor_solution_);
  motor_torque_(motors_) = motor_solution_;
  for (const auto i : motors_) {
    if (std::abs(motor_torque_(i)) > motor_impulse_(i) / dt) return boundMotors(dt);
  }
}

void JointSpaceServo::boundMotors(double dt) {
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    for (const auto i : motors_) {
      // M^-1 is symmetric: its column is its row, and contiguous.
      const double residual = velocity_change_(i) / dt - inverse_inertia_.col(i).dot(motor_torque_);
      const double cap = motor_impulse_(i) / dt;
      motor_torque_(i) =
          std::clamp(motor_torque_(i) + residual / inverse_inertia_(i, i), -cap, cap);
    }
  }
}

}  // namespace ambf_like::detail
