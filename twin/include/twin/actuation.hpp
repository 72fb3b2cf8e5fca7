#pragma once
// How a twin's joints answer the robot's setpoints each 1 ms cycle, and what its sensors read.

#include <any>
#include <array>
#include <cstdint>
#include <string>

#include "raven/arm.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// What the robot's sensors and its control software say about one arm after a cycle.
struct ActuatorReadings {
  raven::ArmJoints position = raven::ArmJoints::Zero();  ///< as the robot estimates it
  raven::ArmJoints velocity = raven::ArmJoints::Zero();
  raven::ArmJoints effort = raven::ArmJoints::Zero();          ///< joint torque (N m) / force (N)
  raven::ArmJoints motor_position = raven::ArmJoints::Zero();  ///< motor shaft (rad)
  raven::ArmJoints motor_velocity = raven::ArmJoints::Zero();
  raven::ArmJoints motor_setpoint = raven::ArmJoints::Zero();  ///< mpos_d (rad)
  /// Tau: the commanded torque at the gearbox output (N m); 0 without a motor model.
  raven::ArmJoints torque = raven::ArmJoints::Zero();
  std::array<std::int32_t, raven::kJointCount> dac{};  ///< amplifier commands (counts)
  std::array<std::int32_t, raven::kJointCount> encoder{};
};

/// Where an arm was when a recording began: what its control software knew.
struct ArmStart {
  raven::ArmJoints motor_position = raven::ArmJoints::Zero();  ///< measured (rad)
  raven::ArmJoints motor_velocity = raven::ArmJoints::Zero();  ///< measured (rad/s)
  raven::ArmJoints integrators = raven::ArmJoints::Zero();     ///< the PID's (motor rad s)
};

/// The actuators between the robot's joint setpoints and the simulated joints.
class Actuation {
 public:
  virtual ~Actuation() = default;
  /// Before the world steps: drive `arm` toward `setpoint`.
  virtual void drive(raven::Arm arm, const raven::ArmJoints& setpoint) = 0;
  /// After the world stepped.
  virtual ActuatorReadings read(raven::Arm arm) const = 0;
  /// Puts `arm`'s actuators (and the joints they hold) where a recording began.
  virtual void place(raven::Arm arm, const ArmStart& start) = 0;
  /// Why the robot must stop (its amplifiers' soft e-stop), or empty.
  virtual std::string fault() const { return {}; }
  /// The robot was enabled again after a fault: its amplifiers take commands.
  virtual void clearFault() {}
  /// What its next cycles depend on beyond the World (TwinPlatform::saveState), restored only
  /// into an actuation of the same kind.
  virtual std::any state() const = 0;
  virtual void restore(const std::any& state) = 0;
};

}  // namespace twin
