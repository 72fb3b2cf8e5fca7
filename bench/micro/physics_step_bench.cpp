// Cost of one 1 ms physics step: the bundled demo scene; our Raven-II (simplified and dense
// collision) holding home, alone and in the peg-transfer scene; and, when ../shared/data is
// present, AMBF's Raven-II and peg_and_base on a floor.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "ambf_like/scene_loader.hpp"
#include "ambf_like/step_guard.hpp"
#include "ambf_like/world.hpp"
#include "raven/platform_profile.hpp"
#include "twin/twin_arms.hpp"

namespace {

const std::filesystem::path kExamples = AMBF_LIKE_EXAMPLES_DIR;
const std::filesystem::path kShared = RAVEN_SHARED_DATA_DIR;

const std::filesystem::path kRavenModels = RAVEN_MODELS_DIR;
const std::filesystem::path kDenseModels = RAVEN_DENSE_MODELS_DIR;

/// Steps a scene; `holdRaven` commands both Raven-II arms to their home pose first. A scene
/// that diverges is reported as this benchmark's error, not thrown out of micro_bench.
void stepScene(benchmark::State& state, const ambf_like::LoadedScene& scene,
               bool holdRaven = false) {
  ambf_like::MeshLibrary meshes;
  ambf_like::World world(scene.spec, meshes);
  if (holdRaven) {
    twin::TwinArms arms(world, twin::ArmBindings::ourRaven());
    const auto home = raven::builtinProfile("physical").home;
    for (auto arm : raven::kArms) arms.command(arm, home);
  }
  try {
    world.step(200);  // let bodies settle into contact first
    for (auto _ : state) world.step();
  } catch (const ambf_like::SimulationDiverged& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  if (!world.isFinite()) state.SkipWithError("the simulation produced NaN");
}

/// Every scene is timed over the same 2 simulated seconds after its settling steps, the same
/// stretch of its motion in every repetition (Google Benchmark would otherwise choose how long
/// one world runs, past where its scene ends).
constexpr benchmark::IterationCount kSceneSteps = 2000;

void BM_DemoScene(benchmark::State& state) {
  stepScene(state, ambf_like::loadLaunchFile(kExamples / "demo/launch.yaml", {}));
}
BENCHMARK(BM_DemoScene)->Iterations(kSceneSteps);

void BM_OurRavenHoldingHome(benchmark::State& state) {
  stepScene(state, ambf_like::loadLaunchFile(kRavenModels / "raven2/launch.yaml", {}), true);
}
BENCHMARK(BM_OurRavenHoldingHome)->Iterations(kSceneSteps);

void BM_OurRavenDenseCollisionHoldingHome(benchmark::State& state) {
  stepScene(state, ambf_like::loadLaunchFile(kDenseModels / "raven2/launch.yaml", {}), true);
}
BENCHMARK(BM_OurRavenDenseCollisionHoldingHome)->Iterations(kSceneSteps);

void BM_PegTransferSceneAtRest(benchmark::State& state) {
  stepScene(state, ambf_like::loadLaunchFile(kRavenModels / "peg_transfer/launch.yaml", {}), true);
}
BENCHMARK(BM_PegTransferSceneAtRest)->Iterations(kSceneSteps);

/// Marks the benchmark skipped when a file of ../shared/data is not there.
bool sharedFileMissing(benchmark::State& state, const std::filesystem::path& file) {
  if (std::filesystem::exists(file)) return false;
  state.SkipWithError("../shared/data is absent");
  return true;
}

void BM_AmbfRaven(benchmark::State& state) {
  const auto launch = kShared / "ambf/ambf_controller/raven2/launch.yaml";
  if (sharedFileMissing(state, launch)) return;
  ambf_like::LoadOptions options;
  stepScene(state, ambf_like::loadLaunchFile(launch, {}, options));
}
BENCHMARK(BM_AmbfRaven)->Iterations(kSceneSteps);

void BM_PegAndBaseOnFloor(benchmark::State& state) {
  const auto puzzle =
      kShared / "ambf/ambf_models/descriptions/multi-bodies/puzzles/peg_and_base.yaml";
  if (sharedFileMissing(state, puzzle)) return;
  stepScene(state, ambf_like::loadModelFiles({puzzle, kExamples / "floor.yaml"}));
}
BENCHMARK(BM_PegAndBaseOnFloor)->Iterations(kSceneSteps);

}  // namespace

BENCHMARK_MAIN();
