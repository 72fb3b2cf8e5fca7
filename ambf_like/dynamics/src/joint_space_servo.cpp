#include "ambf_like/dynamics/joint_space_servo.hpp"

#include <algorithm>
#include <cmath>

namespace ambf_like::detail {

namespace {

/// Gauss-Seidel sweeps over the motors once a bound is hit, from the unbounded solution.
constexpr int kSweeps = 8;
/// The same for a transmission's rows, whose friction rows couple through its cables: at most
/// this many, ending once no impulse moves by more than kRowTolerance of its bound.
constexpr int kRowSweeps = 32;
constexpr double kRowTolerance = 1e-9;

/// Impulses p, each within |p_i| <= bound_i, for rows of effective mass `k` (R W R^T, `factor`
/// its LDLT) that bring the rows' speeds `rhs` further: directly, then by projected
/// Gauss-Seidel from the clamped solution when a bound binds.
Eigen::VectorXd boundedImpulses(const Eigen::MatrixXd& k,
                                const Eigen::LDLT<Eigen::MatrixXd>& factor,
                                const Eigen::VectorXd& rhs, const Eigen::VectorXd& bound) {
  Eigen::VectorXd p = factor.solve(rhs);
  if ((p.array().abs() <= bound.array()).all()) return p;
  p = p.cwiseMax(-bound).cwiseMin(bound);
  for (int sweep = 0; sweep < kRowSweeps; ++sweep) {
    double largest_change = 0.0;
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      // `k` is symmetric: its column is its row, and contiguous.
      const double residual = rhs(i) - k.col(i).dot(p);
      const double next = std::clamp(p(i) + residual / k(i, i), -bound(i), bound(i));
      largest_change = std::max(largest_change, std::abs(next - p(i)) / (bound(i) + 1e-300));
      p(i) = next;
    }
    if (largest_change < kRowTolerance) break;
  }
  return p;
}

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
  if (transmission_) refreshReflectedInertia();
}

void JointSpaceServo::setTransmission(Transmission transmission) {
  transmission_ = std::move(transmission);
  transmitted_ = Eigen::VectorXd::Zero(torque_.size());
  refreshReflectedInertia();
}

void JointSpaceServo::setRotors(const Eigen::VectorXd& inertia, const Eigen::VectorXd& viscous) {
  Transmission& t = *transmission_;
  t.armature = t.coupling.transpose() * inertia.asDiagonal() * t.coupling;
  t.damping = t.coupling.transpose() * viscous.asDiagonal() * t.coupling;
  refreshReflectedInertia();
}

void JointSpaceServo::driveTransmission(const Eigen::VectorXd& torque,
                                        const Eigen::VectorXd& coulomb) {
  transmission_->torque = torque;
  transmission_->coulomb = coulomb;
}

void JointSpaceServo::refreshReflectedInertia() {
  const auto dofs = inverse_inertia_.rows();
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(dofs, dofs);
  inertia_ = inverse_inertia_.llt().solve(identity);
  const Transmission& t = *transmission_;
  reflected_inverse_ = (inertia_ + t.armature + t.step * t.damping).llt().solve(identity);
  rows_.valid = false;
}

void JointSpaceServo::prepareRows() {
  const Transmission& t = *transmission_;
  motors_.clear();
  for (Eigen::Index i = 0; i < motor_impulse_.size(); ++i) {
    if (motor_impulse_(i) > 0.0) motors_.push_back(i);
  }
  frictional_.clear();
  for (Eigen::Index m = 0; m < t.coulomb.size(); ++m) {
    if (t.coulomb(m) > 0.0) frictional_.push_back(m);
  }
  RowSolve& r = rows_;
  if (r.valid && r.motors == motors_ && r.frictional == frictional_) return;
  r.motors = motors_;
  r.frictional = frictional_;
  const auto count = static_cast<Eigen::Index>(motors_.size() + frictional_.size());
  r.rows = Eigen::MatrixXd::Zero(count, inverse_inertia_.rows());
  Eigen::Index row = 0;
  for (const auto i : motors_) r.rows(row++, i) = 1.0;
  for (const auto m : frictional_) r.rows.row(row++) = t.coupling.row(m);
  r.response = reflected_inverse_ * r.rows.transpose();
  r.mass = r.rows * r.response;
  r.factor.compute(r.mass);
  r.valid = true;
}

void JointSpaceServo::request(int dof, const JointActuation& actuation) {
  effort_(dof) = actuation.effort;
  motor_velocity_(dof) = actuation.motor_velocity;
  motor_impulse_(dof) = actuation.motor_on ? actuation.motor_max_impulse : 0.0;
}

const Eigen::VectorXd& JointSpaceServo::torques(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                                                const Eigen::Ref<const Eigen::VectorXd>& position,
                                                double dt) {
  if (transmission_) return reflectedTorques(velocity, position, dt);
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
  if (transmission_) free_velocity_ = velocity;
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

const Eigen::VectorXd& JointSpaceServo::reflectedTorques(
    const Eigen::Ref<const Eigen::VectorXd>& velocity,
    const Eigen::Ref<const Eigen::VectorXd>& position, double dt) {
  const Transmission& t = *transmission_;
  // The speed the joints moved at over the last step, as the encoders saw it. A soft body's
  // contacts act after the positions are integrated: what they put on the links' speed then
  // is a load (in `contact_change`), not a motion, and a light jaw pressed by a ring starts the
  // step with a speed it never moves at. The rotors' friction, viscous and Coulomb, resists how
  // they turn, not the kick a contact gave their links.
  const Eigen::VectorXd moved = last_position_ ? Eigen::VectorXd((position - *last_position_) / dt)
                                               : Eigen::VectorXd(velocity);
  last_position_ = position;
  const Eigen::VectorXd effort = effort_ + t.coupling.transpose() * t.torque - t.damping * moved;
  // What contacts and limits did to the joints last step, after the free motion. They stop
  // links and rotors together (RotorContactSolver, applyLinkImpulse), and a load that lasts
  // does it again: the rows see the motion it leaves, so that pressed on a surface the motors'
  // whole torque comes to rest against it, not on their friction; Bullet, which applies it
  // again, is not given it twice.
  const Eigen::VectorXd contact_change = free_velocity_
                                             ? Eigen::VectorXd(velocity - *free_velocity_)
                                             : Eigen::VectorXd::Zero(velocity.size());
  // Where links and rotors coast to with these torques: f = M a is what Bullet adds itself.
  const Eigen::VectorXd coasting =
      dt * reflected_inverse_ * (effort + inertia_ * free_acceleration_) + contact_change;
  // The rows: each joint motor (a unit row toward its speed), each motor's Coulomb friction
  // (its coupling row, toward rest).
  prepareRows();
  const RowSolve& r = rows_;
  const auto count = r.rows.rows();
  Eigen::VectorXd target = Eigen::VectorXd::Zero(count);
  Eigen::VectorXd bound(count);
  Eigen::Index row = 0;
  for (const auto i : r.motors) {
    target(row) = motor_velocity_(i);
    bound(row++) = motor_impulse_(i);
  }
  for (const auto m : r.frictional) bound(row++) = dt * t.coulomb(m);
  Eigen::VectorXd change = coasting;
  Eigen::VectorXd impulse = Eigen::VectorXd::Zero(count);
  if (count > 0) {
    impulse = boundedImpulses(r.mass, r.factor, target - r.rows * (moved + coasting), bound);
    change.noalias() += r.response * impulse;
  }
  torque_ = inertia_ * ((change - contact_change) / dt - free_acceleration_);
  transmitted_ = effort + r.rows.transpose() * impulse / dt;
  velocity_before_ = velocity;
  step_ = dt;
  return torque_;
}

}  // namespace ambf_like::detail
