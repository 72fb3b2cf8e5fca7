#include "calibration/setpoint_replay.hpp"

#include <cmath>

#include "raven/control_cycle.hpp"

namespace calibration {

namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

/// The recording's setpoint at `t`, linear between rows.
raven::ArmJoints setpointAt(const analysis::ArmTrace& arm, const std::vector<double>& time,
                            std::size_t& row, double t) {
  while (row + 1 < time.size() && time[row + 1] <= t) ++row;
  if (row + 1 >= time.size()) return arm.joint_setpoint[row];
  const double s = (t - time[row]) / (time[row + 1] - time[row]);
  return arm.joint_setpoint[row] + s * (arm.joint_setpoint[row + 1] - arm.joint_setpoint[row]);
}

}  // namespace

twin::RecordedStart recordedStart(const analysis::ActuatorTrace& trace) {
  std::array<recording::ArmSignals, 2> first{};
  for (std::size_t a = 0; a < 2; ++a) {
    const analysis::ArmTrace& t = trace.arms[a];
    first[a] = {t.joints[0],
                t.joint_setpoint[0],
                t.motor[0] / kDegreesPerRadian,
                t.motor_velocity[0] / kDegreesPerRadian,
                t.motor_setpoint[0],
                t.torque[0],
                t.dac[0]};
  }
  return twin::recordedStart(first);
}

analysis::ActuatorTrace replaySetpoints(const analysis::ActuatorTrace& recording,
                                        const twin::ArmsMechanics& mechanics) {
  analysis::ActuatorTrace out;
  out.name = "twin from " + recording.name;
  out.time = recording.time;
  const twin::DriveTrain drive = twin::DriveTrain::raven2();
  const twin::RecordedStart start = recordedStart(recording);
  for (raven::Arm arm : raven::kArms) {
    const auto a = static_cast<std::size_t>(raven::index(arm));
    const analysis::ArmTrace& in = recording.arms[a];
    twin::ArmDrive motors(arm, drive, mechanics[a], raven::kControlCycle, in.joints[0]);
    motors.place(start.arms[a]);
    analysis::ArmTrace& t = out.arms[a];
    std::size_t segment = 0;
    std::size_t cycle = 0;
    for (std::size_t r = 0; r < recording.rows(); ++r) {
      // Run every cycle up to this row's time; the row holds that cycle's signals.
      const auto last =
          static_cast<std::size_t>(std::llround(recording.time[r] / raven::kControlCycle));
      const twin::ActuatorReadings* now = &motors.readings();
      for (; cycle <= last; ++cycle) {
        now = &motors.cycle(setpointAt(in, recording.time, segment,
                                       static_cast<double>(cycle) * raven::kControlCycle));
      }
      t.joints.push_back(now->position);
      t.joint_setpoint.push_back(setpointAt(in, recording.time, segment, recording.time[r]));
      t.motor.push_back(now->motor_position * kDegreesPerRadian);
      t.motor_velocity.push_back(now->motor_velocity * kDegreesPerRadian);
      t.motor_setpoint.push_back(now->motor_setpoint);
      t.torque.push_back(now->torque);
      raven::ArmJoints dac;
      for (int j = 0; j < raven::kJointCount; ++j) dac(j) = now->dac[static_cast<std::size_t>(j)];
      t.dac.push_back(dac);
    }
  }
  return out;
}

}  // namespace calibration
