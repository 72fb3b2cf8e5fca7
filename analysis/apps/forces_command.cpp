#include "forces_command.hpp"

#include <cstdio>

#include "analysis/force_report.hpp"

namespace analysis {

namespace {

void printSummary(const std::vector<ChannelSummary>& channels, bool with_truth) {
  std::printf("%-18s %9s %9s %6s %12s %9s %6s", "channel (N)", "mean", "sd", "rows",
              "jaws apart:", "sd", "rows");
  if (with_truth) std::printf(" %9s %9s %9s %7s", "touching", "truth", "estimate", "in 2sd");
  std::printf("\n");
  for (const auto& c : channels) {
    std::printf("%-18s %9.3f %9.3f %6zu %12.3f %9.3f %6zu", c.name.c_str(), c.mean, c.mean_sd,
                c.rows, c.apart_mean, c.apart_sd, c.apart_rows);
    if (with_truth) {
      std::printf(" %9zu", c.truth_rows);
      if (c.truth_median) {
        std::printf(" %9.3f %9.3f %6.0f%%", *c.truth_median, *c.estimate_median,
                    100.0 * *c.within_2sd);
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
      "names, plus <name>_sd) and DIR/forces.png.");
  forces.add_option("rs_file", args.rs_file, "an rs recording (the twin's or the robot's)")
      ->required()
      ->check(CLI::ExistingFile);
  forces.add_option("--out", args.out, "output directory");
  forces
      .add_option("--calibration", args.calibration,
                  "calibration profile (YAML; default: the shipped one)")
      ->check(CLI::ExistingFile);
  forces
      .add_option("--truth", args.truth,
                  "the twin's cf file of the same run: compared and drawn beside the estimate")
      ->check(CLI::ExistingFile);
  forces
      .add_option("--grip-depth", args.grip.depth,
                  "m from the jaw axis to where the jaws hold the object (the squeeze's lever)")
      ->check(CLI::Range(0.001, 0.011));
  forces
      .add_option("--grip-spread", args.grip.spread,
                  "m either side of the grip depth the contact may lie")
      ->check(CLI::Range(0.0, 0.005));
  forces.add_flag("!--no-figures", args.figures, "write the data only, draw nothing");
  return forces;
}

int runForces(const ForcesArgs& args) {
  const twin::CalibrationProfile profile = twin::CalibrationProfile::load(
      args.calibration.value_or(twin::CalibrationProfile::shippedFile()));
  const ForceTable table = estimateForces(args.rs_file, profile, args.grip);
  std::filesystem::create_directories(args.out);
  writeForces(table, args.out / "forces.csv");
  printSummary(summarise(table, args.truth), args.truth.has_value());
  if (args.figures) {
    if (const auto why = drawForces(args.out, args.truth); !why.empty()) {
      std::fprintf(stderr, "raven_analyze forces: no figure: %s\n", why.c_str());
      return 1;
    }
  }
  std::printf("forces: %s\n", (args.out / "forces.csv").c_str());
  return 0;
}

}  // namespace analysis
