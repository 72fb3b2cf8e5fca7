#include "twin/ideal_actuation.hpp"

namespace twin {

void IdealActuation::drive(raven::Arm arm, const raven::ArmJoints& setpoint) {
  arms_.command(arm, setpoint);
}

void IdealActuation::place(raven::Arm arm, const ArmStart& start) {
  arms_.command(arm, drive_.toJoints(arm, start.motor_position));
}

ActuatorReadings IdealActuation::read(raven::Arm arm) const {
  ActuatorReadings r;
  r.position = arms_.measured(arm);
  r.velocity = arms_.velocities(arm);
  r.effort = arms_.efforts(arm);
  r.motor_position = drive_.toMotor(arm, r.position);
  r.motor_velocity = drive_.toMotor(arm, r.velocity);
  r.motor_setpoint = r.motor_position;
  r.encoder = drive_.encoderCounts(r.motor_position);
  return r;
}

}  // namespace twin
