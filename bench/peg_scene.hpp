#pragma once
// The main job's first seconds as a timed run, shared by the loop-frequency and viewer sections.

#include <filesystem>
#include <vector>

#include "bridge/raven_platform.hpp"
#include "scenario/arm_routine.hpp"
#include "scenario/peg_transfer.hpp"

namespace bench {

/// How one timed run of the peg-transfer scene is made.
struct PegSceneRun {
  std::filesystem::path launch;
  bridge::ClockKind clock = bridge::ClockKind::Simulated;
  bool sleep = true;
  scenario::AssistMode assist = scenario::AssistMode::Off;  ///< friction grasps by default
  double seconds = 0.0;
  scenario::WorldObserver observe{};
  double squeeze = scenario::ArmRoutine::kDefaultSqueeze;  ///< m into the ring's wall
};

/// The loop frequency (physics steps per wall second) of one run, over the whole run and over
/// the manual-loop iterations in which both arms held a ring (0 if they never did together).
struct PegSceneRate {
  double whole = 0.0;
  double both_holding = 0.0;
};

/// `repeat` runs of `run`.
std::vector<PegSceneRate> pegScene(const PegSceneRun& run, int repeat);

/// The whole-run rates of `rates`.
std::vector<double> wholeRates(const std::vector<PegSceneRate>& rates);

}  // namespace bench
