// AMBF's own description files in this engine, beside AMBF's figures on the same files: what a user
// who brings an AMBF scene gets.

#include <fmt/format.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "sections.hpp"
#include "steps_per_second.hpp"

namespace bench {

namespace {

const char* kSection = "AMBF's scenes";

/// Simulated seconds of each run, as AMBF's figures were taken: 20 s of 1 ms steps.
constexpr int kSteps = 20000;

/// One of AMBF's scenes: its world file and models (under AMBF's descriptions folder), whether
/// the world file's floor is in it, and AMBF's own rate on them.
struct AmbfScene {
  std::string name;
  std::string world;
  std::vector<std::string> models;
  bool floor;
  double ambf_steps_per_second;
};

/// AMBF's floor (world.yaml's environment), which ../shared/data does not ship.
const std::filesystem::path kAmbfFloor =
    std::filesystem::path(AMBF_LIKE_EXAMPLES_DIR) / "ambf_checkered_floor.yaml";

/// AMBF (branch ambf-2.0, built headless without ROS) on the same files: medians of three runs of
/// 20 s of 1 ms steps on this machine class, from issue 26 (not measured in this run).
const std::vector<AmbfScene>& scenes() {
  static const std::vector<AmbfScene> all{
      {"raven_world + blender-raven2 (zero gravity, idle)",
       "world/raven_world.yaml",
       {"multi-bodies/robots/blender-raven2.yaml"},
       false,
       37615},
      {"world + puzzles/peg_and_base, on AMBF's floor",
       "world/world.yaml",
       {"multi-bodies/puzzles/peg_and_base.yaml"},
       true,
       209680},
      {"world + puzzles/puzzle2, on AMBF's floor",
       "world/world.yaml",
       {"multi-bodies/puzzles/puzzle2.yaml"},
       true,
       19833},
      {"world + sb/cloth (386-node soft body), AMBF's floor",
       "world/world.yaml",
       {"multi-bodies/sb/cloth.yaml"},
       true,
       7399},
  };
  return all;
}

/// Steps per second of `scene` loaded from `root`, from its first step; in `articulation` if given.
double rate(const std::filesystem::path& root, const AmbfScene& scene,
            std::optional<ambf_like::Articulation> articulation = std::nullopt) {
  std::vector<std::filesystem::path> models;
  for (const auto& m : scene.models) models.push_back(root / m);
  if (scene.floor) models.push_back(kAmbfFloor);
  const auto loaded = ambf_like::loadModelFiles(models, root / scene.world);
  ambf_like::MeshLibrary meshes;
  ambf_like::WorldOptions options;
  options.articulation = articulation;
  ambf_like::World world(loaded.spec, meshes, options);
  return stepsPerSecond(world, kSteps, [](int) {});
}

}  // namespace

void measureAmbfScenes(const BenchSettings& s, Report& report) {
  const auto root = s.shared_data / "ambf/ambf_models/descriptions";
  if (!std::filesystem::exists(root)) {
    report.skip(kSection, "AMBF's scenes", "../shared/data is absent: " + root.string());
    return;
  }
  // Scene by scene within each repetition, so a slow spell of the machine hits all of them.
  std::vector<std::vector<double>> rates(scenes().size());
  for (int i = 0; i < s.repeat; ++i) {
    for (std::size_t k = 0; k < scenes().size(); ++k) rates[k].push_back(rate(root, scenes()[k]));
  }
  for (std::size_t k = 0; k < scenes().size(); ++k) {
    const AmbfScene& scene = scenes()[k];
    report.add(
        atLeast(kSection, scene.name, Spread::of(rates[k]), "steps/s", scene.ambf_steps_per_second,
                fmt::format("20 s of 1 ms steps from load; the bound is AMBF's {:.0f} on the "
                            "same files (issue 26, this machine class, not this run)",
                            scene.ambf_steps_per_second)));
  }
  report.skip(kSection, "the Raven with the cloth (scaled 0.1) over its left grasper",
              "no such scene in ../shared/data; issue 26 gives AMBF 6,406 steps/s on it");
  const AmbfScene& raven = scenes().front();
  try {
    std::vector<double> reduced;
    for (int i = 0; i < s.repeat; ++i) {
      reduced.push_back(rate(root, raven, ambf_like::Articulation::Reduced));
    }
    report.add(atLeast(kSection, raven.name + ", articulation: reduced", Spread::of(reduced),
                       "steps/s", 2.0 * raven.ambf_steps_per_second,
                       "each arm one articulation (0_link, welded between the two static bases, "
                       "stays a rigid body); the bound is 2x AMBF's"));
  } catch (const std::exception& e) {
    report.skip(kSection, raven.name + ", articulation: reduced", e.what());
  }
}

}  // namespace bench
