#pragma once
// raven_analyze forces: a recording's motor signals read back into the forces behind them
// (twin::ArmForceEstimator for each arm), written beside the twin's own cf columns.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "twin/calibration_profile.hpp"
#include "twin/force_estimator.hpp"

namespace analysis {

/// Estimated forces per row: `time`, then per arm (left_, right_) fx, fy, fz, jaw1_normal,
/// jaw2_normal (the cf file's names and meaning), then the same with `_sd` appended, then each
/// arm's jaw opening (`left_opening`, `right_opening`: jaw1 + jaw2, rad).
struct ForceTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  std::size_t column(const std::string& name) const;  ///< throws std::out_of_range
};

/// The estimates of `rs` under `profile` (its mechanics and their uncertainty). Throws
/// recording::RecordingError for a file that is not an rs file, std::invalid_argument naming it
/// when no row has the motor signals (an AMBF recording).
ForceTable estimateForces(const std::filesystem::path& rs, const twin::CalibrationProfile& profile,
                          const twin::GripLever& grip);

void writeForces(const ForceTable& table, const std::filesystem::path& csv);

/// Draws `dir`/forces.png from `dir`/forces.csv, with the cf file's forces beside it when given:
/// runDrawScript's answer (empty on success).
std::string drawForces(const std::filesystem::path& dir,
                       const std::optional<std::filesystem::path>& truth_cf);

/// One recording's estimates, with the twin's cf file of the same run when there is one.
struct ForceRun {
  ForceTable table;
  std::optional<std::filesystem::path> truth_cf;
};

/// Per channel, over every run's rows: the mean estimate and the mean of its sd; the same over
/// the rows where the arm's jaws are apart (faces more than 1 mm apart at their tips: not on
/// each other); over the rows where a run's cf file says the channel touches (a jaw's force
/// above 0.05 N, a tool with contacts), the median estimate and truth, the share of rows within
/// 2 sd of the truth, and the share within 25 % of it or 0.15 N, whichever is larger.
struct ChannelSummary {
  std::string name;
  double mean = 0.0, mean_sd = 0.0;
  std::size_t rows = 0;
  double apart_mean = 0.0, apart_sd = 0.0;
  std::size_t apart_rows = 0;
  std::optional<double> truth_median, estimate_median, within_2sd, within_25_percent;
  std::size_t truth_rows = 0;
};
/// Throws std::invalid_argument naming a cf file whose rows do not pair with its run's.
std::vector<ChannelSummary> summarise(const std::vector<ForceRun>& runs);

}  // namespace analysis
