#include "analysis/force_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "analysis/metrics.hpp"
#include "analysis/report.hpp"
#include "raven/arm_kinematics.hpp"
#include "raven/platform_profile.hpp"
#include "recording/cf_recording.hpp"

namespace analysis {

namespace {

constexpr std::array<const char*, 5> kChannels{"fx", "fy", "fz", "jaw1_normal", "jaw2_normal"};
/// A cf channel counts as touching above this (N): the solver's rounding is far below it.
constexpr double kTouching = 0.05;
/// Jaws opened more than this (rad, jaw1 + jaw2) have their faces apart: 1 mm at their tips.
constexpr double kJawsApart = 0.1;
/// An estimate this close to the truth (N) counts as within 25 % of a smaller one (issue 65).
constexpr double kCloseEnough = 0.15;

/// One arm's values of `e` in kChannels order, then their sd.
std::array<double, 10> channels(const twin::ForceEstimate& e) {
  return {e.tip.x(),    e.tip.y(),    e.tip.z(),    e.jaw[0],    e.jaw[1],
          e.tip_sd.x(), e.tip_sd.y(), e.tip_sd.z(), e.jaw_sd[0], e.jaw_sd[1]};
}

}  // namespace

std::size_t ForceTable::column(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw std::out_of_range("no forces column '" + name + "'");
  return static_cast<std::size_t>(it - names.begin());
}

ForceTable estimateForces(const std::filesystem::path& rs_path,
                          const twin::CalibrationProfile& profile, const twin::GripLever& grip) {
  const recording::RsRecording rs = recording::readRs(rs_path, recording::NonFiniteJoints::Keep);
  const raven::PlatformProfile platform = raven::builtinProfile("physical");
  std::vector<double> times;
  for (std::size_t r = 0; r < rs.rows.size(); ++r) times.push_back(rs.time(r));
  ForceTable table;
  table.names.push_back("time");
  for (const char* suffix : {"", "_sd"}) {
    for (const char* arm : {"left_", "right_"}) {
      for (const char* c : kChannels) table.names.push_back(std::string(arm) + c + suffix);
    }
  }
  table.names.push_back("left_opening");
  table.names.push_back("right_opening");
  table.rows.assign(times.size(), std::vector<double>(table.names.size(), std::nan("")));
  for (std::size_t r = 0; r < times.size(); ++r) table.rows[r][0] = times[r];
  for (raven::Arm arm : raven::kArms) {
    std::vector<recording::ArmSignals> signals;
    for (std::size_t r = 0; r < rs.rows.size(); ++r) signals.push_back(rs.signals(r, arm));
    const twin::ArmForceEstimator estimator(arm, profile.mechanics[raven::slot(arm)],
                                            profile.uncertainty[raven::slot(arm)],
                                            raven::ArmKinematics::of(platform, arm), grip);
    std::vector<twin::ForceEstimate> estimates;
    try {
      estimates = estimator.estimate(times, signals);
    } catch (const std::invalid_argument& e) {  // a clock that runs back: say in which file
      throw std::invalid_argument(rs_path.string() + ": " + e.what());
    }
    const std::size_t base = 1 + raven::slot(arm) * kChannels.size();
    const std::size_t opening = table.names.size() - 2 + raven::slot(arm);
    for (std::size_t r = 0; r < estimates.size(); ++r) {
      table.rows[r][opening] = signals[r].joints(raven::kJaw1) + signals[r].joints(raven::kJaw2);
      const auto values = channels(estimates[r]);
      for (std::size_t c = 0; c < kChannels.size(); ++c) {
        table.rows[r][base + c] = values[c];
        table.rows[r][base + 2 * kChannels.size() + c] = values[kChannels.size() + c];
      }
    }
  }
  const std::size_t left = table.column("left_fx"), right = table.column("right_fx");
  if (std::none_of(table.rows.begin(), table.rows.end(), [&](const auto& row) {
        return std::isfinite(row[left]) || std::isfinite(row[right]);
      })) {
    throw std::invalid_argument(
        rs_path.string() +
        ": no row has the motor signals the estimate reads (jpos, mpos, mvel, mpos_d and Tau or "
        "dac_vals); AMBF's recordings log none");
  }
  return table;
}

std::string drawForces(const std::filesystem::path& dir,
                       const std::optional<std::filesystem::path>& truth_cf) {
  std::vector<std::filesystem::path> args{dir};
  if (truth_cf) args.push_back(*truth_cf);
  return runDrawScript(RAVEN_FORCES_DRAW_SCRIPT, args);
}

void writeForces(const ForceTable& table, const std::filesystem::path& csv) {
  std::ofstream out(csv);
  if (!out) throw std::runtime_error(csv.string() + ": cannot write");
  for (std::size_t c = 0; c < table.names.size(); ++c) {
    out << (c ? "," : "") << table.names[c];
  }
  out << '\n';
  for (const auto& row : table.rows) {
    for (std::size_t c = 0; c < row.size(); ++c)
      out << (c ? "," : "") << fmt::format("{:.6g}", row[c]);
    out << '\n';
  }
  if (!out) throw std::runtime_error(csv.string() + ": write failed");
}

namespace {

/// One channel's summary over `runs` (their cf files read: `cfs`, null where a run has none):
/// `arm` is "left_" or "right_", `channel` one of kChannels.
ChannelSummary summariseChannel(const std::vector<ForceRun>& runs,
                                const std::vector<std::optional<recording::CfRecording>>& cfs,
                                const std::string& arm, const std::string& channel) {
  ChannelSummary s;
  s.name = arm + channel;
  // What says the truth touches: a jaw's own force, the tool's contacts.
  const bool jaw = channel.starts_with("jaw");
  const double touch_above = jaw ? kTouching : 0.0;
  std::vector<double> estimates, truths;
  std::size_t within_2sd = 0, within_25 = 0;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const ForceTable& table = runs[k].table;
    const auto& cf = cfs[k];
    const std::size_t value = table.column(s.name), sd = table.column(s.name + "_sd");
    const std::size_t opening = table.column(arm + "opening");
    const std::size_t truth_column = cf ? cf->column(s.name) : 0;
    const std::size_t touch_column = cf ? cf->column(jaw ? s.name : arm + "contacts") : 0;
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      const auto& row = table.rows[r];
      if (!std::isfinite(row[value]) || !std::isfinite(row[sd])) continue;
      s.mean += row[value];
      s.mean_sd += row[sd];
      ++s.rows;
      if (row[opening] > kJawsApart) {
        s.apart_mean += row[value];
        s.apart_sd += row[sd];
        ++s.apart_rows;
      }
      if (!cf || !(cf->rows[r][touch_column] > touch_above)) continue;
      const double truth = cf->rows[r][truth_column], error = std::abs(row[value] - truth);
      estimates.push_back(row[value]);
      truths.push_back(truth);
      if (error <= 2.0 * row[sd]) ++within_2sd;
      if (error <= std::max(0.25 * std::abs(truth), kCloseEnough)) ++within_25;
    }
  }
  if (s.rows) {
    s.mean /= static_cast<double>(s.rows);
    s.mean_sd /= static_cast<double>(s.rows);
  }
  if (s.apart_rows) {
    s.apart_mean /= static_cast<double>(s.apart_rows);
    s.apart_sd /= static_cast<double>(s.apart_rows);
  }
  s.truth_rows = truths.size();
  if (!truths.empty()) {
    const auto n = static_cast<double>(truths.size());
    s.truth_median = median(truths);
    s.estimate_median = median(estimates);
    s.within_2sd = static_cast<double>(within_2sd) / n;
    s.within_25_percent = static_cast<double>(within_25) / n;
  }
  return s;
}

}  // namespace

std::vector<ChannelSummary> summarise(const std::vector<ForceRun>& runs) {
  std::vector<std::optional<recording::CfRecording>> cfs;
  for (const ForceRun& run : runs) {
    cfs.emplace_back();
    if (!run.truth_cf) continue;
    cfs.back() = recording::readCf(*run.truth_cf);
    if (cfs.back()->rows.size() != run.table.rows.size()) {
      throw std::invalid_argument(fmt::format(
          "{}: {} rows where the recording has {}: a cf file pairs with its rs file row by row",
          run.truth_cf->string(), cfs.back()->rows.size(), run.table.rows.size()));
    }
  }
  std::vector<ChannelSummary> out;
  for (const char* arm : {"left_", "right_"}) {
    for (const char* channel : kChannels) out.push_back(summariseChannel(runs, cfs, arm, channel));
  }
  return out;
}

}  // namespace analysis
