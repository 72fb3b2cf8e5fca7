#pragma once
// Motors that drive joints through a gearbox and cables: a transmission in MuJoCo's sense, with
// the rotors' inertia and friction reflected onto the joints and solved with the links.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ambf_like {

namespace detail {
class JointSpaceServo;
}

/// k motors behind n joints of one articulation (reduced coordinates): the motors' angles are
/// `coupling` times the joints' coordinates (a stiff transmission: one state, the joints'), a
/// motor's torque acts on the joints through the coupling's transpose, and each rotor's inertia
/// and viscous friction move with the links in the same solve as the articulation (the
/// joint-space armature coupling^T diag(inertia) coupling), so contacts and limits that stop a
/// link stop its motors. Units are the motors' own: N m and rad (or N and m).
struct TransmissionSpec {
  std::vector<std::string> joints;  ///< the World's joint names (qualified or unique plain)
  Eigen::MatrixXd coupling;         ///< motors x joints: d(motor angle) / d(joint coordinate)
  Eigen::VectorXd rotor_inertia;    ///< per motor (> 0), kg m^2 on the motor's angle
  Eigen::VectorXd viscous;          ///< per motor (>= 0), N m s per motor rad
};

/// A transmission in a World (World::addTransmission): what its motors apply each step.
class Transmission {
 public:
  Transmission(detail::JointSpaceServo& servo, std::vector<int> dofs, Eigen::MatrixXd coupling);

  /// Each motor's torque and its Coulomb friction (>= 0, the torque it takes to turn it) from the
  /// next step on. Throws std::invalid_argument for a wrong size, NaN or a negative friction.
  void drive(const Eigen::VectorXd& torque, const Eigen::VectorXd& coulomb);
  /// New rotors (TransmissionSpec's rotor_inertia and viscous, checked alike).
  void setRotors(const Eigen::VectorXd& inertia, const Eigen::VectorXd& viscous);
  /// The links' inertia as the motors feel it now, without the rotors: (C M^-1 C^T)^-1.
  Eigen::MatrixXd linkInertia() const;
  /// What holds the links still against the world's gravity, per joint (spec order), as of
  /// the articulation's last inertia refresh (every 10 steps).
  Eigen::VectorXd linkWeight() const;
  int motorCount() const { return static_cast<int>(coupling_.rows()); }

 private:
  detail::JointSpaceServo& servo_;
  std::vector<int> dofs_;     ///< the joints' degrees of freedom in the articulation
  Eigen::MatrixXd coupling_;  ///< motors x joints, as specified
};

}  // namespace ambf_like
