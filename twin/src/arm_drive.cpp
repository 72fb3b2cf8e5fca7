#include "twin/arm_drive.hpp"

#include <algorithm>
#include <stdexcept>

namespace twin {

namespace {

const MotorMechanics& checked(Arm arm, const MotorMechanics& mechanics) {
  const std::string why = mechanics.invalidReason();
  if (!why.empty()) {
    throw std::invalid_argument("actuation of the " + std::string(armName(arm)) + " arm: " + why);
  }
  return mechanics;
}

}  // namespace

ArmDrive::ArmDrive(Arm arm, const DriveTrain& drive, const MotorMechanics& mechanics, double cycle,
                   const ArmJoints& joints, const std::optional<raven::JointLimits>& stops)
    : arm_(arm),
      drive_(drive),
      cycle_(cycle),
      stops_(stops),
      motors_(checked(arm, mechanics)),
      controller_(arm, drive) {
  for (int j = 0; j < kJointCount; ++j) coupling_.col(j) = drive_.toMotor(arm, ArmJoints::Unit(j));
  const ArmJoints motor = drive_.toMotor(arm, joints);
  motors_.place(motor, ArmJoints::Zero());
  last_count_ = drive_.quantise(motor);
  sense();
  readings_.motor_setpoint = readings_.motor_position;
}

void ArmDrive::place(const ArmStart& start) {
  motors_.place(start.motor_position, start.motor_velocity);
  last_count_ = drive_.quantise(start.motor_position - start.motor_velocity * cycle_);
  controller_.setIntegrators(start.integrators);
  readings_.motor_position = drive_.quantise(start.motor_position);
  readings_.motor_velocity = start.motor_velocity;
  readings_.position = drive_.toJoints(arm_, readings_.motor_position);
  readings_.velocity = drive_.toJoints(arm_, readings_.motor_velocity);
}

void ArmDrive::sense() {
  ActuatorReadings& r = readings_;
  r.motor_position = drive_.quantise(motors_.position());
  r.motor_velocity = (r.motor_position - last_count_) / cycle_;
  last_count_ = r.motor_position;
  r.encoder = drive_.encoderCounts(r.motor_position);
  r.position = drive_.toJoints(arm_, r.motor_position);
  r.velocity = drive_.toJoints(arm_, r.motor_velocity);  // linear: velocities map alike
}

const ActuatorReadings& ArmDrive::cycle(const ArmJoints& setpoint) {
  sense();
  ActuatorReadings& r = readings_;
  r.motor_setpoint = drive_.toMotor(arm_, setpoint, r.motor_position(raven::kInsertion));
  MotorCommand command =
      controller_.cycle(r.motor_setpoint, r.motor_position, r.motor_velocity, r.position);
  if (command.overdrive && fault_.empty()) {
    fault_ = "the " + std::string(armName(arm_)) +
             " arm's amplifier command passed the overdrive threshold (soft e-stop)";
  }
  if (!fault_.empty()) {  // the soft e-stop keeps the amplifiers off until the robot is enabled
    command.dac.fill(0);
    command.applied.setZero();
  }
  r.torque = command.torque;
  r.dac = command.dac;
  r.effort = coupling_.transpose() * command.applied.cwiseQuotient(drive_.gearbox);
  motors_.step(command.applied, command.gravity, cycle_);
  holdAtStops();
  return r;
}

void ArmDrive::holdAtStops() {
  if (!stops_) return;
  const raven::JointLimits& stops = *stops_;
  ArmJoints q = drive_.toJoints(arm_, motors_.position());
  if ((q.array() >= stops.low.array() && q.array() <= stops.high.array()).all()) return;
  ArmJoints v = drive_.toJoints(arm_, motors_.velocity());  // linear: velocities map alike
  for (int j = 0; j < kJointCount; ++j) {
    if (q(j) < stops.low(j)) {
      q(j) = stops.low(j);
      v(j) = std::max(v(j), 0.0);
    } else if (q(j) > stops.high(j)) {
      q(j) = stops.high(j);
      v(j) = std::min(v(j), 0.0);
    }
  }
  motors_.place(drive_.toMotor(arm_, q), drive_.toMotor(arm_, v));
}

}  // namespace twin
