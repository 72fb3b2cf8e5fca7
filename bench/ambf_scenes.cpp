// AMBF's own description files in this engine, beside AMBF's figures on the same files: what a user
// who brings an AMBF scene gets.

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <exception>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "child_output.hpp"
#include "harness/temp_dir.hpp"
#include "one_cpu.hpp"
#include "sections.hpp"
#include "steps_per_second.hpp"

namespace bench {

namespace {

const char* kSection = "AMBF's scenes";

/// Simulated seconds of each run, as AMBF's figures were taken: 20 s of 1 ms steps.
constexpr int kSteps = 20000;

/// One of AMBF's scenes: its id (for AMBF's rate on it), its world file and models (under AMBF's
/// descriptions folder), and whether the world file's floor is in it.
struct AmbfScene {
  std::string id;
  std::string name;
  std::string world;
  std::vector<std::string> models;
  bool floor;
};

/// AMBF's floor (world.yaml's environment), which ../shared/data does not ship.
const std::filesystem::path kAmbfFloor =
    std::filesystem::path(AMBF_LIKE_EXAMPLES_DIR) / "ambf_checkered_floor.yaml";

const std::vector<AmbfScene>& scenes() {
  static const std::vector<AmbfScene> all{
      {"raven",
       "raven_world + blender-raven2 (zero gravity, idle)",
       "world/raven_world.yaml",
       {"multi-bodies/robots/blender-raven2.yaml"},
       false},
      {"peg_and_base",
       "world + puzzles/peg_and_base, on AMBF's floor",
       "world/world.yaml",
       {"multi-bodies/puzzles/peg_and_base.yaml"},
       true},
      {"puzzle2",
       "world + puzzles/puzzle2, on AMBF's floor",
       "world/world.yaml",
       {"multi-bodies/puzzles/puzzle2.yaml"},
       true},
      {"cloth",
       "world + sb/cloth (386-node soft body), AMBF's floor",
       "world/world.yaml",
       {"multi-bodies/sb/cloth.yaml"},
       true},
  };
  return all;
}

/// The commit issue 50 compared with AMBF, built on this host: its bench, issue 50's ratio
/// ours/AMBF on each scene (by id) and the start of that scene's row in its table.
struct Baseline {
  std::filesystem::path bench;
  std::map<std::string, double> ratio;
  std::map<std::string, std::string> row;
};

/// AMBF's rate on each scene (by id; "raven_with_cloth" for issue 26's Raven with the cloth) on
/// one host, and which host that is; with a baseline, re-taken in every repetition instead.
struct AmbfRates {
  std::map<std::string, double> steps_per_second;
  std::string host;  ///< for the rows' notes
  std::optional<Baseline> baseline;
};

/// AMBF (branch ambf-2.0 built headless with its bundled Bullet at -O3 -march=native) on the same
/// files on issue 50's host (an Intel Xeon, 2 cores): its ratios ours/AMBF (medians of 3
/// alternating runs, both without soft-body sleep) applied to this bench's medians of 2026-11-27
/// there. Not measured in this run.
AmbfRates issue50Host() {
  return {{{"raven", 57136 / 1.05},
           {"peg_and_base", 310185 / 1.02},
           {"puzzle2", 35211 / 1.07},
           {"cloth", 13176 / 1.51},
           {"raven_with_cloth", 10870 / 1.49}},
          "issue 50's host, an Intel Xeon; not this run",
          std::nullopt};
}

/// AMBF's rates on this host when scripts/ambf-on-this-host.sh has written them into the build
/// directory on a machine with this CPU; issue 50's host's otherwise. A file that cannot be read
/// is an error naming it.
AmbfRates ambfRates(const BenchSettings& s) {
  const auto file = s.programs / "ambf_on_this_host.json";
  if (!std::filesystem::exists(file)) return issue50Host();
  try {
    const auto j = nlohmann::json::parse(std::ifstream(file));
    if (j.at("cpu").get<std::string>() != s.cpu) {
      spdlog::warn("{} was written on a {}, not this {}: AMBF's rates of issue 50's host apply",
                   file.string(), j.at("cpu").get<std::string>(), s.cpu);
      return issue50Host();
    }
    AmbfRates here{{},
                   fmt::format("this host, from scripts/ambf-on-this-host.sh of {}; not this run",
                               j.at("date").get<std::string>()),
                   std::nullopt};
    for (const auto& [id, rate] : issue50Host().steps_per_second) {
      here.steps_per_second[id] = j.at("steps_per_second").at(id).get<double>();
    }
    if (j.contains("baseline")) {
      const auto& b = j.at("baseline");
      here.baseline = Baseline{b.at("bench").get<std::string>(),
                               b.at("ratio").get<std::map<std::string, double>>(),
                               b.at("row").get<std::map<std::string, std::string>>()};
      if (!std::filesystem::exists(here.baseline->bench)) {
        spdlog::warn("{}: the baseline's bench {} is gone; its rates of {} apply", file.string(),
                     here.baseline->bench.string(), j.at("date").get<std::string>());
        here.baseline.reset();
      }
    }
    return here;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
}

/// The lead over AMBF every scene is held to (issue 50; its goal is 2).
constexpr double kLeadOverAmbf = 1.5;

/// AMBF's rate on each scene here from one run of the baseline's AMBF section: its median over
/// issue 50's ratio. Throws, naming the program, if it fails or lacks a row.
std::map<std::string, double> ambfFromBaseline(const Baseline& baseline) {
  harness::TempDir dir;
  const auto out = dir.path() / "baseline.json";
  if (!outputLinesOf(
          {baseline.bench.string(), "--only", "ambf", "--repeat", "1", "--out", out.string()},
          600.0)) {
    throw std::runtime_error(baseline.bench.string() + " failed");
  }
  const auto rows = nlohmann::json::parse(std::ifstream(out)).at("rows");
  std::map<std::string, double> ambf;
  for (const auto& [id, start] : baseline.row) {
    for (const auto& row : rows) {
      if (row.at("item").get<std::string>().rfind(start, 0) == 0 && row.contains("median")) {
        ambf[id] = row.at("median").get<double>() / baseline.ratio.at(id);
        break;
      }
    }
    if (!ambf.count(id)) throw std::runtime_error(baseline.bench.string() + " has no row " + start);
  }
  return ambf;
}

/// `scene` loaded from `root`.
ambf_like::SceneSpec load(const std::filesystem::path& root, const AmbfScene& scene) {
  std::vector<std::filesystem::path> models;
  for (const auto& m : scene.models) models.push_back(root / m);
  if (scene.floor) models.push_back(kAmbfFloor);
  return ambf_like::loadModelFiles(models, root / scene.world).spec;
}

/// Issue 26's "Raven with the cloth (scaled 0.1) draped over its left grasper", which no file
/// describes, composed from AMBF's files: the Raven in raven_world (its model's own zero
/// gravity), AMBF's floor, and cloth.yaml as it is but scaled 0.1 and placed 3 cm above the
/// middle of the left grasper's jaws. Under the world's gravity it hangs from its fixed node and
/// swings through the jaws: its flags (soft-soft only) give it no contact with rigid bodies, in
/// AMBF as here.
ambf_like::SceneSpec ravenWithCloth(const std::filesystem::path& root) {
  auto spec = load(root, scenes().front());
  ambf_like::MeshLibrary meshes;
  const ambf_like::World raven(spec, meshes);
  const ambf_like::Vec3 jaws = 0.5 * (raven.body("grasper1_L").pose().translation() +
                                      raven.body("grasper2_L").pose().translation());
  const std::size_t cloth_model = spec.models.size();
  ambf_like::appendModelFiles(spec, {root / "multi-bodies/sb/cloth.yaml", kAmbfFloor});
  ambf_like::SoftBodySpec& cloth = spec.models[cloth_model].soft_bodies.at(0);
  cloth.scale = 0.1;
  cloth.location.translation() = jaws + ambf_like::Vec3(0, 0, 0.03);
  return spec;
}

/// One row of the section: a scene as loaded with its world settings, and the id of AMBF's rate
/// it is held to 1.5x of, if it is.
struct Run {
  std::string name;
  ambf_like::SceneSpec spec;
  std::optional<std::string> ambf_id;
  std::string note;
};

/// Steps per second of `run`, from its first step.
double rate(const Run& run) {
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(run.spec, meshes);
  return stepsPerSecond(world, kSteps, [](int) {});
}

/// `run` once more, its world settings changed by `change`: its name followed by `how`.
Run variant(const Run& run, const std::string& how,
            const std::function<void(ambf_like::WorldSpec&)>& change, std::string note) {
  Run changed{run.name + ", " + how, run.spec, std::nullopt, std::move(note)};
  change(changed.spec.world);
  return changed;
}

/// AMBF steps every soft body at every step.
ambf_like::SceneSpec asAmbf(ambf_like::SceneSpec spec) {
  spec.world.soft_body_sleep.enabled = false;
  return spec;
}

/// The rows: AMBF's scenes stepped as AMBF steps them (no soft body ever sleeps there), each
/// held to 1.5x AMBF's rate on it, then this simulator's own defaults and fast path beside them.
std::vector<Run> runs(const std::filesystem::path& root) {
  std::vector<Run> all;
  for (const AmbfScene& scene : scenes()) {
    all.push_back({scene.name, asAmbf(load(root, scene)), scene.id,
                   "20 s of 1 ms steps from load, no soft-body sleep"});
  }
  all.push_back({"the Raven with the cloth (scaled 0.1) hanging at its left grasper",
                 asAmbf(ravenWithCloth(root)), "raven_with_cloth",
                 "composed from AMBF's files as docs/ambf-scenes.md says, no soft-body sleep"});
  const Run raven = all.front();
  const Run peg_and_base = all[1];
  const Run puzzle2 = all[2];
  const Run cloth = all[scenes().size() - 1];  // the last of AMBF's scenes
  const Run raven_with_cloth = all.back();
  const std::string sleep_on = "soft-body sleep on (our default)";
  auto sleep = [](ambf_like::WorldSpec& world) { world.soft_body_sleep.enabled = true; };
  all.push_back(variant(cloth, sleep_on, sleep,
                        "the cloth sleeps once it stops moving; AMBF has no such thing"));
  all.push_back(variant(raven_with_cloth, sleep_on, sleep, "the same"));
  auto maximal = [](ambf_like::WorldSpec& world) {
    world.articulation = ambf_like::Articulation::Maximal;
  };
  all.push_back(variant(raven, "articulation: maximal", maximal,
                        "every joint a constraint, AMBF's way (the default makes each arm one "
                        "articulation; 0_link, welded between the two static bases, stays a "
                        "rigid body)"));
  auto every_body_awake = [](ambf_like::WorldSpec& world) {
    world.rigid_body_sleep.enabled = false;
  };
  for (const Run* puzzle : {&peg_and_base, &puzzle2}) {
    all.push_back(variant(*puzzle, "rigid-body sleep off", every_body_awake,
                          "every resting piece stepped, as before issue 50"));
  }
  return all;
}

}  // namespace

void measureAmbfScenes(const BenchSettings& s, Report& report) {
  const auto root = s.shared_data / "ambf/ambf_models/descriptions";
  if (!std::filesystem::exists(root)) {
    report.skip(kSection, "AMBF's scenes", "../shared/data is absent: " + root.string());
    return;
  }
  std::vector<Run> all;
  AmbfRates ambf;
  try {
    all = runs(root);
    ambf = ambfRates(s);
  } catch (const std::exception& e) {
    report.skip(kSection, "AMBF's scenes", e.what());
    return;
  }
  // Row by row within each repetition, so a slow spell of the machine hits all of them; the
  // baseline's rows too, when it is there, so AMBF's rate here is taken beside ours, on the
  // same CPU.
  const OneCpu pinned;
  std::vector<std::vector<double>> rates(all.size());
  std::map<std::string, std::vector<double>> ambf_here;
  for (int i = 0; i < s.repeat; ++i) {
    for (std::size_t k = 0; k < all.size(); ++k) rates[k].push_back(rate(all[k]));
    if (!ambf.baseline) continue;
    try {
      for (const auto& [id, r] : ambfFromBaseline(*ambf.baseline)) ambf_here[id].push_back(r);
    } catch (const std::exception& e) {
      spdlog::warn("{}; AMBF's rates of {} apply", e.what(), ambf.host);
      ambf.baseline.reset();
      ambf_here.clear();
    }
  }
  if (!ambf_here.empty()) {
    for (auto& [id, r] : ambf_here) ambf.steps_per_second[id] = Spread::of(r).median;
    ambf.host = fmt::format(
        "this host: a514963's rate in this run, beside ours on CPU {}, over issue 50's ratio",
        pinned.cpu());
  }
  for (std::size_t k = 0; k < all.size(); ++k) {
    const Run& run = all[k];
    const Spread value = Spread::of(rates[k]);
    if (!run.ambf_id) {
      report.add(measured(kSection, run.name, value, "steps/s", run.note));
      continue;
    }
    const double rate_of_ambf = ambf.steps_per_second.at(*run.ambf_id);
    report.add(atLeast(kSection, run.name, value, "steps/s", kLeadOverAmbf * rate_of_ambf,
                       fmt::format("{}; the bound is 1.5x AMBF's {:.0f} on the same files on {}",
                                   run.note, rate_of_ambf, ambf.host)));
  }
}

}  // namespace bench
