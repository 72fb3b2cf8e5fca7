#include "calibration/setpoint_replay.hpp"

#include <cmath>

#include "raven/control_cycle.hpp"
#include "twin/twin_arms.hpp"

namespace calibration {

namespace {

using Rows = std::vector<recording::ArmSignals>;

/// The recording's setpoint at `t`, linear between rows.
raven::ArmJoints setpointAt(const Rows& arm, const std::vector<double>& time, std::size_t& row,
                            double t) {
  while (row + 1 < time.size() && time[row + 1] <= t) ++row;
  if (row + 1 >= time.size()) return arm[row].joint_setpoint;
  const double s = (t - time[row]) / (time[row + 1] - time[row]);
  return arm[row].joint_setpoint + s * (arm[row + 1].joint_setpoint - arm[row].joint_setpoint);
}

/// What a row of the robot's log would hold for this cycle's readings.
recording::ArmSignals signalsOf(const twin::ActuatorReadings& r, const raven::ArmJoints& setpoint) {
  raven::ArmJoints dac;
  for (int j = 0; j < raven::kJointCount; ++j) dac(j) = r.dac[static_cast<std::size_t>(j)];
  return {r.position, setpoint, r.motor_position, r.motor_velocity, r.motor_setpoint,
          r.torque,   dac};
}

}  // namespace

twin::RecordedStart traceStart(const analysis::ActuatorTrace& trace) {
  return twin::recordedStart({trace.arms[0].front(), trace.arms[1].front()});
}

analysis::ActuatorTrace replaySetpoints(const analysis::ActuatorTrace& recording,
                                        const twin::ArmsMechanics& mechanics) {
  analysis::ActuatorTrace out;
  out.name = "twin from " + recording.name;
  out.time = recording.time;
  const twin::DriveTrain drive = twin::DriveTrain::raven2();
  const twin::RecordedStart start = traceStart(recording);
  for (raven::Arm arm : raven::kArms) {
    const auto a = raven::slot(arm);
    const Rows& in = recording.arms[a];
    // The robot's jaws meet where our model's do; its joints' stops are never reached here.
    twin::ArmDrive motors(arm, drive, mechanics[a], raven::kControlCycle, in.front().joints,
                          {std::nullopt, twin::ArmBindings::ourRaven().jaws_meet});
    motors.place(start.arms[a]);
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
      out.arms[a].push_back(
          signalsOf(*now, setpointAt(in, recording.time, segment, recording.time[r])));
    }
  }
  return out;
}

}  // namespace calibration
