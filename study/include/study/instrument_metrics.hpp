#pragma once
// The surgical simulators' instrument metrics, computed from a trial's recordings: excessive force
// (time and peak of a jaw pressing harder than a threshold), the time each instrument spent
// between a pair of events (out of view), and the workspace range of a path (a tool tip's, or a
// stick's deflections).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "raven/arm.hpp"
#include "recording/cf_recording.hpp"
#include "recording/gamepad_state.hpp"
#include "study/trial_events.hpp"
#include "study/trial_metrics.hpp"

namespace study {

/// How long and how hard the jaws pressed on anything above a threshold.
struct ExcessiveForce {
  double time = 0.0;  ///< s with either arm's harder-pressing jaw above the threshold
  double peak = 0.0;  ///< N: the largest such jaw force; 0 when none went above
};

/// Per cf row, each arm's larger jaw normal force against `threshold` (N). Rows without forces
/// (NaN) count as none.
ExcessiveForce excessiveForce(const recording::CfRecording& cf, double threshold);

/// The time (s) between each `begin` event and its arm's next `end` event (or `trial_end`),
/// summed over the arms.
double timeBetween(const std::vector<TrialEvent>& events, const std::string& begin,
                   const std::string& end, double trial_end);

/// The radius of the volume a path used (the simulators' "master workspace range"): half the
/// largest distance between two of its points, so it does not depend on how long the path
/// stayed where. 0 for fewer than two points.
double workspaceRange(const std::vector<Eigen::Vector3d>& points);

/// Adds the instrument metrics to `m`: collisions (episodes, from the events), excessive force
/// (the cf rows against the threshold the trial recorded), the time out of view, and the
/// workspace ranges of each tool tip (`tips`, controller frame) and each stick (`sticks`, one
/// reading per manual-loop iteration). `end`: the trial's length (s).
void measureInstruments(TrialMetrics& m, const std::vector<TrialEvent>& events,
                        const raven::PerArm<std::vector<Eigen::Vector3d>>& tips,
                        const recording::CfRecording& cf,
                        const std::vector<recording::GamepadState>& sticks, double end);

}  // namespace study
