#pragma once
// One arm's motor-level control as the Raven-II's control software runs it every 1 ms cycle
// (uw-biorobotics/raven2 pid_control.cpp, grav_comp.cpp, t_to_DAC_val.cpp, overdrive_detect.cpp;
// raven2-actuation.md §3-4): PID on motor angles with an unclamped integrator, gravity
// compensation, torque to DAC counts, and the safety clip.

#include <array>
#include <cstdint>
#include <optional>

#include "twin/drive_train.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// The robot's gains (params/r2params.yaml), on the gearbox-output scale per motor radian.
struct MotorGains {
  ArmJoints kp = ArmJoints::Zero();  ///< N m / rad
  ArmJoints kd = ArmJoints::Zero();  ///< N m s / rad
  ArmJoints ki = ArmJoints::Zero();  ///< N m / (rad s)
  static MotorGains raven2(Arm arm);
};

/// The amplifiers' side: DAC counts per N m (signed per arm and adapter) and the clip.
struct DacConversion {
  ArmJoints counts_per_torque = ArmJoints::Zero();
  std::array<std::int32_t, kJointCount> limit{};  ///< |dac| clipped to this (int16 for jaw 2)
  std::int32_t overdrive = 20000;                 ///< |dac| above: zeroed, soft e-stop
  static DacConversion raven2(Arm arm);
};

/// A motor whose amplifier command passed the e-stop threshold, and that command before the clip.
struct Overdrive {
  int motor = 0;
  double counts = 0.0;
};

/// What one cycle sends to the amplifiers.
struct MotorCommand {
  ArmJoints torque = ArmJoints::Zero();   ///< Tau: PID + gravity, before the clip (N m)
  ArmJoints gravity = ArmJoints::Zero();  ///< the gravity compensation's part of it
  std::array<std::int32_t, kJointCount> dac{};
  ArmJoints applied = ArmJoints::Zero();  ///< the torque the amplified current gives (N m)
  std::optional<Overdrive> overdrive;     ///< the first motor past the e-stop threshold, if any
};

/// The control law of one arm with its integrators.
class MotorController {
 public:
  MotorController(Arm arm, const DriveTrain& drive);

  /// One cycle with the PID running (pedal down). `joints`: the measured joints (for gravity).
  MotorCommand cycle(const ArmJoints& motor_setpoint, const ArmJoints& motor_position,
                     const ArmJoints& motor_velocity, const ArmJoints& joints);

  const ArmJoints& integrators() const { return integral_; }
  /// The integrator values that make this cycle's law give `torque` (where ki > 0): how a
  /// recording's first row sets the state it started in.
  ArmJoints integratorsGiving(const ArmJoints& torque, const ArmJoints& motor_error,
                              const ArmJoints& motor_velocity, const ArmJoints& joints) const;
  void setIntegrators(const ArmJoints& values) { integral_ = values; }
  const MotorGains& gains() const { return gains_; }

 private:
  Arm arm_;
  DriveTrain drive_;
  MotorGains gains_;
  DacConversion dac_;
  ArmJoints integral_ = ArmJoints::Zero();  ///< motor rad s
};

}  // namespace twin
