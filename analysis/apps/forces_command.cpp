#include "forces_command.hpp"

#include <cstdio>

#include "analysis/force_report.hpp"
#include "common/number_checks.hpp"
#include "recording/cf_recording.hpp"

namespace analysis {

namespace {

void printSummary(const std::vector<ChannelSummary>& channels, bool with_truth) {
  std::printf("%-18s %9s %9s %6s %12s %9s %6s", "channel (N)", "mean", "sd", "rows",
              "jaws apart:", "sd", "rows");
  if (with_truth) {
    std::printf(" %9s %9s %9s %7s %7s", "touching", "truth", "estimate", "in 2sd", "in 25%");
  }
  std::printf("\n");
  for (const auto& c : channels) {
    std::printf("%-18s %9.3f %9.3f %6zu %12.3f %9.3f %6zu", c.name.c_str(), c.mean, c.mean_sd,
                c.rows, c.apart_mean, c.apart_sd, c.apart_rows);
    if (with_truth) {
      std::printf(" %9zu", c.truth_rows);
      if (c.truth_median) {
        std::printf(" %9.3f %9.3f %6.0f%% %6.0f%%", *c.truth_median, *c.estimate_median,
                    100.0 * *c.within_2sd, 100.0 * *c.within_25_percent);
      }
    }
    std::printf("\n");
  }
}

}  // namespace

CLI::App& addForcesCommand(CLI::App& app, ForcesArgs& args) {
  CLI::App& forces = *app.add_subcommand(
      "forces",
      "Estimates from an rs recording's motor signals (DAC counts or Tau, motor angles, joints) "
      "each tool tip's force and each jaw's squeeze, with their standard deviation, through the "
      "twin's model of the arm (docs/forces.md). Writes DIR/forces.csv (the cf file's column "
      "names, plus <name>_sd) and DIR/forces.png; for several files DIR/<rs stem>/ each, and one "
      "summary over them.");
  forces
      .add_option("rs_files", args.rs_files,
                  "rs recordings (the twin's or the robot's); several: one summary over all")
      ->required()
      ->check(CLI::ExistingFile);
  forces.add_option("--out", args.out, "output directory");
  forces
      .add_option("--calibration", args.calibration,
                  "calibration profile (YAML; default: the shipped one)")
      ->check(CLI::ExistingFile);
  auto* truth =
      forces
          .add_option("--truth", args.truth,
                      "the twin's cf file of the run (one rs file): compared, drawn beside it")
          ->check(CLI::ExistingFile);
  forces
      .add_flag("--truth-beside", args.truth_beside,
                "each rs file's cf file beside it (x_rs.csv, x_cf.csv) as its truth")
      ->excludes(truth);
  forces
      .add_option("--grip-depth", args.grip.depth,
                  "m from the jaw axis to where the jaws hold the object (the squeeze's lever)")
      ->check(common::finiteWithin(0.001, 0.011));
  forces
      .add_option("--grip-spread", args.grip.spread,
                  "m either side of the grip depth the contact may lie")
      ->check(common::finiteWithin(0.0, 0.005));
  forces.add_flag("!--no-figures", args.figures, "write the data only, draw nothing");
  return forces;
}

int runForces(const ForcesArgs& args) {
  if (args.truth && args.rs_files.size() != 1) {
    std::fprintf(stderr,
                 "raven_analyze forces: --truth pairs with one rs file; for several, "
                 "--truth-beside\n");
    return 1;
  }
  const twin::CalibrationProfile profile = twin::CalibrationProfile::load(
      args.calibration.value_or(twin::CalibrationProfile::shippedFile()));
  std::vector<ForceRun> runs;
  for (const auto& rs : args.rs_files) {
    ForceRun run{estimateForces(rs, profile, args.grip), args.truth};
    if (args.truth_beside) run.truth_cf = recording::cfPathFor(rs);
    const auto dir = args.rs_files.size() == 1 ? args.out : args.out / rs.stem();
    std::filesystem::create_directories(dir);
    writeForces(run.table, dir / "forces.csv");
    if (args.figures) {
      if (const auto why = drawForces(dir, run.truth_cf); !why.empty()) {
        std::fprintf(stderr, "raven_analyze forces: no figure: %s\n", why.c_str());
        return 1;
      }
    }
    runs.push_back(std::move(run));
  }
  const bool with_truth = args.truth || args.truth_beside;
  if (args.rs_files.size() > 1) std::printf("%zu recordings\n", runs.size());
  printSummary(summarise(runs), with_truth);
  std::printf("forces: %s\n", args.out.c_str());
  return 0;
}

}  // namespace analysis
