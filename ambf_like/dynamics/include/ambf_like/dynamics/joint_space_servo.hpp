#pragma once
// The motors of one articulation, solved together in joint space.

#include <Eigen/Dense>
#include <optional>
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
  /// Motors behind the joints through a linear transmission, in this articulation's degrees of
  /// freedom (see ambf_like::TransmissionSpec): their rotors' inertia and viscous friction are
  /// reflected onto the joints and solved with them, their Coulomb friction is a bounded row
  /// per motor, their torques act through the coupling's transpose.
  struct Transmission {
    Eigen::MatrixXd coupling;  ///< motors x dofs: motor velocity = coupling * joint velocity
    Eigen::MatrixXd armature;  ///< dofs x dofs: coupling^T diag(rotor inertia) coupling
    Eigen::MatrixXd damping;   ///< dofs x dofs: coupling^T diag(viscous) coupling
    Eigen::VectorXd torque;    ///< per motor, for the coming steps
    Eigen::VectorXd coulomb;   ///< per motor, >= 0
    double step = 0.0;         ///< the world's fixed step: the damping is implicit over it
  };

  explicit JointSpaceServo(int dofs);

  /// Puts motors behind the joints (see Transmission); one per articulation.
  void setTransmission(Transmission transmission);
  bool hasTransmission() const { return transmission_.has_value(); }
  /// The transmission's rotors: their inertia and viscous friction per motor.
  void setRotors(const Eigen::VectorXd& inertia, const Eigen::VectorXd& viscous);
  /// The transmission's torques and Coulomb friction for the coming steps.
  void driveTransmission(const Eigen::VectorXd& torque, const Eigen::VectorXd& coulomb);
  /// The joints were put somewhere (Joint::place): their last free motion and their last
  /// coordinates say nothing now.
  void forgetPrediction() {
    free_velocity_.reset();
    last_position_.reset();
  }
  /// What holds the links still against gravity (refreshed with the inverse inertia).
  void setLinkWeight(const Eigen::VectorXd& weight) { link_weight_ = weight; }
  const Eigen::VectorXd& linkWeight() const { return link_weight_; }
  /// The joint-space inverse inertia of the links alone (no rotors).
  const Eigen::MatrixXd& inverseInertia() const { return inverse_inertia_; }
  /// With a transmission: (M + A + h D)^-1, how links and rotors together answer an impulse.
  const Eigen::MatrixXd& reflectedInverse() const { return reflected_inverse_; }

  /// Sets the joint-space inverse inertia (refreshed as the articulation moves).
  void setInverseInertia(const Eigen::MatrixXd& inverse_inertia);
  /// Records one joint's request for the coming step.
  void request(int dof, const JointActuation& actuation);
  /// The torques for the coming step, given the joints' velocities and coordinates now.
  const Eigen::VectorXd& torques(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                                 const Eigen::Ref<const Eigen::VectorXd>& position, double dt);
  /// The joints' velocities once the step's free motion has been applied.
  void observeFreeMotion(const Eigen::Ref<const Eigen::VectorXd>& velocity);
  /// Torque given to `dof` for the last step (motor plus effort; with a transmission, its
  /// torque and friction, not the part that accelerates its rotors).
  double appliedTorque(int dof) const { return transmission_ ? transmitted_(dof) : torque_(dof); }

 private:
  void solveMotors(double dt);
  void boundMotors(double dt);
  /// torques() with a transmission: the joints move as links and rotors together, (M + A + h D)
  /// dv = h (tau + f - D v), within the motors' and friction's bounded rows, v and the rows taken
  /// from the speed the coordinates moved at over the last step; Bullet, which knows only M, gets
  /// the torque that makes it move so.
  const Eigen::VectorXd& reflectedTorques(const Eigen::Ref<const Eigen::VectorXd>& velocity,
                                          const Eigen::Ref<const Eigen::VectorXd>& position,
                                          double dt);
  void refreshReflectedInertia();
  /// Picks this step's rows (motors on, motors with friction) and, when they or the inertia
  /// changed, rebuilds their effective mass and its factor.
  void prepareRows();

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
  std::optional<Transmission> transmission_;
  Eigen::MatrixXd inertia_;            ///< M, with a transmission
  Eigen::MatrixXd reflected_inverse_;  ///< (M + A + h D)^-1, with a transmission
  Eigen::VectorXd transmitted_;        ///< with a transmission: see appliedTorque
  /// With a transmission: the joints' speeds after the last step's free motion, before
  /// contacts and limits acted.
  std::optional<Eigen::VectorXd> free_velocity_;
  /// With a transmission: the joints' coordinates at the last step's start.
  std::optional<Eigen::VectorXd> last_position_;
  Eigen::VectorXd link_weight_;  ///< with a transmission: see setLinkWeight
  /// With a transmission: the bounded rows of the last step and what they cost to set up, kept
  /// while the rows and the inertia stay the same.
  struct RowSolve {
    std::vector<Eigen::Index> motors;      ///< dofs with a motor: unit rows
    std::vector<Eigen::Index> frictional;  ///< motors with Coulomb friction: coupling rows
    Eigen::MatrixXd rows;                  ///< R
    Eigen::MatrixXd response;              ///< W R^T: joint speeds per row impulse
    Eigen::MatrixXd mass;                  ///< R W R^T
    Eigen::LDLT<Eigen::MatrixXd> factor;   ///< of `mass`
    bool valid = false;
  };
  RowSolve rows_;
  std::vector<Eigen::Index> frictional_;  ///< scratch: this step's frictional motors
};

}  // namespace ambf_like::detail
