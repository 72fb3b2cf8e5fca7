#include "analysis/trial_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

namespace analysis {

namespace {

/// The index of the first row whose time is not finite or not after the one before, if any.
std::optional<std::size_t> firstTimeOutOfOrder(const Trial& trial) {
  for (std::size_t k = 0; k < trial.time.size(); ++k) {
    if (!std::isfinite(trial.time[k]) || (k > 0 && !(trial.time[k] > trial.time[k - 1]))) {
      return std::max<std::size_t>(k, 1);
    }
  }
  return std::nullopt;
}

/// The files named, directories expanded (sorted; ci files are inputs, not states).
std::vector<std::filesystem::path> expand(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::filesystem::path> files;
  for (const auto& input : inputs) {
    if (!std::filesystem::is_directory(input)) {
      files.push_back(input);
      continue;
    }
    std::vector<std::filesystem::path> inside;
    for (const auto& entry : std::filesystem::directory_iterator(input)) {
      const auto name = entry.path().filename().string();
      // Gamepad inputs and grasp forces are not robot states.
      const bool other = name.ends_with("_ci.csv") || name.ends_with("_cf.csv");
      if (entry.path().extension() == ".csv" && !other) {
        inside.push_back(entry.path());
      }
    }
    std::sort(inside.begin(), inside.end());
    files.insert(files.end(), inside.begin(), inside.end());
  }
  return files;
}

/// Runs of NaN in a joint position column, e.g. "jpos2 rows 40-59"; empty when none is long.
std::vector<std::string> nanRuns(const Trial& t) {
  std::vector<std::string> runs;
  for (std::size_t c = 0; c < kJointColumns; ++c) {
    std::size_t start = 0, length = 0;
    for (std::size_t r = 0; r <= t.rows(); ++r) {
      if (r < t.rows() && std::isnan(t.position[r][c])) {
        if (length++ == 0) start = r;
        continue;
      }
      if (length >= kNanRunReported) {
        runs.push_back(fmt::format("jpos{} rows {}-{}", c, start + 2, start + length + 1));
      }
      length = 0;
    }
  }
  return runs;
}

}  // namespace

Trial toTrial(const recording::RsRecording& rs, const RecordingSource& profile) {
  Trial t;
  t.path = rs.path;
  std::array<std::size_t, kJointColumns> pos{}, vel{};
  for (int c = 0; c < kJointColumns; ++c) {
    pos[static_cast<std::size_t>(c)] = rs.column("jpos" + std::to_string(c));
    vel[static_cast<std::size_t>(c)] = rs.column("jvel" + std::to_string(c));
  }
  const std::size_t time_column = rs.column("time");
  const double t0 = rs.rows.empty() ? 0.0 : rs.rows.front()[time_column];
  for (const auto& row : rs.rows) {
    t.time.push_back(row[time_column] - t0);
    JointRow p{}, v{};
    for (std::size_t c = 0; c < kJointColumns; ++c) {
      p[c] = row[pos[c]] + profile.position_offset[c];
      v[c] = row[vel[c]];
    }
    t.position.push_back(p);
    t.velocity.push_back(v);
  }
  return t;
}

const PlatformTrials* TrialSet::find(const std::string& name) const {
  for (const auto& p : platforms) {
    if (p.profile.name == name) return &p;
  }
  return nullptr;
}

TrialSet loadTrials(const std::vector<std::filesystem::path>& inputs,
                    const std::vector<RecordingSource>& profiles) {
  TrialSet set;
  std::map<std::string, std::vector<Trial>> by_platform;
  for (const auto& file : expand(inputs)) {
    try {
      const auto rs = recording::readRs(file, recording::NonFiniteJoints::Keep);
      const RecordingSource* profile = sourceOf(profiles, file, rs.variant);
      if (!profile) {
        set.issues.push_back({file, "no platform profile claims this file"});
        continue;
      }
      if (rs.rows.size() < 2) {
        set.issues.push_back({file, fmt::format("{} rows: nothing to compare", rs.rows.size())});
        continue;
      }
      Trial trial = toTrial(rs, *profile);
      if (const auto bad = firstTimeOutOfOrder(trial)) {
        set.issues.push_back(
            {file, fmt::format("data row {}: time {} s does not come after the row before it "
                               "({} s); times must be finite and increasing (file skipped)",
                               *bad + 1, trial.time[*bad], trial.time[*bad - 1])});
        continue;
      }
      const auto runs = nanRuns(trial);
      if (!runs.empty()) {
        std::string list;
        for (const auto& r : runs) list += (list.empty() ? "" : ", ") + r;
        set.issues.push_back({file, "NaN in " + list + " (those rows are skipped)", false});
      }
      trial.actuators = loggedActuatorTrace(rs);
      by_platform[profile->name].push_back(std::move(trial));
    } catch (const std::exception& e) {
      set.issues.push_back({file, e.what()});
    }
  }
  for (const auto& profile : profiles) {
    auto found = by_platform.find(profile.name);
    if (found == by_platform.end()) continue;
    PlatformTrials platform{profile, std::move(found->second)};
    set.platforms.push_back(std::move(platform));
  }
  // Row-index alignment compares rows up to the shorter trial: say so for every file that is
  // shorter or longer than the most common length.
  std::map<std::size_t, int> lengths;
  for (const auto& p : set.platforms) {
    for (const auto& t : p.trials) ++lengths[t.rows()];
  }
  if (lengths.empty()) return set;
  const auto common = std::max_element(lengths.begin(), lengths.end(), [](auto& a, auto& b) {
                        return a.second < b.second;
                      })->first;
  for (const auto& p : set.platforms) {
    for (const auto& t : p.trials) {
      if (t.rows() != common) {
        set.issues.push_back({t.path,
                              fmt::format("{} rows where most recordings have {}: compared over "
                                          "the rows both files have",
                                          t.rows(), common),
                              false});
      }
    }
  }
  return set;
}

void resampleOnTime(TrialSet& set, double period) {
  if (set.platforms.empty()) return;
  if (!(period > 0.0)) throw std::invalid_argument("the resampling period must be positive");
  double end = std::numeric_limits<double>::infinity();
  for (const auto& p : set.platforms) {
    for (const auto& t : p.trials) end = std::min(end, t.time.back());
  }
  // Times were checked increasing when the trials were read; this bounds what a far jump asks.
  constexpr double kMostSamples = 1e7;
  if (!(end >= 0.0) || end / period > kMostSamples) {
    throw std::invalid_argument(
        fmt::format("resampling {} s of recording every {} s would take more than {:.0f} samples",
                    end, period, kMostSamples));
  }
  const auto samples = static_cast<std::size_t>(std::floor(end / period + 1e-9)) + 1;
  auto interpolate = [](const Trial& t, const std::vector<JointRow>& rows, double at) {
    const auto after = std::upper_bound(t.time.begin(), t.time.end(), at);
    const std::size_t j = std::clamp<std::size_t>(after - t.time.begin(), 1, t.rows() - 1);
    const double span = t.time[j] - t.time[j - 1];
    const double w = span > 0.0 ? std::clamp((at - t.time[j - 1]) / span, 0.0, 1.0) : 0.0;
    JointRow out{};
    for (std::size_t c = 0; c < kJointColumns; ++c) {
      out[c] = (1.0 - w) * rows[j - 1][c] + w * rows[j][c];
    }
    return out;
  };
  for (auto& p : set.platforms) {
    for (auto& t : p.trials) {
      Trial resampled;
      resampled.path = t.path;
      resampled.actuators = std::move(t.actuators);
      for (std::size_t k = 0; k < samples; ++k) {
        const double at = static_cast<double>(k) * period;
        resampled.time.push_back(at);
        resampled.position.push_back(interpolate(t, t.position, at));
        resampled.velocity.push_back(interpolate(t, t.velocity, at));
      }
      t = std::move(resampled);
    }
  }
}

}  // namespace analysis
