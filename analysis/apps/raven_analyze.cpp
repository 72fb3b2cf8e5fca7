// raven_analyze: how far each simulated platform's replays sit from the physical robot's and from
// each other (the paper's T_SS, T_PP, T_PS), per joint and, where the recordings log them, per
// actuator signal (mpos, mvel, Tau, dac_vals), with correlating factors and figures; and
// `raven_analyze forces`, the forces behind a recording's motor signals.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "analysis/actuator_report.hpp"
#include "analysis/metrics.hpp"
#include "analysis/report.hpp"
#include "analysis/trial_set.hpp"
#include "common/number_checks.hpp"
#include "forces_command.hpp"

namespace {

void printSummary(const analysis::TrialSet& set) {
  for (const auto& p : set.platforms) {
    std::printf("%-9s %zu trial(s)\n", p.profile.name.c_str(), p.trials.size());
  }
  for (const auto& issue : set.issues) {
    std::printf("%s %s: %s\n", issue.excluded ? "excluded" : "note    ",
                issue.path.string().c_str(), issue.reason.c_str());
  }
  // The paper's summary figures (Fig. 7): joint positions j_P and joint velocities j_V.
  std::printf("\nmean absolute difference    j_P as recorded / first row removed    j_V\n");
  for (const auto& c : analysis::comparisons(set)) {
    for (const auto& g : {analysis::revoluteJoints(), analysis::prismaticJoints()}) {
      using analysis::Quantity;
      const double raw = analysis::groupFigure(c, g, Quantity::Position, false);
      const double removed = analysis::groupFigure(c, g, Quantity::Position, true);
      const double velocity = analysis::groupFigure(c, g, Quantity::Velocity, false);
      std::printf("  %-4s %-22s %-9s %9.4f / %9.4f %-3s  %9.4f %s/s\n", c.symbol().c_str(),
                  c.describe().c_str(), g.name.c_str(), raw, removed, g.unit.c_str(), velocity,
                  g.unit.c_str());
    }
  }
}

/// The actuator signals, where the recordings log them: per comparison and signal, the median
/// over the joints of the mean |difference| over the robot's own T_PP.
void printActuators(const std::vector<analysis::ActuatorComparison>& comparisons) {
  if (comparisons.empty()) return;
  std::printf(
      "\nactuator signals (rows by index), median over joints of the mean |difference| over the "
      "robot's T_PP\n");
  std::printf("  %-4s %-22s", "", "");
  for (auto s : analysis::kActuatorSignals) std::printf(" %9s", analysis::columnName(s));
  std::printf("\n");
  for (const auto& c : comparisons) {
    if (!c.median_over_robot) continue;
    std::printf("  %-4s %-22s", c.symbol.c_str(), c.description.c_str());
    for (double v : *c.median_over_robot) std::printf(" %8.2fx", v);
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Compares rs recordings of replays on several platforms (physical Raven-II, AMBF, our twin) "
      "and writes a disparity report: metrics as JSON/CSV, figures as PNG and an HTML page."};
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path out = "disparity_report";
  std::filesystem::path profiles_file = analysis::defaultRecordingSourcesFile();
  std::string align = "index";
  double period = 0.02;
  bool figures = true;
  app.add_option("inputs", inputs, "rs files, or directories of them");
  app.add_option("--out", out, "report directory");
  app.add_option("--profiles", profiles_file, "platform profiles (YAML)")->check(CLI::ExistingFile);
  app.add_option("--align", align, "index: rows by index (the paper's); time: resample on time")
      ->check(CLI::IsMember({"index", "time"}));
  app.add_option("--period", period, "resampling period for --align time (s)")
      ->check(common::finiteWithin(1e-4, 10.0));
  app.add_flag("!--no-figures", figures, "write the data only, draw nothing");
  analysis::ForcesArgs forces_args;
  const CLI::App& forces = analysis::addForcesCommand(app, forces_args);
  app.require_subcommand(0, 1);
  CLI11_PARSE(app, argc, argv);

  try {
    if (forces.parsed()) return analysis::runForces(forces_args);
    if (inputs.empty()) {
      std::fprintf(stderr, "raven_analyze: no inputs (rs files or directories; --help)\n");
      return 1;
    }
    const auto profiles = analysis::readRecordingSources(profiles_file);
    analysis::TrialSet set = analysis::loadTrials(inputs, profiles);
    analysis::ReportSettings settings;
    if (align == "time") {
      analysis::resampleOnTime(set, period);
      settings.alignment = "time, resampled every " + std::to_string(period) + " s";
    }
    printSummary(set);
    if (set.platforms.empty()) {
      std::fprintf(stderr, "raven_analyze: no usable recording\n");
      return 1;
    }
    analysis::writeReportData(set, settings, out);
    const auto actuators = analysis::actuatorPlatforms(set);
    const auto actuator_comparisons = analysis::compareActuators(actuators);
    printActuators(actuator_comparisons);
    analysis::writeActuatorReport(actuators, actuator_comparisons, out);
    if (const auto pictures = analysis::writePictures(inputs, out)) {
      std::printf("\n%zu snapshot(s) and video(s) of the runs in %s\n", pictures,
                  (out / "pictures").c_str());
    }
    if (figures) {
      if (const auto why = analysis::drawFigures(out); !why.empty()) {
        std::fprintf(stderr, "raven_analyze: no figures: %s\n", why.c_str());
        return 1;
      }
    }
    std::printf("\nreport: %s\n", (out / (figures ? "index.html" : "metrics.json")).c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raven_analyze: %s\n", e.what());
    return 1;
  }
  return 0;
}
