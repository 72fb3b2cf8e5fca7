#pragma once
// The Raven-II's cable drive as its firmware models it: motor turns per joint unit and the
// motor encoders' resolution.

#include <array>
#include <cstdint>

#include "raven/arm.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// Motor radians per joint radian (per metre for the insertion), and encoder counts.
struct DriveTrain {
  raven::ArmJoints transmission = raven::ArmJoints::Ones();
  double encoder_counts_per_motor_rev = 8192.0;  ///< 2048 lines, quadrature

  /// The firmware's ratios (defines.h): capstan and pulley radii, cable radii and gearboxes.
  static DriveTrain raven2();

  /// Joint value -> motor angle (rad).
  raven::ArmJoints toMotor(const raven::ArmJoints& joint) const {
    return joint.cwiseProduct(transmission);
  }
  double countsPerMotorRadian() const;
  /// The encoder counts of motor angles (rad), rounded.
  std::array<std::int32_t, raven::kJointCount> encoderCounts(const raven::ArmJoints& motor) const;
};

}  // namespace twin
