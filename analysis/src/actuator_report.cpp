#include "analysis/actuator_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "output_file.hpp"

namespace analysis {

namespace {

/// Mean over the trial pairs (each unordered pair once within a platform).
SignalJoints pairMeans(const PlatformActuators& a, const PlatformActuators& b) {
  SignalJoints sum = zeroSignals();
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < a.traces.size(); ++i) {
    for (std::size_t j = (&a == &b ? i + 1 : 0); j < b.traces.size(); ++j, ++pairs) {
      for (std::size_t k = 0; k < kActuatorSignals.size(); ++k) {
        const auto d = meanAbsoluteDifference(*a.traces[i], *b.traces[j], kActuatorSignals[k]);
        for (std::size_t arm = 0; arm < 2; ++arm) sum[k][arm] += d[arm];
      }
    }
  }
  for (auto& s : sum) {
    for (auto& arm : s) arm /= static_cast<double>(std::max<std::size_t>(pairs, 1));
  }
  return sum;
}

std::string symbolOf(const PlatformActuators& a, const PlatformActuators& b) {
  const bool pa = a.platform->profile.role == Role::Physical;
  const bool pb = b.platform->profile.role == Role::Physical;
  if (pa && pb) return "T_PP";
  return pa || pb ? "T_PS" : "T_SS";
}

}  // namespace

std::vector<PlatformActuators> actuatorPlatforms(const TrialSet& set) {
  std::vector<PlatformActuators> out;
  for (const auto& p : set.platforms) {
    PlatformActuators a{&p, {}};
    for (const auto& t : p.trials) {
      if (t.actuators) a.traces.push_back(&*t.actuators);
    }
    if (a.traces.size() != p.trials.size()) a.traces.clear();  // only platforms that log them
    out.push_back(std::move(a));
  }
  return out;
}

std::vector<ActuatorComparison> compareActuators(const std::vector<PlatformActuators>& platforms) {
  std::vector<ActuatorComparison> out;
  const PlatformActuators* robot = nullptr;
  for (const auto& p : platforms) {
    if (p.platform->profile.role == Role::Physical && p.traces.size() >= 2) robot = &p;
  }
  const SignalJoints robot_spread = robot ? pairMeans(*robot, *robot) : zeroSignals();
  auto add = [&](const PlatformActuators& a, const PlatformActuators& b) {
    ActuatorComparison c;
    c.symbol = symbolOf(a, b);
    c.description = &a == &b ? a.platform->profile.name
                             : a.platform->profile.name + " vs " + b.platform->profile.name;
    c.mean_abs = pairMeans(a, b);
    if (robot) {
      std::array<double, 4> medians{};
      for (std::size_t k = 0; k < 4; ++k) medians[k] = medianRatio(c.mean_abs[k], robot_spread[k]);
      c.median_over_robot = medians;
    }
    out.push_back(std::move(c));
  };
  for (const auto& p : platforms) {
    if (p.traces.size() >= 2) add(p, p);
  }
  for (std::size_t i = 0; i < platforms.size(); ++i) {
    for (std::size_t j = i + 1; j < platforms.size(); ++j) {
      if (platforms[i].traces.empty() || platforms[j].traces.empty()) continue;
      // The physical robot second: "twin vs physical".
      const bool swap = platforms[i].platform->profile.role == Role::Physical;
      add(swap ? platforms[j] : platforms[i], swap ? platforms[i] : platforms[j]);
    }
  }
  return out;
}

void writeActuatorReport(const std::vector<PlatformActuators>& platforms,
                         const std::vector<ActuatorComparison>& comparisons,
                         const std::filesystem::path& dir) {
  using nlohmann::json;
  json list = json::array();
  auto csv = openOutputFile(dir / "actuators.csv");
  csv << "symbol,comparison,signal,unit,arm,joint,mean_abs\n";
  for (const auto& c : comparisons) {
    json signals = json::object();
    for (std::size_t k = 0; k < 4; ++k) {
      const char* name = columnName(kActuatorSignals[k]);
      json arms = json::object();
      for (raven::Arm arm : raven::kArms) {
        const auto a = raven::slot(arm);
        const raven::ArmJoints& v = c.mean_abs[k][a];
        arms[std::string(raven::armName(arm))] = std::vector<double>(v.data(), v.data() + v.size());
        for (int j = 0; j < raven::kJointCount; ++j) {
          csv << fmt::format("{},{},{},{},{},{},{}\n", c.symbol, c.description, name,
                             loggedUnit(kActuatorSignals[k]), raven::armName(arm),
                             raven::kJointNames[static_cast<std::size_t>(j)], v(j));
        }
      }
      json entry = {{"unit", loggedUnit(kActuatorSignals[k])}, {"mean_abs", arms}};
      if (c.median_over_robot) entry["median_over_T_PP"] = (*c.median_over_robot)[k];
      signals[name] = entry;
    }
    list.push_back({{"symbol", c.symbol}, {"comparison", c.description}, {"signals", signals}});
  }
  json platforms_json = json::array();
  for (const auto& p : platforms) {
    platforms_json.push_back(
        {{"name", p.platform->profile.name}, {"logs actuators", !p.traces.empty()}});
  }
  openOutputFile(dir / "actuators.json")
      << json({{"platforms", platforms_json}, {"comparisons", list}}).dump(1) << "\n";
  auto traj = openOutputFile(dir / "actuator_trajectories.csv");
  traj << "platform,signal,arm,joint,time,mean\n";
  for (const auto& p : platforms) {
    if (p.traces.empty()) continue;
    std::size_t rows = p.traces.front()->rows();
    for (const ActuatorTrace* t : p.traces) rows = std::min(rows, t->rows());
    for (ActuatorSignal s : kActuatorSignals) {
      for (std::size_t a = 0; a < 2; ++a) {
        for (int j = 0; j < raven::kJointCount; ++j) {
          for (std::size_t r = 0; r < rows; ++r) {
            double sum = 0.0;
            for (const ActuatorTrace* t : p.traces) sum += logged(t->arms[a][r], s)(j);
            traj << fmt::format(
                "{},{},{},{},{},{}\n", p.platform->profile.name, columnName(s),
                raven::armName(raven::kArms[a]), raven::kJointNames[static_cast<std::size_t>(j)],
                p.traces.front()->time[r], sum / static_cast<double>(p.traces.size()));
          }
        }
      }
    }
  }
}

}  // namespace analysis
