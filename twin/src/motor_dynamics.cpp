#include "twin/motor_dynamics.hpp"

#include <cmath>

namespace twin {

std::string MotorMechanics::invalidReason() const {
  for (int i = 0; i < kJointCount; ++i) {
    const std::string joint(raven::kJointNames[static_cast<std::size_t>(i)]);
    if (!(inertia(i) > 0.0) || !std::isfinite(inertia(i)))
      return "inertia of " + joint + " must be > 0";
    if (!(coulomb(i) >= 0.0) || !std::isfinite(coulomb(i)))
      return "coulomb of " + joint + " must be >= 0";
    if (!(viscous(i) >= 0.0) || !std::isfinite(viscous(i)))
      return "viscous of " + joint + " must be >= 0";
    if (!(gravity_error(i) > -1.0) || !std::isfinite(gravity_error(i))) {
      return "gravity_error of " + joint + " must be > -1";
    }
  }
  return {};
}

void MotorAxes::step(const ArmJoints& torque, const ArmJoints& gravity_load, double seconds) {
  const double h = seconds / kSubsteps;
  const ArmJoints drive =
      torque - (ArmJoints::Ones() + mechanics_.gravity_error).cwiseProduct(gravity_load);
  for (int s = 0; s < kSubsteps; ++s) {
    for (int i = 0; i < kJointCount; ++i) {
      const double inertia = mechanics_.inertia(i);
      // Viscous friction implicitly; then Coulomb friction as an impulse that may stop the motor.
      const double free =
          (velocity_(i) + h * drive(i) / inertia) / (1.0 + h * mechanics_.viscous(i) / inertia);
      const double stop = h * mechanics_.coulomb(i) / inertia;
      velocity_(i) = std::abs(free) <= stop ? 0.0 : free - std::copysign(stop, free);
      position_(i) += h * velocity_(i);
    }
  }
}

}  // namespace twin
