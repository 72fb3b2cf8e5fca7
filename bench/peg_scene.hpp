#pragma once
// The main job's first seconds as a timed run, shared by the loop-frequency and viewer sections.

#include <filesystem>
#include <vector>

#include "bridge/raven_platform.hpp"
#include "scenario/run_progress.hpp"

namespace bench {

/// Loop frequencies (steps per wall second) of `repeat` runs of the main job's first `seconds`
/// on the scene of `launch`, each shown to `observe` if set.
std::vector<double> pegScene(const std::filesystem::path& launch, bridge::ClockKind clock,
                             bool sleep, double seconds, int repeat,
                             const scenario::WorldObserver& observe = {});

}  // namespace bench
