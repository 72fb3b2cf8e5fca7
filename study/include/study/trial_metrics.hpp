#pragma once
// What one trial's recordings say about how it went: completion time, targets and rings,
// overshoots, the tool tips' path length, idle time and smoothness (SPARC), the controller's
// joint-limit clamps and velocity-cap splits, the grasp forces (material contact forces) and
// the tools' contacts with the board. Read from the trial's rs, cf and events files only, so a
// finished trial can be measured again by anyone.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace study {

/// Metric name -> value; NaN where it does not apply (no grasp, no targets).
using TrialMetrics = std::map<std::string, double>;

/// Every metric a trial has, in report order.
const std::vector<std::string>& metricNames();
/// What a metric measures, with its unit.
std::string metricMeaning(const std::string& name);
/// Which way is better: -1 lower, +1 higher, 0 neither (forces); 0 for an unknown name.
int metricSense(const std::string& name);

/// Measures the trial recorded in `dir` (its *_rs.csv, *_cf.csv and events.csv). Throws
/// recording::RecordingError naming a missing or unreadable file.
TrialMetrics measureTrial(const std::filesystem::path& dir);

/// The spectral arc length of a speed profile sampled at `rate` Hz (Balasubramanian et al.
/// 2015: 10 Hz cut-off, 5 % amplitude threshold, padded four powers of two): -1.41 for one
/// minimum-jerk reach, more negative as the movement breaks into corrections. NaN for a profile
/// that never moves.
double sparc(const std::vector<double>& speed, double rate);

}  // namespace study
