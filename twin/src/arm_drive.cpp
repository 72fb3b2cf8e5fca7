#include "twin/arm_drive.hpp"

#include <algorithm>
#include <stdexcept>

namespace twin {

ArmDrive::ArmDrive(Arm arm, const DriveTrain& drive, const MotorMechanics& mechanics, double cycle,
                   const ArmJoints& joints, const std::optional<raven::JointLimits>& stops)
    : ArmDrive(arm, drive, cycle, stops, MotorAxes(mechanics.checked(arm))) {
  const ArmJoints motor = drive_.toMotor(arm, joints);
  std::get<MotorAxes>(motors_).place(motor, ArmJoints::Zero());
  last_count_ = drive_.quantise(motor);
  sense();
  readings_.motor_setpoint = readings_.motor_position;
}

ArmDrive::ArmDrive(Arm arm, const DriveTrain& drive, const WorldMotors& motors, double cycle)
    : ArmDrive(arm, drive, cycle, std::nullopt, motors) {
  last_count_ = drive_.quantise(motors.position());
  sense();
  readings_.motor_setpoint = readings_.motor_position;
}

ArmDrive::ArmDrive(Arm arm, const DriveTrain& drive, double cycle,
                   std::optional<raven::JointLimits> stops,
                   std::variant<MotorAxes, WorldMotors> motors)
    : arm_(arm),
      drive_(drive),
      cycle_(cycle),
      stops_(std::move(stops)),
      motors_(std::move(motors)),
      controller_(arm, drive),
      coupling_(drive.coupling(arm)) {}

ArmJoints ArmDrive::linkPosition() const {
  return drive_.toJoints(arm_, std::visit([](const auto& m) { return m.position(); }, motors_));
}

void ArmDrive::place(const ArmStart& start) {
  std::visit([&](auto& m) { m.place(start.motor_position, start.motor_velocity); }, motors_);
  last_count_ = drive_.quantise(start.motor_position - start.motor_velocity * cycle_);
  controller_.setIntegrators(start.integrators);
  readings_.motor_position = drive_.quantise(start.motor_position);
  readings_.motor_velocity = start.motor_velocity;
  readings_.position = drive_.toJoints(arm_, readings_.motor_position);
  readings_.velocity = drive_.toJoints(arm_, readings_.motor_velocity);
}

void ArmDrive::sense() {
  ActuatorReadings& r = readings_;
  r.motor_position =
      drive_.quantise(std::visit([](const auto& m) { return m.position(); }, motors_));
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
    const Overdrive& over = *command.overdrive;
    fault_ = "the " + std::string(armName(arm_)) + " arm's " +
             std::string(kJointNames[static_cast<std::size_t>(over.motor)]) +
             " amplifier command (" + std::to_string(static_cast<long>(over.counts)) +
             " DAC counts) passed the overdrive threshold (soft e-stop)";
  }
  if (!fault_.empty()) {  // the soft e-stop keeps the amplifiers off until the robot is enabled
    command.dac.fill(0);
    command.applied.setZero();
  }
  r.torque = command.torque;
  r.dac = command.dac;
  r.effort = coupling_.transpose() * command.applied.cwiseQuotient(drive_.gearbox);
  std::visit([&](auto& m) { m.step(command.applied, command.gravity, cycle_); }, motors_);
  holdAtStops();
  return r;
}

void ArmDrive::holdAtStops() {
  auto* motors = std::get_if<MotorAxes>(&motors_);
  if (!stops_ || motors == nullptr) return;
  const raven::JointLimits& stops = *stops_;
  ArmJoints q = drive_.toJoints(arm_, motors->position());
  if ((q.array() >= stops.low.array() && q.array() <= stops.high.array()).all()) return;
  ArmJoints v = drive_.toJoints(arm_, motors->velocity());  // linear: velocities map alike
  for (int j = 0; j < kJointCount; ++j) {
    if (q(j) < stops.low(j)) {
      q(j) = stops.low(j);
      v(j) = std::max(v(j), 0.0);
    } else if (q(j) > stops.high(j)) {
      q(j) = stops.high(j);
      v(j) = std::min(v(j), 0.0);
    }
  }
  motors->place(drive_.toMotor(arm_, q), drive_.toMotor(arm_, v));
}

}  // namespace twin
