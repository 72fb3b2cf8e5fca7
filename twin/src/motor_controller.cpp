#include "twin/motor_controller.hpp"

#include <algorithm>
#include <cmath>

#include "raven/control_cycle.hpp"
#include "twin/gravity_compensation.hpp"

namespace twin {

namespace {

constexpr double kDacPerAmpBig = 2730.0;        // high-current amplifiers, 2^15 / 12 A
constexpr double kDacPerAmpTool = 5461.0;       // 2^15 / 6 A
constexpr double kTorqueConstantRe40 = 0.0603;  // N m / A
constexpr double kTorqueConstantRe30 = 0.0538;

}  // namespace

MotorGains MotorGains::raven2(Arm arm) {
  MotorGains g;
  g.kp << 0.30, 0.30, 0.15, 0.09, 0.05, 0.05, 0.05;
  g.kd << 0.008, 0.008, arm == Arm::Left ? 0.012 : 0.010, 0.001, 0.0, 0.0, 0.0;
  g.ki << 0.0, 0.0, 0.0, 0.05, 0.05, 0.05, 0.05;
  return g;
}

DacConversion DacConversion::raven2(Arm arm) {
  const DriveTrain drive = DriveTrain::raven2();
  DacConversion d;
  // The arm motors' torque sign is -1 on gold, +1 on green; the dv adapter's tool motors +1 on
  // both arms, jaw 1 negated (OPPOSE_GRIP).
  const double arm_sign = arm == Arm::Left ? -1.0 : 1.0;
  for (int i = 0; i < kJointCount; ++i) {
    const bool big = i <= raven::kInsertion;
    const double per_amp = (big ? kTorqueConstantRe40 : kTorqueConstantRe30) * drive.gearbox(i);
    const double sign = big ? arm_sign : (i == raven::kJaw1 ? -1.0 : 1.0);
    d.counts_per_torque(i) = sign * (big ? kDacPerAmpBig : kDacPerAmpTool) / per_amp;
  }
  // The loop of overdrive_detect.cpp stops before GRASP2: only int16 saturation applies there.
  d.limit = {2500, 2500, 2000, 3000, 3000, 3800, 32767};
  return d;
}

MotorController::MotorController(Arm arm, const DriveTrain& drive)
    : arm_(arm), drive_(drive), gains_(MotorGains::raven2(arm)), dac_(DacConversion::raven2(arm)) {}

MotorCommand MotorController::cycle(const ArmJoints& motor_setpoint,
                                    const ArmJoints& motor_position,
                                    const ArmJoints& motor_velocity, const ArmJoints& joints) {
  MotorCommand out;
  const ArmJoints error = motor_setpoint - motor_position;
  integral_ += error * raven::kControlCycle;
  // mvel_d is never set by the firmware: the D term damps the measured velocity.
  out.gravity = gravityCompensation(arm_, joints, drive_);
  out.torque = gains_.kp.cwiseProduct(error) - gains_.kd.cwiseProduct(motor_velocity) +
               gains_.ki.cwiseProduct(integral_) + out.gravity;
  for (int i = 0; i < kJointCount; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double counts = std::trunc(out.torque(i) * dac_.counts_per_torque(i));
    const double saturated = std::clamp(counts, -32768.0, 32767.0);
    if (std::abs(saturated) > dac_.overdrive && i != raven::kJaw2 && !out.overdrive) {
      out.overdrive = Overdrive{.motor = i, .counts = saturated};
    }
    const auto limit = static_cast<double>(dac_.limit[k]);
    out.dac[k] = static_cast<std::int32_t>(std::clamp(saturated, -limit, limit));
  }
  if (out.overdrive) out.dac.fill(0);
  for (int i = 0; i < kJointCount; ++i) {
    out.applied(i) = out.dac[static_cast<std::size_t>(i)] / dac_.counts_per_torque(i);
  }
  return out;
}

ArmJoints MotorController::integratorsGiving(const ArmJoints& torque, const ArmJoints& error,
                                             const ArmJoints& velocity,
                                             const ArmJoints& joints) const {
  const ArmJoints rest = torque - gains_.kp.cwiseProduct(error) + gains_.kd.cwiseProduct(velocity) -
                         gravityCompensation(arm_, joints, drive_);
  ArmJoints values = integral_;
  for (int i = 0; i < kJointCount; ++i) {
    if (gains_.ki(i) > 0.0) values(i) = rest(i) / gains_.ki(i);
  }
  return values;
}

}  // namespace twin
