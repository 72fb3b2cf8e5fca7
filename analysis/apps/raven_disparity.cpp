// raven_disparity: how far simulated replays sit from physical ones, as the paper's T_SS, T_PP
// and T_PS figures (../shared/reference/recordings.md), for joint positions and velocities.

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>

#include "analysis/disparity.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "Mean absolute joint differences between recordings (rows aligned by index, no "
      "offsets removed), averaged over every pair of trials."};
  std::vector<std::string> sim_files, physical_files;
  app.add_option("--sim", sim_files, "rs files of one simulated platform")->required();
  app.add_option("--physical", physical_files, "rs files of the physical robot")->required();
  bool velocities = false;
  app.add_flag("--velocities", velocities, "also compare jvel");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<controller::RsRecording> sim, physical;
    for (const auto& f : sim_files) sim.push_back(controller::readRs(f));
    for (const auto& f : physical_files) physical.push_back(controller::readRs(f));
    for (const auto* set : {&sim, &physical}) {
      for (const auto& r : *set) {
        std::printf("%s: %zu rows, %s\n", r.path.filename().c_str(), r.rows.size(),
                    r.variant.describe().c_str());
      }
    }
    auto line = [](const char* label, double value, const analysis::JointGroup& g) {
      if (std::isnan(value)) {
        std::printf("  %-34s %-9s  (needs two files)\n", label, g.name.c_str());
      } else {
        std::printf("  %-34s %-9s %10.6f %s\n", label, g.name.c_str(), value, g.unit.c_str());
      }
    };
    std::vector<analysis::Quantity> quantities{analysis::Quantity::Position};
    if (velocities) quantities.push_back(analysis::Quantity::Velocity);
    for (const auto quantity : quantities) {
      const bool position = quantity == analysis::Quantity::Position;
      std::printf("\njoint %s, mean absolute difference\n", position ? "positions" : "velocities");
      for (auto group : {analysis::revoluteJoints(), analysis::prismaticJoints()}) {
        if (!position) group.unit += "/s";
        line("sim vs sim (T_SS)", analysis::withinSet(sim, group, quantity), group);
        line("physical vs physical (T_PP)", analysis::withinSet(physical, group, quantity), group);
        line("sim vs physical (T_PS)", analysis::acrossSets(sim, physical, group, quantity), group);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raven_disparity: %s\n", e.what());
    return 1;
  }
  return 0;
}
