// Dynamic loop frequency, measured the way the paper reports AMBF's: physics steps of 1 ms per
// wall second, here with both arms moving the soft rings (the main job's first seconds).

#include <fmt/format.h>

#include <cmath>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/world.hpp"
#include "harness/temp_dir.hpp"
#include "peg_scene.hpp"
#include "position_based_pegs.hpp"
#include "raven/platform_profile.hpp"
#include "sections.hpp"
#include "steps_per_second.hpp"
#include "twin/twin_arms.hpp"

namespace bench {

namespace {

const char* kSection = "loop frequency";

/// Our Raven-II alone (`scene`), both arms following a slow sine around home, gravity on, its
/// arms in the given formulation (the model's own is reduced coordinates).
double ravenAloneMoving(ambf_like::SceneSpec scene, ambf_like::Articulation articulation) {
  ambf_like::MeshLibrary meshes;
  scene.world.articulation = articulation;
  ambf_like::World world(scene, meshes);
  twin::TwinArms arms(world, twin::ArmBindings::ourRaven());
  const auto home = raven::builtinProfile("physical").home;
  for (auto arm : raven::kArms) arms.command(arm, home);
  world.step(500);
  return stepsPerSecond(world, 20000, [&](int i) {
    const double phase = 2.0 * M_PI * 0.5 * i * 0.001;  // 0.5 Hz
    for (auto arm : raven::kArms) {
      raven::ArmJoints q = home;
      q[0] += 0.1 * std::sin(phase);
      q[1] += 0.1 * std::sin(phase + 1.0);
      q[2] += 0.01 * std::sin(phase + 2.0);
      arms.command(arm, q);
    }
  });
}

double ambfRavenStill(const std::filesystem::path& launch) {
  ambf_like::LoadOptions load;
  const auto scene = ambf_like::loadLaunchFile(launch, {}, load);
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(scene.spec, meshes);
  world.step(500);
  return stepsPerSecond(world, 20000, [](int) {});
}

/// Our Raven-II alone in both formulations, and AMBF's model of it in this engine.
void measureArmsAlone(const BenchSettings& s, Report& report) {
  // Our arms (in both formulations) and AMBF's model alternate run by run, so a slow spell of
  // the machine hits all three.
  const auto ambf = s.shared_data / "ambf/ambf_controller/raven2/launch.yaml";
  const bool have_ambf = std::filesystem::exists(ambf);
  const auto raven_scene =
      ambf_like::loadLaunchFile(raven::modelDirectory() / "raven2" / "launch.yaml", {}).spec;
  std::vector<double> alone, constrained, ambf_rates, ratios;
  for (int i = 0; i < s.repeat; ++i) {
    alone.push_back(ravenAloneMoving(raven_scene, ambf_like::Articulation::Reduced));
    constrained.push_back(ravenAloneMoving(raven_scene, ambf_like::Articulation::Maximal));
    if (!have_ambf) continue;
    ambf_rates.push_back(ambfRavenStill(ambf));
    ratios.push_back(alone.back() / ambf_rates.back());
  }
  report.add(atLeast(kSection, "Raven-II alone, both arms commanded, gravity on", Spread::of(alone),
                     "steps/s", 46000,
                     "20,000 steps, both arms on a 0.5 Hz sine about home; reduced coordinates "
                     "(the model's own)"));
  report.add(measured(kSection, "Raven-II alone, AMBF's formulation (joints as constraints)",
                      Spread::of(constrained), "steps/s",
                      "the same, `articulation: maximal`, 10 solver iterations"));
  if (have_ambf) {
    report.add(measured(kSection, "AMBF's Raven-II model, standing still, no gravity",
                        Spread::of(ambf_rates), "steps/s",
                        "20,000 steps, 93,239 collision vertices, AMBF's files in this engine"));
    report.add(measured(kSection, "Raven-II alone / AMBF's model", Spread::of(ratios), "x",
                        "run by run, alternating"));
  } else {
    report.skip(kSection, "AMBF's Raven-II model", "../shared/data is absent");
  }
}

}  // namespace

void measureLoopFrequency(const BenchSettings& s, Report& report) {
  const auto simplified = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
  const auto dense = s.dense_models / "peg_transfer" / "launch.yaml";
  const double seconds = s.scene_seconds;
  const std::string moving = fmt::format(
      "main job's first {:.0f} s on the motor twin, the default (both arms moving, rings grasped), "
      "{} runs",
      seconds, s.repeat);

  // Friction grasps (the main job) and the assisted scene alternate run by run.
  std::vector<PegSceneRate> friction, assisted;
  for (int i = 0; i < s.repeat; ++i) {
    friction.push_back(pegScene({.launch = simplified, .seconds = seconds}, 1).front());
    assisted.push_back(
        pegScene(
            {.launch = simplified, .assist = scenario::AssistMode::Contact, .seconds = seconds}, 1)
            .front());
  }
  const auto free_simplified = Spread::of(wholeRates(friction));
  report.add(atLeast(kSection, "peg-transfer scene, simplified collision, free-running",
                     free_simplified, "steps/s", 5000, moving + ", friction grasps"));
  std::vector<double> held, held_assisted;
  for (std::size_t i = 0; i < friction.size(); ++i) {
    held.push_back(friction[i].both_holding);
    held_assisted.push_back(assisted[i].both_holding);
  }
  report.add(atLeast(kSection, "peg-transfer scene, both arms holding a ring (friction grasps)",
                     Spread::of(held), "steps/s", 5000,
                     "the iterations of the same runs in which both arms carried a ring"));
  {
    // The same runs with the rings as they were before they were silicone.
    harness::TempDir dir;
    const auto before = writePositionBasedPegScene(dir.path());
    std::vector<PegSceneRate> position_based;
    for (int i = 0; i < s.repeat; ++i) {
      position_based.push_back(
          pegScene({.launch = before, .seconds = seconds, .squeeze = kPositionBasedSqueeze}, 1)
              .front());
    }
    std::vector<double> held_before;
    for (const auto& r : position_based) held_before.push_back(r.both_holding);
    report.add(measured(kSection,
                        "peg-transfer scene, both arms holding a ring, position-based rings",
                        Spread::of(held_before), "steps/s",
                        "the rings before they were silicone (links, shape matching, 4 substeps "
                        "of 2 iterations, gripped at 1.5 mm), same segment"));
  }
  report.add(measured(kSection, "peg-transfer scene, free-running, grasp assist",
                      Spread::of(wholeRates(assisted)), "steps/s",
                      "the same segment with --grasp-assist contact, alternating"));
  report.add(measured(kSection, "peg-transfer scene, both arms holding a ring (grasp assist)",
                      Spread::of(held_assisted), "steps/s",
                      "the assisted runs' carrying iterations"));
  const auto every_ring = Spread::of(
      wholeRates(pegScene({.launch = simplified, .sleep = false, .seconds = seconds}, 1)));
  report.add(measured(kSection, "peg-transfer scene, simplified, every ring stepped (sleep off)",
                      every_ring, "steps/s", "the same, resting rings never sleep; 1 run"));
  if (std::filesystem::exists(dense)) {
    const auto free_dense =
        Spread::of(wholeRates(pegScene({.launch = dense, .seconds = seconds}, 1)));
    report.add(measured(kSection,
                        "peg-transfer scene, dense collision (~200k vertices), free-running",
                        free_dense, "steps/s", "the same segment; 1 run"));
    report.add(measured(kSection, "simplified / dense ratio",
                        Spread::of({free_simplified.median / free_dense.median}), "x", "medians"));
    // The paper's "before" (reference/paper.md: the visual mesh as collision dropped AMBF's
    // loop from 200 Hz to about 40 Hz on contact): a report beside the simplified row's target.
    report.add(measured(
        kSection, "peg-transfer scene, dense, paced at 1 kHz",
        Spread::of(wholeRates(
            pegScene({.launch = dense, .clock = bridge::ClockKind::Wall, .seconds = 10.0}, 1))),
        "steps/s", "first 10 s on the wall clock; the paper's dense collision, not held to 1 kHz"));
  } else {
    report.skip(kSection, "peg-transfer scene, dense collision", "not built: " + dense.string());
  }
  report.add(
      atLeast(kSection, "peg-transfer scene, simplified, paced at 1 kHz",
              Spread::of(wholeRates(pegScene(
                  {.launch = simplified, .clock = bridge::ClockKind::Wall, .seconds = 10.0}, 1))),
              "steps/s", 990, "first 10 s on the wall clock"));
  measureArmsAlone(s, report);
}

}  // namespace bench
