#include "twin/ideal_actuation.hpp"

namespace twin {

void IdealActuation::drive(raven::Arm arm, const raven::ArmJoints& setpoint,
                           const raven::ArmJoints& /*setpoint_velocity*/) {
  arms_.command(arm, setpoint);
}

ActuatorReadings IdealActuation::read(raven::Arm arm) const {
  ActuatorReadings r;
  r.position = arms_.measured(arm);
  r.velocity = arms_.velocities(arm);
  r.effort = arms_.efforts(arm);
  r.motor_position = drive_.toMotor(r.position);
  r.motor_velocity = drive_.toMotor(r.velocity);
  r.encoder = drive_.encoderCounts(r.motor_position);
  return r;
}

}  // namespace twin
