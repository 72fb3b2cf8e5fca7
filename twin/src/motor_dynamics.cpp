#include "twin/motor_dynamics.hpp"

#include <cmath>
#include <stdexcept>

namespace twin {

ArmJoints& MotorMechanics::field(std::size_t k) {
  return const_cast<ArmJoints&>(static_cast<const MotorMechanics&>(*this).field(k));
}

const ArmJoints& MotorMechanics::field(std::size_t k) const {
  switch (k) {
    case 0:
      return inertia;
    case 1:
      return coulomb;
    case 2:
      return load_friction;
    case 3:
      return viscous;
    case kOffset:
      return offset;
    case kFace:
      return face;
    case kFaceCompliance:
      return face_compliance;
    case kCableFriction:
      return cable_friction;
    case kCableTravel:
      return cable_travel;
    default:
      return gravity_error;
  }
}

std::string MotorMechanics::invalidReason() const {
  for (std::size_t k = 0; k < kNames.size(); ++k) {
    const ValueRange& r = kRanges[k];
    for (int i = 0; i < kJointCount; ++i) {
      const double v = field(k)(i);
      const bool ok = std::isfinite(v) && (r.open ? v > r.low : v >= r.low) && v <= r.high;
      if (!ok) {
        return std::string(kNames[k]) + " of " +
               std::string(raven::kJointNames[static_cast<std::size_t>(i)]) + " must be " + r.says;
      }
    }
  }
  return {};
}

ArmJoints MotorMechanics::stickingFriction(const ArmJoints& torque) const {
  const ArmJoints rigid_cables =
      (cable_travel.array() > 0.0).select(0.0, cable_friction.array()).matrix();
  return coulomb + load_friction.cwiseProduct(torque.cwiseAbs()) + rigid_cables;
}

double MotorMechanics::jawsMeetOffset() const {
  return face(raven::kJaw1) + face(raven::kJaw2);
}

double MotorMechanics::jawsMeetCompliance() const {
  return face_compliance(raven::kJaw1) + face_compliance(raven::kJaw2);
}

const MotorMechanics& MotorMechanics::checked(Arm arm) const {
  const std::string why = invalidReason();
  if (!why.empty()) {
    throw std::invalid_argument("actuation of the " + std::string(armName(arm)) + " arm: " + why);
  }
  return *this;
}

void CableStretch::follow(const MotorMechanics& m, const ArmJoints& motion) {
  stretch_ = (stretch_ + motion).cwiseMax(-m.cable_travel).cwiseMin(m.cable_travel);
}

ArmJoints CableStretch::torque(const MotorMechanics& m) const {
  ArmJoints t = ArmJoints::Zero();
  for (int i = 0; i < kJointCount; ++i) {
    if (m.cable_travel(i) > 0.0) t(i) = m.cable_friction(i) * stretch_(i) / m.cable_travel(i);
  }
  return t;
}

void MotorAxes::step(const ArmJoints& torque, const ArmJoints& gravity_load, double seconds) {
  const double h = seconds / kSubsteps;
  const ArmJoints drive = torque - mechanics_.offset -
                          (ArmJoints::Ones() + mechanics_.gravity_error).cwiseProduct(gravity_load);
  const ArmJoints sticking = mechanics_.stickingFriction(torque);
  for (int s = 0; s < kSubsteps; ++s) {
    const ArmJoints before = position_;
    const ArmJoints cables = cables_.torque(mechanics_);
    for (int i = 0; i < kJointCount; ++i) {
      const double inertia = mechanics_.inertia(i);
      // The cables' pull as a load; Coulomb friction (its constant part, the part the
      // transmitted torque adds, a rigid cable's) as an impulse that may stop the motor, then
      // viscous friction implicitly: at a steady speed the drive balances all three exactly.
      const double free = velocity_(i) + h * (drive(i) - cables(i)) / inertia;
      const double stop = h * sticking(i) / inertia;
      velocity_(i) = std::abs(free) <= stop ? 0.0
                                            : (free - std::copysign(stop, free)) /
                                                  (1.0 + h * mechanics_.viscous(i) / inertia);
      position_(i) += h * velocity_(i);
    }
    cables_.follow(mechanics_, position_ - before);
  }
}

}  // namespace twin
