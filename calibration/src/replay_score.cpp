#include "calibration/replay_score.hpp"

#include <stdexcept>

#include "controller/first_move.hpp"

namespace calibration {

namespace {

/// The first move the trial's controller made (controller::firstMoveOf its setpoints).
std::optional<raven::ArmPair> firstMove(const analysis::ActuatorTrace& trace,
                                        const ReplaySetup& setup) {
  std::vector<raven::ArmPair> setpoints;
  for (std::size_t r = 0; r < trace.rows(); ++r) {
    setpoints.push_back({trace.arms[0][r].joint_setpoint, trace.arms[1][r].joint_setpoint});
  }
  return controller::firstMoveOf(setpoints, setup.inputs, setup.controller.mapping.deadzone);
}

}  // namespace

int ReplayScore::figuresWithin() const {
  int n = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    const auto t = twin[k].values();
    const auto r = robot[k].values();
    for (std::size_t i = 0; i < t.size(); ++i) n += t[i] <= r[i] ? 1 : 0;
  }
  return n;
}

ReplayScore scoreReplays(ReplaySetup setup, const std::vector<analysis::Trial>& physical) {
  if (physical.size() < 2) {
    throw std::invalid_argument("the robot's spread needs two physical trials");
  }
  analysis::RecordingSource twin_profile;
  twin_profile.name = "twin";
  ReplayScore score;
  std::vector<analysis::ActuatorTrace> physical_traces, twin_traces;
  for (const analysis::Trial& trial : physical) {
    if (!trial.actuators) {
      throw std::invalid_argument(trial.path.string() + ": logs no actuator signals to start from");
    }
    physical_traces.push_back(*trial.actuators);
    setup.start = traceStart(*trial.actuators);
    setup.first_move = firstMove(*trial.actuators, setup);
    score.replays.push_back(recordReplay(setup));
    twin_traces.push_back(analysis::actuatorTrace(score.replays.back()));
    const analysis::Trial twin = analysis::toTrial(score.replays.back(), twin_profile);
    for (std::size_t k = 0; k < 2; ++k) {
      const auto f = twinVsPhysical(twin, physicalTrials({trial}), k == 1).values();
      const double n = static_cast<double>(physical.size());
      score.twin[k].revolute_position += f[0] / n;
      score.twin[k].insertion_position += f[1] / n;
      score.twin[k].revolute_velocity += f[2] / n;
      score.twin[k].insertion_velocity += f[3] / n;
    }
  }
  const auto all = physicalTrials(physical);
  score.robot = {robotRepeatability(all, false), robotRepeatability(all, true)};
  score.actuators = analysis::actuatorFidelity(twin_traces, physical_traces);
  return score;
}

}  // namespace calibration
