#include "twin/world_motors.hpp"

#include <algorithm>

namespace twin {

namespace {

/// The smallest share of a motor's fitted inertia its rotor keeps however heavy the links feel:
/// the catalogue rotors through their gearboxes are 0.5-1x the fitted values.
constexpr double kLeastRotorShare = 0.25;

}  // namespace

// The transmission's motor angles are the gearbox outputs (motor rad / gearbox): the scale on
// which the robot logs Tau, so a Tau drives them as it is, and a fitted inertia J (Tau per motor
// rad/s^2) is J x gearbox on them, as is a viscous friction.
WorldMotors::WorldMotors(Arm arm, const DriveTrain& drive, const MotorMechanics& mechanics,
                         TwinArms& arms, ambf_like::World& world)
    : arm_(arm), drive_(drive), mechanics_(mechanics), arms_(&arms) {
  // d(transmission motor angle) / d(model joint coordinate).
  const Eigen::Matrix<double, kJointCount, kJointCount> coupling =
      drive.gearbox.cwiseInverse().asDiagonal() * drive.coupling(arm) *
      arms.scales(arm).cwiseInverse().asDiagonal();
  weight_to_motors_ = coupling.transpose().inverse();
  const ArmJoints fitted = mechanics.inertia.cwiseProduct(drive.gearbox);
  ambf_like::TransmissionSpec spec{arms.jointNames(arm), coupling, fitted,
                                   mechanics.viscous.cwiseProduct(drive.gearbox)};
  transmission_ = &world.addTransmission(spec);
  const ArmJoints links = transmission_->linkInertia().diagonal();
  transmission_->setRotors((fitted - links).cwiseMax(kLeastRotorShare * fitted), spec.viscous);
  cables_followed_to_ = position();
}

void WorldMotors::step(const ArmJoints& torque, const ArmJoints& gravity_load, double /*seconds*/) {
  // The fitted weight, (1 + gravity error) x the firmware's estimate, in place of the links'
  // own: the motors carry what the robot's motors were fitted to carry, the links' weight moving
  // with them as the World distributes it. On the transmission's motors the links' weight is
  // coupling^-T times its joint torques.
  const ArmJoints model_weight = weight_to_motors_ * transmission_->linkWeight();
  const ArmJoints fitted_weight =
      (ArmJoints::Ones() + mechanics_.gravity_error).cwiseProduct(gravity_load);
  const ArmJoints now = position();
  cables_.follow(mechanics_, now - cables_followed_to_);
  cables_followed_to_ = now;
  const ArmJoints drive =
      torque - mechanics_.offset + model_weight - fitted_weight - cables_.torque(mechanics_);
  transmission_->drive(drive, mechanics_.stickingFriction(torque));
}

ArmJoints WorldMotors::position() const {
  return drive_.toMotor(arm_, arms_->measured(arm_));
}

void WorldMotors::place(const ArmJoints& position, const ArmJoints& velocity) {
  arms_->place(arm_, drive_.toJoints(arm_, position), drive_.toJoints(arm_, velocity));
  cables_.release();
  cables_followed_to_ = this->position();
}

}  // namespace twin
