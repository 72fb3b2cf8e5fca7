#include "twin/arm_drive.hpp"

#include <Eigen/LU>
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
      coupling_(drive.coupling(arm)) {
  ArmJoints jaws = ArmJoints::Zero();
  jaws(raven::kJaw1) = jaws(raven::kJaw2) = 1.0;
  // d(jaw1 + jaw2)/d(motor angles) is C^-T (1 on each jaw); joint loads are C^T (torque /
  // gearbox), so the torques that press each jaw with one N m are the gearbox times the same.
  opening_per_motor_ = coupling_.transpose().partialPivLu().solve(jaws);
  opening_torques_ = drive_.gearbox.cwiseProduct(opening_per_motor_);
}

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
  const ArmJoints pushed = command.applied + facesPush(command.applied);
  std::visit([&](auto& m) { m.step(pushed, command.gravity, cycle_); }, motors_);
  holdAtStops();
  return r;
}

double ArmDrive::jawsGap(const MotorAxes& motors) const {
  const ArmJoints q = drive_.toJoints(arm_, motors.position());
  return q(raven::kJaw1) + q(raven::kJaw2) -
         (*stops_.jaws_meet + motors.mechanics().jawsMeetOffset());
}

ArmJoints ArmDrive::facesPush(const ArmJoints& applied) const {
  const auto* motors = std::get_if<MotorAxes>(&motors_);
  if (motors == nullptr || !stops_.jaws_meet) return ArmJoints::Zero();
  const MotorMechanics& m = motors->mechanics();
  const double compliance = m.jawsMeetCompliance();
  if (compliance <= 0.0) return ArmJoints::Zero();
  // The soft row of CoupledLimitConstraint on the opening: the impulse (N m s on each jaw)
  // solves (A + compliance / h^2) impulse = -(opening rate + gap / h), pushing only, where A
  // is how fast one N m s opens the jaws through the motors' inertia, and the rate is the one
  // the motors' torques alone would give at the cycle's end (their friction only slows it).
  const double h = cycle_;
  const double gap = jawsGap(*motors);
  const ArmJoints free_velocity = motors->velocity() + h * applied.cwiseQuotient(m.inertia);
  const double mobility = opening_per_motor_.dot(opening_torques_.cwiseQuotient(m.inertia));
  const double impulse = std::max(-(opening_per_motor_.dot(free_velocity) + gap / h), 0.0) /
                         (mobility + compliance / (h * h));
  return opening_torques_ * (impulse / h);
}

void ArmDrive::holdAtStops() {
  auto* motors = std::get_if<MotorAxes>(&motors_);
  if (motors == nullptr) return;
  ArmJoints q = drive_.toJoints(arm_, motors->position());
  const bool within_joints =
      !stops_.joints ||
      (q.array() >= stops_.joints->low.array() && q.array() <= stops_.joints->high.array()).all();
  const bool rigid_faces = stops_.jaws_meet && motors->mechanics().jawsMeetCompliance() <= 0.0;
  const double closed_past = rigid_faces ? std::max(-jawsGap(*motors), 0.0) : 0.0;
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
