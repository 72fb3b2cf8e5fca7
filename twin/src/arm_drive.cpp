#include "twin/arm_drive.hpp"

#include <algorithm>
#include <stdexcept>

namespace twin {

ArmDrive::ArmDrive(Arm arm, const DriveTrain& drive, const MotorMechanics& mechanics, double cycle,
                   const ArmJoints& joints, ArmStops stops)
    : ArmDrive(arm, drive, cycle, std::move(stops), MotorAxes(mechanics.checked(arm))) {
  const ArmJoints motor = drive_.toMotor(arm, joints);
  std::get<MotorAxes>(motors_).place(motor, ArmJoints::Zero());
  last_count_ = drive_.quantise(motor);
  sense();
  readings_.motor_setpoint = readings_.motor_position;
}

ArmDrive::ArmDrive(Arm arm, const DriveTrain& drive, const WorldMotors& motors, double cycle)
    : ArmDrive(arm, drive, cycle, {}, motors) {
  last_count_ = drive_.quantise(motors.position());
  sense();
  readings_.motor_setpoint = readings_.motor_position;
}

ArmDrive::ArmDrive(Arm arm, const DriveTrain& drive, double cycle, ArmStops stops,
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
             " DAC counts) passed the overdrive threshold (soft e-stop); motor error " +
             std::to_string(r.motor_setpoint(over.motor) - r.motor_position(over.motor)) +
             " rad, velocity " + std::to_string(r.motor_velocity(over.motor)) + " rad/s, Tau " +
             std::to_string(command.torque(over.motor)) + " N m (gravity " +
             std::to_string(command.gravity(over.motor)) + ")";
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
  if (motors == nullptr) return;
  ArmJoints q = drive_.toJoints(arm_, motors->position());
  const bool within_joints =
      !stops_.joints ||
      (q.array() >= stops_.joints->low.array() && q.array() <= stops_.joints->high.array()).all();
  const double closed_past = stops_.jaws_meet
                                 ? *stops_.jaws_meet + motors->mechanics().jawsMeetOffset() -
                                       (q(raven::kJaw1) + q(raven::kJaw2))
                                 : 0.0;
  if (within_joints && closed_past <= 0.0) return;
  ArmJoints v = drive_.toJoints(arm_, motors->velocity());  // linear: velocities map alike
  if (!within_joints) {
    for (int j = 0; j < kJointCount; ++j) {
      if (q(j) < stops_.joints->low(j)) {
        q(j) = stops_.joints->low(j);
        v(j) = std::max(v(j), 0.0);
      } else if (q(j) > stops_.joints->high(j)) {
        q(j) = stops_.joints->high(j);
        v(j) = std::min(v(j), 0.0);
      }
    }
  }
  if (closed_past > 0.0) {
    // The faces' impulse parts the jaws along (1, 1), each by its share of the pair's mobility
    // (its motor's inverse inertia; the two jaws' cables and ratios are alike): the overlap
    // and the closing speed are gone, the pair's twist kept.
    const ArmJoints& inertia = motors->mechanics().inertia;
    const double mobility1 = 1.0 / inertia(raven::kJaw1), mobility2 = 1.0 / inertia(raven::kJaw2);
    const double share1 = mobility1 / (mobility1 + mobility2);
    const double closing = std::min(v(raven::kJaw1) + v(raven::kJaw2), 0.0);
    q(raven::kJaw1) += share1 * closed_past;
    q(raven::kJaw2) += (1.0 - share1) * closed_past;
    v(raven::kJaw1) -= share1 * closing;
    v(raven::kJaw2) -= (1.0 - share1) * closing;
  }
  motors->place(drive_.toMotor(arm_, q), drive_.toMotor(arm_, v));
}

}  // namespace twin
