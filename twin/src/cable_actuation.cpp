#include "twin/cable_actuation.hpp"

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "common/yaml_view.hpp"
#include "yaml_joints.hpp"

namespace twin {

namespace {

using raven::ArmJoints;
using raven::kJointCount;

double readPositive(const common::YamlView& node) {
  const double v = node.asDouble();
  if (v <= 0.0) node.fail("must be > 0");
  return v;
}

}  // namespace

CableActuationParams CableActuationParams::load(const std::filesystem::path& file) {
  const auto root = common::YamlView::parseFile(file);
  std::vector<common::LoadIssue> warnings;
  root.checkKeys(
      {"kp", "kd", "max_motor_torque", "rotor_inertia", "friction", "link_inertia", "cable_mode_hz",
       "cable_damping_ratio", "velocity_filter_hz", "encoder_noise_counts", "seed"},
      {true, warnings});
  if (!warnings.empty()) throw common::LoadError(warnings);
  CableActuationParams p;
  p.kp = readJoints(root["kp"], 0.0, false);
  p.kd = readJoints(root["kd"], 0.0, false);
  p.max_motor_torque = readJoints(root["max_motor_torque"], 0.0, true);
  p.rotor_inertia = readJoints(root["rotor_inertia"], 0.0, true);
  p.friction = readJoints(root["friction"], 0.0, false);
  p.link_inertia = readJoints(root["link_inertia"], 0.0, true);
  p.cable_mode_hz = readJoints(root["cable_mode_hz"], 0.0, true);
  p.cable_damping_ratio = root["cable_damping_ratio"].asDouble();
  if (p.cable_damping_ratio < 0.0) root["cable_damping_ratio"].fail("must be >= 0");
  p.velocity_filter_hz = readPositive(root["velocity_filter_hz"]);
  p.encoder_noise_counts = root["encoder_noise_counts"].asDouble();
  if (p.encoder_noise_counts < 0.0) root["encoder_noise_counts"].fail("must be >= 0");
  const int seed = root["seed"].asInt();
  if (seed < 0) root["seed"].fail("must be >= 0");
  p.seed = static_cast<unsigned>(seed);
  return p;
}

CableActuationParams CableActuationParams::physicalStandIn() {
  return load(std::filesystem::path(RAVEN_TWIN_CONFIG_DIR) / "physical_stand_in.yaml");
}

CableActuation::CableActuation(twin::TwinArms& arms, DriveTrain drive,
                               const CableActuationParams& params, double cycle)
    : arms_(arms),
      drive_(drive),
      params_(params),
      cycle_(cycle),
      velocity_alpha_(1.0 - std::exp(-2.0 * M_PI * params.velocity_filter_hz * cycle)),
      random_(params.seed) {
  for (int i = 0; i < kJointCount; ++i) {
    // Motor (reflected through the transmission) and link, coupled by the cable; the motor
    // torque u acts on the motor side. Exact zero-order-hold discretisation over one cycle.
    const double ratio = drive_.transmission(i);
    const double motor = params.rotor_inertia(i) * ratio * ratio;
    const double link = params.link_inertia(i);
    const double omega = 2.0 * M_PI * params.cable_mode_hz(i);
    const double k = link * omega * omega;
    const double c = 2.0 * params.cable_damping_ratio * std::sqrt(k * link);
    const double b = params.friction(i);
    Eigen::Matrix<double, 5, 5> m = Eigen::Matrix<double, 5, 5>::Zero();
    m.topLeftCorner<4, 4>() << 0, 1, 0, 0,                   //
        -k / motor, -(c + b) / motor, k / motor, c / motor,  //
        0, 0, 0, 1,                                          //
        k / link, c / link, -k / link, -c / link;
    m(1, 4) = 1.0 / motor;
    const Eigen::Matrix<double, 5, 5> e = (m * cycle).exp();
    plant_[static_cast<std::size_t>(i)] = {e.topLeftCorner<4, 4>(), e.topRightCorner<4, 1>()};
  }
  for (raven::Arm arm : raven::kArms) {
    const ArmJoints q = arms_.measured(arm);
    for (int i = 0; i < kJointCount; ++i) {
      state_[index(arm)][static_cast<std::size_t>(i)] = JointState(q(i), 0.0, q(i), 0.0);
    }
    motor_torque_[index(arm)].setZero();
    measure(arm);
    readings_[index(arm)].velocity.setZero();
    readings_[index(arm)].motor_velocity.setZero();
  }
}

void CableActuation::drive(raven::Arm arm, const ArmJoints& setpoint,
                           const ArmJoints& setpoint_velocity) {
  const auto a = index(arm);
  const ActuatorReadings& sensed = readings_[a];
  // The firmware's law, on motor angles: tau = kp (mpos_d - mpos) + kd (mvel_d - mvel), then
  // the amplifiers' current clipping.
  const ArmJoints motor_torque =
      (params_.kp.cwiseProduct(drive_.toMotor(setpoint) - sensed.motor_position) +
       params_.kd.cwiseProduct(drive_.toMotor(setpoint_velocity) - sensed.motor_velocity))
          .cwiseMax(-params_.max_motor_torque)
          .cwiseMin(params_.max_motor_torque);
  motor_torque_[a] = motor_torque;
  ArmJoints link;
  for (int i = 0; i < kJointCount; ++i) {
    auto& x = state_[a][static_cast<std::size_t>(i)];
    const auto& p = plant_[static_cast<std::size_t>(i)];
    x = p.phi * x + p.gamma * (motor_torque(i) * drive_.transmission(i));
    link(i) = x(2);
  }
  arms_.command(arm, link);
  measure(arm);
}

void CableActuation::measure(raven::Arm arm) {
  const auto a = index(arm);
  ActuatorReadings& r = readings_[a];
  const ArmJoints previous = r.position;
  std::normal_distribution<double> noise(0.0, params_.encoder_noise_counts);
  ArmJoints motor;
  for (int i = 0; i < kJointCount; ++i) {
    const double exact = state_[a][static_cast<std::size_t>(i)](0) * drive_.transmission(i);
    const double extra = params_.encoder_noise_counts > 0.0 ? noise(random_) : 0.0;
    const double counts = std::round(exact * drive_.countsPerMotorRadian() + extra);
    r.encoder[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(counts);
    motor(i) = counts / drive_.countsPerMotorRadian();
  }
  r.motor_position = motor;
  r.position = motor.cwiseQuotient(drive_.transmission);
  r.velocity += velocity_alpha_ * ((r.position - previous) / cycle_ - r.velocity);
  r.motor_velocity = drive_.toMotor(r.velocity);
  r.effort = motor_torque_[a].cwiseProduct(drive_.transmission);
}

}  // namespace twin
