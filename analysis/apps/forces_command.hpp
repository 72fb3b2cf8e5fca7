#pragma once
// `raven_analyze forces`: its options and what it runs.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <vector>

#include "twin/force_estimator.hpp"

namespace analysis {

/// The forces command's options, as parsed.
struct ForcesArgs {
  std::vector<std::filesystem::path> rs_files;
  std::filesystem::path out = "forces";
  std::optional<std::filesystem::path> calibration;
  std::optional<std::filesystem::path> truth;
  bool truth_beside = false;  ///< each rs file with the cf file beside it (`x_rs.csv`, `x_cf.csv`)
  twin::GripLever grip;
  bool figures = true;
};

/// Adds `forces` to `app`, parsing into `args`.
CLI::App& addForcesCommand(CLI::App& app, ForcesArgs& args);
/// Estimates each file, writes its forces.csv (and figure): DIR/ for one file, DIR/<rs stem>/
/// for several; prints the summary over all of them; the exit status.
int runForces(const ForcesArgs& args);

}  // namespace analysis
