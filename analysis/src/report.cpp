#include "analysis/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "analysis/factors.hpp"
#include "analysis/metrics.hpp"
#include "output_file.hpp"
#include "recording/cf_recording.hpp"

namespace analysis {

namespace {

using nlohmann::json;

/// NaN as JSON null.
json number(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

json inputsJson(const TrialSet& set, const ReportSettings& settings) {
  json platforms = json::array();
  for (const auto& p : set.platforms) {
    json files = json::array();
    for (const auto& t : p.trials) files.push_back({{"file", t.path.string()}, {"rows", t.rows()}});
    platforms.push_back({{"name", p.profile.name},
                         {"label", p.profile.label},
                         {"role", p.profile.role == Role::Physical ? "physical" : "simulation"},
                         {"trials", files}});
  }
  json issues = json::array();
  for (const auto& i : set.issues) {
    issues.push_back({{"file", i.path.string()}, {"reason", i.reason}, {"excluded", i.excluded}});
  }
  return {{"alignment", settings.alignment}, {"platforms", platforms}, {"file issues", issues}};
}

json statsJson(const DifferenceStats& s) {
  return {{"mean_abs", number(s.mean_abs)}, {"rms", number(s.rms)}, {"max", number(s.max)}};
}

/// Fig. 8's numbers for every simulation-vs-physical comparison: correlations.csv, and the points
/// (thinned) and LOWESS trends it is drawn from; returns the correlations for metrics.json.
json writeCorrelations(const ReportSettings& settings, const std::vector<Comparison>& list,
                       const std::filesystem::path& dir) {
  json correlations = json::array();
  auto corr_csv = openOutputFile(dir / "correlations.csv");
  corr_csv << "comparison,joint,column,factor,pearson_r_difference,spearman_rho_abs_difference,"
              "samples\n";
  auto scatter = openOutputFile(dir / "scatter.csv");
  scatter << "comparison,column,factor,value,difference\n";
  auto trend = openOutputFile(dir / "lowess.csv");
  trend << "comparison,column,factor,value,difference\n";
  for (const auto& c : list) {
    if (c.symbol() != "T_PS") continue;
    for (const auto& joint : recordedJoints()) {
      for (Factor f : kFactors) {
        const FactorSamples samples = factorSamples(c, joint.column, f);
        const FactorCorrelation r = correlate(samples);
        correlations.push_back({{"comparison", c.describe()},
                                {"joint", joint.name},
                                {"column", joint.column},
                                {"factor", factorName(f)},
                                {"pearson_r_difference", number(r.pearson_difference)},
                                {"spearman_rho_abs_difference", number(r.spearman_magnitude)},
                                {"samples", r.samples}});
        corr_csv << fmt::format("{},{},{},{},{},{},{}\n", c.describe(), joint.name, joint.column,
                                factorName(f), r.pearson_difference, r.spearman_magnitude,
                                r.samples);
        const std::size_t n = samples.value.size();
        const std::size_t stride = std::max<std::size_t>(1, n / settings.scatter_points);
        for (std::size_t i = 0; i < n; i += stride) {
          scatter << fmt::format("{},{},{},{},{}\n", c.describe(), joint.column, factorName(f),
                                 samples.value[i], samples.difference[i]);
        }
        for (std::size_t i = 0; i < r.trend.x.size(); ++i) {
          trend << fmt::format("{},{},{},{},{}\n", c.describe(), joint.column, factorName(f),
                               r.trend.x[i], r.trend.y[i]);
        }
      }
    }
  }
  return correlations;
}

void writeMetrics(const TrialSet& set, const ReportSettings& settings,
                  const std::vector<Comparison>& list, const std::filesystem::path& dir) {
  json summary = json::array(), joints = json::array();
  auto csv = openOutputFile(dir / "metrics.csv");
  csv << "comparison,symbol,quantity,joint,column,unit,mean_abs,rms,max,"
         "mean_abs_first_row_removed,rms_first_row_removed,max_first_row_removed,pairs,samples\n";
  for (const auto& c : list) {
    for (Quantity q : {Quantity::Position, Quantity::Velocity}) {
      const std::string per_second = q == Quantity::Velocity ? "/s" : "";
      for (const auto& group : {revoluteJoints(), prismaticJoints()}) {
        summary.push_back({{"comparison", c.describe()},
                           {"symbol", c.symbol()},
                           {"quantity", quantityName(q)},
                           {"group", group.name},
                           {"unit", group.unit + per_second},
                           {"mean_abs", number(groupFigure(c, group, q, false))},
                           {"mean_abs_first_row_removed", number(groupFigure(c, group, q, true))}});
      }
      for (const auto& joint : recordedJoints()) {
        const auto raw = jointStats(c, q, joint.column, false);
        const auto removed = jointStats(c, q, joint.column, true);
        joints.push_back({{"comparison", c.describe()},
                          {"symbol", c.symbol()},
                          {"quantity", quantityName(q)},
                          {"joint", joint.name},
                          {"column", joint.column},
                          {"unit", joint.unit + per_second},
                          {"as recorded", statsJson(raw)},
                          {"first row removed", statsJson(removed)},
                          {"pairs", raw.pairs},
                          {"samples", raw.samples}});
        csv << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", c.describe(), c.symbol(),
                           quantityName(q), joint.name, joint.column, joint.unit + per_second,
                           raw.mean_abs, raw.rms, raw.max, removed.mean_abs, removed.rms,
                           removed.max, raw.pairs, raw.samples);
      }
    }
  }
  const json correlations = writeCorrelations(settings, list, dir);
  json joint_names = json::array();
  for (const auto& j : recordedJoints()) {
    joint_names.push_back({{"column", j.column}, {"name", j.name}, {"unit", j.unit}});
  }
  auto out = openOutputFile(dir / "metrics.json");
  out << json{{"inputs", inputsJson(set, settings)},
              {"joints", joint_names},
              {"summary", summary},
              {"per joint", joints},
              {"correlations", correlations}}
             .dump(1)
      << "\n";
}

/// Per platform, joint and row: the smallest, largest and mean value across its trials (Fig. 6).
void writeTrajectories(const TrialSet& set, const std::filesystem::path& dir) {
  auto out = openOutputFile(dir / "trajectories.csv");
  out << "platform,column,row,time,min,max,mean\n";
  for (const auto& p : set.platforms) {
    std::size_t rows = p.trials.front().rows();
    for (const auto& t : p.trials) rows = std::min(rows, t.rows());
    for (const auto& joint : recordedJoints()) {
      const auto col = static_cast<std::size_t>(joint.column);
      for (std::size_t r = 0; r < rows; ++r) {
        double lo = INFINITY, hi = -INFINITY, sum = 0.0;
        int n = 0;
        for (const auto& t : p.trials) {
          const double v = t.position[r][col];
          if (!std::isfinite(v)) continue;
          lo = std::min(lo, v);
          hi = std::max(hi, v);
          sum += v;
          ++n;
        }
        if (n == 0) continue;
        out << fmt::format("{},{},{},{},{},{},{}\n", p.profile.name, joint.column, r,
                           p.trials.front().time[r], lo, hi, sum / n);
      }
    }
  }
}

/// grasp_forces.csv: the cf recordings beside the trials' rs files, for the grip figures.
void writeGraspForceFiles(const TrialSet& set, const std::filesystem::path& dir) {
  auto out = openOutputFile(dir / "grasp_forces.csv");
  out << "platform,file\n";
  for (const auto& p : set.platforms) {
    for (const auto& t : p.trials) {
      const auto cf = recording::cfPathFor(t.path);
      if (std::filesystem::is_regular_file(cf)) {
        out << csvField(p.profile.name) << "," << csvField(cf.string()) << "\n";
      }
    }
  }
}

void writeIssues(const TrialSet& set, const std::filesystem::path& dir) {
  auto out = openOutputFile(dir / "issues.csv");
  out << "file,excluded,reason\n";
  for (const auto& i : set.issues) {
    out << csvField(i.path.string()) << "," << (i.excluded ? "yes" : "no") << ","
        << csvField(i.reason) << "\n";
  }
}

}  // namespace

void writeReportData(const TrialSet& set, const ReportSettings& settings,
                     const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const auto list = comparisons(set);
  writeMetrics(set, settings, list, dir);
  writeTrajectories(set, dir);
  writeGraspForceFiles(set, dir);
  writeIssues(set, dir);
}

std::string runDrawScript(const std::filesystem::path& script,
                          const std::vector<std::filesystem::path>& args) {
  std::string command = "/usr/bin/python3 '" + script.string() + "'";
  for (const auto& arg : args) {
    if (arg.string().find('\'') != std::string::npos) {
      return "a path given to the drawing script holds a quote: " + arg.string();
    }
    command += " '" + arg.string() + "'";
  }
  const int status = std::system(command.c_str());
  if (status == 0) return {};
  return fmt::format("{} exited with status {} (is python3-matplotlib installed?)", script.string(),
                     status);
}

std::string drawFigures(const std::filesystem::path& dir) {
  return runDrawScript(RAVEN_ANALYSIS_DRAW_SCRIPT, {dir});
}

}  // namespace analysis
