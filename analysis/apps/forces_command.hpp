#pragma once
// `raven_analyze forces`: its options and what it runs.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>

#include "twin/force_estimator.hpp"

namespace analysis {

/// The forces command's options, as parsed.
struct ForcesArgs {
  std::filesystem::path rs_file;
  std::filesystem::path out = "forces";
  std::optional<std::filesystem::path> calibration;
  std::optional<std::filesystem::path> truth;
  twin::GripLever grip;
  bool figures = true;
};

/// Adds `forces` to `app`, parsing into `args`.
CLI::App& addForcesCommand(CLI::App& app, ForcesArgs& args);
/// Estimates, writes DIR/forces.csv (and the figure), prints the summary; the exit status.
int runForces(const ForcesArgs& args);

}  // namespace analysis
