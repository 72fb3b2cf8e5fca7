#pragma once
// The Raven-II's cable drive as its control software models it (uw-biorobotics/raven2 defines.h,
// fwd_/inv_cable_coupling.cpp; ../shared/reference/raven2-actuation.md §1-2): per motor the
// transmission and gearbox, the cables that couple the joints, and the 4000-count encoders.

#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "raven/arm.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// Joint <-> motor maps of one robot (a da Vinci style tool adapter on both arms).
struct DriveTrain {
  /// Motor radians per joint radian (per metre for the insertion).
  ArmJoints transmission = ArmJoints::Ones();
  /// The gearbox between motor shaft and capstan: motor torque = torque at its output / gearbox.
  ArmJoints gearbox = ArmJoints::Ones();
  double shoulder_to_elbow = 0.0;      ///< C01
  double shoulder_to_insertion = 0.0;  ///< C02 (m per rad)
  double elbow_to_insertion = 0.0;     ///< C12 (m per rad)
  double tool_drag = 0.0;              ///< 1 / GB_RATIO: tool motor rad per insertion motor rad
  double wrist_to_jaws = 0.0;          ///< the instrument's wrist coupling wc
  double encoder_counts_per_motor_rev = 4000.0;

  /// The firmware's values; wc 0.5 (the recordings' instrument, raven2-actuation.md §2.3).
  static DriveTrain raven2();
  /// How inserting drags the arm's tool cables (dv adapter: gold -1, green +1).
  static double toolSign(Arm arm) { return arm == Arm::Left ? -1.0 : 1.0; }

  /// Motor angles (rad) of joint values, with the insertion motor at `insertion_motor`
  /// (inv_cable_coupling: the firmware uses the measured one). Linear, so it maps velocities too.
  ArmJoints toMotor(Arm arm, const ArmJoints& joint, double insertion_motor) const;
  /// Motor angles with the insertion motor where these joints put it.
  ArmJoints toMotor(Arm arm, const ArmJoints& joint) const;
  /// The insertion motor's angle of joint values (it turns with the shoulder and elbow too).
  double insertionMotor(const ArmJoints& joint) const;
  /// d(motor angle)/d(joint value) of `arm`: toMotor as a matrix (joint loads are its
  /// transpose times motor torques at the motor shafts).
  Eigen::Matrix<double, kJointCount, kJointCount> coupling(Arm arm) const;
  /// Joint values of motor angles (fwd_cable_coupling), the exact inverse.
  ArmJoints toJoints(Arm arm, const ArmJoints& motor) const;

  double countsPerMotorRadian() const;
  /// Motor angles as the encoders read them: whole counts.
  ArmJoints quantise(const ArmJoints& motor) const;
  std::array<std::int32_t, kJointCount> encoderCounts(const ArmJoints& motor) const;
};

}  // namespace twin
