#include "raven_state_builder.hpp"

#include <cmath>

namespace twin {

namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;
constexpr double kMicronsPerMetre = 1e6;

/// Writes one arm's joint vector, in degrees, into a 16-element array.
void putDegrees(std::array<float, 16>& out, Arm arm, const ArmJoints& q) {
  for (int i = 0; i < raven::kJointCount; ++i) {
    out[static_cast<std::size_t>(bridge::ravenStateIndex(arm, i))] =
        static_cast<float>(q(i) * kDegreesPerRadian);
  }
}

void putPose(std::array<std::int32_t, 6>& position, std::array<float, 18>& rotation, Arm arm,
             const Eigen::Isometry3d& pose) {
  const auto a = raven::slot(arm);
  for (std::size_t r = 0; r < 3; ++r) {
    position[a * 3 + r] = static_cast<std::int32_t>(
        std::lround(pose.translation()(static_cast<int>(r)) * kMicronsPerMetre));
    for (std::size_t c = 0; c < 3; ++c) {
      rotation[a * 9 + r * 3 + c] =
          static_cast<float>(pose.linear()(static_cast<int>(r), static_cast<int>(c)));
    }
  }
}

}  // namespace

std::pair<std::int32_t, std::int32_t> runlevelOf(const OperatingStatus& status) {
  const std::int32_t homed = status.is_homed ? 1 : 0;
  switch (status.state) {
    case OperatingState::Enabled:
      return {status.is_homed ? bridge::kPedalDown : bridge::kInit, homed};
    case OperatingState::Paused:
      return {bridge::kPedalUp, homed};
    case OperatingState::Disabled:
    case OperatingState::Fault:
      break;
  }
  return {bridge::kEStop, homed};
}

RavenStateSnapshot makeRavenState(const TwinStateSources& s) {
  const RavenCore& core = s.core;
  RavenStateSnapshot out;
  out.time = core.time();
  std::tie(out.runlevel, out.sublevel) = runlevelOf(core.status());
  out.last_seq = static_cast<std::int32_t>(core.commandsTaken() & 0x7fffffff);
  out.type = {bridge::kGoldArmType, bridge::kGreenArmType};
  out.dt = core.limits().cycle;
  for (Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const ActuatorReadings& r = s.readings[a];
    const ArmJoints& setpoint = core.setpoint(arm);
    const Eigen::Isometry3d pose = core.reportedPose(arm, r.position);
    putPose(out.pos, out.ori, arm, pose);
    putPose(out.pos_d, out.ori_d, arm, core.reportedPose(arm, setpoint));
    putDegrees(out.mpos, arm, r.motor_position);
    putDegrees(out.mvel, arm, r.motor_velocity);
    putDegrees(out.jpos, arm, r.position);
    putDegrees(out.jvel, arm, r.velocity);
    putDegrees(out.mpos_d, arm, r.motor_setpoint);
    putDegrees(out.jpos_d, arm, setpoint);
    for (int i = 0; i < raven::kJointCount; ++i) {
      const auto k = static_cast<std::size_t>(bridge::ravenStateIndex(arm, i));
      out.enc_vals[k] = r.encoder[static_cast<std::size_t>(i)];
      out.dac_val[k] = r.dac[static_cast<std::size_t>(i)];
      out.tau[k] = static_cast<float>(r.torque(i));
    }
    out.grasp_d[a] =
        static_cast<float>((setpoint(raven::kJaw1) + setpoint(raven::kJaw2)) * kDegreesPerRadian);
    // Tool twist over the last cycle: linear then angular velocity.
    const Eigen::Isometry3d before = core.reportedPose(arm, s.previous_position[a]);
    const double dt = core.limits().cycle;
    const Eigen::Vector3d linear = (pose.translation() - before.translation()) / dt;
    const Eigen::AngleAxisd turn(pose.linear() * before.linear().transpose());
    const Eigen::Vector3d angular = turn.axis() * turn.angle() / dt;
    for (std::size_t k = 0; k < 3; ++k) {
      out.jac_vel[a * 6 + k] = static_cast<float>(linear(static_cast<int>(k)));
      out.jac_vel[a * 6 + 3 + k] = static_cast<float>(angular(static_cast<int>(k)));
    }
  }
  return out;
}

}  // namespace twin
