#pragma once
// Recordings grouped into platforms, in the physical robot's joint convention, with every file
// the analysis could not use (or uses with a caveat) and why.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "analysis/actuator_signals.hpp"
#include "analysis/recording_source.hpp"

namespace analysis {

/// One replay: joint positions (profile offsets applied) and velocities per row, and its
/// actuator signals when the recording logs them.
struct Trial {
  std::filesystem::path path;
  std::vector<double> time;  ///< seconds from the first row
  std::vector<JointRow> position;
  std::vector<JointRow> velocity;
  /// Always by row, in the robot's joint convention (resampleOnTime leaves it as recorded).
  std::optional<ActuatorTrace> actuators;
  std::size_t rows() const { return time.size(); }
};

/// The trials of one platform.
struct PlatformTrials {
  RecordingSource profile;
  std::vector<Trial> trials;
};

/// What was wrong with a file: `excluded` files are left out of every figure; the others are
/// used as described (e.g. compared over their common rows, NaN rows skipped).
struct FileIssue {
  std::filesystem::path path;
  std::string reason;
  bool excluded = true;
};

/// Everything the metrics work on.
struct TrialSet {
  std::vector<PlatformTrials> platforms;  ///< in profile order, only those with trials
  std::vector<FileIssue> issues;
  const PlatformTrials* find(const std::string& name) const;
};

/// One recording as a trial of `profile`'s platform (its offsets applied, time from row 0).
Trial toTrial(const recording::RsRecording& rs, const RecordingSource& profile);

/// A run of at least this many rows with NaN in a joint column is reported.
constexpr std::size_t kNanRunReported = 5;

/// Reads every file once (directories: their *.csv files except *_ci.csv inputs and *_cf.csv
/// grasp forces), assigns each
/// to the first profile that claims it and checks it. Never throws for a bad file: the reason
/// goes into `issues`.
TrialSet loadTrials(const std::vector<std::filesystem::path>& inputs,
                    const std::vector<RecordingSource>& profiles);

/// Resamples every trial onto one time grid (linear interpolation, `period` apart, up to the
/// shortest trial), for aligning by time instead of by row index.
void resampleOnTime(TrialSet& set, double period);

}  // namespace analysis
