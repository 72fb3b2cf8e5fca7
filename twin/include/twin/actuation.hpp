#pragma once
// How a twin's joints answer the robot's setpoints each 1 ms cycle, and what its sensors read.

#include <array>
#include <cstdint>

#include "raven/arm.hpp"
#include "twin/vocabulary.hpp"

namespace twin {

/// What the robot's sensors say about one arm after a cycle.
struct ActuatorReadings {
  raven::ArmJoints position = raven::ArmJoints::Zero();  ///< as the robot estimates it
  raven::ArmJoints velocity = raven::ArmJoints::Zero();
  raven::ArmJoints effort = raven::ArmJoints::Zero();          ///< joint torque (N m) / force (N)
  raven::ArmJoints motor_position = raven::ArmJoints::Zero();  ///< motor shaft (rad)
  raven::ArmJoints motor_velocity = raven::ArmJoints::Zero();
  std::array<std::int32_t, raven::kJointCount> encoder{};
};

/// The actuators between the robot's joint setpoints and the simulated joints.
class Actuation {
 public:
  virtual ~Actuation() = default;
  /// Before the world steps: drive `arm` toward `setpoint` (moving at `setpoint_velocity`).
  virtual void drive(raven::Arm arm, const raven::ArmJoints& setpoint,
                     const raven::ArmJoints& setpoint_velocity) = 0;
  /// After the world stepped.
  virtual ActuatorReadings read(raven::Arm arm) const = 0;
};

}  // namespace twin
